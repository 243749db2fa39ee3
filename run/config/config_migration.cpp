#include "run/config/config_migration.hpp"

namespace morphogen {

using nlohmann::json;

namespace {

// Sets `key` of an object to `value` unless it is there.
void default_to(json& object, const char* key, json value) {
    if (object.is_object() && !object.contains(key)) object[key] = std::move(value);
}

json* section(json& config, const char* name) {
    return config.contains(name) && config[name].is_object() ? &config[name] : nullptr;
}

// A tree fitness anywhere in `fitness` (a sum's terms included) left
// trunk_power out when it was 1.
void migrate_fitness(json& fitness) {
    if (!fitness.is_object()) return;
    if (fitness.contains("type") && fitness["type"] == "tree") default_to(fitness, "trunk_power", 1.0);
    if (fitness.contains("terms") && fitness["terms"].is_array())
        for (json& term : fitness["terms"]) migrate_fitness(term);
}

void migrate_emitters(json& config) {
    if (!config.contains("emitters")) {
        // 0.1.0's MAP-Elites without `emitters`: one gaussian emitter.
        config["emitters"] = json::array({{{"kind", "gaussian"}, {"selection", "uniform"}, {"share", 1.0}}});
        return;
    }
    if (!config["emitters"].is_array()) return;
    for (json& emitter : config["emitters"])
        if (emitter.is_object() && emitter.contains("kind") &&
            (emitter["kind"] == "cma_me" || emitter["kind"] == "cma_mae"))
            default_to(emitter, "covariance", "diagonal");
}

// Format 2 as first written left a branching config's signal switches out
// when off; they are written out as off (algorithm.md §5.9).
void migrate_signal_switches(json& stored) {
    json* growth = section(stored, "growth");
    if (growth == nullptr || !growth->contains("mode") || (*growth)["mode"] != "branching") return;
    default_to(*growth, "exposure", false);
    default_to(*growth, "signal_diffusion", 0);
}

}  // namespace

json migrate_config(json stored) {
    if (!stored.is_object()) return stored;
    if (stored.contains(config_format_key)) {
        if (stored[config_format_key] == config_format_version) migrate_signal_switches(stored);
        return stored;
    }
    stored[config_format_key] = config_format_version;
    if (json* growth = section(stored, "growth")) {
        default_to(*growth, "collisions", "allow");
        default_to(*growth, "mode", "paper");
    }
    bool map_elites = false;
    if (json* evolution = section(stored, "evolution")) {
        default_to(*evolution, "algorithm", "steady_state");
        map_elites = (*evolution)["algorithm"] == "map_elites";
        if (evolution->contains("batch")) default_to(*evolution, "schedule", "batch");
    }
    if (map_elites) migrate_emitters(stored);
    if (stored.contains("fitness")) migrate_fitness(stored["fitness"]);
    return stored;
}

bool holds_all_of(const json& whole, const json& part) {
    if (part.is_object()) {
        if (!whole.is_object()) return false;
        for (const auto& [key, value] : part.items())
            if (!whole.contains(key) || !holds_all_of(whole[key], value)) return false;
        return true;
    }
    if (part.is_array()) {
        if (!whole.is_array() || whole.size() != part.size()) return false;
        for (std::size_t i = 0; i < part.size(); ++i)
            if (!holds_all_of(whole[i], part[i])) return false;
        return true;
    }
    return whole == part;
}

}  // namespace morphogen
