// The Fitness wrapper: every check on a score happens here, once.
#include "fitness/fitness.hpp"

#include "fitness/geometry/cgal_geometry.hpp"
#include "fitness/measures.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace morphogen {

Fitness::Fitness(std::unique_ptr<FitnessFunction> function, bool reject_self_intersecting)
    : function_(std::move(function)), reject_self_intersecting_(reject_self_intersecting) {
    if (!function_) throw std::invalid_argument("Fitness needs a function");
}

namespace {
FitnessOutcome invalid(std::string reason) {
    FitnessOutcome outcome;
    outcome.error = std::move(reason);
    return outcome;
}
}  // namespace

void Fitness::add_cost(FitnessCost& cost, const CostScope& scope) const {
    function_->add_cost(cost, scope);
    if (reject_self_intersecting_) add_self_intersection_cost(cost, scope.faces, scope.path + ".reject_self_intersecting");
}

FitnessOutcome Fitness::evaluate(MeshView mesh) const noexcept {
    evaluations_.fetch_add(1, std::memory_order_relaxed);
    try {
        try {
            check_mesh_view(mesh);
            if (reject_self_intersecting_ && mesh_self_intersects(mesh)) return invalid("the mesh self-intersects");
            double score;
            if (function_->thread_safe()) {
                score = function_->evaluate(mesh);
            } else {
                const std::lock_guard lock(mutex_);
                score = function_->evaluate(mesh);
            }
            if (!std::isfinite(score)) {
                std::ostringstream reason;
                reason << "fitness \"" << function_->type() << "\" gave a non-finite score " << score;
                return invalid(reason.str());
            }
            FitnessOutcome outcome;
            outcome.score = score;
            outcome.valid = true;
            return outcome;
        } catch (const std::exception& e) {
            return invalid("fitness \"" + function_->type() + "\" failed: " + e.what());
        } catch (...) {
            return invalid("fitness \"" + function_->type() + "\" failed with an unknown exception");
        }
    } catch (...) {
        // Building the reason itself failed (out of memory): still no throw.
        return FitnessOutcome{};
    }
}

}  // namespace morphogen
