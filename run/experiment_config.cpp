#include "run/experiment_config.hpp"

#include "base/config_reader.hpp"

#include <filesystem>

namespace morphogen {

using nlohmann::json;

namespace {

// Reads section `name` of `top` with `read` and records its resolved values.
template <class Read>
auto read_section(ObjectReader& top, const std::string& name, ConfigIssues& issues, Read read) {
    ObjectReader reader(top.raw(name), name, issues);
    auto value = read(reader);
    top.set_resolved(name, reader.resolved());
    return value;
}

constexpr long long max_exact_integer = 9007199254740991LL;  // 2^53 - 1

bool valid_name(const std::string& name) {
    if (name.size() > 100 || (!name.empty() && name[0] == '.')) return false;
    for (char c : name) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                        c == '_' || c == '-';
        if (!ok) return false;
    }
    return true;
}

// Applies command-line overrides to a copy of the document. A `run` that is
// not an object is left alone: the reader reports it.
json with_overrides(const json& document, const ConfigOverrides& o) {
    if (!o.seed && !o.generations && !o.threads) return document;
    if (!document.is_object()) return document;
    json out = document;
    if (!out.contains("run")) out["run"] = json::object();
    json& run = out["run"];
    if (!run.is_object()) return out;
    if (o.seed) run["seed"] = *o.seed;
    if (o.generations) run["generations"] = *o.generations;
    if (o.threads) run["threads"] = *o.threads;
    return out;
}
}  // namespace

GaParams read_evolution_params(ObjectReader& reader, Algorithm* algorithm) {
    GaParams p;
    const std::string name = reader.choice("algorithm", "steady_state", {"steady_state", "map_elites"});
    if (algorithm != nullptr) *algorithm = name == "map_elites" ? Algorithm::map_elites : Algorithm::steady_state;
    p.population = static_cast<int>(reader.integer("population", p.population, 2, 1'000'000));
    p.tournament = static_cast<int>(reader.integer("tournament", p.tournament, 1, 1000));
    p.crossover = reader.number("crossover", p.crossover, 0.0, 1.0);
    p.mutation_rate = reader.number("mutation_rate", p.mutation_rate, 0.0, 1.0);
    p.mutation_sigma = reader.number("mutation_sigma", p.mutation_sigma, 0.0, 1000.0);
    // A config that sets a batch size and no schedule keeps the batch
    // schedule it was written for (every run made before the pipeline does).
    const bool batch_given = reader.raw("batch") != nullptr;
    const bool schedule_given = reader.raw("schedule") != nullptr;
    const bool lag_given = reader.raw("lag") != nullptr;
    const std::string schedule =
        reader.choice("schedule", batch_given ? "batch" : "pipeline", {"pipeline", "batch"});
    p.schedule = schedule == "batch" ? ScheduleKind::batch : ScheduleKind::pipeline;
    p.lag = static_cast<int>(reader.integer("lag", p.lag, 1, 1'000'000));
    p.batch = static_cast<int>(reader.integer("batch", p.batch, 1, 1'000'000));
    if (p.schedule == ScheduleKind::pipeline) {
        if (batch_given)
            reader.issues().add(reader.path_of("batch"),
                                "applies to schedule \"batch\" only; the pipeline's births in flight are evolution.lag");
        reader.drop_resolved("batch");
    } else {
        if (lag_given) reader.issues().add(reader.path_of("lag"), "applies to schedule \"pipeline\" only");
        reader.drop_resolved("lag");
        if (!schedule_given) reader.drop_resolved("schedule");
    }
    p.init_range = reader.number("init_range", p.init_range, 0.0, 1000.0);
    reader.finish();
    return p;
}

RunParams read_run_params(ObjectReader& reader) {
    RunParams p;
    p.seed = static_cast<std::uint64_t>(reader.integer("seed", static_cast<long long>(p.seed), 0, max_exact_integer));
    p.generations = static_cast<std::uint64_t>(
        reader.integer("generations", static_cast<long long>(p.generations), 0, 1'000'000'000));
    p.checkpoint_every = static_cast<std::uint64_t>(
        reader.integer("checkpoint_every", static_cast<long long>(p.checkpoint_every), 0, 1'000'000'000));
    p.export_every = static_cast<std::uint64_t>(
        reader.integer("export_every", static_cast<long long>(p.export_every), 0, 1'000'000'000));
    p.threads = static_cast<int>(reader.integer("threads", p.threads, 0, 4096));
    p.name = reader.string("name", p.name);
    if (!valid_name(p.name))
        reader.issues().add(reader.path_of("name"),
                            json(p.name).dump(-1, ' ', false, json::error_handler_t::replace) +
                                " is not a usable directory name: use at most 100 of A-Z a-z 0-9 . _ -, "
                                            "not starting with '.'");
    reader.finish();
    return p;
}

std::string run_name_from_path(const std::string& path) {
    std::string stem = std::filesystem::path(path).stem().string();
    for (char& c : stem) {
        if (c != '.' && !valid_name(std::string(1, c))) c = '_';
    }
    while (!stem.empty() && stem[0] == '.') stem.erase(0, 1);
    if (stem.size() > 100) stem.resize(100);
    return stem.empty() ? "run" : stem;
}

ExperimentConfig read_experiment_config(const json& original, const std::string& source,
                                        const ConfigOverrides& overrides) {
    // The file must be valid as it is, keys the overrides replace included,
    // so that `validate` and `evolve --generations N` agree about it.
    if (overrides.seed || overrides.generations || overrides.threads) read_experiment_config(original, source);
    const json document = with_overrides(original, overrides);
    ConfigIssues issues;
    ObjectReader top(&document, "", issues);
    ExperimentConfig config;
    // "$schema" lets editors find configs/schema.json; it has no effect.
    if (const json* schema = top.raw("$schema"); schema != nullptr && !schema->is_string())
        issues.add("$schema", "expected a string (the path or URL of the schema), got " + schema->dump());

    config.network = read_section(top, "network", issues, read_network_params);
    config.growth = read_section(top, "growth", issues, read_growth_params);
    // The branching mode drives growth with outputs 3-6 (§5.8); caught here,
    // not at the first birth, so a run never starts with every child invalid.
    if (config.growth.mode == GrowthMode::branching && config.network.outputs < kBranchingOutputs)
        issues.add("network.outputs", "growth.mode \"branching\" needs at least " + std::to_string(kBranchingOutputs) +
                                          " outputs, got " + std::to_string(config.network.outputs));
    config.fitness = read_section(top, "fitness", issues, read_fitness);
    config.evolution = read_section(top, "evolution", issues,
                                    [&](ObjectReader& r) { return read_evolution_params(r, &config.algorithm); });
    config.run = read_section(top, "run", issues, read_run_params);
    config.qd = read_qd_params(top, config.algorithm);

    top.finish();
    issues.throw_if_any(source);
    config.resolved = top.resolved();
    // A steady-state config resolves to the same bytes as before MAP-Elites.
    if (config.algorithm == Algorithm::steady_state) config.resolved["evolution"].erase("algorithm");
    return config;
}

ExperimentConfig load_experiment_config(const std::string& path, const ConfigOverrides& overrides) {
    if (path.empty()) return read_experiment_config(json::object(), "default config", overrides);
    ExperimentConfig config = read_experiment_config(load_json_file(path), path, overrides);
    if (config.run.name.empty()) {
        config.run.name = run_name_from_path(path);
        config.resolved["run"]["name"] = config.run.name;
    }
    return config;
}

}  // namespace morphogen
