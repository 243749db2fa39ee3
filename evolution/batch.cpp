#include "evolution/batch.hpp"

#include "evolution/pipeline.hpp"
#include "evolution/worker_threads.hpp"

#include <omp.h>

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>

namespace morphogen {

Evaluation evaluate_safely(const Problem& problem, std::span<const double> params, int worker,
                           double keep_from) noexcept {
    Evaluation result;
    try {
        result = std::isinf(keep_from) && keep_from > 0 ? problem.evaluate(params, worker)
                                                        : problem.evaluate_keeping(params, worker, keep_from);
        if (result.valid && !std::isfinite(result.score)) {
            result.valid = false;
            result.error = "non-finite score " + std::to_string(result.score);
        }
        for (std::size_t k = 0; result.valid && k < result.descriptors.size(); ++k) {
            if (!std::isfinite(result.descriptors[k])) {
                result.valid = false;
                result.error = "non-finite descriptor " + std::to_string(k) + " (" +
                               std::to_string(result.descriptors[k]) + ")";
            }
        }
        if (!result.valid && result.error.empty()) result.error = "invalid";
    } catch (const std::exception& e) {
        result = Evaluation{};
        try {
            result.error = e.what();
        } catch (...) {
            result.error = "exception";
        }
    } catch (...) {
        result = Evaluation{};
        result.error = "unknown exception";
    }
    if (!result.valid) {
        result.size = 0.0;
        result.descriptors.clear();
        result.kept.clear();
    }
    return result;
}

BredBatch breed_batch(Problem& problem, std::uint64_t first, std::size_t count, int threads,
                      const std::function<Individual(std::uint64_t birth)>& conceive) {
    threads = resolve_threads(threads);
    problem.prepare(threads);
    BredBatch out;
    out.children.resize(count);
    out.errors.resize(count);
    std::exception_ptr failure;

#pragma omp parallel for schedule(dynamic) num_threads(threads)
    for (std::size_t i = 0; i < count; ++i) {
        try {
            Individual child = conceive(first + i);
            Evaluation e = evaluate_safely(problem, child.params, omp_get_thread_num());
            take_evaluation(child, out.errors[i], std::move(e));
            out.children[i] = std::move(child);
        } catch (...) {
#pragma omp critical(morphogen_batch_failure)
            if (!failure) failure = std::current_exception();
        }
    }
    if (failure) std::rethrow_exception(failure);
    return out;
}

}  // namespace morphogen
