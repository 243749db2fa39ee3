#pragma once
// GaState <-> JSON for checkpoints. Doubles are stored as JSON numbers, which
// nlohmann writes in shortest round-trip form, so a reload is bit-exact. An
// invalid individual's fitness (-infinity) is stored as null, never as a
// non-finite number.
#include "ga_params.hpp"
#include "steady_state.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace morphogen {

nlohmann::json individual_to_json(const Individual& individual);
// Reads one individual stored by individual_to_json (descriptors are not part
// of it), checking types, `dimension` parameters, finite values and parents
// older than the child. Throws std::invalid_argument naming `path`.
Individual individual_from_json(const nlohmann::json& object, std::size_t dimension, const std::string& path);
nlohmann::json ga_state_to_json(const GaState& state);

// Reads and checks a state against the run's parameters: field types,
// parameter counts, finite values, ids unique and below the birth counter,
// population size consistent with the birth counter. Throws
// std::invalid_argument naming the first defect (with its JSON path).
GaState ga_state_from_json(const nlohmann::json& document, const GaParams& params, std::size_t dimension);

}  // namespace morphogen
