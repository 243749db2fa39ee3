// A fitness type written by the recipe of docs/writing-a-fitness.md and
// defined only here: registered, read from a config, and costed by the
// resource estimate (run/limits/resource_estimate.hpp) by what it states,
// with no file of the product knowing its name.
#include "fitness/cost.hpp"
#include "fitness/fitness.hpp"
#include "run/config/experiment_config.hpp"
#include "run/limits/resource_estimate.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>

using namespace morphogen;

namespace {

// Scores a mesh by its vertices times `probes`; states a cost that no
// built-in type has, so the estimate can only have it from the type itself.
class ProbesFunction final : public FitnessFunction {
public:
    explicit ProbesFunction(double probes) : probes_(probes) {}
    std::string type() const override { return "test_probes"; }
    double evaluate(MeshView mesh) const override { return probes_ * static_cast<double>(mesh.positions.size()); }
    void add_cost(FitnessCost& cost, const CostScope& scope) const override {
        cost.need_bytes(probes_ * scope.faces * 1000);
        cost.work.push_back({"probes of every face (" + scope.path + ")", {scope.path + ".probes"},
                             probes_ * scope.faces * 1e-3});
        cost.caps.push_back({"probes per face (" + scope.path + ")", {scope.path + ".probes"}, probes_, 100});
    }

private:
    double probes_;
};

std::unique_ptr<FitnessFunction> read_probes(ObjectReader& reader) {
    return std::make_unique<ProbesFunction>(reader.number("probes", 1.0, 0.0, 1e9));
}

void register_probes_once() {
    static const bool registered = [] {
        register_fitness_type({"test_probes", read_probes});
        return true;
    }();
    (void)registered;
}

ResourceEstimate probes_estimate(const std::string& fitness, const Workload& workload) {
    const ExperimentConfig config =
        read_experiment_config(nlohmann::json::parse(R"({"fitness": )" + fitness + "}"), "test");
    return estimate_resources(config, seed_extent(make_seed(config.growth)), workload);
}

const EstimatePart* probes_part(const std::vector<EstimatePart>& parts, const std::string& what) {
    const auto it = std::find_if(parts.begin(), parts.end(), [&](const EstimatePart& p) { return p.what == what; });
    return it == parts.end() ? nullptr : &*it;
}

}  // namespace

TEST_CASE("a fitness type registered outside the product is costed by what it states", "[fitness][resource]") {
    register_probes_once();
    Workload workload;
    workload.threads = 2;
    const ResourceEstimate e = probes_estimate(R"({"type": "test_probes", "probes": 3})", workload);
    const double faces = 2 * e.max_vertices - 4;
    REQUIRE(faces > 0);

    const EstimatePart* work = probes_part(e.work, "probes of every face (fitness)");
    REQUIRE(work);
    CHECK(work->amount == Approx(3 * faces * 1e-3));
    CHECK(work->keys == std::vector<std::string>{"fitness.probes"});
    // Nothing else is charged for scoring: no guess from the type's name.
    CHECK(e.work.size() == 2);  // growth, and the probes
    const EstimatePart* memory = probes_part(e.memory, "2 fitness evaluation(s) of up to " + group_digits(faces) + " faces");
    REQUIRE(memory);
    CHECK(memory->amount == Approx(2 * 3 * faces * 1000));
    REQUIRE(e.caps.size() == 1);
    CHECK(e.caps[0].needed == 3);
    CHECK(e.caps[0].cap == 100);
}

TEST_CASE("a registered fitness type's cost and caps are blamed on its own keys, in a sum too", "[fitness][resource]") {
    register_probes_once();
    const ResourceEstimate e =
        probes_estimate(R"({"type": "sum", "terms": [{"type": "height"}, {"type": "test_probes", "probes": 500}]})", {});
    REQUIRE(probes_part(e.work, "probes of every face (fitness.terms[1])"));
    CHECK(probes_part(e.work, "height of the mesh"));
    ResourceLimits limits;
    limits.max_memory_bytes = 1e15;
    limits.max_eval_seconds = 1e9;
    const std::vector<ConfigIssue> issues = resource_issues(e, limits);
    REQUIRE(issues.size() == 1);  // the cap: 500 probes, more than 100
    CHECK(issues[0].path == "fitness.terms[1].probes");
    CHECK(issues[0].message.find("probes per face (fitness.terms[1]): up to 500, more than the 100") !=
          std::string::npos);

    // Its time over the limit names its key too.
    limits.max_eval_seconds = 1e-9;
    const ResourceEstimate slow = probes_estimate(R"({"type": "test_probes", "probes": 1e6})", {});
    bool blamed = false;
    for (const ConfigIssue& issue : resource_issues(slow, limits))
        blamed |= issue.message.find("one evaluation may take") != std::string::npos &&
                  issue.path.rfind("fitness.probes", 0) == 0;
    CHECK(blamed);
}

TEST_CASE("registering a fitness type refuses a taken or empty name and a missing reader", "[fitness][config]") {
    register_probes_once();
    CHECK_THROWS_AS(register_fitness_type({"canopy", read_probes}), std::invalid_argument);
    CHECK_THROWS_AS(register_fitness_type({"test_probes", read_probes}), std::invalid_argument);
    CHECK_THROWS_AS(register_fitness_type({"", read_probes}), std::invalid_argument);
    CHECK_THROWS_AS(register_fitness_type({"test_nothing", nullptr}), std::invalid_argument);
    const std::vector<std::string> names = fitness_type_names();
    CHECK(names.front() == "canopy");
    CHECK(names.back() == "test_probes");
}
