#pragma once
// Random genomes shared by the tests.
#include "evolution/rng.hpp"
#include "core/growth/network/network.hpp"

#include <cstdint>
#include <vector>

namespace morphogen::testing {

inline Genome random_test_genome(const std::vector<int>& layers, std::uint64_t seed, double range = 2.0) {
    RandomStream stream(seed, 0);
    return Genome{layers, random_parameters(parameter_count(layers), range, stream)};
}

}  // namespace morphogen::testing
