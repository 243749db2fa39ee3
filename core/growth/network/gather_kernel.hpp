#pragma once
// The gather phase (docs/algorithm.md §4.2): each vertex's network inputs from the
// previous outputs — its own, the mean and the population standard deviation
// over its neighbours — with the last four overwritten by its growth direction
// and height (and, in the branching mode, the one before them by whether the
// vertex grows, §5.8, and with growth.exposure the one before that by its
// light, §5.9). Compiled for x86-64-v3 and baseline, picked at run time.
#include <Eigen/Core>

#include <cstdint>

namespace morphogen::kernel {

struct GatherInput {
    int outputs = 0;                    // N
    const double* previous = nullptr;   // N x V, vertex after vertex
    const int* neighbour_offsets = nullptr;  // V + 1 offsets into neighbours (CSR)
    const int* neighbours = nullptr;
    const Eigen::Vector3d* directions = nullptr;
    const Eigen::Vector3d* positions = nullptr;
    double height_scale = 10.0;
    // Branching mode (§5.8): 1 where the vertex grows, 0 where it is dormant;
    // null in the paper's mode.
    const std::uint8_t* active = nullptr;
    // growth.exposure (§5.9): each vertex's exposure in [0, 1]; null when off.
    const double* exposure = nullptr;
};

// Writes the 3N inputs of vertices [first, first + count), vertex after
// vertex, to `inputs`.
void gather_inputs(const GatherInput& in, int first, int count, double* inputs);

}  // namespace morphogen::kernel
