#pragma once
// What a CMA emitter (cma_emitter.hpp) carries between births: its search
// distribution and the children of its current iteration.
#include "evolution/emitters/cma/full_cma.hpp"
#include "evolution/individual.hpp"
#include "evolution/emitters/cma/sep_cma.hpp"

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

}  // namespace morphogen
