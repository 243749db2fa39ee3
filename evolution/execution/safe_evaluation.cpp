#include "evolution/execution/safe_evaluation.hpp"

#include <cmath>
#include <exception>
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


}  // namespace morphogen
