#include "run/searches/nslc_search.hpp"

#include "evolution/novelty/nslc_state_json.hpp"
#include "run/config/experiment_config.hpp"
#include "run/persistence/checkpoint_checks.hpp"

#include <stdexcept>
#include <string>

namespace morphogen {

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
    return std::make_unique<PopulationSearch<Nslc, NslcSearchState>>(config.evolution, config.novelty,
                                                                      config.qd.descriptors, config.run.seed, problem,
                                                                      std::move(state));
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
