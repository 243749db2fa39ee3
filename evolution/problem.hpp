#pragma once
// What the GA optimises: a map from parameter vectors to scores (larger is
// better). The GA turns exceptions and non-finite scores into invalid
// individuals, so evaluate() may throw.
#include "evolution/individual.hpp"

#include <span>
#include <vector>

namespace morphogen {

class Problem {
public:
    virtual ~Problem() = default;
    // Number of parameters of a genome.
    virtual std::size_t dimension() const = 0;
    // The crossover units; they must tile [0, dimension()) in order. Empty
    // means every parameter is its own block.
    virtual std::vector<Block> blocks() const { return {}; }
    // Where random genomes are centred (docs/algorithm.md §6.3): one value per
    // parameter, or empty for 0 everywhere.
    virtual std::vector<double> random_centre() const { return {}; }
    // Genomes generation 0 starts from instead of random ones (BirthRules::seeds),
    // each dimension() long; empty for a random start.
    virtual std::vector<std::vector<double>> seed_genomes() const { return {}; }
    // Called before a batch with the number of workers that will call
    // evaluate(); lets the problem size per-worker scratch space.
    virtual void prepare(int workers) { (void)workers; }
    // Must be safe to call concurrently with distinct `worker` in [0, workers).
    virtual Evaluation evaluate(std::span<const double> params, int worker) const = 0;
    // evaluate(), also filling Evaluation::kept with what exporting this
    // genome needs (so it is not grown again) when it is valid with a score
    // of at least `keep_from`. The default keeps nothing.
    virtual Evaluation evaluate_keeping(std::span<const double> params, int worker, double keep_from) const {
        (void)keep_from;
        return evaluate(params, worker);
    }
};

}  // namespace morphogen
