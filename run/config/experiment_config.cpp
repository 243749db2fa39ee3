#include "run/config/experiment_config.hpp"

#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "engine/plant_smooth.hpp"
#include "engine/plant_wind.hpp"
#include "run/config/config_migration.hpp"

#include <filesystem>
#include <optional>

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

// `format_version`: a config a user writes may leave it out (it is then in
// this build's format); the resolved config always records it.
void read_format_version(ObjectReader& top) {
    if (const json* given = top.raw(config_format_key); given != nullptr && *given != config_format_version) {
        const std::string current = std::to_string(config_format_version);
        const bool later = given->is_number() && given->get<double>() > config_format_version;
        top.issues().add(config_format_key,
                         later ? "format " + given->dump() + " was written by a newer morphogen (this build reads format " +
                                     current + "): use that build"
                               : "expected " + current + " (this build's format; a config you write may leave it out), got " +
                                     given->dump());
    }
    top.set_resolved(config_format_key, config_format_version);
}
}  // namespace

namespace {
// export_glb.wind_presets: names of engine/plant_wind.hpp's presets, as
// grow's --wind-preset; only with "wind": true. Resolved only when given.
void read_wind_presets(ObjectReader& options, PlantExportOptions& o) {
    const json* names = options.raw("wind_presets");
    if (names == nullptr) return;
    const std::string path = options.path_of("wind_presets");
    if (!names->is_array()) {
        options.issues().add(path, "must be a list of preset names (color, uv, godot)");
        return;
    }
    for (const json& name : *names) {
        const std::optional<WindPreset> preset =
            name.is_string() ? wind_preset_named(name.get<std::string>()) : std::nullopt;
        if (!preset) {
            options.issues().add(path, name.dump(-1, ' ', false, json::error_handler_t::replace) +
                                           " is not a wind preset: the presets are color, uv and godot");
            return;
        }
        o.wind_presets.push_back(*preset);
    }
    if (!o.wind_presets.empty() && !o.wind)
        options.issues().add(path, "copies the wind data, so it needs \"wind\": true");
    options.set_resolved("wind_presets", *names);
}
}  // namespace

namespace {
// export_glb.leaves, leaf_size and leaf_density: grow's --leaves, --leaf-size
// and --leaf-density. Read (and resolved) only when given, so the resolved
// config of runs without them keeps its bytes.
void read_leaves(ObjectReader& options, PlantExportOptions& o) {
    if (options.raw("leaves") != nullptr) o.leaves = options.boolean("leaves", false);
    if (options.raw("leaf_size") != nullptr)
        o.leaf_size = options.number("leaf_size", kDefaultLeafSize, 0, kMaxLeafSize, true);
    if (options.raw("leaf_density") != nullptr)
        o.leaf_density = options.number("leaf_density", kDefaultLeafDensity, 0, 1, true);
    for (const char* key : {"leaf_size", "leaf_density"})
        if (options.raw(key) != nullptr && !o.leaves)
            options.issues().add(options.path_of(key), "shapes the cards of \"leaves\": true, so it needs it");
}
}  // namespace

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
    // Read only when given, so the resolved config of runs without it keeps its bytes.
    if (const json* from = reader.raw("from"); from != nullptr) {
        bool ok = from->is_array();
        for (const json& source : ok ? *from : json::array()) ok = ok && source.is_string() && !source.get<std::string>().empty();
        if (!ok)
            reader.issues().add(reader.path_of("from"), "expected an array of non-empty paths (genome files, run "
                                                         "directories or breed sessions), got " + from->dump());
        else
            p.from = from->get<std::vector<std::string>>();
        reader.set_resolved("from", *from);
    }
    if (const json* glb = reader.raw("export_glb"); glb != nullptr) {
        ObjectReader options(glb, reader.path_of("export_glb"), reader.issues());
        PlantExportOptions& o = p.export_glb.emplace();
        // 0: a model unit is a metre; 0 levels: one mesh (as grow without --lods).
        if (const double height = options.number("height", 0, 0, kMaxPlantHeightMetres); height > 0) {
            o.height_m = height;
            if (height < kMinPlantHeightMetres)
                options.issues().add(options.path_of("height"),
                                     json(height).dump() + " is below the least height, 0.001 (1 mm); 0 keeps one model unit a metre");
        }
        o.lods = static_cast<int>(options.integer("lods", 0, 0, kMaxPlantLods));
        o.wind = options.boolean("wind", false);
        read_wind_presets(options, o);
        // Read only when given, so the resolved config of runs without it keeps its bytes.
        if (options.raw("colour") != nullptr) o.colour = options.boolean("colour", false);
        if (const std::string problem = plant_export_problem(o); o.colour && !problem.empty())
            options.issues().add(options.path_of("colour"), problem);
        read_leaves(options, o);
        // export_glb.smooth: grow's --smooth; read only when given (the resolved config's bytes).
        if (options.raw("smooth") != nullptr)
            o.smooth = static_cast<int>(options.integer("smooth", 0, 0, kMaxSmoothRounds));
        options.finish();
        reader.set_resolved("export_glb", options.resolved());
    }
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

namespace {
// Command-line values on their own, first: a bad one is blamed on its option
// ("--threads"), not on the key of the file it replaces.
void check_overrides(const ConfigOverrides& o) {
    const json run = with_overrides(json::object(), o).at("run");
    ConfigIssues issues;
    ObjectReader reader(&run, "", issues);
    (void)read_run_params(reader);
    std::string message;
    for (const ConfigIssue& issue : issues.list()) {
        if (!message.empty()) message += '\n';
        message += "--" + issue.path + ": " + issue.message + " (it replaces run." + issue.path + ")";
    }
    if (!message.empty()) throw ConfigError(message);
}
}  // namespace

ExperimentConfig read_experiment_config(const json& original, const std::string& source,
                                        const ConfigOverrides& overrides) {
    // The file must be valid as it is, keys the overrides replace included,
    // so that `validate` and `evolve --generations N` agree about it.
    if (overrides.seed || overrides.generations || overrides.threads) {
        check_overrides(overrides);
        read_experiment_config(original, source);
    }
    const json document = with_overrides(original, overrides);
    ConfigIssues issues;
    ObjectReader top(&document, "", issues);
    ExperimentConfig config;
    // "$schema" lets editors find configs/schema.json; it has no effect.
    if (const json* schema = top.raw("$schema"); schema != nullptr && !schema->is_string())
        issues.add("$schema", "expected a string (the path or URL of the schema), got " + schema->dump());
    read_format_version(top);

    config.network = read_section(top, "network", issues, read_network_params);
    config.growth = read_section(top, "growth", issues, read_growth_params);
    // The branching mode drives growth with outputs 3-6 (§5.8); caught here,
    // not at the first birth, so a run never starts with every child invalid.
    if (config.growth.mode == GrowthMode::branching && config.network.outputs < kBranchingOutputs)
        issues.add("network.outputs", "growth.mode \"branching\" needs at least " + std::to_string(kBranchingOutputs) +
                                          " outputs, got " + std::to_string(config.network.outputs));
    else if (config.growth.mode == GrowthMode::branching && config.growth.signal_diffusion > 0 &&
             config.network.outputs < kSignalOutputs)
        issues.add("network.outputs", "growth.signal_diffusion needs at least " + std::to_string(kSignalOutputs) +
                                          " outputs (it spreads channel 7), got " + std::to_string(config.network.outputs));
    config.fitness = read_section(top, "fitness", issues, read_fitness);
    config.evolution = read_section(top, "evolution", issues,
                                    [&](ObjectReader& r) { return read_evolution_params(r, &config.algorithm, &config.novelty); });
    config.run = read_section(top, "run", issues, read_run_params);
    config.qd = read_qd_params(top, config.algorithm);

    top.finish();
    issues.throw_if_any(source);
    config.resolved = top.resolved();
    return config;
}

ExperimentConfig load_experiment_config(const std::string& path, const ConfigOverrides& overrides) {
    if (path.empty()) return read_experiment_config(json::object(), "default config", overrides);
    ExperimentConfig config = read_experiment_config(load_json_file(path), path, overrides);
    // run.from names files beside the config, wherever it is run from: a
    // config that ships with its seed genome works from any directory. The
    // joined path is made absolute, so a run's recorded config names the same
    // files whichever directory reads it later.
    if (!config.run.from.empty()) {
        const std::filesystem::path folder = std::filesystem::absolute(std::filesystem::path(path)).parent_path();
        for (std::string& source : config.run.from)
            if (std::filesystem::path(source).is_relative()) source = (folder / source).lexically_normal().string();
        config.resolved["run"]["from"] = config.run.from;
    }
    if (config.run.name.empty()) {
        config.run.name = run_name_from_path(path);
        config.resolved["run"]["name"] = config.run.name;
    }
    return config;
}

}  // namespace morphogen
