// The strict readers of the state files morphogen writes (checked_json.hpp):
// the first defect throws std::invalid_argument naming the path; no default.
// The config reader (config_reader.hpp): every issue collected, defaults filled in.
#include "core/base/checked_json.hpp"
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <stdexcept>

using namespace morphogen;
using nlohmann::json;

TEST_CASE("checked json: members, counts and finite numbers, or the path and the defect", "[base][json]") {
    const json object = json::parse(R"({"births": 12, "x": 1.5, "neg": -1, "text": "a"})");
    CHECK(checked_json::member(object, "births", "ga").get<int>() == 12);
    CHECK_THROWS_WITH(checked_json::member(object, "absent", "ga"), Catch::StartsWith("ga"));
    CHECK_THROWS_AS(checked_json::member(json::array(), "births", "ga"), std::invalid_argument);
    CHECK(checked_json::read_u64(object["births"], "ga.births") == 12);
    CHECK_THROWS_WITH(checked_json::read_u64(object["neg"], "ga.neg"), Catch::StartsWith("ga.neg"));
    CHECK_THROWS_AS(checked_json::read_u64(object["x"], "ga.x"), std::invalid_argument);
    CHECK(checked_json::read_finite(object["x"], "ga.x") == 1.5);
    CHECK(checked_json::read_finite(object["births"], "ga.births") == 12.0);
    CHECK_THROWS_WITH(checked_json::read_finite(object["text"], "ga.text"), Catch::StartsWith("ga.text"));
    CHECK_THROWS_AS(checked_json::read_finite(json(std::numeric_limits<double>::infinity()), "inf"),
                    std::invalid_argument);
}

TEST_CASE("config reader: every issue collected with its key path, defaults resolved", "[base][config]") {
    const json object = json::parse(R"({"rate": 2.5, "count": "many", "name": "x", "rats": 1})");
    ConfigIssues issues;
    ObjectReader reader(&object, "growth", issues);
    CHECK(reader.number("rate", 0.1, 0.0, 1.0) == 0.1);       // out of range: an issue, the default used
    CHECK(reader.integer("count", 3, 1, 10) == 3);            // not an integer: an issue
    CHECK(reader.string("name", "y") == "x");
    CHECK(reader.boolean("ground", true));                    // absent: the default, resolved
    reader.finish();                                          // "rats": unknown, "rate" suggested
    REQUIRE(issues.list().size() == 3);
    CHECK(issues.list()[0].path == "growth.rate");
    CHECK(issues.list()[1].path == "growth.count");
    CHECK(issues.list()[2].path == "growth.rats");
    CHECK(issues.list()[2].message.find("rate") != std::string::npos);
    CHECK(reader.resolved()["ground"] == true);
    CHECK(reader.resolved()["name"] == "x");
    CHECK_THROWS_AS(issues.throw_if_any("c.json"), ConfigError);
    CHECK(issues.format("c.json").find("c.json: growth.count: ") != std::string::npos);
    CHECK(edit_distance("rats", "rate") == 1);
    CHECK(nearest("rats", {"rate", "ground"}) == "rate");
    CHECK_FALSE(nearest("zzzzzz", {"rate"}).has_value());
}
