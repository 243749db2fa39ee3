#include "fitness/architecture/architecture_json.hpp"

#include <cmath>

namespace morphogen {

nlohmann::json architecture_json(const Architecture& a) {
    nlohmann::json lengths = nlohmann::json::array(), thicknesses = nlohmann::json::array(),
                   tip_heights = nlohmann::json::array();
    for (const Limb& limb : a.limbs) {
        lengths.push_back(limb.length);
        thicknesses.push_back(limb.thickness);
        tip_heights.push_back(limb.tip.z());
    }
    return {{"tips", a.tips},
            {"limbs", a.limbs.size()},
            {"limb_lengths", std::move(lengths)},
            {"limb_thicknesses", std::move(thicknesses)},
            {"limb_tip_z", std::move(tip_heights)},
            {"first_fork_height", a.first_fork_height},
            {"strahler", a.strahler},
            {"solidity", std::isfinite(a.solidity) ? nlohmann::json(a.solidity) : nlohmann::json()},
            {"forks", a.forks},
            {"band_width", a.band_width}};
}

}  // namespace morphogen
