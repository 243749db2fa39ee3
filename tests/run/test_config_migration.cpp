// Config format versions (run/config/config_migration.hpp): the reader records
// format_version and refuses a later one; a format-1 config (morphogen 0.1.0's
// config.json) is migrated with the defaults 0.1.0 left out written out.
#include "core/base/errors.hpp"
#include "run/config/config_migration.hpp"
#include "run/config/experiment_config.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using nlohmann::json;

namespace {
const std::filesystem::path fixtures = std::filesystem::path(MORPHOGEN_SOURCE_DIR) / "tests/app/fixtures/release-0.1.0";

json fixture_config(const std::string& run) {
    return json::parse(morphogen::testing::read_text(fixtures / run / "run" / "config.json"));
}

std::string errors_of(const json& document) {
    try {
        read_experiment_config(document, "c.json");
        return "";
    } catch (const ConfigError& e) {
        return e.what();
    }
}
}  // namespace

TEST_CASE("the resolved config records format_version; a config may leave it out or give this build's",
          "[run][config][migration]") {
    const json resolved = read_experiment_config(json::object(), "{}").resolved;
    CHECK(resolved[config_format_key] == config_format_version);
    CHECK(read_experiment_config(resolved, "again").resolved == resolved);
    CHECK(errors_of(json{{config_format_key, config_format_version}}) == "");
}

TEST_CASE("a later format_version is refused, naming the newer morphogen; a wrong one names this build's",
          "[run][config][migration]") {
    CHECK_THAT(errors_of(json{{config_format_key, config_format_version + 1}}),
               Catch::Contains("c.json: format_version: format " + std::to_string(config_format_version + 1) +
                               " was written by a newer morphogen"));
    for (const json& wrong : {json(1), json("2"), json(nullptr), json(0.5)})
        CHECK_THAT(errors_of(json{{config_format_key, wrong}}),
                   Catch::Contains("format_version: expected " + std::to_string(config_format_version)));
}

TEST_CASE("a format-1 config: format_version and the defaults 0.1.0 left out are written out",
          "[run][config][migration]") {
    const json v1 = fixture_config("ga");
    REQUIRE_FALSE(v1.contains(config_format_key));
    const json migrated = migrate_config(v1);
    CHECK(migrated[config_format_key] == config_format_version);
    CHECK(migrated["growth"]["collisions"] == "allow");
    CHECK(migrated["growth"]["mode"] == "paper");
    CHECK(migrated["evolution"]["algorithm"] == "steady_state");
    CHECK_FALSE(migrated.contains("emitters"));
    CHECK(holds_all_of(migrated, v1));
    // Exactly what this build resolves: nothing else was left out.
    CHECK(read_experiment_config(migrated, "m").resolved == migrated);
    // Migrating again changes nothing.
    CHECK(migrate_config(migrated) == migrated);
}

TEST_CASE("a format-1 MAP-Elites config without emitters gets 0.1.0's gaussian emitter",
          "[run][config][migration][map_elites]") {
    const json v1 = fixture_config("map_elites");
    REQUIRE_FALSE(v1.contains("emitters"));
    const json migrated = migrate_config(v1);
    CHECK(migrated["emitters"] == json::parse(R"([{"kind": "gaussian", "selection": "uniform", "share": 1.0}])"));
    const ExperimentConfig config = read_experiment_config(migrated, "m");
    REQUIRE(config.qd.emitters.size() == 1);
    CHECK(config.qd.emitters[0].emitter->kind() == "gaussian");
    CHECK(config.qd.emitters[0].emitter->selection() == ParentSelection::uniform);
    CHECK(holds_all_of(config.resolved, migrated));
}

TEST_CASE("format 1: a batch schedule, CMA covariance and a tree's trunk_power are written out where left out",
          "[run][config][migration]") {
    const json v1 = json::parse(R"({
        "evolution": {"algorithm": "map_elites", "batch": 8},
        "emitters": [{"kind": "cma_me"}, {"kind": "cma_mae", "covariance": "full"}, {"kind": "iso_line"}],
        "fitness": {"type": "sum", "terms": [{"type": "tree"}, {"type": "tree", "trunk_power": 3},
                                             {"type": "sum", "terms": [{"type": "tree"}]}]}})");
    const json m = migrate_config(v1);
    CHECK(m["evolution"]["schedule"] == "batch");
    CHECK(m["emitters"][0]["covariance"] == "diagonal");
    CHECK(m["emitters"][1]["covariance"] == "full");
    CHECK_FALSE(m["emitters"][2].contains("covariance"));
    CHECK(m["fitness"]["terms"][0]["trunk_power"] == 1.0);
    CHECK(m["fitness"]["terms"][1]["trunk_power"] == 3);
    CHECK(m["fitness"]["terms"][2]["terms"][0]["trunk_power"] == 1.0);
    CHECK_FALSE(m["fitness"].contains("trunk_power"));
    // A pipeline config (no batch) keeps the reader's default schedule.
    CHECK_FALSE(migrate_config(json{{"evolution", {{"lag", 4}}}})["evolution"].contains("schedule"));
}

TEST_CASE("a versioned config or a non-object is returned as it is", "[run][config][migration]") {
    const json later{{config_format_key, config_format_version + 1}, {"growth", json::object()}};
    CHECK(migrate_config(later) == later);
    CHECK(migrate_config(json::array()) == json::array());
    CHECK(migrate_config(json("text")) == json("text"));
    // Sections of the wrong type are left for the reader to report.
    const json odd = migrate_config(json{{"growth", 3}, {"evolution", "x"}, {"fitness", json::array()}});
    CHECK(odd["growth"] == 3);
    CHECK(odd["evolution"] == "x");
}

TEST_CASE("holds_all_of: every key of the part, with its value, at any depth", "[run][config][migration]") {
    const json whole = json::parse(R"({"a": 1, "b": {"c": [1, {"d": 2, "e": 3}], "f": "g"}})");
    CHECK(holds_all_of(whole, whole));
    CHECK(holds_all_of(whole, json::object()));
    CHECK(holds_all_of(whole, json::parse(R"({"b": {"c": [1, {"e": 3}]}})")));
    CHECK_FALSE(holds_all_of(whole, json::parse(R"({"b": {"c": [1, {"e": 4}]}})")));
    CHECK_FALSE(holds_all_of(whole, json::parse(R"({"b": {"c": [1]}})")));  // arrays of the same length
    CHECK_FALSE(holds_all_of(whole, json::parse(R"({"x": 1})")));
    CHECK_FALSE(holds_all_of(whole, json::parse(R"({"a": {"x": 1}})")));
    CHECK_FALSE(holds_all_of(json(1), json::object()));
}

TEST_CASE("format 2 as first written: a branching config's signal switches left out when off are read as off",
          "[app][config][migration]") {
    const json resolved =
        read_experiment_config(json::parse(R"({"growth": {"mode": "branching"}})"), "c").resolved;
    REQUIRE(resolved["growth"]["exposure"] == false);
    REQUIRE(resolved["growth"]["signal_diffusion"] == 0);
    json old = resolved;
    old["growth"].erase("exposure");
    old["growth"].erase("signal_diffusion");
    CHECK(migrate_config(old) == resolved);
    CHECK(migrate_config(resolved) == resolved);
    // The paper's mode has no signals; a switch that is on is kept.
    const json paper = read_experiment_config(json::object(), "c").resolved;
    CHECK(migrate_config(paper) == paper);
    json on = old;
    on["growth"]["exposure"] = true;
    CHECK(migrate_config(on)["growth"]["exposure"] == true);
}
