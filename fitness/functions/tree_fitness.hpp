#pragma once
// The `tree` fitness (docs/fitness-tree.md "tree"): light captured with
// self-shading above a competitors' height, counted in full only for a tree
// form, minus a construction cost in proportion to the volume:
//
//   tree = light · T · B − material_cost · volume
//   T = min(1, trunk_target / trunk_ratio)^trunk_power
//                                               (0 when trunk_ratio is undefined,
//                                                or the lowest vertex is above root_height)
//   B = min(upper_loops, loops_target) / loops_target
//
// trunk_ratio and upper_loops are the tree measures of fitness/architecture/tree_sections.hpp.
// T and B saturate at a tree's criteria (the targets), so nothing is gained by a thinner
// trunk or more loops than a tree needs; light and cost keep the pressure on.
// Above the target, a stem 10 % thinner is worth trunk_power × 10 % more light.
#include "fitness/functions/light.hpp"
#include "core/mesh/mesh.hpp"

namespace morphogen {

struct TreeFitnessParams {
    LightParams light;           // the `light` keys and defaults
    double trunk_target = 0.25;  // trunk_ratio at or below which T = 1, > 0
    double trunk_power = 1.0;    // T's exponent above the target, in [1, 10]
    int loops_target = 3;        // upper_loops at or above which B = 1, >= 1
    double material_cost = 0.05; // per unit of enclosed volume, >= 0
    double root_height = 0.1;    // a plant whose lowest vertex (of a face) is higher floats: no trunk
};

struct TreeScore {
    bool rooted = false;
    double light = 0, trunk_factor = 0, branch_factor = 0, volume = 0, score = 0;
};

// Thread-safe. Throws what light_captured and tree_sections throw.
TreeScore tree_score(MeshView mesh, const TreeFitnessParams& params);

}  // namespace morphogen
