#include "evolution/evolution_params.hpp"

namespace morphogen {

namespace {
// The novelty_* keys: read for "nslc" only, so other configs resolve to the
// same bytes as before they existed.
NoveltyParams read_novelty_params(ObjectReader& reader, bool nslc) {
    NoveltyParams n;
    if (!nslc) {
        for (const char* key : {"novelty_k", "novelty_archive", "novelty_archive_rate"})
            if (reader.raw(key) != nullptr)
                reader.issues().add(reader.path_of(key), "used only when evolution.algorithm is \"nslc\"");
        return n;
    }
    n.k = static_cast<int>(reader.integer("novelty_k", n.k, 1, 10'000));
    n.archive = static_cast<std::uint64_t>(
        reader.integer("novelty_archive", static_cast<long long>(n.archive), 0, 1'000'000));
    n.archive_rate = reader.number("novelty_archive_rate", n.archive_rate, 0.0, 1.0);
    return n;
}
}  // namespace

GaParams read_evolution_params(ObjectReader& reader, Algorithm* algorithm, NoveltyParams* novelty) {
    GaParams p;
    const std::string name = reader.choice("algorithm", "steady_state", {"steady_state", "map_elites", "nslc"});
    const Algorithm chosen = name == "map_elites" ? Algorithm::map_elites
                             : name == "nslc"     ? Algorithm::nslc
                                                  : Algorithm::steady_state;
    if (algorithm != nullptr) *algorithm = chosen;
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
    const NoveltyParams n = read_novelty_params(reader, chosen == Algorithm::nslc);
    if (novelty != nullptr) *novelty = n;
    reader.finish();
    return p;
}

}  // namespace morphogen
