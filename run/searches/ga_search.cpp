#include "run/searches/ga_search.hpp"

#include "evolution/ga/ga_state_json.hpp"
#include "evolution/operators.hpp"
#include "evolution/ga/population_stats.hpp"
#include "run/persistence/checkpoint_checks.hpp"
#include "run/config/experiment_config.hpp"

#include <stdexcept>
#include <string>

namespace morphogen {

namespace {
// A member replayed from lineage.csv: its id and recorded fitness (parameters zero).
Individual replayed(std::uint64_t id, const RecordedBirth& recorded, std::size_t dimension) {
    Individual member;
    member.id = id;
    member.fitness = recorded.valid ? recorded.fitness : invalid_fitness;
    member.params.assign(dimension, 0.0);
    return member;
}

std::string parent_text(const std::optional<std::uint64_t>& parent) {
    return parent ? std::to_string(*parent) : "null";
}
}  // namespace

nlohmann::json GaSearchState::to_json(GenomeBlobWriter* genomes) const { return ga_state_to_json(state, genomes); }

void GaSearchState::check_history(std::span<const HistoryRow> history, std::span<const RecordedBirth> recorded,
                                  std::uint64_t P) const {
    std::vector<Individual> population;
    population.reserve(P);
    for (std::size_t g = 0; g < history.size() && (g + 1) * P <= recorded.size(); ++g) {
        for (std::uint64_t id = g * P; id < (g + 1) * P; ++id) insert_child(population, replayed(id, recorded[id], 0), P);
        check_row_stats(history[g], g, summarize(population), false, "the population lineage.csv records");
    }
}

// The draws that pick parents do not read parameters, so the replayed
// members' zero parameters re-draw the same parents.
void GaSearchState::check_pending_parents(std::span<const Individual> pending, std::span<const RecordedBirth> recorded,
                                          const BirthReplay& replay, const BirthSchedule& schedule) const {
    const auto P = static_cast<std::uint64_t>(replay.params.population);
    std::vector<Individual> population;
    population.reserve(P);
    std::uint64_t done = 0;
    for (std::size_t i = 0; i < pending.size(); ++i) {
        const Individual& child = pending[i];
        for (const std::uint64_t source = schedule.source(child.id); done < source && done < recorded.size(); ++done)
            insert_child(population, replayed(done, recorded[done], replay.dimension), P);
        const Individual expected =
            conceive(population, replay.params, replay.blocks, replay.dimension, replay.seed, child.id);
        if (expected.parent1 != child.parent1 || expected.parent2 != child.parent2)
            throw std::invalid_argument("pending[" + std::to_string(i) + "] (birth " + std::to_string(child.id) +
                                        ") has parents " + parent_text(child.parent1) + ", " +
                                        parent_text(child.parent2) + "; the population lineage.csv records at " +
                                        "its source state gives " + parent_text(expected.parent1) + ", " +
                                        parent_text(expected.parent2));
    }
}

std::unique_ptr<RunSearch> GaSearchState::start(const ExperimentConfig& config, Problem& problem) {
    return std::make_unique<PopulationSearch<SteadyStateGA, GaSearchState>>(config.evolution, config.run.seed, problem,
                                                                         std::move(state));
}

SearchKind ga_search_kind() {
    return {Algorithm::steady_state, "ga", false,
            [](const ExperimentConfig&, int, spdlog::logger*) -> std::unique_ptr<SearchState> {
                return std::make_unique<GaSearchState>();
            },
            [](const nlohmann::json& stored, const ExperimentConfig& config, std::size_t dimension,
               GenomeBlobReader* genomes) -> std::unique_ptr<SearchState> {
                return std::make_unique<GaSearchState>(ga_state_from_json(stored, config.evolution, dimension, genomes));
            },
            [](nlohmann::json& stored, const std::function<void(nlohmann::json&, const std::string&)>& genome) {
                each_population_genome(stored, "ga", genome);
            }};
}

GaState* ga_state(SearchState& state) {
    auto* ga = dynamic_cast<GaSearchState*>(&state);
    return ga != nullptr ? &ga->state : nullptr;
}

const GaState* ga_state(const SearchState& state) {
    const auto* ga = dynamic_cast<const GaSearchState*>(&state);
    return ga != nullptr ? &ga->state : nullptr;
}

}  // namespace morphogen
