#include "evolution/ga/steady_state.hpp"

#include "evolution/execution/safe_evaluation.hpp"
#include "evolution/operators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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
    centre_ = check_centre(problem_.random_centre(), problem_.dimension(), "GA");
    seeds_ = check_seeds(problem_.seed_genomes(), problem_.dimension(), "GA");
}

Individual SteadyStateGA::conceive(std::uint64_t birth) const {
    return morphogen::conceive(state_.population, params_, blocks_, problem_.dimension(), seed_, birth, centre_, seeds_);
}

Inserted SteadyStateGA::insert(Individual& child, std::string&) {
    if (!child.valid()) ++state_.invalid_in_generation;
    keep_best(state_.best, child);
    (void)insert_child(state_.population, child, static_cast<std::size_t>(params_.population));
    return count_birth(state_.births, state_.invalid_in_generation, population());
}

double SteadyStateGA::export_floor() const {
    const Individual* top = top_ranked(state_.population);
    return top != nullptr ? top->fitness : -std::numeric_limits<double>::infinity();
}

}  // namespace morphogen
