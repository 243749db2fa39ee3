#pragma once
// The steady-state GA as a run drives it (run_search.hpp): its history rows
// summarise the population, it exports the population member that ranks
// highest, and its state is stored under "ga" (evolution/ga/ga_state_json.hpp).
#include "evolution/ga/steady_state.hpp"
#include "run/searches/population_search_state.hpp"

namespace morphogen {

class GaSearchState final : public PopulationSearchState<GaState, GaSearchState> {
public:
    using PopulationSearchState::PopulationSearchState;
    static constexpr bool first_births = true;

    const char* key() const override { return "ga"; }
    nlohmann::json to_json(GenomeBlobWriter* genomes) const override;
    // Every history row's fitness columns against the population replayed
    // from lineage.csv's fitness column with the GA's insertion rule.
    void check_history(std::span<const HistoryRow> history, std::span<const RecordedBirth> recorded,
                       std::uint64_t population) const override;
    // Each pending birth's parents re-drawn from the population replayed at
    // its source state (docs/algorithm.md §8.2) must be the stored ones.
    void check_pending_parents(std::span<const Individual> pending, std::span<const RecordedBirth> recorded,
                               const BirthReplay& replay, const BirthSchedule& schedule) const override;
    std::unique_ptr<RunSearch> start(const ExperimentConfig& config, Problem& problem) override;
};

// The GA's registry row (search_kinds()).
SearchKind ga_search_kind();

// The GA's state a run holds; nullptr when it holds another search's.
GaState* ga_state(SearchState& state);
const GaState* ga_state(const SearchState& state);

}  // namespace morphogen
