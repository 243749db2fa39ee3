#pragma once
// The emitter kinds a config names (docs/map-elites-emitters.md, "Emitters"): one row
// each, with the keys it reads. A new kind is one class implementing Emitter
// (emitters.hpp) and one row here.
#include "core/base/config_reader.hpp"
#include "evolution/emitters/emitters.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphogen {

// The kinds, in the registry's order: "gaussian", "iso_line", "cma_me", "cma_mae".
std::vector<std::string> emitter_kind_names();

// Reads the `emitters` list of a config: a non-empty array of objects, each
// {"kind", "share", "selection"} and the keys of its kind, every problem an
// issue at "emitters[i].key" (a key of another kind: "only for kind ...";
// cma_mae emitters with different learning_rate or threshold_min). `resolved`
// gets the list with every key the kinds read and its value.
std::vector<EmitterSpec> read_emitters(const nlohmann::json& list, ConfigIssues& issues, nlohmann::json& resolved);

// What `map_elites` runs with no `emitters`: two cma_me emitters with
// sigma0 0.2, the best setting measured for budgets of about a thousand
// births (docs/map-elites-emitters.md, "Emitters"). As a config's list, and read.
nlohmann::json default_emitters_config();
std::vector<EmitterSpec> default_emitters();

}  // namespace morphogen
