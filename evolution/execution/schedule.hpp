#pragma once
// When a birth is conceived (docs/algorithm.md §8.4): the population (or
// archive) a birth draws its parents from, as a count of births inserted
// before it. Two schedules:
//   - pipeline, lag W: birth i >= P draws from the state after births
//     0..max(i-W, P-1) were inserted, so W births are in flight and no thread
//     waits for a batch to drain; births below P are random genomes;
//   - batch, size B: births go in batches of min(B, P - births mod P) that
//     never cross a generation boundary, every birth of a batch drawing from
//     the state before the batch (the schedule of runs made before the
//     pipeline; their bytes depend on it).
// The bytes of a run depend on the schedule and never on threads or processes.
#include <cstdint>
#include <string>

namespace morphogen {

enum class ScheduleKind { pipeline, batch };

struct BirthSchedule {
    ScheduleKind kind = ScheduleKind::pipeline;
    std::uint64_t population = 100;  // P: births below P are random genomes (generation 0)
    std::uint64_t width = 64;        // the lag W (pipeline) or the batch size B (batch); >= 1

    // The births inserted before birth `birth` is conceived: its parents come
    // from the state with exactly this many births.
    std::uint64_t source(std::uint64_t birth) const;
    // Once `births` are inserted, every birth below this one may be conceived
    // (and must be, before the next insertion, if its source is `births`).
    std::uint64_t conceivable_end(std::uint64_t births) const;
    // Births at or above `births` whose source is below `births` and that are
    // not random: [births, kept_end(births)) intersected with [P, ...). A stop
    // after `births` insertions must keep them (a checkpoint's "pending"),
    // since the state they came from is gone. Empty at batch boundaries.
    std::uint64_t kept_begin(std::uint64_t births) const;
    std::uint64_t kept_end(std::uint64_t births) const;

    std::string describe() const;  // "pipeline, lag 64" or "batch 32"
};

}  // namespace morphogen
