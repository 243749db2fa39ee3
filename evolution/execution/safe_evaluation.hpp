#pragma once
// What both searches share between a genome's evaluation and its insertion:
// scoring safely and keeping the best.
#include "evolution/individual.hpp"
#include "evolution/problem.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

// Scores one genome and never throws. An exception, a non-finite score or a
// non-finite descriptor makes the result invalid, with the reason in `error`
// ("invalid" if the problem gave none); an invalid result has size 0 and no
// descriptors. `keep_from`: Problem::evaluate_keeping (+infinity: keep nothing).
Evaluation evaluate_safely(const Problem& problem, std::span<const double> params, int worker,
                           double keep_from = std::numeric_limits<double>::infinity()) noexcept;

// Replaces `best` by `child` if the child is valid and strictly fitter (so the
// earliest of equally fit individuals stays).
inline void keep_best(std::optional<Individual>& best, const Individual& child) {
    if (child.valid() && (!best || child.fitness > best->fitness)) best = child;
}

}  // namespace morphogen
