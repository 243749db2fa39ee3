#pragma once
// Parameters of the steady-state GA (docs/algorithm.md §8.8; the `evolution` config
// section). Defaults are the documented ones (docs/config.md, configs/schema.json).
#include "evolution/execution/schedule.hpp"

namespace morphogen {

struct GaParams {
    int population = 100;        // individuals; a generation is this many births
    int tournament = 3;          // draws per tournament (uniform, with replacement)
    double crossover = 0.3;      // probability a child mixes neuron blocks of two parents
    double mutation_rate = 0.05; // per-parameter probability of a normal step
    double mutation_sigma = 0.3; // standard deviation of that step
    ScheduleKind schedule = ScheduleKind::pipeline;  // when births are conceived (schedule.hpp)
    int lag = 64;                // pipeline: births in flight; birth i draws from the state after births <= i - lag
    int batch = 32;              // batch schedule: births drawn from one population snapshot
    double init_range = 2.0;     // initial parameters uniform in [-init_range, +init_range)
};

// The schedule of a run with these parameters.
inline BirthSchedule birth_schedule(const GaParams& p) {
    return {p.schedule, static_cast<std::uint64_t>(p.population),
            static_cast<std::uint64_t>(p.schedule == ScheduleKind::pipeline ? p.lag : p.batch)};
}

}  // namespace morphogen
