#pragma once
// A species pack (`archive RUN --pack DIR`; docs/species-pack.md, "Species
// pack"): in one directory, plant_<id>.glb for each species (the
// engine-ready GLB, engine/plant_export.hpp), scatter.glb (a small field of
// them all, engine/plant_scatter.hpp) and manifest.json (what each file
// holds). The same plants and options give the same bytes.
#include "engine/plant_export.hpp"

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace morphogen {

inline constexpr int kPackFormatVersion = 1;

// Where the pack's plants come from, for manifest.json.
struct PackSource {
    std::string run;                    // run.name ("" when not from a run)
    std::string algorithm;              // "map_elites", "steady_state" ("" : not from a run)
    std::vector<std::string> measures;  // the names of the measures each species carries
};

class SpeciesPack {
public:
    // Makes `dir`. Throws ConfigError for bad options (plant_export_problem),
    // IoError when `dir` exists and is not an empty directory (a pack never
    // mixes with other files; one holding a pack's files but no manifest is
    // named an incomplete pack, with how to write it again) or cannot be made.
    SpeciesPack(std::filesystem::path dir, PackSource source, PlantExportOptions options);

    // Makes the plant engine-ready and writes <dir>/plant_<id>.glb
    // atomically. Throws std::invalid_argument for an id that is not
    // [A-Za-z0-9_-]+ or is already in the pack, and as make_engine_plant.
    void add(const GrownPlant& plant, const PlantRecord& record);

    // Writes scatter.glb, then manifest.json (last: a pack with a manifest
    // is whole). Throws std::invalid_argument for a pack without plants.
    void finish();

    // Removes what the pack wrote (its plant files, and `dir` when this pack
    // made it): for a stop before finish(), so nothing half done is left.
    void abandon() noexcept;

    // manifest.json's text for the plants added so far.
    std::string manifest_text() const;

    std::size_t size() const { return plants_.size(); }

private:
    std::filesystem::path dir_;
    PackSource source_;
    PlantExportOptions options_;
    std::vector<EnginePlant> plants_;     // each with its first level only (the scatter's)
    std::vector<nlohmann::json> entries_; // their manifest entries
    std::set<std::string> ids_;
    bool made_dir_ = false;  // `dir` did not exist before
};

}  // namespace morphogen
