#pragma once
// growth.signal_diffusion (docs/algorithm.md §5.9): after think, one output
// channel spreads over the mesh graph several rings per step, so a vertex can
// feel what happens far beyond its one-ring: the long-range inhibitor of a
// reaction-diffusion pair (Meinhardt; Holloway and Harrison), whose
// short-range activator is any channel the network reinforces through its
// own value and its neighbours' mean (§4.2).
#include "core/growth/growth_params.hpp"

#include <span>
#include <vector>

namespace morphogen {

// `iterations` Jacobi steps of u_i := u_i + rate · (mean_{j ∈ Nb(i)} u_j − u_i)
// on channel kSignalChannel of `outputs` (N per vertex), every vertex at once
// from the previous iterate. Neighbour lists in CSR (offsets V + 1); a vertex
// without neighbours keeps its value. Values stay in the range they started
// in (each is a convex combination for rate in (0, 1]). `scratch` is reused.
void diffuse_signal(std::span<double> outputs, int N, std::span<const int> neighbour_offsets,
                    std::span<const int> neighbours, int iterations, double rate, std::vector<double>& scratch);

}  // namespace morphogen
