#pragma once
// The CMA emitters of MAP-Elites (docs/algorithm.md §9.9): each runs its own
// separable CMA-ES (sep_cma.hpp) whose iterations are the emitter's births in
// one generation (lambda = its births_per_generation), ranked by what they did
// to the archive. With `covariance: "full"` the distribution is full CMA-ES
// (full_cma.hpp) instead.
//
// - cma_me (Fontaine et al. 2020, the improvement emitter): a child that
//   filled a cell ranks before one that improved an elite, each group by
//   fitness gain (a new cell's gain is its fitness), then the rest.
// - cma_mae (Fontaine & Nikolaidis 2023): every valid child ranks by
//   fitness - threshold of its cell (the threshold archive, map_elites.hpp);
//   status 1 when that is > 0.
// Parents (EmitterSpec::parents): "filter", the children with status > 0, or
// "mu", the best floor(lambda / 2) valid ones. Restart (EmitterSpec::restart)
// when CMA-ES's own stop tests fire (sep_cma_converged), or the valid
// children's ranking values span less than 1e-12, or there are no parents,
// and with "no_improvement" also when no child has status > 0. A (re)start
// takes an elite (the emitter's parent selection, from its own stream) as the
// mean, sigma0 as the step size and C = I.
#include "evolution/emitters.hpp"
#include "evolution/full_cma.hpp"
#include "evolution/individual.hpp"
#include "evolution/sep_cma.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace morphogen {

// One child of the current iteration, as the emitter ranks it.
struct CmaChild {
    std::vector<double> params;
    int status = 0;                 // 2: filled a cell, 1: improved (an elite, or for cma_mae a threshold), 0: neither
    double value = invalid_fitness; // the ranking value; -infinity when invalid
};

struct CmaEmitterState {
    bool started = false;                 // false until an elite exists to start from
    SepCmaState cma;                      // meaningful only when started, for the diagonal model
    FullCmaState full;                    // meaningful only when started, for the full model
    std::optional<std::uint64_t> origin;  // the elite the current run started from (its children's parent1)
    std::uint64_t restarts = 0;           // starts after the first
    std::vector<CmaChild> children;       // this iteration's children so far, in birth order
};

inline bool is_cma(EmitterKind kind) { return kind == EmitterKind::cma_me || kind == EmitterKind::cma_mae; }

// Starts (or restarts) `state` from `elite`: mean = its parameters, sigma =
// spec.sigma0, C = I, paths zero, origin = its id, no children.
void start_cma_emitter(const EmitterSpec& spec, CmaEmitterState& state, const Individual& elite);

// Birth `birth` of a started emitter: sep_cma_sample (or full_cma_sample)
// from RandomStream(seed, birth).
Individual sample_cma_child(const EmitterSpec& spec, const CmaEmitterState& state, std::uint64_t seed,
                            std::uint64_t birth);

// Ends an iteration: ranks the children (status, then value, both
// descending; ties in birth order), updates the distribution from the
// parents, clears the children. True when the emitter must restart.
bool finish_cma_iteration(const EmitterSpec& spec, CmaEmitterState& state);

}  // namespace morphogen
