#include "checkpoint.hpp"

#include "atomic_file.hpp"
#include "checkpoint_checks.hpp"
#include "errors.hpp"
#include "experiment_config.hpp"
#include "fnv_hash.hpp"
#include "ga_state_json.hpp"
#include "map_elites_state_json.hpp"
#include "json_text.hpp"
#include "network.hpp"

namespace morphogen {

using nlohmann::json;

namespace {
constexpr const char* format_name = "morphogen-checkpoint";

json content_of(const RunState& s) {
    json history = json::array();
    for (const HistoryRow& row : s.history) history.push_back(history_row_to_json(row));
    json content{{"config", s.config},
                 {"seed", s.seed},
                 {"history", std::move(history)},
                 {"lineage", {{"bytes", s.lineage_bytes}, {"hash", s.lineage_hash}}},
                 {"elapsed_s", s.elapsed_s}};
    if (s.elites)
        content["map_elites"] = map_elites_state_to_json(*s.elites);
    else
        content["ga"] = ga_state_to_json(s.ga);
    return content;
}
}  // namespace

std::string checkpoint_text(const json& content) {
    const json document{{"format", format_name},
                        {"version", checkpoint_version},
                        {"hash", fnv1a64_hex(content.dump())},
                        {"content", content}};
    return document.dump() + "\n";
}

json checkpoint_content(const std::string& text, const std::string& source) {
    auto refuse = [&](const std::string& why) -> CheckpointError {
        return CheckpointError("checkpoint " + source + " refused: " + why);
    };
    if (text.empty()) throw refuse("the file is empty");
    json document;
    try {
        document = read_json_object(text);
    } catch (const JsonTextError& e) {
        throw refuse(std::string("invalid JSON (truncated, corrupt or hostile) at ") + e.what());
    }
    if (!document.is_object() || !document.contains("format") || document["format"] != format_name)
        throw refuse("not a morphogen checkpoint (\"format\" is not \"" + std::string(format_name) + "\")");
    if (!document.contains("version") || !document["version"].is_number_integer())
        throw refuse("it has no version number");
    if (document["version"] != checkpoint_version)
        throw refuse("version " + document["version"].dump() + " is not supported (this build reads version " +
                     std::to_string(checkpoint_version) + ")");
    if (!document.contains("content") || !document.contains("hash") || !document["hash"].is_string())
        throw refuse("\"content\" or \"hash\" is missing");
    if (document.size() != 4) throw refuse("unexpected keys besides format, version, hash, content");
    const std::string expected = fnv1a64_hex(document["content"].dump());
    if (document["hash"] != expected)
        throw refuse("content hash mismatch (corrupt): stored " + document["hash"].get<std::string>() +
                     ", computed " + expected);
    if (checkpoint_text(document["content"]) != text)
        throw refuse("the file is not in the form morphogen writes (edited or corrupt)");
    return std::move(document["content"]);
}

void save_checkpoint(const std::filesystem::path& path, const RunState& state) {
    write_file_atomically(path, checkpoint_text(content_of(state)));
}

RunState load_checkpoint(const std::filesystem::path& path) {
    std::string text;
    try {
        text = read_file_bytes(path);
    } catch (const IoError& e) {
        throw CheckpointError("checkpoint " + path.string() + " cannot be read: " + e.what());
    }
    const json content = checkpoint_content(text, path.string());
    auto refuse = [&](const std::string& why) -> CheckpointError {
        return CheckpointError("checkpoint " + path.string() + " refused: " + why);
    };
    RunState state;
    try {
        state.config = content.at("config");
        state.seed = content.at("seed").get<std::uint64_t>();
        ExperimentConfig config;
        try {
            config = read_experiment_config(state.config, "checkpoint config");
        } catch (const ConfigError& e) {
            throw refuse(std::string("its config is not valid: ") + e.what());
        }
        if (config.resolved != state.config) throw refuse("its config is not a resolved config");
        if (config.run.seed != state.seed) throw refuse("its seed differs from its config's run.seed");
        const std::size_t dimension = parameter_count(config.network.layers());
        const auto P = static_cast<std::uint64_t>(config.evolution.population);
        if (content.size() != 6) throw refuse("unexpected keys in its content");
        if (config.algorithm == Algorithm::map_elites) {
            if (!content.contains("map_elites")) throw refuse("its config is a map_elites run but it holds no map_elites state");
            state.elites = map_elites_state_from_json(content.at("map_elites"), config.qd.archive, config.qd.descriptors,
                                                      config.qd.cells(), P, dimension);
        } else {
            state.ga = ga_state_from_json(content.at("ga"), config.evolution, dimension);
        }
        for (const json& row : content.at("history")) state.history.push_back(history_row_from_json(row));
        if (state.history.size() != state.births() / P)
            throw refuse(std::to_string(state.history.size()) + " history rows for " +
                         std::to_string(state.births()) + " births");
        for (const HistoryRow& row : state.history)
            if (row.qd != (config.algorithm == Algorithm::map_elites))
                throw refuse("its history rows do not fit its algorithm");
        for (std::size_t g = 0; g < state.history.size(); ++g)
            if (state.history[g].generation != g) throw refuse("history rows out of order");
        state.lineage_bytes = content.at("lineage").at("bytes").get<std::uint64_t>();
        state.lineage_hash = content.at("lineage").at("hash").get<std::string>();
        state.elapsed_s = content.at("elapsed_s").get<double>();
        try {
            check_checkpoint_content(state, config);
        } catch (const std::invalid_argument& e) {
            throw refuse(std::string("it contradicts itself: ") + e.what());
        }
    } catch (const CheckpointError&) {
        throw;
    } catch (const std::exception& e) {
        throw refuse(std::string("its content does not fit: ") + e.what());
    }
    return state;
}

}  // namespace morphogen
