#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "core/growth/growth_params.hpp"
#include "tests/support/config_issues.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using morphogen::testing::has_issue;
using nlohmann::json;

namespace {
ConfigIssues read_growth(const json& section, GrowthParams* out = nullptr) {
    ConfigIssues issues;
    ObjectReader reader(&section, "growth", issues);
    GrowthParams p = read_growth_params(reader);
    if (out) *out = p;
    return issues;
}
}  // namespace

TEST_CASE("defaults fill an empty section and are recorded", "[config]") {
    ConfigIssues issues;
    ObjectReader reader(nullptr, "growth", issues);
    const GrowthParams p = read_growth_params(reader);
    CHECK(issues.empty());
    CHECK(p.steps == 200);
    CHECK(reader.resolved()["split_area"] == 0.75);
    CHECK(reader.resolved()["seed_mesh"] == "icosahedron");
    CHECK(reader.resolved()["collisions"] == "allow");
    CHECK(reader.resolved()["mode"] == "paper");
    // every key but turn_rate, which the paper's mode does not use
    CHECK(reader.resolved().size() == 14);
    CHECK_FALSE(reader.resolved().contains("turn_rate"));
}

TEST_CASE("growth.collisions is allow or prevent", "[config]") {
    GrowthParams p;
    CHECK(read_growth(json::parse(R"({"collisions": "prevent"})"), &p).empty());
    CHECK(p.collisions == Collisions::prevent);
    // Either value is recorded, the default too.
    ConfigIssues issues;
    ObjectReader reader(nullptr, "growth", issues);
    CHECK(read_growth_params(reader).collisions == Collisions::allow);
    CHECK(reader.resolved()["collisions"] == "allow");
    const json section = json::parse(R"({"collisions": "prevent"})");
    ObjectReader prevent(&section, "growth", issues);
    read_growth_params(prevent);
    CHECK(prevent.resolved()["collisions"] == "prevent");
    CHECK(has_issue(read_growth(json::parse(R"({"collisions": "forbid"})")), "growth.collisions", "forbid"));
}

TEST_CASE("every problem is reported at once with its key path", "[config]") {
    const ConfigIssues issues = read_growth(
        json::parse(R"({"stpes": 10, "speed": "fast", "split_area": -1, "max_vertices": 2.5,
                        "flip_every": 0, "ground": 1, "seed_radius": 0})"));
    CHECK(issues.list().size() == 7);
    CHECK(has_issue(issues, "growth.stpes", "did you mean \"steps\""));
    CHECK(has_issue(issues, "growth.speed", "expected a number, got string \"fast\""));
    CHECK(has_issue(issues, "growth.split_area", "-1 is out of range"));
    CHECK(has_issue(issues, "growth.max_vertices", "expected an integer"));
    CHECK(has_issue(issues, "growth.flip_every", "0 is out of range [1,"));
    CHECK(has_issue(issues, "growth.ground", "expected true or false"));
    CHECK(has_issue(issues, "growth.seed_radius", "out of range"));
    CHECK_THROWS_WITH(issues.throw_if_any("x.json"), Catch::Contains("x.json: growth.speed:"));
}

TEST_CASE("values are read exactly", "[config]") {
    GrowthParams p;
    const ConfigIssues issues =
        read_growth(json::parse(R"({"steps": 7, "speed": 0.1, "ground": false, "seed_mesh": "octahedron"})"), &p);
    CHECK(issues.empty());
    CHECK(p.steps == 7);
    CHECK(p.speed == 0.1);
    CHECK_FALSE(p.ground);
    CHECK(p.seed_mesh == "octahedron");
}

TEST_CASE("network section: lists and their items", "[config]") {
    ConfigIssues issues;
    const json section = json::parse(R"({"outputs": 2, "hidden": [30, -1, "x"]})");
    ObjectReader reader(&section, "network", issues);
    read_network_params(reader);
    CHECK(has_issue(issues, "network.outputs", "out of range [3,"));
    CHECK(has_issue(issues, "network.hidden[1]", "out of range"));
    CHECK(has_issue(issues, "network.hidden[2]", "expected an integer"));
    ConfigIssues ok;
    const json empty_hidden = json::parse(R"({"hidden": []})");
    ObjectReader r2(&empty_hidden, "network", ok);
    CHECK(read_network_params(r2).layers() == std::vector<int>{45, 15});
}

TEST_CASE("invalid JSON is reported with line and column", "[config]") {
    CHECK_THROWS_WITH(parse_json_text("{\n  \"a\": 1,\n  \"b\" 2\n}", "c.json"),
                      Catch::Contains("c.json") && Catch::Contains("line 3, column"));
}

TEST_CASE("nearest-key suggestions", "[config]") {
    CHECK(edit_distance("kitten", "sitting") == 3);
    CHECK(nearest("split_are", {"steps", "split_area"}) == std::optional<std::string>("split_area"));
    CHECK_FALSE(nearest("zzzzzzzz", {"steps", "speed"}).has_value());
}

TEST_CASE("integers written in float form are exact up to 2^53 - 1", "[config]") {
    const json section = json::parse(R"({"a": 9e15, "b": 9007199254740991.0, "c": 3.0, "d": 9007199254740992.0,
                                         "e": 1e16, "f": 2.5, "g": -9e15})");
    ConfigIssues issues;
    ObjectReader reader(&section, "run", issues);
    const long long big = 9007199254740991LL;
    CHECK(reader.integer("a", 0, 0, big) == 9'000'000'000'000'000LL);
    CHECK(reader.integer("b", 0, 0, big) == big);
    CHECK(reader.integer("c", 0, 0, 10) == 3);
    CHECK(reader.integer("d", 1, 0, big + 1) == 1);  // 2^53: 2^53 + 1 reads the same, so it may not be what was meant
    CHECK(reader.integer("e", 1, 0, big) == 1);     // beyond the range anyway
    CHECK(reader.integer("f", 1, 0, big) == 1);
    CHECK(reader.integer("g", 0, -big, big) == -9'000'000'000'000'000LL);
    CHECK(issues.list().size() == 3);
    CHECK(has_issue(issues, "run.d", "plain integer"));
    CHECK(has_issue(issues, "run.e", "out of range"));
    CHECK(has_issue(issues, "run.f", "expected an integer"));
    CHECK(reader.resolved()["a"] == 9'000'000'000'000'000LL);
    // Lists of integers read their items the same way.
    const json network = json::parse(R"({"hidden": [30.0, 2e1], "outputs": 4.0})");
    ConfigIssues none;
    ObjectReader net(&network, "network", none);
    CHECK(read_network_params(net).layers() == std::vector<int>{12, 30, 20, 4});
    CHECK(none.empty());
    CHECK(net.resolved()["hidden"] == json::parse("[30, 20]"));
    const json bad = json::parse(R"({"hidden": [1.5, 1e300, 18446744073709551615]})");
    ConfigIssues three;
    ObjectReader bad_reader(&bad, "network", three);
    (void)read_network_params(bad_reader);
    CHECK(has_issue(three, "network.hidden[0]", "expected an integer"));
    CHECK(has_issue(three, "network.hidden[1]", "out of range"));
    CHECK(has_issue(three, "network.hidden[2]", "out of range"));
}

TEST_CASE("keys and strings that would break the line are shown escaped", "[config]") {
    const json section = json::parse(R"({"ste\nps": 1, "seed_mesh": "x"})");
    ConfigIssues issues;
    ObjectReader reader(&section, "growth", issues);
    (void)read_growth_params(reader);
    REQUIRE(issues.list().size() == 1);
    CHECK(issues.list()[0].path == "growth.\"ste\\nps\"");
    CHECK(issues.format("c.json").find('\n') == std::string::npos);
}
