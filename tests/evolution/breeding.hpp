#pragma once
// Breeding a search in tests as a run does: through the birth pipeline
// (evolution/execution/pipeline.hpp) with the batch schedule, scored by a
// ThreadEvaluator. The library has one birth engine; this is its loop.
#include "evolution/execution/safe_evaluation.hpp"
#include "evolution/execution/pipeline.hpp"
#include "evolution/execution/schedule.hpp"
#include "evolution/execution/thread_evaluator.hpp"
#include "core/base/parallel_for.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace morphogen::test {

// One inserted birth, as the pipeline reported it.
struct Bred {
    Individual child;
    std::string error;  // why it is invalid ("" if valid)
    Inserted what;
};

// Breeds `breeder` until `target` births are inserted, in batches of
// `batch` that never cross a generation of `population` births, scored by
// `threads` threads (<= 0: the machine's). `each` is called right after each
// insertion (the breeder's state is then the one after it).
inline std::vector<Bred> breed_until(Breeder& breeder, Problem& problem, std::uint64_t population, std::uint64_t batch,
                                     int threads, std::uint64_t target,
                                     const std::function<void(const Bred&)>& each = {}) {
    ThreadEvaluator evaluator(problem, resolve_threads(threads));
    BirthPipeline pipeline(BirthSchedule{ScheduleKind::batch, population, batch}, breeder, evaluator);
    std::vector<Bred> out;
    pipeline.run(
        target,
        [&](const Individual& child, const std::string& error, const Inserted& what, const std::string&) {
            out.push_back({child, error, what});
            if (each) each(out.back());
        },
        [] { return false; });
    return out;
}

// The next batch of the batch schedule: min(batch, population - births mod population) births.
inline std::vector<Bred> breed_batch(Breeder& breeder, Problem& problem, std::uint64_t population, std::uint64_t batch,
                                     int threads, const std::function<void(const Bred&)>& each = {}) {
    const std::uint64_t births = breeder.births();
    const std::uint64_t count = std::min(batch, population - births % population);
    return breed_until(breeder, problem, population, batch, threads, births + count, each);
}

}  // namespace morphogen::test
