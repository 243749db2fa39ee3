#pragma once
// MAP-Elites as a run drives it (run_search.hpp): its history rows summarise
// the archive, it exports the fittest elite, it writes archive.csv, and its
// state is stored under "map_elites" (evolution/schedulers/map_elites_state_json.hpp).
#include "evolution/schedulers/map_elites.hpp"
#include "run/searches/run_search.hpp"
#include "run/searches/search_state.hpp"

#include <spdlog/logger.h>

#include <optional>

namespace morphogen {

class ElitesSearchState final : public SearchState {
public:
    explicit ElitesSearchState(MapElitesState state) : state(std::move(state)) {}
    MapElitesState state;

    std::unique_ptr<SearchState> clone() const override { return std::make_unique<ElitesSearchState>(state); }
    const char* key() const override { return "map_elites"; }
    std::uint64_t births() const override { return state.births; }
    const std::optional<Individual>& best() const override { return state.best; }
    SearchView view() const override;
    void fill(HistoryRow& row, const ExperimentConfig& config) const override;
    nlohmann::json to_json(GenomeBlobWriter* genomes) const override;
    std::string archive_text() const override;
    // Nothing beyond the common checks: an archive is not replayed.
    void check_history(std::span<const HistoryRow>, std::span<const RecordedBirth>, std::uint64_t) const override {}
    // An emitter's parent is an elite: a valid birth recorded before the
    // pending birth's source state.
    void check_pending_parents(std::span<const Individual> pending, std::span<const RecordedBirth> recorded,
                               const BirthReplay& replay, const BirthSchedule& schedule) const override;
    void check_replayed_parents(std::span<const Individual> pending, std::span<const RecordedBirth> recorded,
                                const BirthReplay& replay, const BirthSchedule& schedule,
                                std::span<const std::uint64_t> per_generation) const;
    std::unique_ptr<RunSearch> start(const ExperimentConfig& config, Problem& problem) override;
};

// MAP-Elites' registry row (search_kinds()).
SearchKind elites_search_kind();

// A new MAP-Elites run's empty archive, for the first checkpoint: a CVT's
// centroids are computed from run.seed here, once (their rounds reported to
// `progress` if given); later sessions read them from the checkpoint.
// nullopt if a stop signal (stop_signals.hpp) came while they were placed.
std::optional<MapElitesState> initial_elites_state(const ExperimentConfig& config, int threads,
                                                   spdlog::logger* progress = nullptr);

// The MAP-Elites state a run holds; nullptr when it holds another search's.
const MapElitesState* elites_state(const SearchState& state);

}  // namespace morphogen
