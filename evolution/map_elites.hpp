#pragma once
// The MAP-Elites driver (docs/algorithm.md §9), a Breeder for the birth
// pipeline (§8.4) with step() for the batch schedule. Births [0, P) are
// random genomes (generation 0); every later birth is made by its emitter
// (§9.8, emitters.hpp; the default: parents drawn uniformly from the occupied
// cells, then crossover and mutation as in §8.3) from the archive as it stood
// at the birth's source. Children are inserted in birth order, and the CMA
// emitters (§9.9, cma_emitter.hpp) and the threshold archive change only
// there. So the state after any number of births is the same for every
// thread count and process layout.
//
// A birth after generation 0 while the archive is still empty (every earlier
// child was invalid) is a random genome, as in generation 0.
#include "evolution/archive.hpp"
#include "evolution/batch.hpp"
#include "evolution/cma_emitter.hpp"
#include "evolution/emitters.hpp"
#include "evolution/generation_count.hpp"
#include "evolution/individual.hpp"
#include "evolution/operators.hpp"
#include "evolution/pipeline.hpp"
#include "evolution/problem.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

struct MapElitesParams {
    int population = 100;         // generation size; generation 0 is this many random genomes
    double crossover = 0.3;       // probability a child mixes the blocks of two elites
    double mutation_rate = 0.05;  // per-parameter probability of a normal step
    double mutation_sigma = 0.3;  // standard deviation of that step
    int batch = 32;               // births drawn from one archive snapshot and evaluated in parallel
    double init_range = 2.0;      // initial parameters uniform in [-init_range, +init_range)
    // Who makes the births after generation 0 (emitters.hpp); empty: one
    // gaussian emitter with uniform selection, the behaviour before emitters.
    std::vector<EmitterSpec> emitters = {};
};

// Everything needed to continue a run exactly (with the parameters and seed).
// The archive holds its CVT centroids, so a resume never recomputes them.
struct MapElitesState {
    std::uint64_t births = 0;                   // births done; the next birth's index
    Archive archive;                            // the elites
    std::optional<Individual> best;             // best valid individual ever born (earliest on ties)
    std::uint64_t invalid_in_generation = 0;    // invalid births so far in the current generation
    std::uint64_t new_cells_in_generation = 0;  // cells first filled so far in the current generation
    // One per emitter of the parameters when any is a CMA emitter (the
    // stateless ones' entries stay default), else empty.
    std::vector<CmaEmitterState> emitters = {};
    // With a cma_mae emitter, the threshold archive (§9.9): the cells whose
    // threshold rose above threshold_min, and that threshold. Every such cell
    // holds an elite (a child that beats a threshold enters its cell).
    std::map<std::uint64_t, double> thresholds = {};
};

struct EliteBatchOutcome {
    std::vector<Individual> children;          // in birth order, each with fitness and descriptors
    std::vector<std::string> errors;           // parallel: why it is invalid ("" if valid)
    std::vector<std::optional<std::uint64_t>> cells;  // parallel: its cell (none if invalid)
    std::vector<Archive::Placement> placements;       // parallel: what insertion did
    bool ends_generation = false;              // the batch completed a generation
    std::uint64_t generation_invalid = 0;      // if so: invalid births in that generation
    std::uint64_t generation_new_cells = 0;    // if so: cells first filled in that generation
};

class MapElites : public GenerationCount<MapElites>, public Breeder {
public:
    // Throws std::invalid_argument for parameters out of range or blocks that
    // do not tile the problem's parameters. `state` is trusted to match.
    MapElites(const MapElitesParams& params, std::uint64_t seed, Problem& problem, MapElitesState state);

    // One batch of the batch schedule with `threads` workers (<= 0:
    // OpenMP's default), as SteadyStateGA::step. A child whose evaluation
    // throws, or gives a non-finite score or descriptor, or a descriptor
    // vector of the wrong length, is invalid and enters nowhere.
    EliteBatchOutcome step(int threads);

    // Breeder (pipeline.hpp): parents from the archive as it is now. Not
    // safe to call concurrently (it caches the archive's snapshot).
    std::uint64_t births() const override { return state_.births; }
    Individual conceive(std::uint64_t birth) const override;
    Inserted insert(Individual& child, std::string& error) override;
    double export_floor() const override;

    const MapElitesState& state() const { return state_; }
    const MapElitesParams& params() const { return params_; }
    std::uint64_t seed() const { return seed_; }

private:
    BirthRules rules() const {
        return {population(), params_.init_range, params_.crossover, params_.mutation_rate, params_.mutation_sigma};
    }

    MapElitesParams params_;
    std::uint64_t seed_;
    Problem& problem_;
    std::vector<Block> blocks_;
    // Birth `birth` by its emitter with parents drawn from `pool` (the elites in cell order).
    Individual conceive_from(const ParentPool& pool, std::uint64_t birth) const;
    // The emitter of a birth after generation 0, and whether `birth` is its
    // last one in its generation (its CMA iteration ends there).
    std::size_t emitter_index(std::uint64_t birth) const { return emitter_of(birth, per_generation_, population()); }
    bool ends_iteration(std::uint64_t birth, std::size_t emitter) const;
    // What `child` (valid, in `cell`) means to the CMA emitters, computed
    // before it enters the archive: updates the thresholds (with cma_mae)
    // and returns the child as emitter `emitter` ranks it.
    CmaChild rank_for_emitter(const Individual& child, std::uint64_t cell, std::size_t emitter);
    // After insertion: ends a CMA iteration, (re)starts emitters.
    void update_emitters(std::uint64_t birth);
    void start_emitter(std::size_t emitter, std::uint64_t birth);

    MapElitesState state_;
    std::vector<EmitterSpec> emitters_;           // at least one
    std::vector<std::uint64_t> per_generation_;   // births of a generation for each emitter
    bool weighs_fitness_ = false;                 // some emitter selects fitness-proportionally
    bool has_cma_ = false;                        // some emitter is cma_me or cma_mae
    bool annealing_ = false;                      // some emitter is cma_mae: thresholds are kept
    double learning_rate_ = 0.0, threshold_min_ = 0.0;  // the cma_mae emitters' (all the same)
    // The parents for conceive(), rebuilt after a cell is first filled (a
    // replaced elite keeps its place: the map's nodes do not move), or after
    // any insertion when selection weighs fitness.
    mutable std::optional<ParentPool> pool_;
    // What insert() did with its child: its cell and placement.
    std::optional<std::uint64_t> last_cell_;
    Archive::Placement last_placement_ = Archive::Placement::rejected;
};

}  // namespace morphogen
