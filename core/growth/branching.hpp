#pragma once
// growth.mode "branching" (docs/algorithm.md §5.8): what the branching mode
// adds to a step, between think and move. Output 3 stops and starts a
// vertex's growth (tips and dormancy); outputs 4-6 turn its direction toward
// or away from its normal, the vertical, and the way it differs from its
// neighbours' directions. Deterministic, no random numbers.
#include "core/mesh/mesh.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace morphogen {

// The output channels the branching mode reads (§5.8).
inline constexpr int kSwitchChannel = 3;      // stop below 1/3, start above 2/3
inline constexpr int kTurnNormalChannel = 4;  // toward (> 0.5) or away from the vertex normal
inline constexpr int kTurnUpChannel = 5;      // toward (> 0.5) or away from +z
inline constexpr int kTurnApartChannel = 6;   // away from (> 0.5) or toward the neighbours' mean direction
inline constexpr double kStopBelow = 1.0 / 3.0, kStartAbove = 2.0 / 3.0;

// §5.8 (1): a growing vertex whose w[3] is below 1/3 goes dormant, a dormant
// one whose w[3] is above 2/3 grows again; between them the state holds.
// `outputs` holds N channels per vertex; active[i] is 1 (grows) or 0.
void update_activity(std::span<std::uint8_t> active, std::span<const double> outputs, int N);

// §5.8 (2): every direction turns at once, from the old directions:
//   h_i := normalize(h_i + turn_rate · ((2w4−1)·n_i + (2w5−1)·ẑ + (2w6−1)·u_i))
// with n_i the unit area-weighted vertex normal and u_i the unit vector of
// h_i minus the mean of its neighbours' h (each 0 where its length is at most
// 1e-12); a sum of length at most 1e-12 leaves h_i as it was. The neighbour
// lists are CSR (offsets V + 1, as Grower builds them). `scratch` is reused
// (no allocation once it has grown).
void steer_directions(std::span<Vec3> directions, const TriMesh& mesh, std::span<const double> outputs, int N,
                      std::span<const int> neighbour_offsets, std::span<const int> neighbours, double turn_rate,
                      std::vector<Vec3>& scratch);

}  // namespace morphogen
