// MAP-Elites emitters (emitters.hpp): shares that add up to the generation,
// the gaussian and iso+line emitters alone, fitness-proportional
// statistics, and the same run for any threads, order of results and stop.
#include "evolution/emitters/emitters.hpp"
#include "evolution/emitters/gaussian_emitter.hpp"
#include "evolution/emitters/iso_line_emitter.hpp"
#include "evolution/schedulers/map_elites.hpp"
#include "evolution/schedulers/map_elites_state_json.hpp"
#include "evolution/execution/pipeline.hpp"
#include "evolution/execution/thread_evaluator.hpp"
#include "tests/evolution/breeding.hpp"
#include "tests/evolution/search_fixtures.hpp"
#include "tests/evolution/toy_problems.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <optional>
#include <random>

using namespace morphogen;
using namespace morphogen::test;
using morphogen::test::DescribedSphereProblem;

namespace {
EmitterSpec iso_line(double share, double sigma_iso, double sigma_line,
                     ParentSelection selection = ParentSelection::uniform) {
    return {share, std::make_shared<IsoLineEmitter>(selection, IsoLineSettings{sigma_iso, sigma_line})};
}


// Birth `birth` of `spec`'s emitter from `pool` (population 10, dimension 4, seed `seed`).
Individual emit(const EmitterSpec& spec, std::span<const Block> blocks, std::uint64_t seed, std::uint64_t birth,
                const ParentPool& pool) {
    const BirthRules r{10, 2.0, 0.3, 0.05, 0.3, {}};
    return spec.emitter->conceive(EmitterSource{r, blocks, 4, seed, pool}, birth);
}

Individual elite(std::uint64_t id, std::vector<double> params, double fitness) {
    Individual e;
    e.id = id;
    e.params = std::move(params);
    e.fitness = fitness;
    return e;
}


std::string run(Problem& problem, const MapElitesParams& params, GenomeEvaluator& evaluator, std::uint64_t births,
                const BirthSchedule& schedule) {
    MapElites me(params, 11, problem, empty_state());
    BirthPipeline pipeline(schedule, me, evaluator);
    REQUIRE(pipeline.run(births, ignore, never));
    return map_elites_state_to_json(me.state()).dump();
}
}  // namespace

TEST_CASE("emitter shares add up to the generation, by largest remainders", "[evolution][emitters]") {
    const std::vector<EmitterSpec> three{gaussian(), gaussian(), gaussian()};
    CHECK(births_per_generation(three, 10) == std::vector<std::uint64_t>{4, 3, 3});
    std::vector<EmitterSpec> two{gaussian(), gaussian()};
    two[0].share = 3;
    CHECK(births_per_generation(two, 10) == std::vector<std::uint64_t>{8, 2});  // 7.5 and 2.5: the tie to the first
    CHECK(births_per_generation(std::vector<EmitterSpec>{gaussian()}, 7) == std::vector<std::uint64_t>{7});
    std::mt19937 random(3);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<EmitterSpec> specs(1 + random() % 6);
        for (EmitterSpec& e : specs) e.share = std::uniform_real_distribution<double>(0.01, 5.0)(random);
        const std::uint64_t P = 1 + random() % 300;
        const std::vector<std::uint64_t> n = births_per_generation(specs, P);
        CHECK(std::accumulate(n.begin(), n.end(), std::uint64_t{0}) == P);
        double total = 0;
        for (const EmitterSpec& e : specs) total += e.share;
        for (std::size_t k = 0; k < specs.size(); ++k) CHECK(std::abs(double(n[k]) - P * specs[k].share / total) < 1.0);
        // Every birth of a generation has exactly one emitter, in consecutive runs.
        std::vector<std::uint64_t> counted(specs.size(), 0);
        for (std::uint64_t b = 3 * P; b < 4 * P; ++b) ++counted[emitter_of(b, n, P)];
        CHECK(counted == n);
    }
    std::vector<EmitterSpec> bad{gaussian()};
    bad[0].share = 0;
    CHECK_THROWS_AS(births_per_generation(bad, 10), std::invalid_argument);
    CHECK_THROWS_AS(births_per_generation(std::vector<EmitterSpec>{}, 10), std::invalid_argument);
}

TEST_CASE("iso+line variation: isotropic steps of sigma_iso, line steps of sigma_line", "[evolution][emitters]") {
    const std::vector<Block> blocks{{0, 2}, {2, 2}};
    const std::vector<double> x{0.5, -1.0, 2.0, 0.0}, y{1.5, 1.0, 2.0, -3.0};
    const int n = 20000;
    {  // One elite: y = x, so the child is x plus the isotropic step alone.
        const Individual only = elite(3, x, 1.0);
        const ParentPool pool({&only});
        double sum = 0, squares = 0;
        for (int b = 0; b < n; ++b) {
            const Individual child = emit(iso_line(1, 0.1, 0.7), blocks, 5, 10 + b, pool);
            CHECK(child.parent1 == 3u);
            for (std::size_t i = 0; i < 4; ++i) {
                const double step = child.params[i] - x[i];
                sum += step;
                squares += step * step;
            }
        }
        const double mean = sum / (4.0 * n), sd = std::sqrt(squares / (4.0 * n) - mean * mean);
        CHECK(std::abs(mean) < 4 * 0.1 / std::sqrt(4.0 * n));
        CHECK(sd == Approx(0.1).epsilon(0.03));
    }
    {  // Two elites, no isotropic step: the child lies on the line x + t (y - x), t ~ N(0, sigma_line).
        const Individual a = elite(1, x, 1.0), b = elite(2, y, 2.0);
        const ParentPool pool({&a, &b});
        double sum = 0, squares = 0;
        int on_line = 0;
        for (int k = 0; k < n; ++k) {
            const Individual child = emit(iso_line(1, 0.0, 0.7), blocks, 8, 10 + k, pool);
            const std::vector<double>& from = *child.parent1 == 1 ? x : y;
            const std::vector<double>& to = *child.parent2 == 1 ? x : y;
            if (child.parent1 == child.parent2) {
                CHECK(child.params == from);
                continue;
            }
            const double t = (child.params[0] - from[0]) / (to[0] - from[0]);
            for (std::size_t i = 0; i < 4; ++i) CHECK(child.params[i] == Approx(from[i] + t * (to[i] - from[i])).margin(1e-12));
            sum += t;
            squares += t * t;
            ++on_line;
        }
        CHECK(on_line == Approx(n / 2.0).epsilon(0.05));  // parents differ half the time
        const double mean = sum / on_line, sd = std::sqrt(squares / on_line - mean * mean);
        CHECK(std::abs(mean) < 4 * 0.7 / std::sqrt(double(on_line)));
        CHECK(sd == Approx(0.7).epsilon(0.03));
    }
    // An empty archive gives random genomes, as the gaussian birth does.
    const ParentPool none({});
    CHECK(emit(iso_line(1, 0.1, 0.2), blocks, 5, 13, none).params == emit(gaussian(), blocks, 5, 13, none).params);
    CHECK_FALSE(emit(iso_line(1, 0.1, 0.2), blocks, 5, 13, none).parent1);
}

TEST_CASE("the gaussian emitter is conceive_birth with the pool's picks", "[evolution][emitters]") {
    const std::vector<Block> blocks{{0, 2}, {2, 2}};
    const Individual a = elite(1, {0.5, -1.0, 2.0, 0.0}, 1.0), b = elite(2, {1.5, 1.0, 2.0, -3.0}, 4.0);
    const ParentPool pool({&a, &b});
    const BirthRules r{10, 2.0, 0.3, 0.05, 0.3, {}};
    for (ParentSelection selection : {ParentSelection::uniform, ParentSelection::fitness_proportional}) {
        const EmitterSpec spec{1.0, std::make_shared<GaussianEmitter>(selection)};
        for (std::uint64_t birth = 10; birth < 60; ++birth) {
            const Individual child = emit(spec, blocks, 5, birth, pool);
            const Individual expected = conceive_birth(r, blocks, 4, 5, birth, pool.picker(selection));
            CHECK(child.params == expected.params);
            CHECK(child.parent1 == expected.parent1);
            CHECK(child.parent2 == expected.parent2);
        }
    }
    // A stateless emitter keeps no checkpoint entry and takes only null.
    GaussianEmitter fresh;
    CHECK_FALSE(fresh.keeps_state());
    CHECK(fresh.state_to_json(nullptr).is_null());
    CHECK_NOTHROW(fresh.state_from_json(nullptr, {}, "e", nullptr));
    CHECK_THROWS_WITH(fresh.state_from_json(nlohmann::json::object(), {}, "e", nullptr),
                      Catch::Contains("e: a stateless emitter's entry must be null"));
}

TEST_CASE("fitness-proportional selection draws elites by fitness - worst + spread/20", "[evolution][emitters]") {
    const Individual a = elite(1, {0.0}, 0.0), b = elite(2, {0.0}, 1.0), c = elite(3, {0.0}, 3.0);
    const ParentPool pool({&a, &b, &c});
    // Weights 0.15, 1.15, 3.15 (delta = 3/20).
    const double total = 0.15 + 1.15 + 3.15;
    std::vector<int> counts(4, 0);
    const int n = 30000;
    for (int k = 0; k < n; ++k) {
        RandomStream stream(17, static_cast<std::uint64_t>(k));
        ++counts[pool.pick(ParentSelection::fitness_proportional, stream).id];
    }
    CHECK(counts[1] / double(n) == Approx(0.15 / total).epsilon(0.08));
    CHECK(counts[2] / double(n) == Approx(1.15 / total).epsilon(0.03));
    CHECK(counts[3] / double(n) == Approx(3.15 / total).epsilon(0.02));
    // Uniform ignores fitness.
    std::vector<int> uniform(4, 0);
    for (int k = 0; k < n; ++k) {
        RandomStream stream(17, static_cast<std::uint64_t>(k));
        ++uniform[pool.pick(ParentSelection::uniform, stream).id];
    }
    for (int id = 1; id <= 3; ++id) CHECK(uniform[id] / double(n) == Approx(1 / 3.0).epsilon(0.03));
}

TEST_CASE("emitters change the run, threads do not", "[evolution][emitters][determinism]") {
    DescribedSphereProblem problem(6, 2, /*faulty=*/true);
    const BirthSchedule schedule{ScheduleKind::pipeline, 12, 7};
    MapElitesParams plain;
    plain.population = 12;
    plain.mutation_rate = 0.3;
    plain.emitters = {gaussian()};
    ThreadEvaluator one(problem, 1);
    const std::string before = run(problem, plain, one, 400, schedule);

    MapElitesParams mixed = plain;
    mixed.emitters = {gaussian(), iso_line(2, 0.05, 0.3, ParentSelection::fitness_proportional)};
    const std::string expected = run(problem, mixed, one, 400, schedule);
    CHECK(expected != before);
    ThreadEvaluator eight(problem, 8);
    CHECK(run(problem, mixed, eight, 400, schedule) == expected);
    // The batch schedule, a pipeline per batch or one for the run, agrees with emitters too.
    mixed.batch = 5;
    MapElites stepped5(mixed, 11, problem, empty_state());
    while (stepped5.state().births < 300) test::breed_batch(stepped5, problem, 12, 5, 2);
    CHECK(run(problem, mixed, eight, 300, {ScheduleKind::batch, 12, 5}) ==
          map_elites_state_to_json(stepped5.state()).dump());
}

TEST_CASE("a MAP-Elites run with emitters stopped at any birth continues exactly", "[evolution][emitters][resume]") {
    DescribedSphereProblem problem(6, 2, true);
    const BirthSchedule schedule{ScheduleKind::pipeline, 12, 6};
    MapElitesParams params;
    params.population = 12;
    params.mutation_rate = 0.3;
    params.emitters = {iso_line(1, 0.02, 0.5), gaussian(), iso_line(1, 0.1, 0.0, ParentSelection::fitness_proportional)};
    ThreadEvaluator pool(problem, 2);
    const std::string expected = run(problem, params, pool, 300, schedule);
    for (std::uint64_t stop_at : {7u, 12u, 13u, 40u, 251u}) {
        std::optional<MapElitesState> saved;
        std::vector<Individual> kept;
        {
            MapElites me(params, 11, problem, empty_state());
            BirthPipeline pipeline(schedule, me, pool);
            CHECK_FALSE(pipeline.run(300, ignore, [&] { return me.births() >= stop_at; }));
            saved = me.state();
            kept = pipeline.kept();
        }
        MapElites me(params, 11, problem, std::move(*saved));
        BirthPipeline pipeline(schedule, me, pool, kept);
        REQUIRE(pipeline.run(300, ignore, never));
        CHECK(map_elites_state_to_json(me.state()).dump() == expected);
    }
}
