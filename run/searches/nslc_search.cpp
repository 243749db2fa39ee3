#include "run/searches/nslc_search.hpp"

#include "evolution/ga/population_stats.hpp"
#include "evolution/novelty/nslc_state_json.hpp"
#include "evolution/operators.hpp"
#include "run/config/experiment_config.hpp"
#include "run/persistence/checkpoint_checks.hpp"

#include <stdexcept>
#include <string>

namespace morphogen {

namespace {
class NslcSearch final : public SearchOver<Nslc> {
public:
    NslcSearch(const ExperimentConfig& c, Problem& problem, NslcState state)
        : SearchOver(c.evolution, c.novelty, c.qd.descriptors, c.run.seed, problem, std::move(state)) {}

    void fill(HistoryRow& row, const Inserted&) const override {
        fill_statistics(row, summarize(search_.state().population));
    }
    const Individual* exported() const override { return top_ranked(search_.state().population); }
    std::unique_ptr<SearchState> save() const override { return std::make_unique<NslcSearchState>(search_.state()); }
};
}  // namespace

SearchView NslcSearchState::view() const {
    SearchView v;
    v.births = state.births;
    v.best = &state.best;
    for (const Individual& member : state.population) v.members.push_back(&member);
    v.members_name = "nslc.population";
    v.members_source = "the population it holds";
    v.invalid_in_generation = state.invalid_in_generation;
    return v;
}

void NslcSearchState::fill(HistoryRow& row, const ExperimentConfig&) const {
    fill_statistics(row, summarize(state.population));
}

nlohmann::json NslcSearchState::to_json(GenomeBlobWriter* genomes) const { return nslc_state_to_json(state, genomes); }

void NslcSearchState::check_history(std::span<const HistoryRow>, std::span<const RecordedBirth> recorded,
                                    std::uint64_t) const {
    for (std::size_t i = 0; i < state.archive.size(); ++i) {
        const Individual& point = state.archive[i];
        const bool same = point.id < recorded.size() && recorded[point.id].valid &&
                          recorded[point.id].fitness == point.fitness &&
                          (recorded[point.id].descriptors.empty() || recorded[point.id].descriptors == point.descriptors);
        if (!same)
            throw std::invalid_argument("nslc.archive[" + std::to_string(i) + "] (id " + std::to_string(point.id) +
                                        ") differs from its lineage.csv row");
    }
}

void NslcSearchState::check_pending_parents(std::span<const Individual> pending,
                                            std::span<const RecordedBirth> recorded, const BirthReplay&,
                                            const BirthSchedule& schedule) const {
    check_parents_recorded_valid(pending, recorded, schedule);
}

std::unique_ptr<RunSearch> NslcSearchState::start(const ExperimentConfig& config, Problem& problem) {
    return std::make_unique<NslcSearch>(config, problem, std::move(state));
}

SearchKind nslc_search_kind() {
    return {Algorithm::nslc, "nslc", false,
            [](const ExperimentConfig&, int, spdlog::logger*) -> std::unique_ptr<SearchState> {
                return std::make_unique<NslcSearchState>();
            },
            [](const nlohmann::json& stored, const ExperimentConfig& config, std::size_t dimension,
               GenomeBlobReader* genomes) -> std::unique_ptr<SearchState> {
                return std::make_unique<NslcSearchState>(nslc_state_from_json(
                    stored, config.evolution, config.novelty, config.qd.descriptors, dimension, genomes));
            },
            [](nlohmann::json& stored, const std::function<void(nlohmann::json&, const std::string&)>& genome) {
                each_population_genome(stored, "nslc", genome);
            }};
}

const NslcState* nslc_state(const SearchState& state) {
    const auto* nslc = dynamic_cast<const NslcSearchState*>(&state);
    return nslc != nullptr ? &nslc->state : nullptr;
}

}  // namespace morphogen
