#pragma once
// What the run loop (evolution_run.hpp) needs of a search, for the GA and
// MAP-Elites alike: one step (children in birth order with their errors,
// whether it ended a generation and that generation's invalid births), the
// best ever, the statistics of a history row, the individual exported to
// best/, and saving the state into the checkpoint's RunState.
#include "evolution/batch.hpp"
#include "evolution/map_elites.hpp"
#include "evolution/steady_state.hpp"
#include "run/experiment_config.hpp"
#include "run/run_records.hpp"
#include "run/run_state.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace morphogen {

struct StepResult {
    std::vector<Individual> children;
    std::vector<std::string> errors;
    bool ends_generation = false;
    std::uint64_t generation_invalid = 0;
    std::uint64_t generation_new_cells = 0;
};

// What every driver answers the same way from its search's state.
template <class Search>
class SearchDriver {
public:
    std::uint64_t births() const { return search_.state().births; }
    std::uint64_t completed_generations() const { return search_.completed_generations(); }
    const std::optional<Individual>& best() const { return search_.state().best; }

protected:
    template <class... Args>
    explicit SearchDriver(Args&&... args) : search_(std::forward<Args>(args)...) {}
    Search search_;
};

// The steady-state GA; its history rows summarise the population.
class GaDriver : public SearchDriver<SteadyStateGA> {
public:
    GaDriver(const ExperimentConfig& config, Problem& problem, RunState& state);
    StepResult step(int threads, BatchEvaluator* remote);
    void fill(HistoryRow& row, const StepResult& step) const;
    // The population member that ranks highest, if it is valid.
    const Individual* exported() const;
    void save(RunState& state) const { state.ga = search_.state(); }
    std::string archive_text() const { return {}; }
};

// MAP-Elites; its history rows summarise the archive.
class EliteDriver : public SearchDriver<MapElites> {
public:
    EliteDriver(const ExperimentConfig& config, Problem& problem, RunState& state, int threads);
    StepResult step(int threads, BatchEvaluator* remote);
    void fill(HistoryRow& row, const StepResult& step) const;
    // The fittest elite (ties: the lower cell).
    const Individual* exported() const;
    void save(RunState& state) const { state.elites = search_.state(); }
    std::string archive_text() const;

private:
    double qd_offset_;
};

// A new MAP-Elites run's empty archive, for the first checkpoint: a CVT's
// centroids are computed from run.seed here, once; later sessions read them
// from the checkpoint.
MapElitesState initial_elites_state(const ExperimentConfig& config, int threads);

}  // namespace morphogen
