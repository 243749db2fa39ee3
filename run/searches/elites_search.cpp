#include "run/searches/elites_search.hpp"

#include "evolution/archives/archive_stats.hpp"
#include "evolution/archives/cvt.hpp"
#include "evolution/emitters/cma/cma_emitter.hpp"
#include "evolution/emitters/emitter_state_json.hpp"
#include "evolution/schedulers/map_elites_state_json.hpp"
#include "run/persistence/archive_csv.hpp"
#include "run/persistence/checkpoint_checks.hpp"
#include "run/config/experiment_config.hpp"
#include "run/loop/stop_signals.hpp"

#include <algorithm>
#include <map>
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

namespace {
std::string parents_text(const std::optional<std::uint64_t>& parent1, const std::optional<std::uint64_t>& parent2) {
    const auto one = [](const std::optional<std::uint64_t>& p) { return p ? std::to_string(*p) : std::string("null"); };
    return one(parent1) + ", " + one(parent2);
}

// A CMA emitter's children take their parents from its state alone:
// parent1 its origin (null before its first start), parent2 null. Its state
// changes only where it may restart: after its last birth of a generation is
// inserted, and at a generation's end (a first start). Between two such
// points every child it conceives has the same parents. `first` and `count`:
// where its births lie in each generation.
struct CmaBirths {
    std::uint64_t population = 0, end = 0;  // end: its last birth's offset in a generation, plus one
    const CmaEmitter* now = nullptr;        // its state after the checkpoint's births
    // The stretch between two restart points that a source state lies in.
    std::uint64_t stretch(std::uint64_t source) const {
        return 2 * (source / population) + (source % population >= end ? 1 : 0);
    }
};
}  // namespace

// An emitter without state (gaussian, iso_line) conceives from the archive at
// the birth's source alone: that archive is replayed from lineage.csv (ids,
// fitness, descriptors; the parameters, which no draw of parents reads, zero)
// and the parents drawn again. Not for a lineage.csv without descriptor
// columns (a run begun before it had them).
void ElitesSearchState::check_replayed_parents(std::span<const Individual> pending,
                                               std::span<const RecordedBirth> recorded, const BirthReplay& replay,
                                               const BirthSchedule& schedule,
                                               std::span<const std::uint64_t> per_generation) const {
    const auto P = static_cast<std::uint64_t>(replay.params.population);
    const Archive& now = state.archive;
    const auto stateless = [&](std::uint64_t id) {
        return id >= P && !replay.emitters[emitter_of(id, per_generation, P)].emitter->keeps_state();
    };
    if (std::none_of(pending.begin(), pending.end(), [&](const Individual& c) { return stateless(c.id); })) return;
    for (const RecordedBirth& birth : recorded)
        if (birth.valid && birth.descriptors.size() != now.dimensions()) return;
    Archive archive = now.kind() == ArchiveKind::grid ? Archive::grid(now.ranges()) : Archive::cvt(now.ranges(), now.centroids());
    if (const std::optional<ThresholdParams> t = archive_thresholds(replay.emitters)) archive.keep_thresholds(*t);
    const BirthRules rules{P, replay.params.init_range, replay.params.crossover, replay.params.mutation_rate,
                           replay.params.mutation_sigma, {}, {}};
    std::uint64_t done = 0;
    for (std::size_t i = 0; i < pending.size(); ++i) {
        const Individual& child = pending[i];
        if (!stateless(child.id)) continue;
        for (const std::uint64_t source = schedule.source(child.id); done < source && done < recorded.size(); ++done) {
            Individual born;
            born.id = done;
            born.fitness = recorded[done].valid ? recorded[done].fitness : invalid_fitness;
            born.descriptors = recorded[done].descriptors;
            born.params.assign(replay.dimension, 0.0);
            (void)archive.insert(born);
        }
        const ParentPool pool(archive.snapshot());
        const EmitterSource source{rules, replay.blocks, replay.dimension, replay.seed, pool};
        const Individual expected =
            replay.emitters[emitter_of(child.id, per_generation, P)].emitter->conceive(source, child.id);
        if (expected.parent1 != child.parent1 || expected.parent2 != child.parent2)
            throw std::invalid_argument("pending[" + std::to_string(i) + "] (birth " + std::to_string(child.id) +
                                        ") has parents " + parents_text(child.parent1, child.parent2) +
                                        "; the archive lineage.csv records at its source state gives " +
                                        parents_text(expected.parent1, expected.parent2));
    }
}

void ElitesSearchState::check_pending_parents(std::span<const Individual> pending,
                                              std::span<const RecordedBirth> recorded, const BirthReplay& replay,
                                              const BirthSchedule& schedule) const {
    check_parents_recorded_valid(pending, recorded, schedule);
    // The CMA emitters' children (docs/algorithm.md §9.8): the same parents
    // as every other child of that emitter conceived between the same two
    // restart points (lineage.csv's or pending), and, conceived after the
    // emitter's last restart point, its origin now.
    const auto P = static_cast<std::uint64_t>(replay.params.population);
    if (replay.emitters.empty() || P == 0) return;
    const std::vector<std::uint64_t> per_generation = births_per_generation(replay.emitters, P);
    check_replayed_parents(pending, recorded, replay, schedule, per_generation);
    if (replay.emitters.size() != state.emitters.size()) return;
    std::vector<CmaBirths> cma(state.emitters.size());
    std::uint64_t offset = 0;
    for (std::size_t k = 0; k < cma.size(); ++k) {
        offset += per_generation[k];
        cma[k] = {P, offset, dynamic_cast<const CmaEmitter*>(state.emitters[k].get())};
    }
    struct Seen {
        std::uint64_t id;
        std::optional<std::uint64_t> parent1, parent2;
    };
    std::map<std::pair<std::size_t, std::uint64_t>, Seen> first_in;  // (emitter, stretch) -> its first child
    const auto check = [&](std::uint64_t id, const std::optional<std::uint64_t>& parent1,
                           const std::optional<std::uint64_t>& parent2, const std::string& where) {
        if (id < P) return;
        const std::size_t k = emitter_of(id, per_generation, P);
        if (cma[k].now == nullptr) return;
        const std::uint64_t source = schedule.source(id);
        const auto refuse = [&](const std::string& why) {
            throw std::invalid_argument(where + " (birth " + std::to_string(id) + ", CMA emitter " + std::to_string(k) +
                                        ") has parents " + parents_text(parent1, parent2) + "; " + why);
        };
        if (parent2) refuse("a CMA emitter's child has one parent, its origin");
        const auto [at, fresh] = first_in.try_emplace({k, cma[k].stretch(source)}, Seen{id, parent1, parent2});
        if (!fresh && at->second.parent1 != parent1)
            refuse("birth " + std::to_string(at->second.id) + ", conceived from the same state of that emitter, has " +
                   parents_text(at->second.parent1, at->second.parent2));
        const CmaEmitterState& now = cma[k].now->state();
        if (cma[k].stretch(source) == cma[k].stretch(births()) && parent1 != (now.started ? now.origin : std::nullopt))
            refuse("that emitter's state, unchanged since its source, gives " +
                   parents_text(now.started ? now.origin : std::nullopt, std::nullopt));
    };
    for (std::uint64_t id = 0; id < recorded.size(); ++id)
        check(id, recorded[id].parent1, recorded[id].parent2, "lineage.csv row " + std::to_string(id + 1));
    for (std::size_t i = 0; i < pending.size(); ++i)
        check(pending[i].id, pending[i].parent1, pending[i].parent2, "pending[" + std::to_string(i) + "]");
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
