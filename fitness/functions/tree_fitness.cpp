#include "fitness/functions/tree_fitness.hpp"

#include "fitness/measures.hpp"
#include "fitness/architecture/tree_sections.hpp"

#include <algorithm>
#include <cmath>

namespace morphogen {

TreeScore tree_score(MeshView mesh, const TreeFitnessParams& params) {
    TreeScore s;
    const TreeSections sections = tree_sections(mesh);
    // A plant must stand on the ground: one that floats has no trunk, however
    // its sections look. An undefined ratio (no height, nothing above the
    // middle) is no trunk either.
    s.rooted = sections.zmin <= params.root_height;
    s.trunk_factor = !s.rooted || std::isnan(sections.trunk_ratio) ? 0.0
                     : sections.trunk_ratio <= params.trunk_target
                         ? 1.0
                         : std::pow(params.trunk_target / sections.trunk_ratio, params.trunk_power);
    s.branch_factor = static_cast<double>(std::min(sections.upper_loops, params.loops_target)) / params.loops_target;
    s.volume = mesh_volume(mesh);
    // Light is the costly part: skip it when it cannot count.
    s.light = s.trunk_factor * s.branch_factor > 0.0 ? light_captured(mesh, params.light) : 0.0;
    s.score = s.light * s.trunk_factor * s.branch_factor - params.material_cost * s.volume;
    return s;
}

}  // namespace morphogen
