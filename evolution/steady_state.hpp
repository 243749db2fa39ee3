#pragma once
// The steady-state GA driver (docs/algorithm.md §8). step() performs one batch:
// it conceives every child of the batch from the population as it stood
// before the batch, evaluates them in parallel (OpenMP, dynamic schedule),
// and inserts them in birth order. Because every child's randomness comes
// from RandomStream(seed, birth) and insertion is sequential, the state after
// any number of steps is the same for every thread count.
//
// Generation g (g >= 0) is births [g*P, (g+1)*P); generation 0 is the random
// initial population. Batches never cross a generation boundary.
#include "evolution/batch.hpp"
#include "evolution/ga_params.hpp"
#include "evolution/generation_count.hpp"
#include "evolution/individual.hpp"
#include "evolution/pipeline.hpp"
#include "evolution/problem.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

// Everything needed to continue a run exactly (with the parameters and seed).
struct GaState {
    std::uint64_t births = 0;                // births done; the next birth's index
    std::vector<Individual> population;      // slot order; < P members only during generation 0
    std::optional<Individual> best;          // best valid individual ever born (earliest on ties)
    std::uint64_t invalid_in_generation = 0; // invalid births so far in the current generation
};

struct BatchOutcome {
    std::vector<Individual> children;  // in birth order, each with its fitness
    std::vector<std::string> errors;   // parallel to children: why it is invalid ("" if valid)
    std::vector<bool> inserted;        // parallel to children: whether it entered the population
    bool ends_generation = false;      // the batch completed a generation
    std::uint64_t generation_invalid = 0;  // if so: invalid births in that generation
};

class SteadyStateGA : public GenerationCount<SteadyStateGA>, public Breeder {
public:
    // Throws std::invalid_argument for parameters out of range or blocks that
    // do not tile the problem's parameters. `state` is trusted to match (see
    // ga_state_from_json for checking one read from a file).
    SteadyStateGA(const GaParams& params, std::uint64_t seed, Problem& problem, GaState state = {});

    // One batch of the batch schedule with `threads` workers (<= 0:
    // OpenMP's default): births conceived from the population as it is, bred
    // in parallel, inserted in order (what BirthPipeline does with a batch
    // schedule of params.batch). Exceptions from the problem make that child
    // invalid; only failures outside evaluation (e.g. out of memory)
    // propagate, after the parallel region.
    BatchOutcome step(int threads);

    // Breeder (pipeline.hpp): tournament parents from the population as it is now.
    std::uint64_t births() const override { return state_.births; }
    Individual conceive(std::uint64_t birth) const override;
    Inserted insert(Individual& child, std::string& error) override;
    double export_floor() const override;

    const GaState& state() const { return state_; }
    const GaParams& params() const { return params_; }
    std::uint64_t seed() const { return seed_; }

private:
    GaParams params_;
    std::uint64_t seed_;
    Problem& problem_;
    std::vector<Block> blocks_;
    GaState state_;
    bool last_inserted_ = false;  // whether insert()'s child entered the population
};

}  // namespace morphogen
