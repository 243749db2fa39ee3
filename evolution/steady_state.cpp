#include "steady_state.hpp"

#include "operators.hpp"

#include <omp.h>

#include <cmath>
#include <exception>
#include <stdexcept>

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

// Scores one child; never throws.
Evaluation evaluate_safely(const Problem& problem, const Individual& child, int worker) noexcept {
    Evaluation result;
    try {
        result = problem.evaluate(child.params, worker);
        if (result.valid && !std::isfinite(result.score)) {
            result.valid = false;
            result.error = "non-finite score " + std::to_string(result.score);
        }
        if (!result.valid && result.error.empty()) result.error = "invalid";
    } catch (const std::exception& e) {
        result = Evaluation{};
        result.error = e.what();
    } catch (...) {
        result = Evaluation{};
        result.error = "unknown exception";
    }
    if (!result.valid) result.size = 0.0;
    return result;
}
}  // namespace

SteadyStateGA::SteadyStateGA(const GaParams& params, std::uint64_t seed, Problem& problem, GaState state)
    : params_(params), seed_(seed), problem_(problem), state_(std::move(state)) {
    check_params(params_);
    blocks_ = check_blocks(problem_.blocks(), problem_.dimension());
}

BatchOutcome SteadyStateGA::step(int threads) {
    if (threads <= 0) threads = omp_get_max_threads();
    const std::size_t count = batch_size(state_.births, params_);
    const std::uint64_t first = state_.births;
    const std::size_t dimension = problem_.dimension();
    problem_.prepare(threads);

    BatchOutcome out;
    out.children.resize(count);
    out.errors.resize(count);
    std::exception_ptr failure;
    const std::vector<Individual>& snapshot = state_.population;  // not modified until the region ends

#pragma omp parallel for schedule(dynamic) num_threads(threads)
    for (std::size_t i = 0; i < count; ++i) {
        try {
            Individual child = conceive(snapshot, params_, blocks_, dimension, seed_, first + i);
            const Evaluation e = evaluate_safely(problem_, child, omp_get_thread_num());
            child.fitness = e.valid ? e.score : invalid_fitness;
            child.size = e.size;
            out.errors[i] = e.valid ? std::string() : e.error;
            out.children[i] = std::move(child);
        } catch (...) {
#pragma omp critical(morphogen_ga_failure)
            if (!failure) failure = std::current_exception();
        }
    }
    if (failure) std::rethrow_exception(failure);

    out.inserted.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Individual& child = out.children[i];
        if (!child.valid()) ++state_.invalid_in_generation;
        if (child.valid() && (!state_.best || child.fitness > state_.best->fitness)) state_.best = child;
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
