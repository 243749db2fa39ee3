#include "run/searches/elites_search.hpp"

#include "evolution/archives/archive_stats.hpp"
#include "evolution/archives/cvt.hpp"
#include "evolution/emitters/emitter_state_json.hpp"
#include "evolution/schedulers/map_elites_state_json.hpp"
#include "run/persistence/archive_csv.hpp"
#include "run/config/experiment_config.hpp"
#include "run/loop/stop_signals.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {
MapElitesParams map_elites_params(const GaParams& p, const QdParams& qd) {
    return {p.population, p.crossover, p.mutation_rate, p.mutation_sigma, p.batch, p.init_range, qd.emitters};
}

// The statistics columns of a history row over the archive's elites.
void fill_archive_statistics(HistoryRow& row, const Archive& archive, double qd_offset) {
    const ArchiveStats stats = archive_stats(archive, qd_offset);
    fill_statistics(row, stats.fitness);
    row.qd = true;
    row.coverage = stats.coverage;
    row.qd_score = stats.qd_score;
}

class EliteSearch final : public SearchOver<MapElites> {
public:
    EliteSearch(const ExperimentConfig& c, Problem& problem, MapElitesState state)
        : SearchOver(map_elites_params(c.evolution, c.qd), c.run.seed, problem, std::move(state)),
          qd_offset_(c.qd.qd_offset) {}

    void fill(HistoryRow& row, const Inserted& step) const override {
        fill_archive_statistics(row, search_.state().archive, qd_offset_);
        row.new_cells = step.generation_new_cells;
    }
    // The fittest elite (ties: the lower cell).
    const Individual* exported() const override { return fittest().second; }
    std::optional<std::uint64_t> exported_cell() const override {
        const auto [cell, elite] = fittest();
        return elite != nullptr ? std::optional<std::uint64_t>(cell) : std::nullopt;
    }
    std::unique_ptr<SearchState> save() const override {
        return std::make_unique<ElitesSearchState>(search_.state());
    }

private:
    std::pair<std::uint64_t, const Individual*> fittest() const {
        std::pair<std::uint64_t, const Individual*> best{0, nullptr};
        for (const auto& [cell, elite] : search_.state().archive.elites())
            if (best.second == nullptr || elite.fitness > best.second->fitness) best = {cell, &elite};
        return best;
    }
    double qd_offset_;
};
}  // namespace

SearchView ElitesSearchState::view() const {
    SearchView v;
    v.births = state.births;
    v.best = &state.best;
    for (const auto& [cell, elite] : state.archive.elites()) v.members.push_back(&elite);
    v.members_name = "map_elites.archive.elites";
    v.members_source = "the archive it holds";
    v.invalid_in_generation = state.invalid_in_generation;
    return v;
}

void ElitesSearchState::fill(HistoryRow& row, const ExperimentConfig& config) const {
    fill_archive_statistics(row, state.archive, config.qd.qd_offset);
}

nlohmann::json ElitesSearchState::to_json(GenomeBlobWriter* genomes) const {
    return map_elites_state_to_json(state, genomes);
}

std::string ElitesSearchState::archive_text() const { return archive_csv(state.archive); }

void ElitesSearchState::check_pending_parents(std::span<const Individual> pending,
                                              std::span<const RecordedBirth> recorded, const BirthReplay&,
                                              const BirthSchedule& schedule) const {
    for (std::size_t i = 0; i < pending.size(); ++i) {
        const Individual& child = pending[i];
        const std::uint64_t source = schedule.source(child.id);
        for (const std::optional<std::uint64_t>& parent : {child.parent1, child.parent2})
            if (parent && (*parent >= source || *parent >= recorded.size() || !recorded[*parent].valid))
                throw std::invalid_argument("pending[" + std::to_string(i) + "] (birth " + std::to_string(child.id) +
                                            ") has parent " + std::to_string(*parent) +
                                            ", not a valid birth before its source state (" + std::to_string(source) +
                                            " births) in lineage.csv");
    }
}

std::unique_ptr<RunSearch> ElitesSearchState::start(const ExperimentConfig& config, Problem& problem) {
    return std::make_unique<EliteSearch>(config, problem, std::move(state));
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

SearchKind elites_search_kind() {
    return {Algorithm::map_elites, "map_elites", true,
            [](const ExperimentConfig& config, int threads, spdlog::logger* progress) -> std::unique_ptr<SearchState> {
                std::optional<MapElitesState> state = initial_elites_state(config, threads, progress);
                if (!state) return nullptr;
                return std::make_unique<ElitesSearchState>(std::move(*state));
            },
            [](const nlohmann::json& stored, const ExperimentConfig& config, std::size_t dimension,
               GenomeBlobReader* genomes) -> std::unique_ptr<SearchState> {
                const auto P = static_cast<std::uint64_t>(config.evolution.population);
                return std::make_unique<ElitesSearchState>(
                    map_elites_state_from_json(stored, config.qd.archive, config.qd.descriptors, config.qd.cells(), P,
                                               dimension, config.qd.emitters, genomes));
            },
            [](nlohmann::json& stored, const std::function<void(nlohmann::json&, const std::string&)>& genome) {
                if (!stored.is_object()) return;
                if (stored.contains("archive") && stored["archive"].is_object()) {
                    nlohmann::json& archive = stored["archive"];
                    if (archive.contains("elites") && archive["elites"].is_array())
                        for (std::size_t i = 0; i < archive["elites"].size(); ++i)
                            genome(archive["elites"][i], "map_elites.archive.elites[" + std::to_string(i) + "]");
                }
                if (stored.contains("best")) genome(stored["best"], "map_elites.best");
                if (stored.contains("emitters")) for_each_emitter_vector(stored["emitters"], "map_elites.emitters", genome);
            }};
}

const MapElitesState* elites_state(const SearchState& state) {
    const auto* elites = dynamic_cast<const ElitesSearchState*>(&state);
    return elites != nullptr ? &elites->state : nullptr;
}

}  // namespace morphogen
