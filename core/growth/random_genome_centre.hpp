#pragma once
// Where random genomes are centred (docs/algorithm.md §6.3). A random genome
// draws each parameter uniform in [centre - init_range, centre + init_range).
// In the paper's mode every centre is 0. In the branching mode (§5.8) the
// thresholds of the two output neurons that start a shoot, w[0] (how far a
// vertex moves) and w[3] (the growth switch), are centred at
// -branching_shoot_bias: a random shoot starts out moving and growing, as a
// germinating seed's meristems do, instead of 62 of 100 going dormant or
// still at the first step. Only the prior moves; evolution reaches the same
// genomes as before.
#include "core/growth/growth_params.hpp"

#include <vector>

namespace morphogen {

// Chosen in docs/algorithm.md §6.3: 5 lets 88-92 of 100 random genomes grow
// to twice the seed's height at configs/tree.json's settings (0: 15-16).
inline constexpr double branching_shoot_bias = 5.0;

// One centre per parameter of a network with these layer sizes (§6.1), or
// empty where every centre is 0 (the paper's mode, or a network without the
// branching outputs).
std::vector<double> random_genome_centre(const std::vector<int>& layers, GrowthMode mode);

}  // namespace morphogen
