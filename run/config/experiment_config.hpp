#pragma once
// The whole experiment config: sections `network`, `growth`, `fitness`,
// `evolution`, `run` (and `descriptors`, `archive`, `emitters` for MAP-Elites),
// and `format_version` (run/config/config_migration.hpp: a config a user writes may
// leave it out; one of a later format is refused). Every key has a default,
// so `{}` is valid. Reading
// collects every problem (unknown keys with a suggestion, wrong types, out of
// range) and throws one ConfigError listing them all with their key paths.
// configs/schema.json documents the same keys, ranges and defaults (a test
// keeps the two in step).
#include "engine/plant_export.hpp"
#include "evolution/evolution_params.hpp"
#include "fitness/fitness.hpp"
#include "core/growth/growth_params.hpp"
#include "run/config/map_elites_config.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

// The `run` section: how an `evolve` run is driven (not what it computes,
// except `seed`).
struct RunParams {
    std::uint64_t seed = 1;          // run.seed, [0, 2^53-1] so any JSON tool keeps it exact
    std::uint64_t generations = 100; // GA generations after the initial population (generation 0)
    std::uint64_t checkpoint_every = 1;  // generations between checkpoints; 0 = only at the end / on stop
    std::uint64_t export_every = 1;      // generations between best-mesh exports; 0 = never
    int threads = 0;                 // worker threads; 0 = all cores
    std::string name;                // run name; "" = the config file's stem
    // run.export_glb: the best of generation as an engine-ready GLB with
    // these options (docs/config.md); none: the plain GLB.
    std::optional<PlantExportOptions> export_glb;
    // run.from: genome files, run directories or breed sessions whose genomes
    // start generation 0 (seed_genomes.hpp); empty: random genomes. `evolve
    // --from` appends to it. Read once, by evolve: a run keeps its copies.
    // load_experiment_config resolves a relative path against the config
    // file's folder (the resolved config records the absolute joined path).
    std::vector<std::string> from;
};

struct ExperimentConfig {
    NetworkParams network;
    GrowthParams growth;
    std::shared_ptr<const Fitness> fitness;
    GaParams evolution;
    Algorithm algorithm = Algorithm::steady_state;  // evolution.algorithm
    QdParams qd;  // descriptors (map_elites, nslc; a GA's if given) and archive (map_elites only)
    NoveltyParams novelty;  // evolution.novelty_* (nslc only; defaults otherwise)
    RunParams run;
    // The config with every default filled in and format_version recorded
    // (keys that do not apply, such as growth.turn_rate in the paper's mode,
    // are left out): what config.json and checkpoints store.
    nlohmann::json resolved;
};

// Values from the command line that replace the document's, before checking
// (so they are range-checked like any key and recorded in `resolved`).
struct ConfigOverrides {
    std::optional<std::uint64_t> seed, generations;
    std::optional<int> threads;
};

// `source` names the document in messages (usually the file path).
ExperimentConfig read_experiment_config(const nlohmann::json& document, const std::string& source,
                                        const ConfigOverrides& overrides = {});
// An empty path means the default config `{}`. An empty run.name becomes the
// file's stem (characters outside [A-Za-z0-9._-] replaced by '_').
ExperimentConfig load_experiment_config(const std::string& path, const ConfigOverrides& overrides = {});

// The `run` section on its own (calls reader.finish()); `evolution` is read
// by evolution/evolution_params.hpp.
RunParams read_run_params(ObjectReader& reader);

// A run name derived from a config path: its stem, sanitised.
std::string run_name_from_path(const std::string& path);

}  // namespace morphogen
