#pragma once
// Novelty search with local competition (docs/algorithm.md §14; Lehman &
// Stanley 2011), a steady-state Breeder for the birth pipeline (§8.4): the
// GA's births (§8.3: tournaments, crossover, mutation; the same schedules)
// with parents ranked by Pareto front of novelty and local competition
// (novelty.hpp) instead of fitness, and a child that replaces the member
// ranked lowest among the population and itself. A novelty archive of
// behaviours keeps the places the search has been. Children are inserted in
// birth order and every draw comes from the run's seed and a birth index, so
// the state after any number of births is the same for every thread count.
#include "evolution/archives/archive.hpp"
#include "evolution/execution/pipeline.hpp"
#include "evolution/ga/ga_params.hpp"
#include "evolution/generation_count.hpp"
#include "evolution/individual.hpp"
#include "evolution/novelty/novelty.hpp"
#include "evolution/novelty/novelty_params.hpp"
#include "evolution/problem.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

// Everything needed to continue a run exactly (with the parameters and seed).
struct NslcState {
    std::uint64_t births = 0;            // births done; the next birth's index
    std::vector<Individual> population;  // valid members with descriptors, slot order; at most P
    // The novelty archive, oldest first: id, fitness and descriptors of
    // children that entered it (no parameters).
    std::vector<Individual> archive;
    std::optional<Individual> best;           // best valid individual ever born (earliest on ties)
    std::uint64_t invalid_in_generation = 0;  // invalid births so far in the current generation
};

// The stream of birth b's archive coin (§14.5): RandomStream(seed, b + this),
// apart from the birth's own RandomStream(seed, b).
inline constexpr std::uint64_t kArchiveCoinStreams = std::uint64_t{1} << 63;

class Nslc : public GenerationCount<Nslc>, public Breeder {
public:
    // `ranges`: the descriptors' [min, max] (bins unused), at least one.
    // Throws std::invalid_argument for parameters out of range or blocks that
    // do not tile the problem's parameters. `state` is trusted to match (see
    // nslc_state_from_json for checking one read from a file).
    Nslc(const GaParams& params, const NoveltyParams& novelty, std::vector<DescriptorRange> ranges,
         std::uint64_t seed, Problem& problem, NslcState state = {});

    // Breeder (pipeline.hpp): tournament parents ranked by novelty_ranks_above.
    std::uint64_t births() const override { return state_.births; }
    Individual conceive(std::uint64_t birth) const override;
    // A valid child whose descriptors do not fit the ranges becomes invalid.
    Inserted insert(Individual& child, std::string& error) override;
    // The population's highest fitness: the export is its fittest member, and
    // a child below it becomes that only once the fitter ones are replaced
    // (the run then grows it again).
    double export_floor() const override;

    const NslcState& state() const { return state_; }
    const GaParams& params() const { return params_; }
    std::uint64_t seed() const { return seed_; }
    // The population's scores against itself and the archive, slot by slot.
    const std::vector<NoveltyScore>& scores() const { return scores_; }

private:
    void rescore();
    // Slot of the member ranked lowest among the population and `child` (its
    // slot is the population's size).
    std::size_t lowest_with(const Individual& child) const;
    std::vector<BehaviourPoint> archive_points() const;

    GaParams params_;
    NoveltyParams novelty_;
    std::vector<DescriptorRange> ranges_;
    std::uint64_t seed_;
    Problem& problem_;
    std::vector<Block> blocks_;
    std::vector<double> centre_;              // of random genomes (Problem::random_centre)
    std::vector<std::vector<double>> seeds_;  // Problem::seed_genomes
    NslcState state_;
    std::vector<NoveltyScore> scores_;  // of state_.population, after the last insertion
    std::vector<std::size_t> place_;    // each slot's place in the ranking (0: the highest)
};

}  // namespace morphogen
