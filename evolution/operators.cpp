#include "evolution/operators.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace morphogen {

std::size_t tournament(std::span<const Individual> population, int size, RandomStream& stream) {
    return tournament(population.size(), size, stream,
                      [&](std::size_t a, std::size_t b) { return ranks_above(population[a], population[b]); });
}

std::size_t tournament(std::size_t count, int size, RandomStream& stream,
                       const std::function<bool(std::size_t, std::size_t)>& above) {
    std::size_t winner = stream.below(count);
    for (int i = 1; i < size; ++i) {
        const std::size_t slot = stream.below(count);
        if (above(slot, winner)) winner = slot;
    }
    return winner;
}

const Individual* top_ranked(std::span<const Individual> population) {
    const Individual* best = nullptr;
    for (const Individual& member : population)
        if (best == nullptr || ranks_above(member, *best)) best = &member;
    return best != nullptr && best->valid() ? best : nullptr;
}

std::vector<double> crossover(std::span<const double> a, std::span<const double> b, std::span<const Block> blocks,
                              RandomStream& stream) {
    std::vector<double> child(a.begin(), a.end());
    for (const auto& [offset, length] : blocks) {
        if (stream.bernoulli(0.5)) {
            for (std::size_t i = offset; i < offset + length; ++i) child[i] = b[i];
        }
    }
    return child;
}

std::size_t mutate(std::vector<double>& params, double rate, double sigma, RandomStream& stream) {
    std::size_t changed = 0;
    for (double& p : params) {
        if (stream.bernoulli(rate)) {
            p += sigma * stream.normal();
            ++changed;
        }
    }
    return changed;
}

std::size_t worst_slot(std::span<const Individual> population) {
    std::size_t worst = 0;
    for (std::size_t slot = 1; slot < population.size(); ++slot) {
        if (ranks_above(population[worst], population[slot])) worst = slot;
    }
    return worst;
}

bool insert_child(std::vector<Individual>& population, Individual child, std::size_t capacity) {
    if (population.size() < capacity) {
        population.push_back(std::move(child));
        return true;
    }
    const std::size_t worst = worst_slot(population);
    // ">=" on fitness alone: a child as good as the worst still replaces it,
    // which lets the population drift across plateaus.
    if (!(child.fitness >= population[worst].fitness)) return false;
    population[worst] = std::move(child);
    return true;
}

BirthRules birth_rules(const GaParams& params) {
    return {static_cast<std::uint64_t>(params.population), params.init_range, params.crossover, params.mutation_rate,
            params.mutation_sigma, {}, {}};
}

void check_shared_params(const BirthRules& r, int batch, const std::string& search) {
    auto require = [&search](bool ok, const char* what) {
        if (!ok) throw std::invalid_argument(search + " parameter out of range: " + what);
    };
    require(r.crossover >= 0 && r.crossover <= 1, "0 <= crossover <= 1");
    require(r.mutation_rate >= 0 && r.mutation_rate <= 1, "0 <= mutation_rate <= 1");
    require(r.mutation_sigma >= 0 && std::isfinite(r.mutation_sigma), "mutation_sigma >= 0");
    require(batch >= 1, "batch >= 1");
    require(r.init_range >= 0 && std::isfinite(r.init_range), "init_range >= 0");
}

Individual conceive_birth(const BirthRules& rules, std::span<const Block> blocks, std::size_t dimension,
                          std::uint64_t seed, std::uint64_t birth, const ParentPicker& pick) {
    RandomStream stream(seed, birth);
    Individual child;
    child.id = birth;
    if (birth < rules.population || !pick) {
        if (rules.seeds.empty()) {
            child.params = random_parameters(dimension, rules.init_range, stream, rules.centre);
        } else {
            child.params = rules.seeds[birth % rules.seeds.size()];
            if (birth >= rules.seeds.size()) mutate(child.params, rules.mutation_rate, rules.mutation_sigma, stream);
        }
        return child;
    }
    const Individual& first = pick(stream);
    const Individual& second = pick(stream);
    child.parent1 = first.id;
    if (stream.bernoulli(rules.crossover)) {
        child.parent2 = second.id;
        child.params = crossover(first.params, second.params, blocks, stream);
    } else {
        child.params = first.params;
    }
    mutate(child.params, rules.mutation_rate, rules.mutation_sigma, stream);
    return child;
}

Individual conceive(std::span<const Individual> snapshot, const GaParams& params, std::span<const Block> blocks,
                    std::size_t dimension, std::uint64_t seed, std::uint64_t birth, std::span<const double> centre,
                    std::span<const std::vector<double>> seeds) {
    const ParentPicker pick = [&](RandomStream& stream) -> const Individual& {
        return snapshot[tournament(snapshot, params.tournament, stream)];
    };
    BirthRules rules = birth_rules(params);
    rules.centre = centre;
    rules.seeds = seeds;
    return conceive_birth(rules, blocks, dimension, seed, birth, pick);
}

std::vector<double> check_centre(std::vector<double> centre, std::size_t dimension, const std::string& search) {
    if (!centre.empty() && centre.size() != dimension)
        throw std::invalid_argument(search + " problem out of range: random centre of size " +
                                    std::to_string(centre.size()) + " for dimension " + std::to_string(dimension));
    return centre;
}

std::vector<std::vector<double>> check_seeds(std::vector<std::vector<double>> seeds, std::size_t dimension,
                                             const std::string& search) {
    for (const std::vector<double>& s : seeds)
        if (s.size() != dimension)
            throw std::invalid_argument(search + " problem out of range: a given genome of size " +
                                        std::to_string(s.size()) + " for dimension " + std::to_string(dimension));
    return seeds;
}

std::size_t batch_size(std::uint64_t births, std::uint64_t population, int batch) {
    const std::uint64_t to_generation_end = population - births % population;
    return static_cast<std::size_t>(std::min<std::uint64_t>(to_generation_end, static_cast<std::uint64_t>(batch)));
}

std::size_t batch_size(std::uint64_t births, const GaParams& params) {
    return batch_size(births, static_cast<std::uint64_t>(params.population), params.batch);
}

std::vector<Block> check_blocks(std::vector<Block> blocks, std::size_t dimension) {
    if (blocks.empty()) {
        blocks.reserve(dimension);
        for (std::size_t i = 0; i < dimension; ++i) blocks.emplace_back(i, 1);
        return blocks;
    }
    std::size_t next = 0;
    for (const auto& [offset, length] : blocks) {
        if (offset != next || length == 0)
            throw std::invalid_argument("crossover blocks must tile the parameters in order; block at " +
                                        std::to_string(offset) + " expected at " + std::to_string(next));
        next = offset + length;
    }
    if (next != dimension)
        throw std::invalid_argument("crossover blocks cover " + std::to_string(next) + " of " +
                                    std::to_string(dimension) + " parameters");
    return blocks;
}

}  // namespace morphogen
