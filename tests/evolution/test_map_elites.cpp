// The MAP-Elites driver: determinism across thread counts, generation 0,
// parents from the archive, invalid children, the archive's invariants.
#include "evolution/archives/archive_stats.hpp"
#include "evolution/execution/safe_evaluation.hpp"
#include "evolution/emitters/cma/cma_emitter.hpp"
#include "evolution/archives/cvt.hpp"
#include "evolution/emitters/emitter_registry.hpp"
#include "evolution/ga/ga_state_json.hpp"
#include "evolution/schedulers/map_elites.hpp"
#include "evolution/emitters/gaussian_emitter.hpp"
#include "evolution/operators.hpp"
#include "tests/evolution/breeding.hpp"
#include "tests/evolution/toy_problems.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <sstream>

using namespace morphogen;
using morphogen::test::DescribedSphereProblem;

namespace {
MapElitesParams small_params() {
    MapElitesParams p;
    p.population = 20;
    p.batch = 6;  // 20 = 6+6+6+2: exercises the boundary
    p.mutation_rate = 0.3;
    p.crossover = 0.5;
    p.emitters = {{1.0, std::make_shared<GaussianEmitter>()}};
    return p;
}

// One batch of the batch schedule (what a run with `batch` does).
std::vector<test::Bred> step(MapElites& me, Problem& problem, int threads,
                             std::vector<Archive::Insertion>* insertions = nullptr) {
    return test::breed_batch(me, problem, static_cast<std::uint64_t>(me.params().population),
                             static_cast<std::uint64_t>(me.params().batch), threads,
                             [&](const test::Bred&) {
                                 if (insertions) insertions->push_back(me.last_insertion());
                             });
}

Archive grid2() { return Archive::grid({{"x", -2, 2, 8}, {"y", -2, 2, 8}}); }

// Every bit of a state, as text (doubles in shortest round-trip form).
std::string dump(const MapElitesState& s) {
    nlohmann::json out = nlohmann::json::object();
    out["births"] = s.births;
    out["invalid"] = s.invalid_in_generation;
    out["new_cells"] = s.new_cells_in_generation;
    out["best"] = s.best ? individual_to_json(*s.best) : nullptr;
    nlohmann::json elites = nlohmann::json::array();
    for (const auto& [cell, e] : s.archive.elites()) {
        nlohmann::json row = individual_to_json(e);
        row["cell"] = cell;
        row["descriptors"] = e.descriptors;
        elites.push_back(row);
    }
    out["elites"] = elites;
    out["centroids"] = s.archive.centroids();
    return out.dump();
}

std::string run(Problem& problem, const MapElitesParams& params, Archive archive, int threads, std::uint64_t births,
                std::vector<std::string>* outcomes = nullptr) {
    MapElites me(params, 42, problem, MapElitesState{0, std::move(archive), {}, 0, 0});
    while (me.state().births < births) {
        std::vector<Archive::Insertion> insertions;
        const std::vector<test::Bred> out = step(me, problem, threads, &insertions);
        if (!outcomes) continue;
        std::ostringstream line;
        for (std::size_t i = 0; i < out.size(); ++i)
            line << out[i].child.id << ':' << (insertions[i].cell ? std::to_string(*insertions[i].cell) : "-") << ':'
                 << static_cast<int>(insertions[i].placement) << ':' << out[i].error << ' ';
        line << out.back().what.ends_generation << out.back().what.generation_invalid << '/'
             << out.back().what.generation_new_cells;
        outcomes->push_back(line.str());
    }
    return dump(me.state());
}
}  // namespace

TEST_CASE("MAP-Elites is the same for 1, 2 and 8 threads", "[evolution][map_elites][determinism]") {
    DescribedSphereProblem problem(6, 2, true);
    const auto params = small_params();
    std::vector<std::string> one_outcomes, outcomes;
    const std::string one = run(problem, params, grid2(), 1, 400, &one_outcomes);
    CHECK(run(problem, params, grid2(), 2, 400, &outcomes) == one);
    CHECK(outcomes == one_outcomes);
    outcomes.clear();
    CHECK(run(problem, params, grid2(), 8, 400, &outcomes) == one);
    CHECK(outcomes == one_outcomes);
    // with a CVT archive too
    const std::vector<double> centroids = cvt_centroids(42, 30, 2);
    const Archive cvt = Archive::cvt({{"x", -2, 2, 1}, {"y", -2, 2, 1}}, centroids);
    const std::string cvt_one = run(problem, params, cvt, 1, 200);
    CHECK(run(problem, params, cvt, 8, 200) == cvt_one);
    // batch size and seed matter
    auto other = params;
    other.batch = 5;
    CHECK(run(problem, other, grid2(), 1, 400) != one);
}

TEST_CASE("MAP-Elites: generation 0 is random, later parents are elites of the snapshot", "[evolution][map_elites]") {
    DescribedSphereProblem problem(6, 2);
    const auto params = small_params();
    MapElites me(params, 9, problem, MapElitesState{0, grid2(), {}, 0, 0});
    std::map<std::uint64_t, Individual> replay;  // cell -> the expected elite, by the rule applied here
    std::uint64_t new_cells = 0, crossed = 0;
    while (me.state().births < 300) {
        // the ids of the elites before the batch: every parent must be one of them
        std::set<std::uint64_t> before;
        for (const auto& [cell, e] : me.state().archive.elites()) before.insert(e.id);
        const std::uint64_t first = me.state().births;
        const std::size_t occupied_before = me.state().archive.occupied();
        std::vector<Archive::Insertion> insertions;
        const std::vector<test::Bred> out = step(me, problem, 2, &insertions);
        std::size_t filled = 0;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const Individual& c = out[i].child;
            CHECK(c.id == first + i);
            if (c.id < 20) {
                CHECK_FALSE(c.parent1);
                for (double p : c.params) CHECK((p >= -2.0 && p < 2.0));
            } else {
                REQUIRE(c.parent1);
                CHECK(before.count(*c.parent1) == 1);
                if (c.parent2) {
                    CHECK(before.count(*c.parent2) == 1);
                    ++crossed;
                }
            }
            REQUIRE(c.valid());
            CHECK(c.descriptors == std::vector<double>(c.params.begin(), c.params.begin() + 2));
            CHECK(insertions[i].cell == me.state().archive.cell_of(c.descriptors));
            filled += insertions[i].placement == Archive::Placement::filled;
            auto [it, fresh] = replay.try_emplace(*insertions[i].cell, c);
            if (!fresh && c.fitness >= it->second.fitness) it->second = c;
        }
        CHECK(me.state().archive.occupied() == occupied_before + filled);
        new_cells += filled;
        if (out.back().what.ends_generation) CHECK(out.back().what.generation_new_cells <= new_cells);
    }
    CHECK(crossed > 0);
    CHECK(new_cells == me.state().archive.occupied());
    // every elite is the fittest child ever placed in its cell (the latest on ties)
    // and sits in the cell its descriptors give
    REQUIRE(replay.size() == me.state().archive.occupied());
    for (const auto& [cell, e] : me.state().archive.elites()) {
        CHECK(me.state().archive.cell_of(e.descriptors) == cell);
        CHECK(replay.at(cell).id == e.id);
    }
    CHECK(me.state().best->fitness == *archive_stats(me.state().archive).fitness.best);
    CHECK(me.completed_generations() == 15);
}

TEST_CASE("MAP-Elites fills more of the map than generation 0 and improves the elites", "[evolution][map_elites]") {
    DescribedSphereProblem problem(6, 2);
    MapElites me(small_params(), 3, problem, MapElitesState{0, grid2(), {}, 0, 0});
    while (me.state().births < 20) step(me, problem, 1);
    const ArchiveStats initial = archive_stats(me.state().archive);
    test::breed_until(me, problem, 20, 6, 1, 3000);
    const ArchiveStats later = archive_stats(me.state().archive);
    CHECK(later.occupied > initial.occupied);
    CHECK(later.qd_score > initial.qd_score + 0.0);
    CHECK(*later.fitness.best > *initial.fitness.best);
    CHECK(later.coverage > 0.5);
}

TEST_CASE("MAP-Elites: invalid children enter nowhere and never fail the run", "[evolution][map_elites]") {
    DescribedSphereProblem problem(4, 2, true);
    MapElitesParams params = small_params();
    params.init_range = 3.0;  // many genomes trip the faults
    MapElites me(params, 5, problem, MapElitesState{0, grid2(), {}, 0, 0});
    bool saw_throw = false, saw_nan = false;
    std::uint64_t invalid = 0, generation_invalid = 0;
    while (me.state().births < 200) {
        std::vector<Archive::Insertion> insertions;
        const std::vector<test::Bred> out = step(me, problem, 2, &insertions);
        for (std::size_t i = 0; i < out.size(); ++i) {
            if (out[i].what.ends_generation) generation_invalid += out[i].what.generation_invalid;
            if (out[i].child.valid()) continue;
            ++invalid;
            CHECK_FALSE(insertions[i].cell);
            CHECK(insertions[i].placement == Archive::Placement::rejected);
            CHECK(out[i].child.descriptors.empty());
            saw_throw |= out[i].error == "genome too wild";
            saw_nan |= out[i].error.find("non-finite descriptor 0") != std::string::npos;
        }
    }
    CHECK(saw_throw);
    CHECK(saw_nan);
    CHECK(invalid == generation_invalid);
    for (const auto& [cell, e] : me.state().archive.elites()) CHECK(e.valid());
}

TEST_CASE("MAP-Elites: descriptors of the wrong length make a child invalid", "[evolution][map_elites]") {
    DescribedSphereProblem problem(4, 3);  // three descriptors for a two-descriptor grid
    MapElites me(small_params(), 5, problem, MapElitesState{0, grid2(), {}, 0, 0});
    const std::vector<test::Bred> out = step(me, problem, 1);
    REQUIRE(out.size() == 6);
    for (const test::Bred& b : out) {
        CHECK_FALSE(b.child.valid());
        CHECK(b.error == "3 descriptors, the archive has 2");
    }
    CHECK(me.state().archive.occupied() == 0);
    CHECK_FALSE(me.state().best);
    // with an empty archive after generation 0, births are random genomes
    while (me.state().births < 26) step(me, problem, 1);
    CHECK(me.state().births == 26);
}

TEST_CASE("MAP-Elites continues exactly from a copied state", "[evolution][map_elites][resume]") {
    DescribedSphereProblem problem(6, 2, true);
    const auto params = small_params();
    const std::string whole = run(problem, params, grid2(), 2, 200);
    for (std::uint64_t stop : {6ULL, 20ULL, 38ULL, 100ULL}) {
        MapElites first(params, 42, problem, MapElitesState{0, grid2(), {}, 0, 0});
        while (first.state().births < stop) step(first, problem, 1);
        MapElites second(params, 42, problem, first.state());
        while (second.state().births < 200) step(second, problem, 8);
        CHECK(dump(second.state()) == whole);
    }
}

TEST_CASE("MAP-Elites without emitters runs the default ones: two cma_me", "[evolution][map_elites][emitters]") {
    DescribedSphereProblem problem(6, 2);
    MapElitesParams params = small_params();
    params.emitters.clear();
    MapElites me(params, 4, problem, MapElitesState{0, grid2(), {}, 0, 0});
    REQUIRE(me.state().emitters.size() == 2);
    for (const EmitterSlot& e : me.state().emitters) {
        CHECK(e->kind() == "cma_me");
        CHECK(dynamic_cast<const CmaEmitter&>(*e).settings().sigma0 == 0.2);
    }
    while (me.state().births < 60) step(me, problem, 1);
    CHECK(dynamic_cast<const CmaEmitter&>(*me.state().emitters[0]).state().started);
    MapElitesParams given = small_params();
    given.emitters = default_emitters();
    MapElites same(given, 4, problem, MapElitesState{0, grid2(), {}, 0, 0});
    while (same.state().births < 60) step(same, problem, 1);
    CHECK(dump(same.state()) == dump(me.state()));
}

TEST_CASE("MAP-Elites refuses bad parameters", "[evolution][map_elites]") {
    DescribedSphereProblem problem(4, 2);
    auto bad = small_params();
    bad.batch = 0;
    CHECK_THROWS_AS(MapElites(bad, 1, problem, MapElitesState{0, grid2(), {}, 0, 0}), std::invalid_argument);
    bad = small_params();
    bad.crossover = 1.5;
    CHECK_THROWS_AS(MapElites(bad, 1, problem, MapElitesState{0, grid2(), {}, 0, 0}), std::invalid_argument);
    // a state whose emitters are not the parameters' kinds
    MapElitesState other{0, grid2(), {}, 0, 0};
    other.emitters = fresh_emitters(default_emitters());
    CHECK_THROWS_AS(MapElites(small_params(), 1, problem, other), std::invalid_argument);
}

TEST_CASE("evaluate_safely: non-finite descriptors invalidate, problems without descriptors are unaffected",
          "[evolution][batch]") {
    DescribedSphereProblem described(4, 2, true);
    const std::vector<double> nan_descriptor{0.0, 2.0, 0.0, 0.0};
    const Evaluation e = evaluate_safely(described, nan_descriptor, 0);
    CHECK_FALSE(e.valid);
    CHECK(e.descriptors.empty());
    CHECK(e.size == 0.0);
    CHECK(e.error.find("non-finite descriptor 0") != std::string::npos);
    const Evaluation ok = evaluate_safely(described, std::vector<double>{0.5, 0.25, 0, 0}, 0);
    CHECK(ok.valid);
    CHECK(ok.descriptors == std::vector<double>{0.5, 0.25});
    test::SphereProblem plain(4, 2);
    const Evaluation p = evaluate_safely(plain, std::vector<double>{1, 1, 1, 1}, 0);
    CHECK(p.valid);
    CHECK(p.score == 0.0);
    CHECK(p.descriptors.empty());
}

TEST_CASE("conceive_birth: random genomes without a picker, parents from the picker otherwise",
          "[evolution][operators]") {
    const std::vector<Block> blocks{{0, 2}, {2, 2}};
    const BirthRules rules{10, 1.5, 1.0, 0.0, 0.0, {}};  // always crossover, never mutate
    RandomStream reference(7, 25);
    const Individual random = conceive_birth(rules, blocks, 4, 7, 25, {});
    CHECK(random.params == random_parameters(4, 1.5, reference));
    CHECK_FALSE(random.parent1);
    Individual a, b;
    a.id = 3, a.params = {1, 1, 1, 1};
    b.id = 5, b.params = {2, 2, 2, 2};
    int calls = 0;
    const ParentPicker pick = [&](RandomStream&) -> const Individual& { return ++calls == 1 ? a : b; };
    const Individual child = conceive_birth(rules, blocks, 4, 7, 25, pick);
    CHECK(calls == 2);
    CHECK(child.parent1 == 3u);
    CHECK(child.parent2 == 5u);
    for (double p : child.params) CHECK((p == 1.0 || p == 2.0));
    CHECK(child.params[0] == child.params[1]);  // blocks stay together
    CHECK(child.params[2] == child.params[3]);
    // below the population a picker is not consulted
    calls = 0;
    CHECK(conceive_birth(rules, blocks, 4, 7, 9, pick).params.size() == 4);
    CHECK(calls == 0);
}
