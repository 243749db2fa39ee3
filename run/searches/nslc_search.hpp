#pragma once
// Novelty search with local competition as a run drives it (run_search.hpp;
// docs/algorithm.md §14): its history rows summarise the population, it
// exports the population's fittest member (as the GA does), and its state is
// stored under "nslc" (evolution/novelty/nslc_state_json.hpp).
#include "evolution/novelty/nslc.hpp"
#include "run/searches/population_search_state.hpp"

namespace morphogen {

class NslcSearchState final : public PopulationSearchState<NslcState, NslcSearchState> {
public:
    using PopulationSearchState::PopulationSearchState;
    static constexpr bool first_births = false;  // invalid births take no slot

    const char* key() const override { return "nslc"; }
    nlohmann::json to_json(GenomeBlobWriter* genomes) const override;
    // Every archive point as lineage.csv records its birth: valid, with the
    // same fitness and descriptors.
    void check_history(std::span<const HistoryRow> history, std::span<const RecordedBirth> recorded,
                       std::uint64_t population) const override;
    // A parent is a member the search kept: a valid birth before the pending
    // birth's source state.
    void check_pending_parents(std::span<const Individual> pending, std::span<const RecordedBirth> recorded,
                               const BirthReplay& replay, const BirthSchedule& schedule) const override;
    std::unique_ptr<RunSearch> start(const ExperimentConfig& config, Problem& problem) override;
};

// NSLC's registry row (search_kinds()).
SearchKind nslc_search_kind();

// The NSLC state a run holds; nullptr when it holds another search's.
const NslcState* nslc_state(const SearchState& state);

}  // namespace morphogen
