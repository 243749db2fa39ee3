// The GA driver: determinism across thread counts, invalid children,
// improvement on a toy problem, exact continuation from a saved state.
#include "evolution/ga/ga_state_json.hpp"
#include "evolution/ga/population_stats.hpp"
#include "evolution/ga/steady_state.hpp"
#include "tests/evolution/breeding.hpp"
#include "tests/evolution/toy_problems.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using morphogen::test::SphereProblem;

namespace {
GaParams small_ga_params() {
    GaParams p;
    p.population = 20;
    p.batch = 6;  // 20 = 6+6+6+2: exercises the boundary
    p.mutation_rate = 0.2;
    return p;
}

// One batch of the batch schedule (what a run with params.batch does).
std::vector<test::Bred> step(SteadyStateGA& ga, Problem& problem, int threads) {
    return test::breed_batch(ga, problem, static_cast<std::uint64_t>(ga.params().population),
                             static_cast<std::uint64_t>(ga.params().batch), threads);
}

// Runs until `births` births; returns the state as canonical JSON text.
std::string run_ga(Problem& problem, const GaParams& params, int threads, std::uint64_t births, GaState start = {}) {
    SteadyStateGA ga(params, 42, problem, std::move(start));
    while (ga.state().births < births) step(ga, problem, threads);
    return ga_state_to_json(ga.state()).dump();
}
}  // namespace

TEST_CASE("a run is the same for 1 or 2 or 8 threads", "[evolution][determinism]") {
    SphereProblem problem(12, 3, true);
    const auto params = small_ga_params();
    const std::string one = run_ga(problem, params, 1, 400);
    CHECK(run_ga(problem, params, 2, 400) == one);
    CHECK(run_ga(problem, params, 8, 400) == one);
    // batch size changes the result (parents come from the batch's snapshot); the seed too
    auto other = params;
    other.batch = 5;
    CHECK(run_ga(problem, other, 1, 400) != one);
}

TEST_CASE("the GA improves a sphere function", "[evolution]") {
    SphereProblem problem(12, 3);
    SteadyStateGA ga(small_ga_params(), 1, problem);
    while (ga.state().births < 20) step(ga, problem, 1);
    const double initial = *summarize(ga.state().population).best;
    test::breed_until(ga, problem, 20, 6, 1, 2000);
    const auto stats = summarize(ga.state().population);
    CHECK(*stats.best > initial);
    CHECK(*stats.best > -1.0);
    CHECK(ga.state().best->fitness == *stats.best);
    CHECK(ga.completed_generations() == 100);
}

TEST_CASE("exceptions and non-finite scores make a child invalid and never fail the run", "[evolution]") {
    SphereProblem problem(6, 2, true);
    GaParams params = small_ga_params();
    params.init_range = 3.0;  // many genomes trip the faults
    SteadyStateGA ga(params, 5, problem);
    std::uint64_t invalid = 0, generation_invalid = 0;
    bool saw_throw = false, saw_nan = false;
    while (ga.state().births < 100) {
        for (const test::Bred& b : step(ga, problem, 2)) {
            if (b.what.ends_generation) generation_invalid += b.what.generation_invalid;
            if (b.child.valid()) continue;
            ++invalid;
            CHECK(b.child.fitness == invalid_fitness);
            saw_throw |= b.error == "genome too wild";
            saw_nan |= b.error.find("non-finite") != std::string::npos;
        }
    }
    CHECK(saw_throw);
    CHECK(saw_nan);
    CHECK(invalid == generation_invalid);
    CHECK(ga.state().invalid_in_generation == 0);
    // the JSON never holds a non-finite number
    const std::string text = ga_state_to_json(ga.state()).dump();
    CHECK(text.find("inf") == std::string::npos);
    CHECK(text.find("NaN") == std::string::npos);
}

TEST_CASE("a state saved mid-generation continues exactly", "[evolution][resume]") {
    SphereProblem problem(12, 3, true);
    const auto params = small_ga_params();
    const std::string whole = run_ga(problem, params, 2, 200);
    for (std::uint64_t stop : {6ULL, 20ULL, 38ULL, 100ULL}) {
        SteadyStateGA first(params, 42, problem);
        while (first.state().births < stop) step(first, problem, 1);
        const auto saved = nlohmann::json::parse(ga_state_to_json(first.state()).dump());
        GaState restored = ga_state_from_json(saved, params, problem.dimension());
        CHECK(run_ga(problem, params, 8, 200, std::move(restored)) == whole);
    }
}

TEST_CASE("ga_state_from_json refuses states that do not fit", "[evolution][resume]") {
    SphereProblem problem(4, 2);
    const auto params = small_ga_params();
    SteadyStateGA ga(params, 42, problem);
    while (ga.state().births < 26) step(ga, problem, 1);
    const auto good = ga_state_to_json(ga.state());
    CHECK_NOTHROW(ga_state_from_json(good, params, 4));
    CHECK_THROWS_WITH(ga_state_from_json(good, params, 5), Catch::Contains("parameters"));
    auto bad = good;
    bad["births"] = 19;
    CHECK_THROWS_AS(ga_state_from_json(bad, params, 4), std::invalid_argument);
    bad = good;
    bad["population"][3]["id"] = bad["population"][4]["id"];
    CHECK_THROWS_WITH(ga_state_from_json(bad, params, 4), Catch::Contains("duplicate"));
    bad = good;
    bad["population"][0].erase("params");
    CHECK_THROWS_WITH(ga_state_from_json(bad, params, 4), Catch::Contains("params"));
    bad = good;
    bad["population"][0]["fitness"] = "x";
    CHECK_THROWS_AS(ga_state_from_json(bad, params, 4), std::invalid_argument);
}
