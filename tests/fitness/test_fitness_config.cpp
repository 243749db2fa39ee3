// Reading fitness configs: the registry, defaults in resolved(), and
// ConfigIssues with their key paths.
#include "fitness/fitness.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using nlohmann::json;
using morphogen::test::make_box;

namespace {
struct Read {
    std::unique_ptr<Fitness> fitness;
    json resolved;
    ConfigIssues issues;
};

Read read(const json* section) {
    Read r;
    ObjectReader reader(section, "fitness", r.issues);
    r.fitness = read_fitness(reader);
    r.resolved = reader.resolved();
    return r;
}
Read read(const json& section) { return read(&section); }

bool has_issue(const ConfigIssues& issues, const std::string& path, const std::string& fragment) {
    for (const ConfigIssue& issue : issues.list())
        if (issue.path == path && issue.message.find(fragment) != std::string::npos) return true;
    return false;
}
}  // namespace

TEST_CASE("no fitness section means canopy at height 10, cell 0.1", "[fitness][config]") {
    const Read r = read(nullptr);
    REQUIRE(r.issues.empty());
    REQUIRE(r.fitness);
    CHECK(r.fitness->function().type() == "canopy");
    CHECK_FALSE(r.fitness->reject_self_intersecting());
    CHECK(r.resolved == json::parse(R"({"type": "canopy", "height": 10.0, "cell": 0.1,
                                        "reject_self_intersecting": false})"));
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 11});
    const FitnessOutcome outcome = r.fitness->evaluate(box.view());
    CHECK(outcome.valid);
    CHECK(outcome.score == 1.0);
    CHECK(r.fitness->canopy_params().height == 10.0);
}

TEST_CASE("a sum of weighted terms", "[fitness][config]") {
    const json section = json::parse(R"({"type": "sum", "reject_self_intersecting": true,
        "terms": [{"type": "canopy", "weight": 1, "height": 10.5}, {"type": "vertices", "weight": -0.001},
                  {"type": "height"}]})");
    const Read r = read(section);
    REQUIRE(r.issues.empty());
    REQUIRE(r.fitness);
    CHECK(r.fitness->function().type() == "sum");
    CHECK(r.fitness->reject_self_intersecting());
    CHECK(r.resolved["terms"][0] == json::parse(R"({"type": "canopy", "weight": 1.0, "height": 10.5, "cell": 0.1})"));
    CHECK(r.resolved["terms"][1] == json::parse(R"({"type": "vertices", "weight": -0.001})"));
    CHECK(r.resolved["terms"][2]["weight"] == 1.0);
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 11});
    CHECK(r.fitness->evaluate(box.view()).score == Approx(1.0 - 0.008 + 11.0));
    CHECK(r.fitness->canopy_params().height == 10.5);
    // The resolved section reads back to itself.
    const Read again = read(r.resolved);
    CHECK(again.issues.empty());
    CHECK(again.resolved == r.resolved);
}

TEST_CASE("every registered type reads with its defaults", "[fitness][config]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 11});
    for (const std::string& type : fitness_type_names()) {
        if (type == "sum") continue;
        INFO(type);
        const Read r = read(json{{"type", type}});
        REQUIRE(r.issues.empty());
        REQUIRE(r.fitness);
        CHECK(r.fitness->function().type() == type);
        CHECK(r.fitness->evaluate(box.view()).valid);
        CHECK(read(r.resolved).resolved == r.resolved);
    }
    const Read light = read(json{{"type", "light"}});
    CHECK(light.resolved == json::parse(R"({"type": "light", "elevations_deg": [90.0, 45.0],
        "azimuths_deg": [0.0, 90.0, 180.0, 270.0], "spacing": 0.1, "min_height": 0.0, "stand_spacing": 0.0,
        "reject_self_intersecting": false})"));
}

TEST_CASE("bad fitness configs give issues with their paths", "[fitness][config]") {
    SECTION("unknown type, with a suggestion, and no noise about its keys") {
        const Read r = read(json::parse(R"({"type": "canopi", "height": 3})"));
        CHECK_FALSE(r.fitness);
        CHECK(has_issue(r.issues, "fitness.type", "did you mean \"canopy\"?"));
        CHECK(r.issues.list().size() == 1);
    }
    SECTION("unknown key in a term") {
        const Read r = read(json::parse(R"({"type": "sum", "terms": [{"type": "canopy"},
                                             {"type": "vertices", "wieght": -0.001}]})"));
        CHECK_FALSE(r.fitness);
        REQUIRE(r.issues.list().size() == 1);
        CHECK(has_issue(r.issues, "fitness.terms[1].wieght", "unknown key"));
        CHECK(has_issue(r.issues, "fitness.terms[1].wieght", "did you mean \"weight\"?"));
        CHECK(r.issues.format("exp.json").find("exp.json: fitness.terms[1].wieght: unknown key") == 0);
    }
    SECTION("wrong types and ranges") {
        const Read r = read(json::parse(R"({"height": "ten", "cell": -0.1, "reject_self_intersecting": 1})"));
        CHECK_FALSE(r.fitness);
        CHECK(has_issue(r.issues, "fitness.height", "expected a number"));
        CHECK(has_issue(r.issues, "fitness.cell", "out of range"));
        CHECK(has_issue(r.issues, "fitness.reject_self_intersecting", "expected true or false"));
        CHECK(r.issues.list().size() == 3);
    }
    SECTION("zero cell, keys of another type, weight outside a sum") {
        const Read r = read(json::parse(R"({"type": "canopy", "cell": 0, "spacing": 1, "weight": 2})"));
        CHECK(has_issue(r.issues, "fitness.cell", "out of range"));
        CHECK(has_issue(r.issues, "fitness.spacing", "unknown key"));
        CHECK(has_issue(r.issues, "fitness.weight", "unknown key"));
    }
    SECTION("sum without terms, or with a bad term") {
        CHECK(has_issue(read(json{{"type", "sum"}}).issues, "fitness.terms", "non-empty list"));
        CHECK(has_issue(read(json::parse(R"({"type": "sum", "terms": []})")).issues, "fitness.terms", "non-empty"));
        const Read r = read(json::parse(R"({"type": "sum", "terms": [3, {"type": "area", "weight": "x"},
                                             {"type": "sum", "terms": [{"type": "nope"}]}]})"));
        CHECK(has_issue(r.issues, "fitness.terms[0]", "expected an object"));
        CHECK(has_issue(r.issues, "fitness.terms[1].weight", "expected a number"));
        CHECK(has_issue(r.issues, "fitness.terms[2].terms[0].type", "is not one of"));
    }
    SECTION("light keys") {
        const Read r = read(json::parse(R"({"type": "light", "elevations_deg": [0, 95], "spacing": 0,
                                             "azimuths_deg": "north"})"));
        CHECK(has_issue(r.issues, "fitness.elevations_deg[1]", "out of range"));
        CHECK(has_issue(r.issues, "fitness.spacing", "out of range"));
        CHECK(has_issue(r.issues, "fitness.azimuths_deg", "expected a list"));
        const Read zero = read(json::parse(R"({"type": "light", "elevations_deg": [0]})"));
        CHECK(has_issue(zero.issues, "fitness.elevations_deg[0]", "out of range"));
        CHECK(has_issue(read(json::parse(R"({"type": "light", "elevations_deg": []})")).issues,
                        "fitness.elevations_deg", "at least one"));
    }
    SECTION("not an object") {
        const Read r = read(json("canopy"));
        CHECK(has_issue(r.issues, "fitness", "expected an object"));
    }
}
