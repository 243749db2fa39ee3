#pragma once
// MAP-Elites emitters (docs/algorithm.md §9.8): who makes which birth of a
// generation, how it picks its parents from the archive and how it varies
// them. The stateless ones are here: a birth is a pure function of (the
// elites at its source, seed, birth), like every birth (§8.4). The CMA
// emitters (cma_me, cma_mae) carry a search distribution in the run's state
// (cma_emitter.hpp, §9.9); only their parameters are here.
//
// - gaussian (the default, the behaviour before emitters): the GA's birth
//   (operators.hpp conceive_birth: crossover of two parents' blocks, then a
//   normal step per parameter with the evolution section's rate and sigma);
// - iso_line (Vassiliades & Mouret 2018): parents x and y, then
//   child = x + sigma_iso * N(0, I) + sigma_line * N(0, 1) * (y - x).
//
// Parent selection, per emitter: uniform over the occupied cells (as before
// emitters) or fitness-proportional over the elites.
#include "evolution/full_cma.hpp"
#include "evolution/individual.hpp"
#include "evolution/operators.hpp"
#include "evolution/rng.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

enum class EmitterKind { gaussian, iso_line, cma_me, cma_mae };
enum class ParentSelection { uniform, fitness_proportional };
// A CMA emitter's parents (cma_emitter.hpp): the children that filled or
// improved a cell ("filter"), or the best half of the valid ones ("mu").
enum class CmaParents { filter, mu };
// When a CMA emitter restarts besides CMA-ES's own stop tests ("basic"):
// also after an iteration in which no child filled or improved a cell.
enum class CmaRestart { no_improvement, basic };
// A CMA emitter's covariance model (algorithm.md §9.9): separable (a
// diagonal C, sep_cma.hpp; O(n) a child) or full (full_cma.hpp; O(n^2) a
// child and an O(n^3) eigendecomposition an iteration).
enum class CmaCovariance { diagonal, full };

struct EmitterSpec {
    EmitterKind kind = EmitterKind::gaussian;
    double share = 1.0;  // > 0: its part of every generation's births, relative to the others
    ParentSelection selection = ParentSelection::uniform;
    double sigma_iso = 0.05;  // iso_line: the isotropic step
    double sigma_line = 0.2;  // iso_line: the step along the line to the second parent
    double sigma0 = 0.5;         // cma_me, cma_mae: the step size of a (re)start
    double learning_rate = 0.01; // cma_mae: alpha, how far a cell's threshold moves toward a child that beats it
    double threshold_min = 0.0;  // cma_mae: the threshold of a cell no child has beaten yet
    // cma_me's defaults (Fontaine et al. 2020); cma_mae's are mu and basic.
    CmaParents parents = CmaParents::filter;
    CmaRestart restart = CmaRestart::no_improvement;
    CmaCovariance covariance = CmaCovariance::diagonal;  // cma_me, cma_mae
    // With the full model: another update rule than full_cma_update (§9.9),
    // set by code that links the library (bench/); empty: the textbook's.
    // Never read from a config or a checkpoint.
    FullCmaUpdate full_update = {};
};

// Births of one generation for each emitter: P x share / (sum of shares),
// rounded by largest remainders (ties: the earlier emitter), so they add up
// to P exactly. Throws std::invalid_argument for no emitters or a share that
// is not positive and finite.
std::vector<std::uint64_t> births_per_generation(std::span<const EmitterSpec> emitters, std::uint64_t population);

// Which emitter makes birth `birth` (>= population): the emitters take
// consecutive runs of each generation's births in list order.
std::size_t emitter_of(std::uint64_t birth, std::span<const std::uint64_t> per_generation, std::uint64_t population);

// The elites a birth may draw from, in cell-index order, with what
// fitness-proportional selection needs (built once per archive state).
class ParentPool {
public:
    explicit ParentPool(std::vector<const Individual*> elites);
    bool empty() const { return elites_.empty(); }
    // One parent, drawing one number from `stream`: uniform is
    // elites[below(n)]; fitness-proportional weighs elite e by
    // f_e - f_min + delta, delta = max(1e-12, (f_max - f_min) / 20), so the
    // worst elite keeps a chance, and takes the first whose running sum
    // exceeds uniform() x the total.
    const Individual& pick(ParentSelection selection, RandomStream& stream) const;

private:
    std::vector<const Individual*> elites_;
    std::vector<double> cumulative_;  // running sums of the weights
};

// Birth `birth` by `emitter`, drawing only from RandomStream(seed, birth):
// gaussian is conceive_birth with the pool's picks; iso_line draws, in this
// order, parent x, parent y, the line's N(0,1), then one N(0,1) per
// parameter. An empty pool gives a random genome (as conceive_birth does).
// Not for the CMA kinds (std::logic_error).
Individual emit(const EmitterSpec& emitter, const BirthRules& rules, std::span<const Block> blocks,
                std::size_t dimension, std::uint64_t seed, std::uint64_t birth, const ParentPool& pool);

}  // namespace morphogen
