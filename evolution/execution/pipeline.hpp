#pragma once
// The birth pipeline (docs/algorithm.md §8.4), shared by the GA and
// MAP-Elites: births are conceived on the calling thread at the moment their
// schedule (schedule.hpp) says, the evaluator scores them wherever and in
// whatever order it likes, and they are inserted strictly in birth order. So
// the search's state after any number of births depends on the schedule and
// the seed alone, never on threads, processes or timing.
#include "evolution/execution/genome_evaluator.hpp"
#include "evolution/individual.hpp"
#include "evolution/execution/schedule.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

// What inserting one child did, for the run's records.
struct Inserted {
    bool ends_generation = false;           // it completed a generation
    std::uint64_t generation_invalid = 0;   // if so: invalid births in that generation
    std::uint64_t generation_new_cells = 0; // if so: cells first filled in it (MAP-Elites)
};

// Counts an inserted birth: `births` + 1 and, if that ends a generation of
// `population` births, what it did (its invalid births, then reset to 0).
Inserted count_birth(std::uint64_t& births, std::uint64_t& invalid_in_generation, std::uint64_t population);

// A search as the pipeline drives it (SteadyStateGA, MapElites, Nslc).
class Breeder {
public:
    virtual ~Breeder() = default;
    // Births inserted so far; the next birth to insert.
    virtual std::uint64_t births() const = 0;
    // Birth `birth`, not yet evaluated, from the state as it is now.
    virtual Individual conceive(std::uint64_t birth) const = 0;
    // Inserts the next birth, evaluated; may make it invalid (with `error`).
    virtual Inserted insert(Individual& child, std::string& error) = 0;
    // A child scoring below this can never become the individual the run
    // exports (the best population member or elite, which only ever gets
    // better); -infinity while there is none.
    virtual double export_floor() const = 0;
};

// Moves an evaluation's results into its child (one place, so no path can
// disagree on a bit): fitness (invalid_fitness when invalid), size,
// descriptors, and `error` ("" when valid).
void take_evaluation(Individual& child, std::string& error, Evaluation&& evaluation);

// At most this many births in flight (submitted, not yet inserted) may keep
// export files (Evaluation::kept): the others are submitted with nothing to
// keep, and the run grows such a child again if it is exported after all.
// So a large lag costs memory for its genomes, not for as many meshes, in
// the evaluator's queues as in the pipeline.
inline constexpr std::size_t kMaxKeepingBirths = 8;

class BirthPipeline {
public:
    // `kept`: the births a checkpoint kept (schedule.kept_begin/kept_end of
    // the breeder's births), in birth order, not yet evaluated.
    BirthPipeline(const BirthSchedule& schedule, Breeder& breeder, GenomeEvaluator& evaluator,
                  std::vector<Individual> kept = {});
    // Abandons what is in flight (evaluator.cancel()).
    ~BirthPipeline();
    BirthPipeline(const BirthPipeline&) = delete;
    BirthPipeline& operator=(const BirthPipeline&) = delete;

    // `kept`: what the evaluation kept for exporting the child (Evaluation::kept;
    // asked for when it could beat export_floor()), else empty.
    using OnInsert = std::function<void(const Individual& child, const std::string& error, const Inserted& what,
                                        const std::string& kept)>;
    // Inserts births in order, calling `on_insert` after each, until `target`
    // births are done (true) or `stop()` says so (false; asked between
    // insertions and at least every 100 ms while waiting). Only births below
    // `target` are scored; later ones are conceived when due and kept.
    bool run(std::uint64_t target, const OnInsert& on_insert, const std::function<bool()>& stop);

    // The births a checkpoint taken now must keep (schedule.hpp: kept_begin..kept_end).
    std::vector<Individual> kept() const;

private:
    struct Slot {
        Individual child;
        std::optional<Evaluation> evaluation;
        bool may_keep = false;  // submitted with a keep_from (one of kMaxKeepingBirths)
    };
    void conceive_due(std::uint64_t target);
    void submit_below(std::uint64_t target);

    BirthSchedule schedule_;
    Breeder& breeder_;
    GenomeEvaluator& evaluator_;
    std::deque<Slot> slots_;    // births breeder_.births() + k, conceived, in order
    std::size_t submitted_ = 0;  // slots_[0, submitted_) went to the evaluator
    std::size_t keeping_ = 0;    // slots with may_keep
};

}  // namespace morphogen
