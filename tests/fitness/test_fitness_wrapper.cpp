// The Fitness wrapper: finite scores or a clear failure, counting, the
// self-intersection rule and the guard for functions that are not thread-safe.
#include "fitness/fitness.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace morphogen;
using morphogen::test::make_box;
using morphogen::test::merge;

namespace {
class Constant final : public FitnessFunction {
public:
    explicit Constant(double value) : value_(value) {}
    std::string type() const override { return "constant"; }
    void add_cost(FitnessCost&, const CostScope&) const override {}  // costs nothing to speak of
    double evaluate(MeshView) const override { return value_; }

private:
    double value_;
};

class Throwing final : public FitnessFunction {
public:
    std::string type() const override { return "throwing"; }
    void add_cost(FitnessCost&, const CostScope&) const override {}  // costs nothing to speak of
    double evaluate(MeshView) const override { throw std::runtime_error("boom"); }
};

class ThrowingInt final : public FitnessFunction {
public:
    std::string type() const override { return "int"; }
    void add_cost(FitnessCost&, const CostScope&) const override {}  // costs nothing to speak of
    double evaluate(MeshView) const override { throw 42; }
};

// Records the most evaluations ever running at once.
class Overlap final : public FitnessFunction {
public:
    explicit Overlap(bool safe) : safe_(safe) {}
    std::string type() const override { return "overlap"; }
    void add_cost(FitnessCost&, const CostScope&) const override {}  // costs nothing to speak of
    bool thread_safe() const override { return safe_; }
    double evaluate(MeshView) const override {
        const int now = ++inside_;
        int seen = most_.load();
        while (now > seen && !most_.compare_exchange_weak(seen, now)) {
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        --inside_;
        return 1.0;
    }
    int most() const { return most_.load(); }

private:
    bool safe_;
    mutable std::atomic<int> inside_{0};
    mutable std::atomic<int> most_{0};
};

int run_concurrently(const Fitness& fitness, MeshView mesh) {
    std::atomic<int> valid{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 6; ++t)
        threads.emplace_back([&] {
            for (int i = 0; i < 10; ++i) valid += fitness.evaluate(mesh).valid;
        });
    for (auto& thread : threads) thread.join();
    return valid.load();
}
}  // namespace

TEST_CASE("non-finite scores are invalid, not a crash", "[fitness][wrapper]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 1});
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                       -std::numeric_limits<double>::infinity()}) {
        const Fitness fitness(std::make_unique<Constant>(bad), false);
        const FitnessOutcome outcome = fitness.evaluate(box.view());
        CHECK_FALSE(outcome.valid);
        CHECK(outcome.error.find("non-finite") != std::string::npos);
        CHECK(outcome.error.find("constant") != std::string::npos);
    }
    const Fitness fine(std::make_unique<Constant>(-3.5), false);
    const FitnessOutcome outcome = fine.evaluate(box.view());
    CHECK(outcome.valid);
    CHECK(outcome.score == -3.5);
    CHECK(outcome.error.empty());
}

TEST_CASE("throwing functions give invalid outcomes with the reason", "[fitness][wrapper]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 1});
    const Fitness throwing(std::make_unique<Throwing>(), false);
    const FitnessOutcome outcome = throwing.evaluate(box.view());
    CHECK_FALSE(outcome.valid);
    CHECK(outcome.error.find("boom") != std::string::npos);
    CHECK_FALSE(Fitness(std::make_unique<ThrowingInt>(), false).evaluate(box.view()).valid);
    CHECK_THROWS_AS(Fitness(nullptr, false), std::invalid_argument);
    // A malformed view is refused before the function sees it.
    MeshArrays broken = box;
    broken.faces.push_back({0, 1, 8});
    const Fitness constant(std::make_unique<Constant>(1.0), false);
    CHECK(constant.evaluate(broken.view()).error.find("refers to vertex 8") != std::string::npos);
    broken = box;
    broken.positions[3].x() = std::nan("");
    CHECK_FALSE(constant.evaluate(broken.view()).valid);
}

TEST_CASE("evaluations are counted, valid or not", "[fitness][wrapper]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 1});
    const Fitness fitness(std::make_unique<Throwing>(), false);
    for (int i = 0; i < 5; ++i) fitness.evaluate(box.view());
    CHECK(fitness.evaluations() == 5);
}

TEST_CASE("reject_self_intersecting makes self-intersecting meshes invalid", "[fitness][wrapper]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 11});
    const MeshArrays crossing = merge(box, make_box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
    ConfigIssues issues;
    const nlohmann::json section = {{"reject_self_intersecting", true}};
    ObjectReader reader(&section, "fitness", issues);
    const auto fitness = read_fitness(reader);
    REQUIRE(fitness);
    CHECK(fitness->evaluate(box.view()).valid);
    const FitnessOutcome outcome = fitness->evaluate(crossing.view());
    CHECK_FALSE(outcome.valid);
    CHECK(outcome.error.find("self-intersect") != std::string::npos);
    // Without the rule the same mesh scores.
    CHECK(Fitness(std::make_unique<Constant>(2.0), false).evaluate(crossing.view()).valid);
}

TEST_CASE("a function that is not thread-safe never runs concurrently", "[fitness][wrapper]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 1});
    auto unsafe = std::make_unique<Overlap>(false);
    const Overlap& unsafe_ref = *unsafe;
    const Fitness guarded(std::move(unsafe), false);
    CHECK(run_concurrently(guarded, box.view()) == 60);
    CHECK(unsafe_ref.most() == 1);
    CHECK(guarded.evaluations() == 60);
    // A thread-safe one is not serialised (the guard is what made the difference).
    auto safe = std::make_unique<Overlap>(true);
    const Overlap& safe_ref = *safe;
    const Fitness free(std::move(safe), false);
    CHECK(run_concurrently(free, box.view()) == 60);
    CHECK(safe_ref.most() > 1);
}

TEST_CASE("the shipped functions are thread-safe and agree across threads", "[fitness][wrapper]") {
    const MeshArrays mesh = morphogen::test::make_bumpy(11, 2);
    ConfigIssues issues;
    const nlohmann::json section = nlohmann::json::parse(
        R"({"type": "sum", "terms": [{"type": "canopy"}, {"type": "light", "spacing": 0.3},
            {"type": "self_intersecting"}, {"type": "footprint"}]})");
    ObjectReader reader(&section, "fitness", issues);
    const auto fitness = read_fitness(reader);
    REQUIRE(fitness);
    CHECK(fitness->function().thread_safe());
    const double expected = fitness->evaluate(mesh.view()).score;
    std::vector<double> scores(4);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] { scores[t] = fitness->evaluate(mesh.view()).score; });
    for (auto& thread : threads) thread.join();
    for (double s : scores) CHECK(s == expected);
}
