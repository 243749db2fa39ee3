// The birth pipeline (pipeline.hpp): the same run for any thread count and
// any order of results, the batch schedule equal to its loop, lag 1 equal to a
// plain sequential loop, and a stop at any birth resuming exactly.
#include "evolution/ga/ga_state_json.hpp"
#include "evolution/schedulers/map_elites.hpp"
#include "evolution/schedulers/map_elites_state_json.hpp"
#include "evolution/execution/pipeline.hpp"
#include "evolution/ga/steady_state.hpp"
#include "evolution/execution/thread_evaluator.hpp"
#include "evolution/execution/safe_evaluation.hpp"
#include "evolution/emitters/gaussian_emitter.hpp"
#include "tests/evolution/breeding.hpp"
#include "tests/evolution/search_fixtures.hpp"
#include "tests/evolution/toy_problems.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>

using namespace morphogen;
using namespace morphogen::test;
using morphogen::test::DescribedSphereProblem;
using morphogen::test::SphereProblem;

namespace {
// Holds every genome it is given and returns a random one of those it holds,
// as a cluster would: only the genome decides its evaluation.
class ShuffledEvaluator : public GenomeEvaluator {
public:
    ShuffledEvaluator(const Problem& problem, unsigned seed) : problem_(problem), random_(seed) {}
    void submit(std::uint64_t birth, std::span<const double> params, double) override {
        held_.emplace(birth, std::vector<double>(params.begin(), params.end()));
        most_held = std::max(most_held, held_.size());
    }
    std::optional<ScoredBirth> next(std::chrono::milliseconds) override {
        if (held_.empty()) return std::nullopt;
        auto it = held_.begin();
        std::advance(it, std::uniform_int_distribution<std::size_t>(0, held_.size() - 1)(random_));
        ScoredBirth out{it->first, evaluate_safely(problem_, it->second, 0)};
        held_.erase(it);
        return out;
    }
    void cancel() override { held_.clear(); }
    int capacity() const override { return 1; }
    std::string description() const override { return "shuffled"; }
    std::size_t most_held = 0;

private:
    const Problem& problem_;
    std::mt19937 random_;
    std::map<std::uint64_t, std::vector<double>> held_;
};

GaParams ga_params(ScheduleKind kind, int width) {
    GaParams p;
    p.population = 20;
    p.mutation_rate = 0.2;
    p.schedule = kind;
    (kind == ScheduleKind::batch ? p.batch : p.lag) = width;
    return p;
}

MapElitesParams me_params(int batch) {
    MapElitesParams p;
    p.population = 12;
    p.batch = batch;
    p.mutation_rate = 0.3;
    p.emitters = {{1.0, std::make_shared<GaussianEmitter>()}};
    return p;
}

MapElitesState me_state() {
    return MapElitesState{0, Archive::grid({{"x", -2, 3, 6}, {"y", -2, 3, 6}}), {}, 0, 0};
}


// A GA run of `births` births through the pipeline, as its state's JSON.
std::string ga_run(Problem& problem, const GaParams& params, GenomeEvaluator& evaluator, std::uint64_t births) {
    SteadyStateGA ga(params, 7, problem);
    BirthPipeline pipeline(birth_schedule(params), ga, evaluator);
    REQUIRE(pipeline.run(births, ignore, never));
    return ga_state_to_json(ga.state()).dump();
}

std::string me_run(Problem& problem, const MapElitesParams& params, const BirthSchedule& schedule,
                   GenomeEvaluator& evaluator, std::uint64_t births) {
    MapElites me(params, 7, problem, me_state());
    BirthPipeline pipeline(schedule, me, evaluator);
    REQUIRE(pipeline.run(births, ignore, never));
    return map_elites_state_to_json(me.state()).dump();
}
}  // namespace

TEST_CASE("the pipeline gives the same GA run for 1, 2 and 8 threads and any order of results",
          "[evolution][pipeline][determinism]") {
    SphereProblem problem(12, 3, /*faulty=*/true);
    const GaParams params = ga_params(ScheduleKind::pipeline, 9);
    ThreadEvaluator one(problem, 1);
    const std::string expected = ga_run(problem, params, one, 500);
    for (int threads : {2, 8}) {
        ThreadEvaluator pool(problem, threads);
        CHECK(ga_run(problem, params, pool, 500) == expected);
    }
    for (unsigned seed : {1u, 2u, 3u}) {
        ShuffledEvaluator shuffled(problem, seed);
        CHECK(ga_run(problem, params, shuffled, 500) == expected);
        CHECK(shuffled.most_held <= 20);  // generation 0 at once, then at most lag 9 in flight
    }
    // The lag changes the run; threads never do.
    ThreadEvaluator again(problem, 2);
    CHECK(ga_run(problem, ga_params(ScheduleKind::pipeline, 8), again, 500) != expected);
}

TEST_CASE("the pipeline keeps at most lag births in flight after generation 0", "[evolution][pipeline]") {
    SphereProblem problem(12, 3);
    GaParams params = ga_params(ScheduleKind::pipeline, 5);
    SteadyStateGA ga(params, 3, problem);
    ShuffledEvaluator shuffled(problem, 9);
    BirthPipeline pipeline(birth_schedule(params), ga, shuffled);
    REQUIRE(pipeline.run(20, ignore, never));
    shuffled.most_held = 0;
    REQUIRE(pipeline.run(300, ignore, never));
    CHECK(shuffled.most_held == 5);
}

namespace {
// The batch schedule written out: every birth of a batch conceived from the
// state before it, then each scored and inserted in birth order.
void batch_loop(Breeder& breeder, const Problem& problem, std::uint64_t population, std::uint64_t batch,
                std::uint64_t births) {
    while (breeder.births() < births) {
        const std::uint64_t first = breeder.births();
        const std::uint64_t count = std::min(batch, population - first % population);
        std::vector<Individual> children;
        for (std::uint64_t birth = first; birth < first + count; ++birth) children.push_back(breeder.conceive(birth));
        for (Individual& child : children) {
            std::string error;
            take_evaluation(child, error, evaluate_safely(problem, child.params, 0));
            breeder.insert(child, error);
        }
    }
}
}  // namespace

TEST_CASE("the batch schedule through the pipeline is the batch loop", "[evolution][pipeline][batch]") {
    SphereProblem problem(12, 3, true);
    const GaParams params = ga_params(ScheduleKind::batch, 6);
    SteadyStateGA looped(params, 7, problem);
    batch_loop(looped, problem, 20, 6, 400);
    ShuffledEvaluator shuffled(problem, 4);
    CHECK(ga_run(problem, params, shuffled, 400) == ga_state_to_json(looped.state()).dump());

    DescribedSphereProblem described(6, 2, true);
    MapElites me(me_params(5), 7, described, me_state());
    batch_loop(me, described, 12, 5, 300);
    ThreadEvaluator pool(described, 3);
    const std::string whole = me_run(described, me_params(5), {ScheduleKind::batch, 12, 5}, pool, 300);
    CHECK(whole == map_elites_state_to_json(me.state()).dump());
    // and a pipeline per batch (the tests' breed_batch) gives the same
    MapElites batched(me_params(5), 7, described, me_state());
    while (batched.births() < 300) test::breed_batch(batched, described, 12, 5, 2);
    CHECK(map_elites_state_to_json(batched.state()).dump() == whole);
}

TEST_CASE("the pipeline with lag 1 is a plain sequential loop", "[evolution][pipeline]") {
    SphereProblem problem(12, 3, true);
    const GaParams params = ga_params(ScheduleKind::pipeline, 1);
    SteadyStateGA loop(params, 7, problem);
    std::vector<Individual> generation0;
    for (std::uint64_t birth = 0; birth < 20; ++birth) generation0.push_back(loop.conceive(birth));
    auto insert = [&](Individual child) {
        std::string error;
        take_evaluation(child, error, evaluate_safely(problem, child.params, 0));
        loop.insert(child, error);
    };
    for (Individual& child : generation0) insert(std::move(child));
    for (std::uint64_t birth = 20; birth < 300; ++birth) insert(loop.conceive(birth));
    ThreadEvaluator pool(problem, 4);
    CHECK(ga_run(problem, params, pool, 300) == ga_state_to_json(loop.state()).dump());
}

TEST_CASE("the MAP-Elites pipeline is the same for any threads and order of results",
          "[evolution][pipeline][determinism]") {
    DescribedSphereProblem problem(6, 2, true);
    const BirthSchedule schedule{ScheduleKind::pipeline, 12, 7};
    ThreadEvaluator one(problem, 1);
    const std::string expected = me_run(problem, me_params(32), schedule, one, 400);
    ThreadEvaluator eight(problem, 8);
    CHECK(me_run(problem, me_params(32), schedule, eight, 400) == expected);
    ShuffledEvaluator shuffled(problem, 5);
    CHECK(me_run(problem, me_params(32), schedule, shuffled, 400) == expected);
}

TEST_CASE("a pipeline stopped at any birth continues exactly from its state and kept births",
          "[evolution][pipeline][resume]") {
    SphereProblem problem(12, 3, true);
    for (ScheduleKind kind : {ScheduleKind::pipeline, ScheduleKind::batch}) {
        const GaParams params = ga_params(kind, 7);
        ShuffledEvaluator whole(problem, 1);
        const std::string expected = ga_run(problem, params, whole, 300);
        for (std::uint64_t stop_at : {5u, 20u, 21u, 26u, 133u, 299u}) {
            GaState saved;
            std::vector<Individual> kept;
            {
                SteadyStateGA ga(params, 7, problem);
                ThreadEvaluator pool(problem, 3);
                BirthPipeline pipeline(birth_schedule(params), ga, pool);
                CHECK_FALSE(pipeline.run(300, ignore, [&] { return ga.births() >= stop_at; }));
                CHECK(ga.births() == stop_at);
                saved = ga.state();
                kept = pipeline.kept();
                const BirthSchedule schedule = birth_schedule(params);
                CHECK(kept.size() == schedule.kept_end(stop_at) - schedule.kept_begin(stop_at));
            }
            // The saved state through JSON, as a checkpoint stores it.
            GaState reread = ga_state_from_json(nlohmann::json::parse(ga_state_to_json(saved).dump()), params, 12);
            SteadyStateGA ga(params, 7, problem, std::move(reread));
            ShuffledEvaluator rest(problem, 2);
            BirthPipeline pipeline(birth_schedule(params), ga, rest, kept);
            REQUIRE(pipeline.run(300, ignore, never));
            CHECK(ga_state_to_json(ga.state()).dump() == expected);
        }
    }
}

TEST_CASE("the pipeline refuses an evaluator that returns a birth it was not given", "[evolution][pipeline]") {
    SphereProblem problem(12, 3);
    class Liar : public GenomeEvaluator {
    public:
        void submit(std::uint64_t, std::span<const double>, double) override {}
        std::optional<ScoredBirth> next(std::chrono::milliseconds) override { return ScoredBirth{1000, {}}; }
        void cancel() override {}
        int capacity() const override { return 1; }
        std::string description() const override { return "liar"; }
    } liar;
    const GaParams params = ga_params(ScheduleKind::pipeline, 4);
    SteadyStateGA ga(params, 7, problem);
    BirthPipeline pipeline(birth_schedule(params), ga, liar);
    CHECK_THROWS_AS(pipeline.run(100, ignore, never), std::logic_error);
}

namespace {
// The sphere, keeping 1 KB of "export files" for every child at least as fit as keep_from.
class KeepingProblem : public SphereProblem {
public:
    Evaluation evaluate_keeping(std::span<const double> params, int worker, double keep_from) const override {
        Evaluation e = evaluate(params, worker);
        if (e.score >= keep_from) e.kept.assign(1024, 'k');
        return e;
    }
};

// Scores the latest birth it holds first, so every other birth in flight
// waits for the earliest one: the most births ever wait at once.
class LatestFirstEvaluator : public GenomeEvaluator {
public:
    explicit LatestFirstEvaluator(const Problem& problem) : problem_(problem) {}
    void submit(std::uint64_t birth, std::span<const double> params, double keep_from) override {
        held_.emplace(birth, Job{std::vector<double>(params.begin(), params.end()), keep_from});
    }
    std::optional<ScoredBirth> next(std::chrono::milliseconds) override {
        if (held_.empty()) return std::nullopt;
        const auto it = std::prev(held_.end());
        ScoredBirth out{it->first, evaluate_safely(problem_, it->second.params, 0, it->second.keep_from)};
        held_.erase(it);
        return out;
    }
    void cancel() override { held_.clear(); }
    int capacity() const override { return 1; }
    std::string description() const override { return "latest first"; }

private:
    struct Job {
        std::vector<double> params;
        double keep_from;
    };
    const Problem& problem_;
    std::map<std::uint64_t, Job> held_;
};
}  // namespace

TEST_CASE("at most kMaxKeepingBirths births in flight keep export files", "[evolution][pipeline]") {
    KeepingProblem problem;
    const GaParams params = ga_params(ScheduleKind::pipeline, 60);
    SteadyStateGA ga(params, 5, problem);
    LatestFirstEvaluator evaluator(problem);
    BirthPipeline pipeline(birth_schedule(params), ga, evaluator);
    // Every birth could keep its files (the sphere's scores always reach the
    // floor of generation 0, -infinity), and all of generation 0 waits for
    // birth 0, which is scored last.
    std::vector<std::uint64_t> with_files;
    REQUIRE(pipeline.run(20, [&](const Individual& child, const std::string&, const Inserted&,
                                 const std::string& kept) { if (!kept.empty()) with_files.push_back(child.id); },
                         never));
    std::vector<std::uint64_t> first(kMaxKeepingBirths);
    std::iota(first.begin(), first.end(), 0);
    CHECK(with_files == first);  // the first births submitted hold the budget
    // Freed budget passes on: later births keep files again.
    with_files.clear();
    REQUIRE(pipeline.run(200, [&](const Individual& child, const std::string&, const Inserted&,
                                  const std::string& kept) { if (!kept.empty()) with_files.push_back(child.id); },
                         never));
    CHECK_FALSE(with_files.empty());
}
