#include "run/persistence/seed_genomes.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "core/base/fnv_hash.hpp"
#include "core/growth/genome_io.hpp"
#include "run/config/config_migration.hpp"
#include "run/config/experiment_config.hpp"
#include "run/genome_source.hpp"
#include "run/persistence/checkpoint.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace morphogen {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
constexpr std::string_view kGenomeSuffix = ".genome.json";

// A run directory's best (GA) or elites (MAP-Elites), from its checkpoint.
void read_run_dir(const fs::path& dir, const std::vector<int>& layers, std::vector<GivenGenome>& out) {
    const fs::path config_file = dir / "config.json";
    const ExperimentConfig theirs =
        read_experiment_config(migrate_config(load_json_file(config_file.string())), config_file.string());
    if (theirs.network.layers() != layers)
        throw ConfigError(dir.string() + ": the run's network " + show_layers(theirs.network.layers()) +
                          " does not match the config's network " + show_layers(layers) +
                          " (set network.outputs and network.hidden to match)");
    const RunState state = load_checkpoint(dir / "checkpoint.json");
    const std::size_t before = out.size();
    if (std::string_view(state.search->key()) == "map_elites") {
        std::size_t elite = 0;
        for (const Individual* member : state.search->view().members)
            if (member->valid()) out.push_back({member->params, dir.string() + " (elite " + std::to_string(elite++) + ")"});
    } else if (const std::optional<Individual>& best = state.search->best(); best && best->valid()) {
        out.push_back({best->params, dir.string() + " (best)"});
    }
    if (out.size() == before) throw IoError(dir.string() + ": the run holds no valid genome yet");
}

// A breed session's exports/, or the *.genome.json files of a directory, by name.
void read_genome_dir(const fs::path& dir, const std::vector<int>& layers, std::vector<GivenGenome>& out) {
    const fs::path from = fs::is_directory(dir / "exports") ? dir / "exports" : dir;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(from))
        if (entry.is_regular_file() && entry.path().filename().string().ends_with(kGenomeSuffix))
            files.push_back(entry.path());
    if (files.empty())
        throw IoError(dir.string() + ": holds no *.genome.json file (expected a genome file, a run directory or a " +
                      "breed session with exports)");
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) out.push_back({load_genome_for(layers, file.string()).params, file.string()});
}
}  // namespace

std::vector<GivenGenome> read_given_genomes(const std::vector<std::string>& sources, const std::vector<int>& layers) {
    std::vector<GivenGenome> genomes;
    for (const std::string& source : sources) {
        std::error_code ec;
        if (!fs::exists(source, ec)) throw IoError("run.from / --from " + source + ": no such file or directory");
        if (!fs::is_directory(source, ec))
            genomes.push_back({load_genome_for(layers, source).params, source});
        else if (fs::exists(fs::path(source) / "checkpoint.json", ec))
            read_run_dir(source, layers, genomes);
        else
            read_genome_dir(source, layers, genomes);
    }
    return genomes;
}

void record_given_genomes(const fs::path& run_dir, const std::vector<GivenGenome>& genomes,
                          const std::vector<int>& layers) {
    const fs::path dir = run_dir / "seeds";
    std::error_code ec;
    fs::remove_all(dir, ec);
    fs::create_directories(dir, ec);
    if (ec) throw IoError(dir.string() + ": cannot create: " + ec.message());
    json manifest = json::array();
    for (std::size_t i = 0; i < genomes.size(); ++i) {
        char name[48];
        std::snprintf(name, sizeof name, "seed_%03zu.genome.json", i);
        save_genome(Genome{layers, genomes[i].params}, (dir / name).string());
        const std::string bytes = read_file_bytes(dir / name, memory_bound("genome files"));
        manifest.push_back({{"file", name}, {"origin", genomes[i].origin}, {"fnv1a64", fnv1a64_hex(bytes)}});
    }
    write_file_atomically(dir / "manifest.json", json{{"seeds", manifest}}.dump(2) + "\n");
}

std::vector<std::vector<double>> load_recorded_genomes(const fs::path& run_dir, const std::vector<int>& layers) {
    const fs::path dir = run_dir / "seeds";
    const fs::path manifest_file = dir / "manifest.json";
    if (!fs::exists(manifest_file)) return {};
    std::vector<std::vector<double>> genomes;
    try {
        const json manifest = load_json_file(manifest_file.string());
        for (const json& entry : manifest.at("seeds")) {
            const fs::path file = dir / entry.at("file").get<std::string>();
            const std::string bytes = read_file_bytes(file, memory_bound("genome files"));
            if (fnv1a64_hex(bytes) != entry.at("fnv1a64").get<std::string>())
                throw CheckpointError(file.string() + " was changed after the run began (its hash differs from " +
                                      manifest_file.string() + ")");
            genomes.push_back(load_genome_for(layers, file.string()).params);
        }
    } catch (const CheckpointError&) {
        throw;
    } catch (const std::exception& e) {
        throw CheckpointError(manifest_file.string() + ": the run's given genomes cannot be read: " + e.what());
    }
    return genomes;
}

}  // namespace morphogen
