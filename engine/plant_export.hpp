#pragma once
// The engine-ready GLB of a grown plant (`--height`, `--lods`, `--wind` of
// grow, archive and the best-of-generation export; docs/file-formats.md,
// "Engine-ready GLB"): placed at its foot and scaled (plant_frame.hpp),
// named plant_<id>, its record in extras (plant_record.hpp).
#include "engine/leaf_cards.hpp"
#include "engine/plant_record.hpp"
#include "engine/plant_wind.hpp"
#include "core/mesh/mesh.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

struct PlantExportOptions {
    std::optional<double> height_m;  // --height: scale to this many metres; none: a unit is a metre
    int lods = 0;                    // --lods: 0 writes one mesh, N >= 1 writes LOD0 .. LOD(N-1)
    bool wind = false;               // --wind: the _WIND vertex attribute
    std::vector<WindPreset> wind_presets{};  // --wind-preset: copies of _WIND where engines read them (needs wind)
    bool colour = false;             // --colour: COLOR_0 from growth history (docs/algorithm.md §13)
    bool leaves = false;             // --leaves: foliage cards (engine/leaf_cards.hpp)
    std::optional<double> leaf_size{};     // --leaf-size: card length / plant height (needs leaves)
    std::optional<double> leaf_density{};  // --leaf-density: cards per eligible vertex (needs leaves)
    int smooth = 0;                  // --smooth: LOD0 after this many rounds of Loop subdivision (plant_smooth.hpp)

    LeafParams leaf_params() const {
        return {.size = leaf_size.value_or(kDefaultLeafSize), .density = leaf_density.value_or(kDefaultLeafDensity)};
    }

    // Whether any option asks for the engine-ready GLB rather than the plain one.
    // --colour alone is not: grow writes it into OBJ and PLY files as well.
    bool engine_ready() const { return height_m.has_value() || lods > 0 || wind || leaves || smooth != 0; }
};

inline constexpr int kMaxPlantLods = 8;
inline constexpr double kMaxPlantHeightMetres = 1e4;
// 1 mm: far below any plant an engine shows, and far above the heights whose
// scale underflows to a plant of zero size (1e-300 m).
inline constexpr double kMinPlantHeightMetres = 1e-3;

// Why `options` cannot be used, naming the option ("--height -1: must be a
// positive number of metres"), or "" when they can.
std::string plant_export_problem(const PlantExportOptions& options);

// A grown plant as its growth left it.
struct GrownPlant {
    MeshView mesh;
    // For --wind: the step after which each vertex first existed (0: the
    // seed's), one per vertex, and the steps the growth did.
    std::span<const int> birth_steps;
    int steps = 0;
    // For --colour: 4 linear floats per vertex (RGBA, A = 1), colour_rgba()
    // of engine/plant_colour.hpp.
    std::span<const float> colours{};
    // For --leaves: each vertex's light in [0, 1] (leaf_light() of
    // engine/leaf_cards.hpp); empty: its height stands in.
    std::span<const double> light{};
};

// A plant made engine-ready and not yet laid out in glTF: what its GLB holds,
// and what a species pack (engine/species_pack.hpp) reads from it besides.
struct EnginePlant {
    std::string name;                      // "plant_<id>"
    nlohmann::json extras;                 // the record and the placement (docs/file-formats.md)
    std::vector<MeshArrays> levels;        // placed: one mesh without --lods, else LOD0 .. LOD(N-1)
    std::vector<std::vector<float>> wind;  // per level: 4 floats per vertex with --wind, else empty
    std::vector<WindPreset> wind_presets;  // --wind-preset: written beside each level's _WIND
    std::vector<std::vector<float>> colours;  // per level: COLOR_0, 4 floats per vertex with --colour, else empty
    bool lod_nodes = false;                // --lods: levels as child nodes plant_<id>_LOD<i>
    // --lods: per level, its two-sided Hausdorff distance from LOD0 over
    // LOD0's diagonal (plant_lods.hpp); levels may be fewer than asked.
    std::vector<double> lod_distances;
    double height_m = 0.0;                 // the placed plant's height in metres
    std::vector<LeafMesh> leaves{};        // per level with --leaves: its cards (lod_leaves), else empty
};

// A fraction as a percentage rounded to 3 decimals, as extras and the pack's
// manifest write the LOD distances.
double lod_percent(double fraction);

// Places the plant, makes its levels and wind data. With --lods the chain
// stops at the first level that cannot keep its distance bound
// (simplify_lods): extras record `lods_requested` and `lods_written`, and one
// line on stderr says so. With --leaves, the cards (leaf_cards, seeded by the
// record's genome hash) go to every level, thinned as lod_leaves says; a
// plant with none says so on stderr. Throws as plant_glb_bytes.
EnginePlant make_engine_plant(const GrownPlant& plant, const PlantRecord& record, const PlantExportOptions& options);

// The GLB bytes of a plant made engine-ready; IoError naming `source` when
// it cannot be encoded.
std::string plant_glb_bytes(const EnginePlant& plant, const std::string& source);

// The GLB bytes. Throws ConfigError for bad options (plant_export_problem),
// MeshError for a plant that cannot be placed or scaled,
// std::invalid_argument for --wind without one birth step per vertex or
// --colour without 4 colour floats per vertex, IoError naming
// `source` when it cannot be encoded.
std::string plant_glb_bytes(const GrownPlant& plant, const PlantRecord& record, const PlantExportOptions& options,
                            const std::string& source);
// Writes them atomically to `out` (core/base/atomic_file.hpp).
void write_plant_glb(const std::filesystem::path& out, const GrownPlant& plant, const PlantRecord& record,
                     const PlantExportOptions& options);

}  // namespace morphogen
