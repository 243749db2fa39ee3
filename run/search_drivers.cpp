#include "run/search_drivers.hpp"

#include "evolution/archive_stats.hpp"
#include "evolution/cvt.hpp"
#include "evolution/operators.hpp"
#include "evolution/population_stats.hpp"
#include "run/archive_csv.hpp"

namespace morphogen {

namespace {
MapElitesParams map_elites_params(const GaParams& p, const QdParams& qd) {
    return {p.population, p.crossover, p.mutation_rate, p.mutation_sigma, p.batch, p.init_range, qd.emitters};
}

// The fitness columns of a history row, from the GA's population or the archive's elites.
void fill_fitness(HistoryRow& row, const PopulationStats& stats) {
    row.best = stats.best;
    row.mean = stats.mean;
    row.median = stats.median;
    row.worst = stats.worst;
    row.mean_vertices = stats.mean_size;
}
}  // namespace

GaDriver::GaDriver(const ExperimentConfig& c, Problem& problem, RunState& state)
    : SearchDriver(c.evolution, c.run.seed, problem, std::move(state.ga)) {}

void GaDriver::fill(HistoryRow& row, const Inserted&) const { fill_fitness(row, summarize(search_.state().population)); }

const Individual* GaDriver::exported() const {
    const Individual* best = nullptr;
    for (const Individual& member : search_.state().population)
        if (best == nullptr || ranks_above(member, *best)) best = &member;
    return best != nullptr && best->valid() ? best : nullptr;
}

MapElitesState initial_elites_state(const ExperimentConfig& c, int threads) {
    if (c.qd.archive == ArchiveKind::grid) return MapElitesState{0, Archive::grid(c.qd.descriptors), {}, 0, 0};
    return MapElitesState{
        0, Archive::cvt(c.qd.descriptors, cvt_centroids(c.run.seed, c.qd.cvt_cells, c.qd.descriptors.size(), threads)),
        {}, 0, 0};
}

EliteDriver::EliteDriver(const ExperimentConfig& c, Problem& problem, RunState& state, int threads)
    : SearchDriver(map_elites_params(c.evolution, c.qd), c.run.seed, problem,
                   state.elites ? std::move(*state.elites) : initial_elites_state(c, threads)),
      qd_offset_(c.qd.qd_offset) {}

void EliteDriver::fill(HistoryRow& row, const Inserted& step) const {
    const ArchiveStats stats = archive_stats(search_.state().archive, qd_offset_);
    fill_fitness(row, stats.fitness);
    row.qd = true;
    row.coverage = stats.coverage;
    row.qd_score = stats.qd_score;
    row.new_cells = step.generation_new_cells;
}

const Individual* EliteDriver::exported() const {
    const Individual* best = nullptr;
    for (const auto& [cell, elite] : search_.state().archive.elites())
        if (best == nullptr || elite.fitness > best->fitness) best = &elite;
    return best;
}

std::string EliteDriver::archive_text() const { return archive_csv(search_.state().archive); }

}  // namespace morphogen
