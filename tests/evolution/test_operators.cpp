// Unit tests of the GA operators: selection, crossover, mutation,
// replacement and batch boundaries (docs/algorithm.md §8.2-§8.5).
#include "evolution/operators.hpp"
#include "tests/evolution/toy_problems.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

using namespace morphogen;

namespace {
std::vector<Individual> ranked_population(std::size_t n) {
    // Slot i has fitness i, ids scrambled so slot order != id order.
    std::vector<Individual> population(n);
    for (std::size_t i = 0; i < n; ++i) {
        population[i].id = (i * 7) % n + 100;
        population[i].fitness = static_cast<double>(i);
    }
    return population;
}
}  // namespace

TEST_CASE("tournament winners follow the order-statistics law", "[evolution][selection]") {
    const std::size_t n = 10;
    const int k = 3;
    const auto population = ranked_population(n);
    std::vector<double> counts(n, 0.0);
    const int draws = 200000;
    RandomStream stream(7, 0);
    for (int i = 0; i < draws; ++i) counts[tournament(population, k, stream)] += 1;
    // P(winner has rank r of n, 1-based from the worst) = (r/n)^k - ((r-1)/n)^k.
    double chi2 = 0.0;
    for (std::size_t r = 1; r <= n; ++r) {
        const double p = std::pow(double(r) / n, k) - std::pow(double(r - 1) / n, k);
        const double expected = p * draws;
        chi2 += (counts[r - 1] - expected) * (counts[r - 1] - expected) / expected;
    }
    // 9 degrees of freedom: P(chi2 > 27.9) = 0.001.
    CHECK(chi2 < 27.9);
}

TEST_CASE("tournament of size 1 is uniform and ties go to the younger (higher id)", "[evolution][selection]") {
    std::vector<Individual> population(4);
    for (std::size_t i = 0; i < 4; ++i) {
        population[i].id = 10 + i;  // slot 3 has the highest id
        population[i].fitness = 1.0;
    }
    RandomStream stream(1, 2);
    // With every fitness equal, a big tournament almost surely draws slot 3 and it must win.
    std::map<std::size_t, int> wins;
    for (int i = 0; i < 1000; ++i) ++wins[tournament(population, 50, stream)];
    CHECK(wins[3] == 1000);
    std::vector<int> uniform(4, 0);
    for (int i = 0; i < 40000; ++i) ++uniform[tournament(population, 1, stream)];
    for (int c : uniform) CHECK(std::abs(c - 10000) < 500);
    // invalid members (-inf) lose to any valid one
    population[0].fitness = invalid_fitness;
    CHECK(ranks_above(population[1], population[0]));
}

TEST_CASE("crossover exchanges whole blocks (neurons)", "[evolution][crossover]") {
    const std::vector<Block> blocks{{0, 4}, {4, 4}, {8, 2}, {10, 5}};
    std::vector<double> a(15), b(15);
    for (std::size_t i = 0; i < 15; ++i) {
        a[i] = static_cast<double>(i);
        b[i] = -static_cast<double>(i) - 1;
    }
    std::vector<int> from_b(blocks.size(), 0);
    const int trials = 4000;
    for (int t = 0; t < trials; ++t) {
        RandomStream stream(3, t);
        const auto child = crossover(a, b, blocks, stream);
        for (std::size_t k = 0; k < blocks.size(); ++k) {
            const auto [offset, length] = blocks[k];
            const bool first_from_b = child[offset] == b[offset];
            for (std::size_t i = offset; i < offset + length; ++i) REQUIRE(child[i] == (first_from_b ? b[i] : a[i]));
            from_b[k] += first_from_b;
        }
    }
    for (int c : from_b) CHECK(std::abs(c - trials / 2) < 200);  // fair coin per block
}

TEST_CASE("mutation changes each parameter with probability rate by a normal step of sd sigma", "[evolution][mutation]") {
    const double rate = 0.05, sigma = 0.3;
    RandomStream stream(11, 5);
    std::vector<double> params(200000, 0.0);
    const std::size_t changed = mutate(params, rate, sigma, stream);
    double sum = 0, squares = 0;
    std::size_t nonzero = 0;
    for (double p : params) {
        if (p != 0.0) ++nonzero;
        sum += p;
        squares += p * p;
    }
    CHECK(nonzero == changed);
    const double n = static_cast<double>(params.size());
    // rate: binomial sd = sqrt(n p (1-p)) ~ 97; allow 5 sd.
    CHECK(std::abs(static_cast<double>(changed) - rate * n) < 5 * std::sqrt(n * rate * (1 - rate)));
    const double mean = sum / changed;
    const double sd = std::sqrt(squares / changed - mean * mean);
    CHECK(std::abs(mean) < 5 * sigma / std::sqrt(double(changed)));
    CHECK(sd == Approx(sigma).epsilon(0.03));
    // rate 0 changes nothing, rate 1 everything
    std::vector<double> small(100, 0.0);
    CHECK(mutate(small, 0.0, 1.0, stream) == 0);
    CHECK(mutate(small, 1.0, 1.0, stream) == 100);
}

TEST_CASE("a child replaces the worst when at least as good", "[evolution][replacement]") {
    std::vector<Individual> population(3);
    population[0] = {5, {}, {}, {}, 2.0};
    population[1] = {3, {}, {}, {}, 1.0};
    population[2] = {4, {}, {}, {}, 1.0};
    CHECK(worst_slot(population) == 1);  // tie at 1.0: the lower id (older) goes first

    Individual worse{10, 1, {}, {}, 0.5};
    CHECK_FALSE(insert_child(population, worse, 3));
    Individual equal{11, 1, {}, {}, 1.0};
    CHECK(insert_child(population, equal, 3));
    CHECK(population[1].id == 11);
    CHECK(worst_slot(population) == 2);  // id 4 is now the oldest of the worst
    Individual invalid{12, 1, {}, {}, invalid_fitness};
    CHECK_FALSE(insert_child(population, invalid, 3));
    population[2].fitness = invalid_fitness;
    CHECK(insert_child(population, invalid, 3));  // -inf >= -inf
    CHECK(population[2].id == 12);
    // below capacity: appended
    CHECK(insert_child(population, Individual{13, {}, {}, {}, -5.0}, 4));
    CHECK(population.size() == 4);
}

TEST_CASE("batches never cross a generation boundary", "[evolution][batches]") {
    GaParams params;
    params.population = 100;
    params.batch = 32;
    std::vector<std::size_t> sizes;
    std::uint64_t births = 0;
    while (births < 300) {
        sizes.push_back(batch_size(births, params));
        births += sizes.back();
    }
    const std::vector<std::size_t> expected{32, 32, 32, 4, 32, 32, 32, 4, 32, 32, 32, 4};
    CHECK(sizes == expected);
    params.batch = 1000;
    CHECK(batch_size(0, params) == 100);
    CHECK(batch_size(150, params) == 50);
}

TEST_CASE("conceive: initial genomes are uniform in the init range and later ones have parents", "[evolution]") {
    GaParams params;
    params.population = 4;
    params.init_range = 2.0;
    const std::vector<Block> blocks = check_blocks({}, 50);
    std::vector<Individual> snapshot;
    for (std::uint64_t b = 0; b < 4; ++b) {
        Individual ind = conceive(snapshot, params, blocks, 50, 9, b);
        CHECK(ind.id == b);
        CHECK_FALSE(ind.parent1);
        for (double p : ind.params) CHECK((p >= -2.0 && p < 2.0));
        ind.fitness = static_cast<double>(b);
        snapshot.push_back(ind);
    }
    // same (seed, birth) -> same child; different seed -> different child
    CHECK(conceive(snapshot, params, blocks, 50, 9, 7).params == conceive(snapshot, params, blocks, 50, 9, 7).params);
    CHECK(conceive(snapshot, params, blocks, 50, 9, 7).params != conceive(snapshot, params, blocks, 50, 10, 7).params);
    int crossovers = 0;
    for (std::uint64_t b = 4; b < 2004; ++b) {
        const Individual child = conceive(snapshot, params, blocks, 50, 9, b);
        REQUIRE(child.parent1);
        crossovers += child.parent2.has_value();
    }
    CHECK(std::abs(crossovers - 600) < 80);  // crossover probability 0.3
}

TEST_CASE("blocks must tile the parameters", "[evolution]") {
    CHECK(check_blocks({}, 3).size() == 3);
    CHECK_NOTHROW(check_blocks({{0, 2}, {2, 1}}, 3));
    CHECK_THROWS_AS(check_blocks({{0, 2}, {3, 1}}, 4), std::invalid_argument);
    CHECK_THROWS_AS(check_blocks({{0, 2}}, 3), std::invalid_argument);
}
