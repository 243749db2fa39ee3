#pragma once
// The batch step both algorithms share (docs/algorithm.md §8.4, batch schedule): the children of a
// run of consecutive births are conceived from a frozen snapshot and evaluated
// in parallel (OpenMP, dynamic schedule); the caller then inserts them in
// birth order. Each child depends only on (snapshot, seed, birth index), so
// the result is the same for every thread count.
#include "evolution/individual.hpp"
#include "evolution/problem.hpp"

#include <cstdint>
#include <functional>
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

struct BredBatch {
    std::vector<Individual> children;  // in birth order; fitness, size and descriptors filled in
    std::vector<std::string> errors;   // parallel to children: why it is invalid ("" if valid)
};

// Births [first, first + count): conceive(birth) makes each child (it must
// only read state that stays unchanged during the call, and may run on any
// thread), then the problem scores it with worker = the OpenMP thread number.
// Calls problem.prepare(threads) first; threads as resolve_threads (worker_threads.hpp).
// Failures outside evaluation (e.g. std::bad_alloc while conceiving) are
// rethrown after the parallel region. Runs use BirthPipeline (pipeline.hpp);
// this is the batch schedule's step for tests and tools.
BredBatch breed_batch(Problem& problem, std::uint64_t first, std::size_t count, int threads,
                      const std::function<Individual(std::uint64_t birth)>& conceive);

// Replaces `best` by `child` if the child is valid and strictly fitter (so the
// earliest of equally fit individuals stays).
inline void keep_best(std::optional<Individual>& best, const Individual& child) {
    if (child.valid() && (!best || child.fitness > best->fitness)) best = child;
}

}  // namespace morphogen
