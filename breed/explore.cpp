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

ExploreSettings explore_settings(const ExperimentConfig& config, int grid) {
    ExploreSettings s;
    s.descriptors = config.qd.descriptors;
    if (s.descriptors.empty() || s.descriptors.size() > 3)
        s.descriptors = {{"spread", 0.0, 4.0, 10}, {"slenderness", 0.0, 4.0, 10}};
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
    explicit Scorer(const PlantGrowth& growth) : growth_(growth) {}
    std::size_t dimension() const override { return growth_.dimension(); }
    std::vector<Block> blocks() const override { return neuron_blocks(growth_.grower().layers()); }
    Evaluation evaluate(std::span<const double> params, int) const override { return growth_.evaluate(params); }

private:
    const PlantGrowth& growth_;
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
    Scorer scorer(growth_);
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
    for (std::size_t i : pick_different_good(elites, settings_.descriptors, picks_))
        result.picked.push_back(elites[i]->params);
    return result;
}

std::vector<std::size_t> pick_different_good(const std::vector<const Individual*>& elites,
                                             const std::vector<DescriptorRange>& ranges, std::size_t count) {
    std::vector<double> fitness;
    for (const Individual* e : elites) fitness.push_back(e->fitness);
    std::vector<double> sorted = fitness;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.empty() ? 0.0 : sorted[(sorted.size() - 1) / 2];

    auto distance = [&](std::size_t a, std::size_t b) {
        double d = 0.0;
        for (std::size_t k = 0; k < ranges.size(); ++k) {
            const double span = ranges[k].max - ranges[k].min;
            const double x = (elites[a]->descriptors.at(k) - elites[b]->descriptors.at(k)) / span;
            d += x * x;
        }
        return d;
    };
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
        std::vector<double> nearest(good.size(), std::numeric_limits<double>::infinity());
        while (picked.size() < std::min(count, good.size())) {
            std::size_t best = good.size();
            for (std::size_t g = 0; g < good.size(); ++g) {
                nearest[g] = std::min(nearest[g], distance(good[g], picked.back()));
                if (std::find(picked.begin(), picked.end(), good[g]) != picked.end()) continue;
                if (best == good.size() || nearest[g] > nearest[best]) best = g;
            }
            picked.push_back(good[best]);
        }
    }
    std::sort(rest.begin(), rest.end(), fitter);
    for (std::size_t i = 0; i < rest.size() && picked.size() < count; ++i) picked.push_back(rest[i]);
    return picked;
}

}  // namespace morphogen
