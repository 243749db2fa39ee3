#pragma once
// A search as a run drives it, and the registry of searches. The run loop
// (evolution_run.hpp) and the checkpoint (checkpoint.hpp) know a search only
// through these: adding one is a RunSearch and a SearchState
// (search_state.hpp) of its own, its state to and from JSON, and a row of
// search_kinds().
#include "evolution/genome_blob.hpp"
#include "evolution/individual.hpp"
#include "evolution/execution/pipeline.hpp"
#include "evolution/ga/population_stats.hpp"
#include "run/config/map_elites_config.hpp"
#include "run/loop/run_records.hpp"
#include "run/searches/search_state.hpp"

#include <nlohmann/json.hpp>
#include <spdlog/logger.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>

namespace morphogen {

struct ExperimentConfig;

// The search of one session, from the state it started from.
class RunSearch {
public:
    virtual ~RunSearch() = default;
    // The search as the birth pipeline drives it.
    virtual Breeder& breeder() = 0;
    virtual std::uint64_t births() const = 0;
    virtual std::uint64_t completed_generations() const = 0;
    // The best valid individual ever born.
    virtual const std::optional<Individual>& best() const = 0;
    // The statistics columns of the history row of the generation `generation_end` ended.
    virtual void fill(HistoryRow& row, const Inserted& generation_end) const = 0;
    // The individual exported to best/ (nullptr: none yet).
    virtual const Individual* exported() const = 0;
    // The MAP-Elites cell of exported(), for its record (none: no cell).
    virtual std::optional<std::uint64_t> exported_cell() const { return std::nullopt; }
    // A copy of its state as it is, for a checkpoint.
    virtual std::unique_ptr<SearchState> save() const = 0;
};

// One search algorithm: how its state enters and leaves a run.
struct SearchKind {
    Algorithm algorithm;
    const char* key;  // its state's key in the checkpoint's content
    bool qd_history;  // history.csv has the QD columns (history_header_qd)
    // A new run's state before its first birth; nullptr when a stop signal
    // (stop_signals.hpp) came while it was made. `threads` may do the work;
    // `progress` (if given) hears of a long start.
    std::unique_ptr<SearchState> (*initial)(const ExperimentConfig& config, int threads, spdlog::logger* progress);
    // Reads and checks the state stored under `key` against the run's config
    // and genome length (parameters from `genomes` when given, else inline);
    // throws std::invalid_argument naming the first defect.
    std::unique_ptr<SearchState> (*load)(const nlohmann::json& stored, const ExperimentConfig& config,
                                         std::size_t dimension, GenomeBlobReader* genomes);
    // Calls `genome(object, path)` on every object of a stored state that may
    // hold a "genome": k, so a tool can put the parameters inline.
    void (*each_genome)(nlohmann::json& stored, const std::function<void(nlohmann::json&, const std::string&)>& genome);
};

// Every search, one row each.
std::span<const SearchKind> search_kinds();
// The row of `algorithm`.
const SearchKind& search_kind(Algorithm algorithm);

// SearchKind::each_genome of a state that keeps a "population" array and a
// "best" (the GA's, NSLC's), stored under `key`.
void each_population_genome(nlohmann::json& stored, const std::string& key,
                            const std::function<void(nlohmann::json&, const std::string&)>& genome);

// The statistics columns of a history row (best .. mean_vertices) from a
// summary of the members, for every search.
void fill_statistics(HistoryRow& row, const PopulationStats& stats);

// What the live search of every algorithm answers the same way from its
// evolution/ class (SteadyStateGA, MapElites: a Breeder with state() and
// completed_generations()).
template <class Search>
class SearchOver : public RunSearch {
public:
    Breeder& breeder() override { return search_; }
    std::uint64_t births() const override { return search_.state().births; }
    std::uint64_t completed_generations() const override { return search_.completed_generations(); }
    const std::optional<Individual>& best() const override { return search_.state().best; }

protected:
    template <class... Args>
    explicit SearchOver(Args&&... args) : search_(std::forward<Args>(args)...) {}
    Search search_;
};

}  // namespace morphogen
