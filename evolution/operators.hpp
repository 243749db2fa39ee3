#pragma once
// The GA's operators as free functions (docs/algorithm.md §8.2-§8.5), each drawing only
// from the RandomStream it is given, so a birth is a pure function of
// (population snapshot, parameters, seed, birth index). Variation and the
// birth itself (conceive_birth) are shared with MAP-Elites (§9.4), which only
// picks parents differently.
#include "evolution/ga/ga_params.hpp"
#include "evolution/individual.hpp"
#include "evolution/rng.hpp"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

// True if `a` ranks above `b`: higher fitness; on a tie the higher (younger)
// id. One strict total order for both selection and replacement, so neither
// depends on slot order or thread timing. Preferring the younger on ties means
// tournaments favour new variants and replacement removes the oldest of equally
// bad members: the population keeps drifting across fitness plateaus (e.g. the
// many zero-canopy genomes early in a run) instead of freezing.
inline bool ranks_above(const Individual& a, const Individual& b) {
    if (a.fitness != b.fitness) return a.fitness > b.fitness;
    return a.id > b.id;
}

// Slot of the tournament winner: `size` slots drawn uniformly with
// replacement, the one that ranks highest wins. population must be non-empty.
std::size_t tournament(std::span<const Individual> population, int size, RandomStream& stream);
// The same draws over `count` slots (>= 1) ranked by `above(a, b)` (slot a
// ranks above slot b), for searches that rank by more than fitness.
std::size_t tournament(std::size_t count, int size, RandomStream& stream,
                       const std::function<bool(std::size_t, std::size_t)>& above);

// The member that ranks highest (ranks_above) if it is valid, else nullptr:
// what a population search exports and the floor of what it keeps to export.
const Individual* top_ranked(std::span<const Individual> population);

// Child parameters taking each block from `a` or `b` with probability 1/2.
// Blocks must tile the parameters (checked by check_blocks).
std::vector<double> crossover(std::span<const double> a, std::span<const double> b, std::span<const Block> blocks,
                              RandomStream& stream);

// Each parameter, with probability `rate`, gets a N(0, sigma^2) step.
// Returns how many were changed.
std::size_t mutate(std::vector<double>& params, double rate, double sigma, RandomStream& stream);

// Slot of the individual that ranks lowest (lowest fitness; on a tie the
// oldest, i.e. the lower id). population must be non-empty.
std::size_t worst_slot(std::span<const Individual> population);

// Inserts a finished child: while the population is below `capacity` it is
// appended; otherwise it replaces the worst if its fitness is at least the
// worst's. Returns whether the child entered the population.
bool insert_child(std::vector<Individual>& population, Individual child, std::size_t capacity);

// What a birth needs besides its parents; shared by the GA and MAP-Elites.
struct BirthRules {
    std::uint64_t population = 0;  // births below this are random genomes (generation 0)
    double init_range = 0.0;       // random parameters uniform in [-init_range, +init_range)
    double crossover = 0.0;        // probability a child mixes the blocks of two parents
    double mutation_rate = 0.0;    // per-parameter probability of a normal step
    double mutation_sigma = 0.0;   // standard deviation of that step
    std::span<const double> centre;  // random parameters are shifted by this (empty: by 0)
    // Given genomes (evolve --from): generation 0's birth i is seeds[i] for
    // i < seeds.size(), else a mutant of seeds[i % seeds.size()]. Empty: random.
    std::span<const std::vector<double>> seeds;
};
BirthRules birth_rules(const GaParams& params);
// Checks what every search shares (the birth rules and the batch size);
// throws std::invalid_argument("<search> parameter out of range: ...").
void check_shared_params(const BirthRules& rules, int batch, const std::string& search);

// Draws one parent from a frozen snapshot with the birth's own stream.
using ParentPicker = std::function<const Individual&(RandomStream& stream)>;

// The birth `birth` (not yet evaluated), drawing only from RandomStream(seed,
// birth): a random genome (or a given one or its mutant, see
// BirthRules::seeds) if birth < rules.population or `pick` is empty;
// otherwise, in this order, parent 1 = pick, parent 2 = pick (drawn always,
// used only on crossover), the crossover coin, the block coins (crossover
// only), then mutation of every parameter.
Individual conceive_birth(const BirthRules& rules, std::span<const Block> blocks, std::size_t dimension,
                          std::uint64_t seed, std::uint64_t birth, const ParentPicker& pick);

// The GA's birth: conceive_birth with parents chosen by tournament on `snapshot`.
Individual conceive(std::span<const Individual> snapshot, const GaParams& params, std::span<const Block> blocks,
                    std::size_t dimension, std::uint64_t seed, std::uint64_t birth,
                    std::span<const double> centre = {}, std::span<const std::vector<double>> seeds = {});
// `centre` if it is empty or has `dimension` entries; throws
// std::invalid_argument naming `search` otherwise.
std::vector<double> check_centre(std::vector<double> centre, std::size_t dimension, const std::string& search);
// The same for given genomes (Problem::seed_genomes): each `dimension` long.
std::vector<std::vector<double>> check_seeds(std::vector<std::vector<double>> seeds, std::size_t dimension,
                                             const std::string& search);

// Births in the batch that starts at `births` done: at most `batch` and never
// past the end of the current generation (a multiple of `population`).
std::size_t batch_size(std::uint64_t births, std::uint64_t population, int batch);
std::size_t batch_size(std::uint64_t births, const GaParams& params);

// Blocks for a problem: `blocks` if they tile [0, dimension) in order (throws
// std::invalid_argument otherwise), or one block per parameter if empty.
std::vector<Block> check_blocks(std::vector<Block> blocks, std::size_t dimension);

}  // namespace morphogen
