#include "breed/explore.hpp"

#include "evolution/emitters/emitter_registry.hpp"
#include "evolution/emitters/emitters.hpp"
#include "evolution/execution/pipeline.hpp"
#include "evolution/problem.hpp"
#include "core/growth/network/network.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace morphogen {

std::string explore_along_name(ExploreAlong along) {
    return along == ExploreAlong::architecture ? "architecture" : "descriptors";
}

std::optional<ExploreAlong> explore_along_from(const std::string& name) {
    if (name == "architecture") return ExploreAlong::architecture;
    if (name == "descriptors") return ExploreAlong::descriptors;
    return std::nullopt;
}

ExploreSettings explore_settings(const ExperimentConfig& config, int grid, ExploreAlong along) {
    ExploreSettings s;
    s.along = along;
    if (along == ExploreAlong::architecture) {
        // A limb a cell up to 10, the fork by tenths of the height, tips by twos:
        // small steps toward more limbs and a lower fork each keep a cell.
        s.descriptors = {{"limbs", 0.0, 10.0, 10}, {"first_fork", 0.0, 1.0, 10}, {"tips", 0.0, 20.0, 10}};
    } else {
        s.descriptors = config.qd.descriptors;
        if (s.descriptors.empty() || s.descriptors.size() > 3)
            s.descriptors = {{"spread", 0.0, 4.0, 10}, {"slenderness", 0.0, 4.0, 10}};
    }
    const GaParams& ga = config.evolution;
    s.params.population = grid;
    s.params.crossover = ga.crossover;
    s.params.mutation_rate = ga.mutation_rate;
    s.params.mutation_sigma = ga.mutation_sigma;
    s.params.batch = 1;
    s.params.init_range = ga.init_range;
    s.params.emitters = config.algorithm == Algorithm::map_elites && !config.qd.emitters.empty()
                            ? config.qd.emitters
                            : default_emitters();
    return s;
}

// The search's Problem: a birth scores as the session scores a plant, and
// is valid only where it is placeable (finite descriptors).
class ExploreSearch::Scorer final : public Problem {
public:
    Scorer(const PlantGrowth& growth, const ExploreSettings& settings) : growth_(growth), settings_(settings) {}
    std::size_t dimension() const override { return growth_.dimension(); }
    std::vector<Block> blocks() const override { return neuron_blocks(growth_.grower().layers()); }
    Evaluation evaluate(std::span<const double> params, int) const override {
        return settings_.along == ExploreAlong::architecture ? growth_.evaluate_architecture(params, settings_.min_height)
                                                             : growth_.evaluate(params);
    }

private:
    const PlantGrowth& growth_;
    const ExploreSettings& settings_;
};

ExploreSearch::ExploreSearch(const PlantGrowth& growth, const ExploreSettings& settings,
                             std::vector<ExploreSeed> seeds, std::uint64_t seed, std::uint64_t births,
                             std::size_t picks)
    : growth_(growth), settings_(settings), seeds_(std::move(seeds)), seed_(seed), births_(births), picks_(picks) {
    if (seeds_.empty()) throw std::invalid_argument("explore needs at least one seed plant");
    if (births < 1) throw std::invalid_argument("explore needs at least one birth");
    if (picks < 1) throw std::invalid_argument("explore must pick at least one plant");
    if (seeds_.size() >= static_cast<std::size_t>(settings_.params.population))
        throw std::invalid_argument("explore has more seeds than a generation");
}

ExploreResult ExploreSearch::run() {
    Scorer scorer(growth_, settings_);
    MapElitesState state{static_cast<std::uint64_t>(settings_.params.population), Archive::grid(settings_.descriptors),
                         {}, 0, 0, fresh_emitters(settings_.params.emitters)};
    for (std::size_t i = 0; i < seeds_.size(); ++i) {
        Individual seed_plant;
        seed_plant.id = i;  // below the first birth, which is `population`
        seed_plant.params = seeds_[i].params;
        seed_plant.fitness = seeds_[i].fitness;
        seed_plant.descriptors = seeds_[i].descriptors;
        state.archive.insert(seed_plant);
        if (!state.best || seed_plant.fitness > state.best->fitness) state.best = seed_plant;
    }
    MapElites search(settings_.params, seed_, scorer, std::move(state));
    const std::uint64_t first = search.births();
    while (!stop_ && search.births() < first + births_) {
        Individual child = search.conceive(search.births());
        std::string error;
        take_evaluation(child, error, scorer.evaluate(child.params, 0));
        search.insert(child, error);
        done_ = search.births() - first;
        elites_ = search.state().archive.occupied();
    }
    const std::vector<const Individual*> elites = search.state().archive.snapshot();
    ExploreResult result;
    result.done = done_;
    const std::vector<std::size_t> picks = settings_.along == ExploreAlong::architecture
                                               ? pick_tree_like(elites, settings_.descriptors, picks_)
                                               : pick_different_good(elites, settings_.descriptors, picks_);
    for (std::size_t i : picks)
        result.picked.push_back(elites[i]->params);
    return result;
}

namespace {

// Squared distance of two elites' descriptors, each scaled by its range.
double scaled_distance(const Individual& a, const Individual& b, const std::vector<DescriptorRange>& ranges) {
    double d = 0.0;
    for (std::size_t k = 0; k < ranges.size(); ++k) {
        const double x = (a.descriptors.at(k) - b.descriptors.at(k)) / (ranges[k].max - ranges[k].min);
        d += x * x;
    }
    return d;
}

// Adds to `picked` (already holding at least one of `pool`) the members of
// `pool` farthest from all picked so far, one after another, until it holds
// `count` or the pool is used up (ties: the earlier in the pool).
void add_farthest(const std::vector<const Individual*>& elites, const std::vector<DescriptorRange>& ranges,
                  const std::vector<std::size_t>& pool, std::size_t count, std::vector<std::size_t>& picked) {
    std::vector<double> nearest(pool.size(), std::numeric_limits<double>::infinity());
    for (std::size_t g = 0; g < pool.size(); ++g)
        for (std::size_t p : picked) nearest[g] = std::min(nearest[g], scaled_distance(*elites[pool[g]], *elites[p], ranges));
    while (picked.size() < count) {
        std::size_t best = pool.size();
        for (std::size_t g = 0; g < pool.size(); ++g) {
            if (std::find(picked.begin(), picked.end(), pool[g]) != picked.end()) continue;
            if (best == pool.size() || nearest[g] > nearest[best]) best = g;
        }
        if (best == pool.size()) return;
        picked.push_back(pool[best]);
        for (std::size_t g = 0; g < pool.size(); ++g)
            nearest[g] = std::min(nearest[g], scaled_distance(*elites[pool[g]], *elites[picked.back()], ranges));
    }
}

}  // namespace

std::vector<std::size_t> pick_tree_like(const std::vector<const Individual*>& elites,
                                        const std::vector<DescriptorRange>& ranges, std::size_t count) {
    std::vector<std::size_t> order(elites.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const std::vector<double>& x = elites[a]->descriptors;
        const std::vector<double>& y = elites[b]->descriptors;
        if (x.at(0) != y.at(0)) return x[0] > y[0];  // more limbs
        if (x.at(1) != y.at(1)) return x[1] < y[1];  // a lower fork
        return elites[a]->fitness > elites[b]->fitness;
    });
    const std::size_t wanted = std::min(count, elites.size());
    std::vector<std::size_t> picked(order.begin(), order.begin() + static_cast<std::ptrdiff_t>((wanted + 1) / 2));
    if (!picked.empty()) add_farthest(elites, ranges, order, wanted, picked);
    return picked;
}

std::vector<std::size_t> pick_different_good(const std::vector<const Individual*>& elites,
                                             const std::vector<DescriptorRange>& ranges, std::size_t count) {
    std::vector<double> fitness;
    for (const Individual* e : elites) fitness.push_back(e->fitness);
    std::vector<double> sorted = fitness;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.empty() ? 0.0 : sorted[(sorted.size() - 1) / 2];

    // Fittest first; ties: the lower index (the lower cell).
    auto fitter = [&](std::size_t a, std::size_t b) { return fitness[a] > fitness[b] || (fitness[a] == fitness[b] && a < b); };

    // Good: at or above the median, and above the lowest fitness when any
    // elite is (many elites of a plateau, e.g. plants scoring 0, make the
    // median the lowest fitness).
    const double lowest = sorted.empty() ? 0.0 : sorted.front();
    const bool above_lowest = !sorted.empty() && sorted.back() > lowest;
    std::vector<std::size_t> good, rest;
    for (std::size_t i = 0; i < elites.size(); ++i)
        (fitness[i] >= median && (!above_lowest || fitness[i] > lowest) ? good : rest).push_back(i);
    std::vector<std::size_t> picked;
    if (!good.empty()) {
        picked.push_back(*std::min_element(good.begin(), good.end(), fitter));
        add_farthest(elites, ranges, good, std::min(count, good.size()), picked);
    }
    std::sort(rest.begin(), rest.end(), fitter);
    for (std::size_t i = 0; i < rest.size() && picked.size() < count; ++i) picked.push_back(rest[i]);
    return picked;
}

}  // namespace morphogen
