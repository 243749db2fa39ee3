// The batch step with a remote evaluator (batch.hpp: BatchEvaluator, what
// cluster/ implements over MPI): the same states and outcomes as the local
// OpenMP path, whatever order the evaluator scores genomes in.
#include "evolution/ga_state_json.hpp"
#include "evolution/map_elites.hpp"
#include "evolution/steady_state.hpp"
#include "tests/evolution/toy_problems.hpp"

#include <catch2/catch.hpp>

#include <cstring>

using namespace morphogen;
using morphogen::test::DescribedSphereProblem;
using morphogen::test::SphereProblem;

namespace {
// Scores the genomes last to first, as a far-away process would: only the genome counts.
class ReversedEvaluator : public BatchEvaluator {
public:
    explicit ReversedEvaluator(const Problem& problem) : problem_(problem) {}
    std::vector<Evaluation> evaluate(const std::vector<std::vector<double>>& genomes) override {
        std::vector<Evaluation> out(genomes.size());
        for (std::size_t i = genomes.size(); i-- > 0;) out[i] = evaluate_safely(problem_, genomes[i], 0);
        ++batches;
        return out;
    }
    std::string description() const override { return "reversed"; }
    int batches = 0;

private:
    const Problem& problem_;
};

// Returns one evaluation too few.
class ShortEvaluator : public BatchEvaluator {
public:
    std::vector<Evaluation> evaluate(const std::vector<std::vector<double>>& genomes) override {
        return std::vector<Evaluation>(genomes.size() - 1);
    }
    std::string description() const override { return "short"; }
};

GaParams ga_params() {
    GaParams p;
    p.population = 20;
    p.batch = 6;
    p.mutation_rate = 0.2;
    return p;
}
}  // namespace

TEST_CASE("a GA run scored by a remote evaluator equals the local run", "[evolution][batch][determinism]") {
    SphereProblem problem(12, 3, /*faulty=*/true);  // exceptions and NaN scores too
    SteadyStateGA local(ga_params(), 42, problem);
    SteadyStateGA remote(ga_params(), 42, problem);
    ReversedEvaluator evaluator(problem);
    while (local.state().births < 300) {
        const BatchOutcome a = local.step(2);
        const BatchOutcome b = remote.step(2, &evaluator);
        CHECK(a.errors == b.errors);
        CHECK(a.inserted == b.inserted);
    }
    CHECK(evaluator.batches > 40);
    CHECK(ga_state_to_json(local.state()).dump() == ga_state_to_json(remote.state()).dump());
}

TEST_CASE("a MAP-Elites run scored by a remote evaluator equals the local run", "[evolution][batch][determinism]") {
    DescribedSphereProblem problem(6, 2, /*faulty=*/true);
    MapElitesParams params;
    params.population = 12;
    params.batch = 5;
    params.mutation_rate = 0.2;
    const auto archive = [] { return Archive::grid({{"a", -2, 2, 5}, {"b", -2, 2, 5}}); };
    MapElites local(params, 7, problem, MapElitesState{0, archive(), {}, 0, 0});
    MapElites remote(params, 7, problem, MapElitesState{0, archive(), {}, 0, 0});
    ReversedEvaluator evaluator(problem);
    while (local.state().births < 200) {
        const EliteBatchOutcome a = local.step(2);
        const EliteBatchOutcome b = remote.step(1, &evaluator);
        REQUIRE(a.children.size() == b.children.size());
        for (std::size_t i = 0; i < a.children.size(); ++i) {
            CHECK(a.children[i].params == b.children[i].params);
            CHECK(std::memcmp(&a.children[i].fitness, &b.children[i].fitness, sizeof(double)) == 0);
            CHECK(a.children[i].descriptors == b.children[i].descriptors);
            CHECK(a.cells[i] == b.cells[i]);
            CHECK(a.placements[i] == b.placements[i]);
        }
        CHECK(a.errors == b.errors);
        CHECK(a.generation_new_cells == b.generation_new_cells);
    }
    CHECK(local.state().archive.elites().size() == remote.state().archive.elites().size());
}

TEST_CASE("an evaluator that loses genomes is a failure, not a wrong run", "[evolution][batch]") {
    SphereProblem problem(12, 3);
    SteadyStateGA ga(ga_params(), 42, problem);
    ShortEvaluator evaluator;
    CHECK_THROWS_AS(ga.step(1, &evaluator), std::logic_error);
    CHECK(ga.state().births == 0);  // nothing was inserted
}
