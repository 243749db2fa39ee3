#include "engine/plant_export.hpp"
#include "engine/plant_smooth.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "engine/leaf_texture.hpp"
#include "engine/plant_frame.hpp"
#include "engine/plant_lods.hpp"
#include "engine/plant_wind.hpp"
#include "core/io/plant_glb.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace morphogen {

namespace {
std::string shortest(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// --leaves: each level's cards, thinned with its triangles (lod_leaves), and
// their counts in extras. `wind`: LOD0's, where the cards are anchored.
void add_leaves(EnginePlant& ready, std::span<const LeafCard> cards, std::span<const float> wind,
                const PlantExportOptions& options) {
    const LeafParams params = options.leaf_params();
    ready.extras["leaves"] = cards.size();
    ready.extras["leaf_size"] = params.size;
    ready.extras["leaf_density"] = params.density;
    if (cards.empty())
        std::cerr << "morphogen: " << ready.name << ": --leaves: no young, lit vertex to carry a card, so it has none\n";
    const double faces = static_cast<double>(ready.levels.front().faces.size());
    for (const MeshArrays& level : ready.levels) {
        const LodLeaves lod = lod_leaves(cards.size(), static_cast<double>(level.faces.size()) / faces);
        ready.leaves.push_back(leaf_mesh(cards, lod.count, lod.scale, wind));
    }
}
}  // namespace

double lod_percent(double fraction) { return std::round(fraction * 1e5) / 1e3; }

std::string plant_export_problem(const PlantExportOptions& options) {
    if (options.height_m && !(*options.height_m >= kMinPlantHeightMetres && *options.height_m <= kMaxPlantHeightMetres))
        return "--height " + shortest(*options.height_m) + ": must be a number of metres in [0.001, 10000]";
    if (options.lods < 0 || options.lods > kMaxPlantLods)
        return "--lods " + std::to_string(options.lods) + ": must be between 1 and " + std::to_string(kMaxPlantLods);
    if ((options.leaf_size || options.leaf_density) && !options.leaves)
        return std::string(options.leaf_size ? "--leaf-size " + shortest(*options.leaf_size)
                                             : "--leaf-density " + shortest(*options.leaf_density)) +
               ": shapes the cards of --leaves, so it needs --leaves";
    if (options.leaves)
        if (std::string problem = leaf_params_problem(options.leaf_params(), "--leaf-size", "--leaf-density");
            !problem.empty())
            return problem;
    if (!options.wind_presets.empty() && !options.wind)
        return "--wind-preset " + std::string(wind_preset_name(options.wind_presets.front())) +
               ": copies the wind data, so it needs --wind";
    if (std::string problem = smooth_rounds_problem(options.smooth); !problem.empty()) return problem;
    if (options.colour && std::ranges::find(options.wind_presets, WindPreset::color) != options.wind_presets.end())
        return "--colour and --wind-preset color both write COLOR_0: use --wind-preset uv or godot with --colour "
               "(the wind data stays in _WIND)";
    return {};
}

namespace {

// --smooth: LOD0 subdivided, its wind data and colours with it; the other
// levels keep the grown mesh's simplifications.
void smooth_first_level(EnginePlant& ready, int rounds) {
    if (rounds == 0 || ready.levels.empty()) return;
    const std::span<const float> carried[] = {ready.wind.front(), ready.colours.front()};
    SmoothedMesh smooth = smooth_mesh(ready.levels.front().view(), rounds, carried);
    ready.levels.front() = std::move(smooth.mesh);
    ready.wind.front() = std::move(smooth.attributes[0]);
    ready.colours.front() = std::move(smooth.attributes[1]);
    ready.extras["smooth"] = rounds;
}

}  // namespace

EnginePlant make_engine_plant(const GrownPlant& plant, const PlantRecord& record, const PlantExportOptions& options) {
    if (const std::string problem = plant_export_problem(options); !problem.empty()) throw ConfigError(problem);
    PlacedPlant placed = place_plant(plant.mesh, options.height_m);

    EnginePlant ready{.name = "plant_" + record.id, .extras = record_json(record), .levels = {}, .wind = {},
                      .wind_presets = options.wind_presets, .colours = {}, .lod_nodes = options.lods > 0, .lod_distances = {},
                      .height_m = placed.height_m};
    ready.extras["generator"] = "morphogen";
    ready.extras["height_m"] = placed.height_m;
    ready.extras["metres_per_unit"] = placed.metres_per_unit;
    if (options.wind) ready.extras["wind"] = "_WIND";
    if (!options.wind_presets.empty()) {
        nlohmann::json names = nlohmann::json::array();
        for (const std::string_view name : kWindPresetNames)
            if (std::ranges::find(options.wind_presets, *wind_preset_named(name)) != options.wind_presets.end())
                names.push_back(name);
        ready.extras["wind_presets"] = names;
    }
    std::vector<float> wind;
    if (options.wind) wind = plant_wind(placed.mesh.view(), plant.birth_steps, plant.steps);
    std::vector<float> colours;
    if (options.colour) {
        if (plant.colours.size() != 4 * plant.mesh.positions.size())
            throw std::invalid_argument("--colour: " + std::to_string(plant.colours.size()) + " colour floats for " +
                                        std::to_string(plant.mesh.positions.size()) + " vertices (4 each)");
        colours.assign(plant.colours.begin(), plant.colours.end());
        ready.extras["colour"] = "COLOR_0";
    }
    std::vector<LeafCard> cards;
    if (options.leaves)
        cards = leaf_cards({.placed = placed.mesh.view(), .birth_steps = plant.birth_steps, .steps = plant.steps,
                            .light = plant.light, .seed = leaf_seed(record.genome_hash)},
                           options.leaf_params());
    if (options.lods == 0) {
        ready.levels.push_back(std::move(placed.mesh));
        if (options.leaves) add_leaves(ready, cards, wind, options);
        ready.wind.push_back(std::move(wind));
        ready.colours.push_back(std::move(colours));
        smooth_first_level(ready, options.smooth);
        return ready;
    }
    PlantLods lods = simplify_lods(placed.mesh.view(), options.lods);
    const bool short_chain = lods.short_chain();
    ready.levels = std::move(lods.levels);
    ready.lod_distances = lods.distances;
    ready.extras["lods_requested"] = options.lods;
    ready.extras["lods_written"] = ready.levels.size();
    if (short_chain) {
        const int next = static_cast<int>(ready.levels.size());
        std::cerr << "morphogen: " << ready.name << ": --lods " << options.lods << ": wrote " << next << " level(s); ";
        if (lods.refused_distance > 0)
            std::cerr << "LOD" << next << " came no nearer than " << lod_percent(lods.refused_distance)
                      << " % of the diagonal to LOD0 (bound " << lod_percent(lod_distance_bound(next))
                      << " %) at half the triangles or a little more";
        else
            std::cerr << "LOD" << next << " could not be made (the plant has " << ready.levels.front().faces.size()
                      << " triangles; a level keeps at least " << kMinLodFaces << ")";
        std::cerr << ", so the chain stops at LOD" << next - 1 << "\n";
    }
    for (const MeshArrays& level : ready.levels) {
        if (!options.wind) ready.wind.emplace_back();
        else if (ready.wind.empty()) ready.wind.push_back(wind);
        else ready.wind.push_back(transfer_wind(placed.mesh.view(), wind, level.view()));
        // Colours go to the levels as the wind does: each vertex takes LOD0's nearest.
        if (!options.colour) ready.colours.emplace_back();
        else if (ready.colours.empty()) ready.colours.push_back(colours);
        else ready.colours.push_back(transfer_wind(placed.mesh.view(), colours, level.view()));
    }
    if (options.leaves) add_leaves(ready, cards, wind, options);
    smooth_first_level(ready, options.smooth);
    return ready;
}

std::string plant_glb_bytes(const EnginePlant& plant, const std::string& source) {
    const bool coloured = !plant.colours.empty() && !plant.colours.front().empty();
    PlantGlb glb{.name = plant.name, .extras = plant.extras, .levels = {}, .lod_nodes = plant.lod_nodes,
                 .vertex_colours = coloured};
    if (!plant.leaves.empty() && plant.leaves.front().cards() > 0) glb.leaf_png = leaf_texture_png();
    for (std::size_t i = 0; i < plant.levels.size(); ++i) {
        nlohmann::json extras;
        if (plant.lod_nodes) extras = {{"triangles", plant.levels[i].faces.size()}};
        if (plant.lod_nodes && i > 0) extras["hausdorff_percent"] = lod_percent(plant.lod_distances[i]);
        if (plant.lod_nodes && !plant.leaves.empty()) extras["leaves"] = plant.leaves[i].cards();
        std::vector<VertexAttribute> attributes = wind_preset_attributes(plant.wind[i], plant.wind_presets);
        if (coloured) attributes.push_back({.name = "COLOR_0", .components = 4, .values = plant.colours[i]});
        glb.levels.push_back(PlantLevel{.mesh = plant.levels[i].view(),
                                        .wind = plant.wind[i],
                                        .attributes = std::move(attributes),
                                        .extras = extras});
        if (!plant.leaves.empty())
            glb.levels.back().leaves = {.mesh = plant.leaves[i].mesh.view(), .uv = plant.leaves[i].uv,
                                        .wind = plant.leaves[i].wind,
                                        .attributes = wind_preset_attributes(plant.leaves[i].wind, plant.wind_presets)};
    }
    return plant_glb_bytes(glb, source);
}

std::string plant_glb_bytes(const GrownPlant& plant, const PlantRecord& record, const PlantExportOptions& options,
                            const std::string& source) {
    return plant_glb_bytes(make_engine_plant(plant, record, options), source);
}

void write_plant_glb(const std::filesystem::path& out, const GrownPlant& plant, const PlantRecord& record,
                     const PlantExportOptions& options) {
    write_file_atomically(out, plant_glb_bytes(plant, record, options, out.string()));
}

}  // namespace morphogen
