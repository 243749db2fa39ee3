#include "evolution/evolution_params.hpp"

namespace morphogen {

GaParams read_evolution_params(ObjectReader& reader, Algorithm* algorithm) {
    GaParams p;
    const std::string name = reader.choice("algorithm", "steady_state", {"steady_state", "map_elites"});
    if (algorithm != nullptr) *algorithm = name == "map_elites" ? Algorithm::map_elites : Algorithm::steady_state;
    p.population = static_cast<int>(reader.integer("population", p.population, 2, 1'000'000));
    p.tournament = static_cast<int>(reader.integer("tournament", p.tournament, 1, 1000));
    p.crossover = reader.number("crossover", p.crossover, 0.0, 1.0);
    p.mutation_rate = reader.number("mutation_rate", p.mutation_rate, 0.0, 1.0);
    p.mutation_sigma = reader.number("mutation_sigma", p.mutation_sigma, 0.0, 1000.0);
    const bool batch_given = reader.raw("batch") != nullptr;
    const bool lag_given = reader.raw("lag") != nullptr;
    const std::string schedule =
        reader.choice("schedule", batch_given ? "batch" : "pipeline", {"pipeline", "batch"});
    p.schedule = schedule == "batch" ? ScheduleKind::batch : ScheduleKind::pipeline;
    p.lag = static_cast<int>(reader.integer("lag", p.lag, 1, 1'000'000));
    p.batch = static_cast<int>(reader.integer("batch", p.batch, 1, 1'000'000));
    // Only the schedule's own size applies; the other is not resolved.
    if (p.schedule == ScheduleKind::pipeline) {
        if (batch_given)
            reader.issues().add(reader.path_of("batch"),
                                "applies to schedule \"batch\" only; the pipeline's births in flight are evolution.lag");
        reader.drop_resolved("batch");
    } else {
        if (lag_given) reader.issues().add(reader.path_of("lag"), "applies to schedule \"pipeline\" only");
        reader.drop_resolved("lag");
    }
    p.init_range = reader.number("init_range", p.init_range, 0.0, 1000.0);
    reader.finish();
    return p;
}

}  // namespace morphogen
