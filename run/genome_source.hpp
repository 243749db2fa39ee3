#pragma once
// Where a command's genome comes from: `--random SEED` or `--genome FILE`.
#include "core/growth/growth_params.hpp"
#include "core/growth/network/network.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace morphogen {

// Every parameter uniform in [-init_range, init_range) around its centre for
// `mode` (docs/algorithm.md §6.3), drawn from RandomStream(seed, 0): `grow
// --random S`, gallery entry with seed S and birth 0 of a run with seed S agree.
Genome random_genome(const std::vector<int>& layers, GrowthMode mode, double init_range, std::uint64_t seed);

// "[12, 4, 4]": a network shape as the errors name it.
std::string show_layers(const std::vector<int>& layers);

// Loads a genome file and checks its layers match the config's (ConfigError
// naming both if not).
Genome load_genome_for(const std::vector<int>& layers, const std::string& path);

}  // namespace morphogen
