#pragma once
// A search's state as a run keeps it between sessions: what the checkpoint's
// content holds under the search's key (checkpoint.hpp). Each search
// (run_search.hpp's registry) writes, reads and checks its own state; the
// checkpoint code seals it in the envelope and checks what every search has
// alike (checkpoint_checks.hpp) through view().
#include "evolution/emitters/emitters.hpp"
#include "evolution/ga/ga_params.hpp"
#include "evolution/genome_blob.hpp"
#include "evolution/individual.hpp"
#include "evolution/execution/schedule.hpp"
#include "run/loop/run_records.hpp"

#include <nlohmann/json.hpp>

#include <concepts>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

class Problem;
class RunSearch;
struct ExperimentConfig;

// What the common checks read of any search's state.
struct SearchView {
    std::uint64_t births = 0;
    const std::optional<Individual>* best = nullptr;
    std::vector<const Individual*> members;  // the population, or the archive's elites in cell order
    std::string members_name;                // their path in the content ("ga.population")
    std::string members_source;              // what a history row summarises ("the population it holds")
    std::uint64_t invalid_in_generation = 0;
    // In generation 0, member i is birth i with no parents (the GA's slots).
    bool members_are_first_births = false;
};

// One birth as lineage.csv records it, for the checks that replay a run.
struct RecordedBirth {
    bool valid = false;
    double fitness = 0.0;
    std::optional<std::uint64_t> parent1, parent2;
    std::vector<double> descriptors;  // its descriptor cells (none for an invalid birth or a 5-column lineage.csv)
};

// What re-drawing a birth's parents needs (docs/algorithm.md §8.2): the GA's
// parameters, the run's seed and the genome's blocks and length.
struct BirthReplay {
    GaParams params;
    std::uint64_t seed = 0;
    std::vector<Block> blocks;
    std::size_t dimension = 0;
    std::vector<EmitterSpec> emitters;  // MAP-Elites' (resolved: never empty there)
};

class SearchState {
public:
    virtual ~SearchState() = default;
    virtual std::unique_ptr<SearchState> clone() const = 0;

    // Its key in the checkpoint's content (SearchKind::key).
    virtual const char* key() const = 0;
    virtual std::uint64_t births() const = 0;
    virtual const std::optional<Individual>& best() const = 0;
    virtual SearchView view() const = 0;
    // The statistics columns of a history row taken now (best .. mean_vertices;
    // qd, coverage and qd_score for an archive): what the run wrote at the
    // generation end this state was saved at.
    virtual void fill(HistoryRow& row, const ExperimentConfig& config) const = 0;
    // Its part of the checkpoint's content, genomes into `genomes` (format 2) or inline.
    virtual nlohmann::json to_json(GenomeBlobWriter* genomes) const = 0;
    // archive.csv's text; empty when the search writes none.
    virtual std::string archive_text() const { return {}; }

    // Checks against lineage.csv beyond the common ones; each throws
    // std::invalid_argument saying what contradicts what. `recorded` holds
    // one entry per birth, in birth order.
    virtual void check_history(std::span<const HistoryRow> history, std::span<const RecordedBirth> recorded,
                               std::uint64_t population) const = 0;
    virtual void check_pending_parents(std::span<const Individual> pending, std::span<const RecordedBirth> recorded,
                                       const BirthReplay& replay, const BirthSchedule& schedule) const = 0;

    // The search of a session, continuing from this state (which it takes:
    // this one is left empty).
    virtual std::unique_ptr<RunSearch> start(const ExperimentConfig& config, Problem& problem) = 0;
};

// A SearchState held by value: copies clone it. Empty until a search's state is put in.
class HeldSearchState {
public:
    HeldSearchState() = default;
    template <std::derived_from<SearchState> State>
    HeldSearchState(std::unique_ptr<State> state) : state_(std::move(state)) {}
    HeldSearchState(const HeldSearchState& other) : state_(other.state_ ? other.state_->clone() : nullptr) {}
    HeldSearchState(HeldSearchState&&) noexcept = default;
    HeldSearchState& operator=(HeldSearchState other) noexcept {
        state_ = std::move(other.state_);
        return *this;
    }

    explicit operator bool() const { return state_ != nullptr; }
    SearchState* operator->() const { return state_.get(); }
    SearchState& operator*() const { return *state_; }
    SearchState* get() const { return state_.get(); }

private:
    std::unique_ptr<SearchState> state_;
};

}  // namespace morphogen
