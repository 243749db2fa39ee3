#include "evolution/steady_state.hpp"

#include "evolution/batch.hpp"
#include "evolution/operators.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {
void check_params(const GaParams& p) {
    if (p.population < 2) throw std::invalid_argument("GA parameter out of range: population >= 2");
    if (p.tournament < 1) throw std::invalid_argument("GA parameter out of range: tournament >= 1");
    check_shared_params(birth_rules(p), p.batch, "GA");
}
}  // namespace

SteadyStateGA::SteadyStateGA(const GaParams& params, std::uint64_t seed, Problem& problem, GaState state)
    : params_(params), seed_(seed), problem_(problem), state_(std::move(state)) {
    check_params(params_);
    blocks_ = check_blocks(problem_.blocks(), problem_.dimension());
}

BatchOutcome SteadyStateGA::step(int threads, BatchEvaluator* remote) {
    const std::size_t count = batch_size(state_.births, params_);
    const std::size_t dimension = problem_.dimension();
    const std::vector<Individual>& snapshot = state_.population;  // not modified until the batch is bred
    BredBatch bred = breed_batch(problem_, state_.births, count, threads, [&](std::uint64_t birth) {
        return conceive(snapshot, params_, blocks_, dimension, seed_, birth);
    }, remote);

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
