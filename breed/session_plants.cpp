// The files of BreedSession's plants (breed/session.hpp): genomes/ID.genome.json,
// meshes/ID.glb and thumbs/ID.png, written when plants are born, grown again
// when missing, and removed when no recorded choice owns them.
#include "breed/session.hpp"

#include "core/base/atomic_file.hpp"
#include "core/growth/genome_io.hpp"
#include "core/io/mesh_file_types.hpp"
#include "report/render.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <utility>

namespace morphogen {

namespace fs = std::filesystem;

namespace {

// Where a plant's files are: its folder and the suffix after its id.
constexpr std::pair<const char*, const char*> kPlantFiles[] = {
    {"genomes", ".genome.json"}, {"meshes", ".glb"}, {"thumbs", ".png"}};

std::string plant_id(std::uint64_t number) {
    char text[32];
    std::snprintf(text, sizeof text, "p%06llu", static_cast<unsigned long long>(number));
    return text;
}

// A PNG written beside its place, then renamed over it (write_png is not atomic).
void write_png_atomically(const Image& image, const fs::path& path) {
    const fs::path temporary = temporary_path(path);
    write_png(image, temporary.string());
    fs::rename(temporary, path);
}

}  // namespace

std::vector<std::string> BreedSession::add_plants(std::vector<std::vector<double>> genomes,
                                                  const std::vector<std::vector<std::string>>& parents,
                                                  int generation) {
    const std::vector<PlantOutcome> grown = growth_.grow_all(genomes, threads());
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < genomes.size(); ++i) {
        BreedPlant p;
        p.id = plant_id(next_plant_++);
        p.parents = parents[i];
        p.generation = generation;
        p.params = std::move(genomes[i]);
        p.fitness = grown[i].fitness;
        p.measures = grown[i].measures;
        p.descriptors = grown[i].descriptors;
        save_genome(Genome{growth_.grower().layers(), p.params}, (dir_ / "genomes" / (p.id + ".genome.json")).string());
        write_file_atomically(dir_ / "meshes" / (p.id + ".glb"), grown[i].glb);
        write_png_atomically(grown[i].thumb, dir_ / "thumbs" / (p.id + ".png"));
        ids.push_back(p.id);
        plants_[p.id] = std::move(p);
    }
    return ids;
}

std::string BreedSession::mesh_glb(const std::string& id) {
    std::lock_guard lock(mutex_);
    const BreedPlant& p = plant(id);
    const fs::path path = dir_ / "meshes" / (id + ".glb");
    if (!fs::exists(path)) write_file_atomically(path, growth_.grow(p.params).glb);
    return read_file_bytes(path, {kMaxMeshFileBytes, "mesh files"});
}

std::string BreedSession::thumb_png(const std::string& id) {
    std::lock_guard lock(mutex_);
    const BreedPlant& p = plant(id);
    const fs::path path = dir_ / "thumbs" / (id + ".png");
    if (!fs::exists(path)) write_png_atomically(growth_.grow(p.params).thumb, path);
    return read_file_bytes(path, {std::uint64_t{64} << 20, "thumbnails"});
}

void BreedSession::remove_plant_files(const std::string& id) const {
    for (const auto& [folder, suffix] : kPlantFiles) {
        std::error_code ignored;  // best effort: a file never written is no loss
        fs::remove(dir_ / folder / (id + suffix), ignored);
    }
}

// A later choice may never take the ids of a choice cut short again (an
// undo, or the session's end), and replay would not write their files.
std::vector<std::string> BreedSession::remove_unowned_plant_files() const {
    std::vector<std::string> removed;
    for (const auto& [folder, suffix] : kPlantFiles) {
        if (!fs::is_directory(dir_ / folder)) continue;
        for (const fs::directory_entry& entry : fs::directory_iterator(dir_ / folder)) {
            const std::string name = entry.path().filename().string();
            const bool owned = name.ends_with(suffix) && plants_.contains(name.substr(0, name.size() - std::strlen(suffix)));
            if (owned || !(entry.is_regular_file() || entry.is_symlink())) continue;
            fs::remove(entry.path());
            removed.push_back(std::string(folder) + "/" + name);
        }
    }
    std::sort(removed.begin(), removed.end());
    return removed;
}

}  // namespace morphogen
