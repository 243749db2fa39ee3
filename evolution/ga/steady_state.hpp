#pragma once
// The steady-state GA (docs/algorithm.md §8), a Breeder for the birth
// pipeline (pipeline.hpp, §8.4): it conceives a child from the population
// as it stands at the birth's source and inserts children in birth order.
// Because every child's randomness comes from RandomStream(seed, birth) and
// insertion is sequential, the state after any number of births is the same
// for every thread count.
//
// Generation g (g >= 0) is births [g*P, (g+1)*P); generation 0 is the random
// initial population.
#include "evolution/execution/safe_evaluation.hpp"
#include "evolution/ga/ga_params.hpp"
#include "evolution/generation_count.hpp"
#include "evolution/individual.hpp"
#include "evolution/execution/pipeline.hpp"
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

class SteadyStateGA : public GenerationCount<SteadyStateGA>, public Breeder {
public:
    // Throws std::invalid_argument for parameters out of range or blocks that
    // do not tile the problem's parameters. `state` is trusted to match (see
    // ga_state_from_json for checking one read from a file).
    SteadyStateGA(const GaParams& params, std::uint64_t seed, Problem& problem, GaState state = {});

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
    std::vector<double> centre_;  // of random genomes (Problem::random_centre)
    std::vector<std::vector<double>> seeds_;  // Problem::seed_genomes
    GaState state_;
};

}  // namespace morphogen
