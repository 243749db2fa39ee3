#pragma once
// The architecture measures as JSON, for `morphogen score --json` and the
// HTML report: {"tips", "limbs", "limb_lengths", "limb_thicknesses",
// "first_fork_height", "strahler", "solidity" (null when NaN), "forks",
// "band_width"}.
#include "fitness/architecture/architecture.hpp"

#include <nlohmann/json.hpp>

namespace morphogen {

nlohmann::json architecture_json(const Architecture& architecture);

}  // namespace morphogen
