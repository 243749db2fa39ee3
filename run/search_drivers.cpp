#include "run/search_drivers.hpp"

#include "evolution/archive_stats.hpp"
#include "evolution/cvt.hpp"
#include "evolution/operators.hpp"
#include "evolution/population_stats.hpp"
#include "run/archive_csv.hpp"
#include "run/stop_signals.hpp"

#include <algorithm>
#include <stdexcept>

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

std::optional<MapElitesState> initial_elites_state(const ExperimentConfig& c, int threads, spdlog::logger* progress) {
    std::optional<Archive> archive;
    if (c.qd.archive == ArchiveKind::grid) {
        archive.emplace(Archive::grid(c.qd.descriptors));
    } else {
        CvtWatch watch;
        watch.stop = [] { return StopSignals::requested(); };
        if (progress != nullptr) {
            progress->info("placing {} CVT centroids over {} descriptors (at most {} rounds)", c.qd.cvt_cells,
                           c.qd.descriptors.size(), kCvtLloydIterations);
            watch.round_done = [progress](int round) { progress->info("CVT centroids: round {} done", round); };
        }
        std::vector<double> centroids = cvt_centroids(c.run.seed, c.qd.cvt_cells, c.qd.descriptors.size(), threads, watch);
        if (centroids.empty()) return std::nullopt;
        archive.emplace(Archive::cvt(c.qd.descriptors, std::move(centroids)));
    }
    MapElitesState state{0, std::move(*archive), {}, 0, 0};
    // Fresh emitters, as MapElites makes them: the checkpoint written before
    // the first birth must hold what resume asks of every later one.
    state.emitters = fresh_emitters(c.qd.emitters);
    return state;
}

namespace {
MapElitesState take_elites(RunState& state) {
    if (!state.elites) throw std::logic_error("EliteDriver: the run state holds no MAP-Elites state");
    return std::move(*state.elites);
}
}  // namespace

EliteDriver::EliteDriver(const ExperimentConfig& c, Problem& problem, RunState& state)
    : SearchDriver(map_elites_params(c.evolution, c.qd), c.run.seed, problem, take_elites(state)),
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
