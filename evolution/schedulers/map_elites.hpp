#pragma once
// MAP-Elites (docs/algorithm.md §9), the scheduler of its three parts: the
// archive (archive.hpp, with the thresholds CMA-MAE ranks by), the emitters
// (emitters.hpp) and this class, a Breeder for the birth pipeline (§8.4).
// Births [0, P) are random genomes (generation 0); every later birth is
// made by its emitter (emitter_of: each takes a run of consecutive births of
// every generation, by its share) from the archive as it stood at the
// birth's source. Children are inserted in birth order: the archive takes
// each, then its emitter is told what the archive did, so emitters and
// thresholds change only there and the state after any number of births is
// the same for every thread count and process layout.
#include "evolution/archives/archive.hpp"
#include "evolution/emitters/emitters.hpp"
#include "evolution/generation_count.hpp"
#include "evolution/individual.hpp"
#include "evolution/operators.hpp"
#include "evolution/execution/pipeline.hpp"
#include "evolution/problem.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

struct MapElitesParams {
    int population = 100;         // generation size; generation 0 is this many random genomes
    double crossover = 0.3;       // probability a gaussian child mixes the blocks of two elites
    double mutation_rate = 0.05;  // per-parameter probability of a normal step (gaussian)
    double mutation_sigma = 0.3;  // standard deviation of that step
    int batch = 32;               // the batch schedule's size (schedule.hpp)
    double init_range = 2.0;      // initial parameters uniform in [-init_range, +init_range)
    // Who makes the births after generation 0; empty: default_emitters()
    // (emitter_registry.hpp).
    std::vector<EmitterSpec> emitters = {};
};

// Everything needed to continue a run exactly (with the parameters and seed).
// The archive holds its CVT centroids, so a resume never recomputes them,
// and its thresholds.
struct MapElitesState {
    std::uint64_t births = 0;                   // births done; the next birth's index
    Archive archive;                            // the elites
    std::optional<Individual> best;             // best valid individual ever born (earliest on ties)
    std::uint64_t invalid_in_generation = 0;    // invalid births so far in the current generation
    std::uint64_t new_cells_in_generation = 0;  // cells first filled so far in the current generation
    // One per emitter of the parameters, with its state; empty: fresh ones.
    std::vector<EmitterSlot> emitters = {};
};

class MapElites : public GenerationCount<MapElites>, public Breeder {
public:
    // Throws std::invalid_argument for parameters out of range, blocks that
    // do not tile the problem's parameters, emitters that do not match the
    // parameters' kinds, or thresholds the archive cannot keep.
    MapElites(const MapElitesParams& params, std::uint64_t seed, Problem& problem, MapElitesState state);

    // Breeder (pipeline.hpp): parents from the archive as it is now. Not
    // safe to call concurrently (it caches the archive's snapshot). A child
    // whose descriptors do not fit the archive becomes invalid.
    std::uint64_t births() const override { return state_.births; }
    Individual conceive(std::uint64_t birth) const override;
    Inserted insert(Individual& child, std::string& error) override;
    double export_floor() const override;

    const MapElitesState& state() const { return state_; }
    const MapElitesParams& params() const { return params_; }
    std::uint64_t seed() const { return seed_; }
    // What the last insert() did in the archive.
    const Archive::Insertion& last_insertion() const { return last_; }

private:
    BirthRules rules() const {
        return {population(), params_.init_range, params_.crossover, params_.mutation_rate, params_.mutation_sigma,
                centre_, seeds_};
    }
    // The emitter of a birth after generation 0, and whether `birth` is its
    // last one in its generation.
    std::size_t emitter_index(std::uint64_t birth) const { return emitter_of(birth, per_generation_, population()); }
    bool ends_turn(std::uint64_t birth, std::size_t emitter) const;
    // The elite emitter `emitter` (re)starts from after birth `birth`.
    ElitePicker picker(std::uint64_t birth, std::size_t emitter);
    const ParentPool& pool() const;

    MapElitesParams params_;
    std::uint64_t seed_;
    Problem& problem_;
    std::vector<Block> blocks_;
    std::vector<double> centre_;  // of random genomes (Problem::random_centre)
    std::vector<std::vector<double>> seeds_;  // Problem::seed_genomes
    MapElitesState state_;
    std::vector<std::uint64_t> per_generation_;  // births of a generation for each emitter
    bool weighs_fitness_ = false;                // some emitter selects fitness-proportionally
    // The parents for conceive(), rebuilt after a cell is first filled (a
    // replaced elite keeps its place: the map's nodes do not move), or after
    // any insertion when selection weighs fitness.
    mutable std::optional<ParentPool> pool_;
    Archive::Insertion last_;
};

}  // namespace morphogen
