#pragma once
// The update of pyribs 0.4's CMA-ES (ribs/emitters/opt/_cma_es.py, which the
// CMA-MAE paper's benchmark code vendors), for morphogen-bench-qd's
// reproduction of the published sphere figures only
// (experiments/2026-11-25-every-emitter-three-grids.md and the sphere study).
// It differs from the textbook update (evolution/emitters/cma/full_cma.hpp) in six ways:
// the rank-one term is weighted by c1^2 instead of c1 (pyribs applies c1
// twice); p_c accumulates m' - m without dividing by sigma (so that term is
// also sigma^2 times the textbook's); steps are not clipped;
// sigma *= exp(min(1, cs/ds (|p_s|^2/n - 1)/2)); h_sigma tests
// |p_s|^2/n/(1 - (1-cs)^(2u)) < 2 + 4/(n+1); and basis and scales (used to
// sample and to whiten) are recomputed only once lambda (u - decomposed_at)
// > n lambda / (2 n^2 (c1 + cmu)) children have passed since the last time
// (every 3 updates at n = 100, lambda = 36), not after every update.
#include "evolution/emitters/cma/full_cma.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace morphogen {

// One update; `decomposed_at` is the update count when basis and scales were
// last recomputed (0 after a start), advanced here when they are again.
void pyribs_cma_update(FullCmaState& state, std::uint64_t& decomposed_at,
                       std::span<const std::vector<double>* const> parents_best_first, std::size_t lambda);

// A CmaSettings::full_update running pyribs_cma_update, keeping each
// emitter state's decomposed_at beside it (by the state's address, which
// a run's emitter keeps; a restart, updates back to 0, starts it again).
FullCmaUpdate pyribs_full_update();

}  // namespace morphogen
