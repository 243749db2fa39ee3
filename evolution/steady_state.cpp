#include "steady_state.hpp"

#include "batch.hpp"
#include "operators.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {
void check_params(const GaParams& p) {
    auto require = [](bool ok, const char* what) {
        if (!ok) throw std::invalid_argument(std::string("GA parameter out of range: ") + what);
    };
    require(p.population >= 2, "population >= 2");
    require(p.tournament >= 1, "tournament >= 1");
    require(p.crossover >= 0 && p.crossover <= 1, "0 <= crossover <= 1");
    require(p.mutation_rate >= 0 && p.mutation_rate <= 1, "0 <= mutation_rate <= 1");
    require(p.mutation_sigma >= 0 && std::isfinite(p.mutation_sigma), "mutation_sigma >= 0");
    require(p.batch >= 1, "batch >= 1");
    require(p.init_range >= 0 && std::isfinite(p.init_range), "init_range >= 0");
}
}  // namespace

SteadyStateGA::SteadyStateGA(const GaParams& params, std::uint64_t seed, Problem& problem, GaState state)
    : params_(params), seed_(seed), problem_(problem), state_(std::move(state)) {
    check_params(params_);
    blocks_ = check_blocks(problem_.blocks(), problem_.dimension());
}

BatchOutcome SteadyStateGA::step(int threads) {
    const std::size_t count = batch_size(state_.births, params_);
    const std::size_t dimension = problem_.dimension();
    const std::vector<Individual>& snapshot = state_.population;  // not modified until the batch is bred
    BredBatch bred = breed_batch(problem_, state_.births, count, threads, [&](std::uint64_t birth) {
        return conceive(snapshot, params_, blocks_, dimension, seed_, birth);
    });

    BatchOutcome out;
    out.children = std::move(bred.children);
    out.errors = std::move(bred.errors);
    out.inserted.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Individual& child = out.children[i];
        if (!child.valid()) ++state_.invalid_in_generation;
        keep_best(state_.best, child);
        out.inserted[i] = insert_child(state_.population, child, static_cast<std::size_t>(params_.population));
        ++state_.births;
    }
    if (at_generation_end()) {
        out.ends_generation = true;
        out.generation_invalid = state_.invalid_in_generation;
        state_.invalid_in_generation = 0;
    }
    return out;
}

}  // namespace morphogen
