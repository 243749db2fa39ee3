// The species pack (see species_pack.hpp).
#include "engine/species_pack.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "engine/plant_scatter.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <system_error>

namespace morphogen {

namespace fs = std::filesystem;

namespace {

constexpr const char* kScatterFile = "scatter.glb";
constexpr const char* kManifestFile = "manifest.json";

// Whether `dir` holds a file a pack writes (plant_*.glb, scatter.glb) and no
// manifest.json: what a stopped or killed `archive --pack` leaves.
bool holds_incomplete_pack(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists(dir / kManifestFile, ec)) return false;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name == kScatterFile || (name.rfind("plant_", 0) == 0 && name.find(".glb") != std::string::npos)) return true;
    }
    return false;
}

bool file_name_safe(const std::string& id) {
    return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
    });
}

}  // namespace

SpeciesPack::SpeciesPack(fs::path dir, PackSource source, PlantExportOptions options)
    : dir_(std::move(dir)), source_(std::move(source)), options_(options) {
    if (const std::string problem = plant_export_problem(options_); !problem.empty()) throw ConfigError(problem);
    std::error_code ec;
    if (fs::exists(dir_, ec)) {
        if (!fs::is_directory(dir_, ec)) throw IoError(dir_.string() + ": exists and is not a directory");
        if (holds_incomplete_pack(dir_))
            throw IoError(dir_.string() + ": holds an incomplete species pack (plant files but no " + kManifestFile +
                          ": a pack that was stopped or killed); remove the directory and run the same command "
                          "again to write it whole");
        if (!fs::is_empty(dir_, ec))
            throw IoError(dir_.string() + ": exists and is not empty (a pack is written into a new or empty directory)");
    } else {
        made_dir_ = true;
    }
    fs::create_directories(dir_, ec);
    if (ec) throw IoError(dir_.string() + ": cannot create: " + ec.message());
}

void SpeciesPack::add(const GrownPlant& plant, const PlantRecord& record) {
    if (!file_name_safe(record.id))
        throw std::invalid_argument("species pack: plant id '" + record.id + "' must be letters, digits, _ or -");
    if (ids_.count(record.id) != 0) throw std::invalid_argument("species pack: plant " + record.id + " is already in it");
    EnginePlant ready = make_engine_plant(plant, record, options_);
    const std::string file = ready.name + ".glb";
    write_file_atomically(dir_ / file, plant_glb_bytes(ready, (dir_ / file).string()));

    nlohmann::json entry = record_json(record);
    entry.erase("run");  // the pack's, once
    entry["file"] = file;
    entry["height_m"] = ready.height_m;
    nlohmann::json triangles = nlohmann::json::array();
    for (const MeshArrays& level : ready.levels) triangles.push_back(level.faces.size());
    entry["triangles"] = triangles;
    if (options_.leaves) {
        nlohmann::json cards = nlohmann::json::array();
        for (const LeafMesh& level : ready.leaves) cards.push_back(level.cards());
        entry["leaves"] = cards;  // per level, as triangles
    }
    if (options_.lods > 0) {
        entry["lods_written"] = ready.levels.size();  // fewer than options.lods where the chain stopped
        nlohmann::json distances = nlohmann::json::array();
        for (const double d : ready.lod_distances) distances.push_back(lod_percent(d));
        entry["hausdorff_percent"] = distances;
    }
    ready.levels.resize(1);
    ready.wind.resize(1);
    plants_.push_back(std::move(ready));
    entries_.push_back(std::move(entry));
    ids_.insert(record.id);
}

void SpeciesPack::abandon() noexcept {
    std::error_code ec;
    for (const EnginePlant& plant : plants_) fs::remove(dir_ / (plant.name + ".glb"), ec);
    fs::remove(dir_ / kScatterFile, ec);
    if (made_dir_) fs::remove(dir_, ec);  // only if empty: nothing but ours
}

std::string SpeciesPack::manifest_text() const {
    nlohmann::json options = {{"lods", options_.lods}, {"wind", options_.wind}, {"height_m", nullptr}};
    if (options_.height_m) options["height_m"] = *options_.height_m;
    nlohmann::json species = nlohmann::json::array();
    for (const nlohmann::json& entry : entries_) species.push_back(entry);
    const nlohmann::json manifest = {{"format", "morphogen species pack"},
                                     {"format_version", kPackFormatVersion},
                                     {"generator", "morphogen"},
                                     {"run", source_.run},
                                     {"algorithm", source_.algorithm},
                                     {"measures", source_.measures},
                                     {"options", options},
                                     {"scatter", {{"file", kScatterFile}, {"copies_per_species", kScatterCopies}}},
                                     {"species", species}};
    return manifest.dump(2) + "\n";
}

void SpeciesPack::finish() {
    if (plants_.empty()) throw std::invalid_argument("species pack: no plants to write");
    write_file_atomically(dir_ / kScatterFile,
                          plant_scatter_bytes(plants_, source_.run, (dir_ / kScatterFile).string()));
    write_file_atomically(dir_ / kManifestFile, manifest_text());
}

}  // namespace morphogen
