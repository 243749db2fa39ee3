#include "evolution/novelty/nslc.hpp"

#include "evolution/execution/safe_evaluation.hpp"
#include "evolution/operators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {
void check_params(const GaParams& p, const NoveltyParams& n, const std::vector<DescriptorRange>& ranges) {
    const auto require = [](bool ok, const char* what) {
        if (!ok) throw std::invalid_argument(std::string("NSLC parameter out of range: ") + what);
    };
    require(p.population >= 2, "population >= 2");
    require(p.tournament >= 1, "tournament >= 1");
    require(n.k >= 1, "novelty_k >= 1");
    require(n.archive_rate >= 0 && n.archive_rate <= 1, "0 <= novelty_archive_rate <= 1");
    require(!ranges.empty(), "at least one descriptor");
    for (const DescriptorRange& r : ranges)
        require(std::isfinite(r.min) && std::isfinite(r.max) && r.min < r.max && std::isfinite(r.max - r.min),
                "descriptor ranges with finite min < max");
    check_shared_params(birth_rules(p), p.batch, "NSLC");
}

bool fits(const std::vector<double>& descriptors, std::size_t dimensions) {
    return descriptors.size() == dimensions &&
           std::all_of(descriptors.begin(), descriptors.end(), [](double x) { return std::isfinite(x); });
}

std::vector<BehaviourPoint> points_of(const std::vector<Individual>& individuals) {
    std::vector<BehaviourPoint> points;
    points.reserve(individuals.size() + 1);
    for (const Individual& ind : individuals) points.push_back(behaviour_point(ind));
    return points;
}
}  // namespace

Nslc::Nslc(const GaParams& params, const NoveltyParams& novelty, std::vector<DescriptorRange> ranges,
           std::uint64_t seed, Problem& problem, NslcState state)
    : params_(params), novelty_(novelty), ranges_(std::move(ranges)), seed_(seed), problem_(problem),
      state_(std::move(state)) {
    check_params(params_, novelty_, ranges_);
    blocks_ = check_blocks(problem_.blocks(), problem_.dimension());
    centre_ = check_centre(problem_.random_centre(), problem_.dimension(), "NSLC");
    seeds_ = check_seeds(problem_.seed_genomes(), problem_.dimension(), "NSLC");
    rescore();
}

std::vector<BehaviourPoint> Nslc::archive_points() const { return points_of(state_.archive); }

void Nslc::rescore() {
    const std::vector<BehaviourPoint> members = points_of(state_.population);
    scores_ = ranked_scores(members, archive_points(), ranges_, novelty_.k);
    std::vector<std::size_t> order(state_.population.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return novelty_ranks_above(scores_[a], state_.population[a].id, scores_[b], state_.population[b].id);
    });
    place_.assign(order.size(), 0);
    for (std::size_t i = 0; i < order.size(); ++i) place_[order[i]] = i;
}

Individual Nslc::conceive(std::uint64_t birth) const {
    const std::vector<Individual>& population = state_.population;
    ParentPicker pick;
    // No valid member yet: a random genome (or a given one), as in generation 0.
    if (!population.empty())
        pick = [&](RandomStream& stream) -> const Individual& {
            return population[tournament(population.size(), params_.tournament, stream,
                                         [&](std::size_t a, std::size_t b) { return place_[a] < place_[b]; })];
        };
    BirthRules rules = birth_rules(params_);
    rules.centre = centre_;
    rules.seeds = seeds_;
    return conceive_birth(rules, blocks_, problem_.dimension(), seed_, birth, pick);
}

std::size_t Nslc::lowest_with(const Individual& child) const {
    std::vector<BehaviourPoint> members = points_of(state_.population);
    members.push_back(behaviour_point(child));
    const std::vector<NoveltyScore> scores = ranked_scores(members, archive_points(), ranges_, novelty_.k);
    const auto id = [&](std::size_t slot) { return slot < state_.population.size() ? state_.population[slot].id : child.id; };
    std::size_t lowest = 0;
    for (std::size_t slot = 1; slot < scores.size(); ++slot)
        if (novelty_ranks_above(scores[lowest], id(lowest), scores[slot], id(slot))) lowest = slot;
    return lowest;
}

Inserted Nslc::insert(Individual& child, std::string& error) {
    if (child.valid() && !fits(child.descriptors, ranges_.size())) {
        error = std::to_string(child.descriptors.size()) + " descriptors (or one not finite), the search has " +
                std::to_string(ranges_.size());
        child.fitness = invalid_fitness;
        child.size = 0.0;
        child.descriptors.clear();
    }
    const std::uint64_t birth = state_.births;
    if (!child.valid()) {
        ++state_.invalid_in_generation;
    } else {
        keep_best(state_.best, child);
        RandomStream coin(seed_, kArchiveCoinStreams + birth);
        if (novelty_.archive > 0 && coin.bernoulli(novelty_.archive_rate)) {
            state_.archive.push_back(Individual{child.id, {}, {}, {}, child.fitness, 0.0, child.descriptors});
            if (state_.archive.size() > novelty_.archive) state_.archive.erase(state_.archive.begin());
        }
        if (state_.population.size() < static_cast<std::size_t>(params_.population)) {
            state_.population.push_back(child);
        } else if (const std::size_t lowest = lowest_with(child); lowest < state_.population.size()) {
            state_.population[lowest] = child;
        }
        rescore();
    }
    return count_birth(state_.births, state_.invalid_in_generation, population());
}

double Nslc::export_floor() const {
    const Individual* top = top_ranked(state_.population);
    return top != nullptr ? top->fitness : -std::numeric_limits<double>::infinity();
}

}  // namespace morphogen
