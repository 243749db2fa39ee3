#pragma once
// What the run loop (evolution_run.hpp) needs of a search, for the GA and
// MAP-Elites alike: the search as the birth pipeline drives it (Breeder), the
// best ever, the statistics of a history row, the individual exported to
// best/, and saving the state into the checkpoint's RunState.
#include "evolution/map_elites.hpp"
#include "evolution/pipeline.hpp"
#include "evolution/steady_state.hpp"
#include "run/experiment_config.hpp"
#include "run/run_records.hpp"
#include "run/run_state.hpp"

#include <spdlog/logger.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace morphogen {

// What every driver answers the same way from its search's state.
template <class Search>
class SearchDriver {
public:
    std::uint64_t births() const { return search_.state().births; }
    std::uint64_t completed_generations() const { return search_.completed_generations(); }
    const std::optional<Individual>& best() const { return search_.state().best; }
    Breeder& breeder() { return search_; }

protected:
    template <class... Args>
    explicit SearchDriver(Args&&... args) : search_(std::forward<Args>(args)...) {}
    Search search_;
};

// The steady-state GA; its history rows summarise the population.
class GaDriver : public SearchDriver<SteadyStateGA> {
public:
    GaDriver(const ExperimentConfig& config, Problem& problem, RunState& state);
    void fill(HistoryRow& row, const Inserted& generation_end) const;
    // The population member that ranks highest, if it is valid.
    const Individual* exported() const;
    void save(RunState& state) const { state.ga = search_.state(); }
    std::string archive_text() const { return {}; }
};

// MAP-Elites; its history rows summarise the archive.
class EliteDriver : public SearchDriver<MapElites> {
public:
    // state.elites must hold the search's state (initial_elites_state for a new run).
    EliteDriver(const ExperimentConfig& config, Problem& problem, RunState& state);
    void fill(HistoryRow& row, const Inserted& generation_end) const;
    // The fittest elite (ties: the lower cell).
    const Individual* exported() const;
    void save(RunState& state) const { state.elites = search_.state(); }
    std::string archive_text() const;

private:
    double qd_offset_;
};

// A new MAP-Elites run's empty archive, for the first checkpoint: a CVT's
// centroids are computed from run.seed here, once (their rounds reported to
// `progress` if given); later sessions read them from the checkpoint.
// nullopt if a stop signal (stop_signals.hpp) came while they were placed.
std::optional<MapElitesState> initial_elites_state(const ExperimentConfig& config, int threads,
                                                   spdlog::logger* progress = nullptr);

}  // namespace morphogen
