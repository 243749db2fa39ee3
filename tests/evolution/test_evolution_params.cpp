// The `evolution` config section read beside its struct
// (evolution/evolution_params.hpp): defaults, what is resolved, the schedule
// a section implies, and its problems with their key paths.
#include "core/base/config_reader.hpp"
#include "evolution/evolution_params.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using nlohmann::json;

namespace {
struct ReadParams {
    GaParams params;
    Algorithm algorithm = Algorithm::steady_state;
    json resolved;
    ConfigIssues issues;
};

ReadParams read_params(const json& section) {
    ReadParams out;
    out.algorithm = Algorithm::map_elites;  // so a default read is seen to set it
    ObjectReader reader(&section, "evolution", out.issues);
    out.params = read_evolution_params(reader, &out.algorithm);
    out.resolved = reader.resolved();
    return out;
}

std::string messages(const ConfigIssues& issues) { return issues.format("test"); }
}  // namespace

TEST_CASE("evolution: an empty section gives the documented defaults, every one resolved", "[evolution][config]") {
    const ReadParams r = read_params(json::object());
    CHECK(r.issues.empty());
    CHECK(r.algorithm == Algorithm::steady_state);
    const GaParams defaults;
    CHECK(r.params.population == defaults.population);
    CHECK(r.params.schedule == ScheduleKind::pipeline);
    CHECK(r.resolved == json::parse(R"({"algorithm": "steady_state", "population": 100, "tournament": 3,
        "crossover": 0.3, "mutation_rate": 0.05, "mutation_sigma": 0.3, "schedule": "pipeline", "lag": 64,
        "init_range": 2.0})"));
}

TEST_CASE("evolution: the values given are used and recorded", "[evolution][config]") {
    const ReadParams r = read_params(json::parse(R"({"algorithm": "map_elites", "population": 7, "tournament": 2,
        "crossover": 0.5, "mutation_rate": 0.1, "mutation_sigma": 0.2, "lag": 3, "init_range": 1.5})"));
    CHECK(r.issues.empty());
    CHECK(r.algorithm == Algorithm::map_elites);
    CHECK(r.params.population == 7);
    CHECK(r.params.tournament == 2);
    CHECK(r.params.crossover == 0.5);
    CHECK(r.params.mutation_rate == 0.1);
    CHECK(r.params.mutation_sigma == 0.2);
    CHECK(r.params.lag == 3);
    CHECK(r.params.init_range == 1.5);
    CHECK(r.resolved["algorithm"] == "map_elites");
    CHECK(r.resolved["lag"] == 3);
    // A null algorithm pointer is allowed.
    ConfigIssues issues;
    const json empty = json::object();
    ObjectReader reader(&empty, "evolution", issues);
    CHECK(read_evolution_params(reader).population == 100);
}

TEST_CASE("evolution: a section that sets batch keeps the batch schedule; only the schedule's size is resolved",
          "[evolution][config]") {
    const ReadParams batch = read_params(json{{"batch", 8}});
    CHECK(batch.issues.empty());
    CHECK(batch.params.schedule == ScheduleKind::batch);
    CHECK(batch.params.batch == 8);
    CHECK(batch.resolved["schedule"] == "batch");
    CHECK(batch.resolved["batch"] == 8);
    CHECK_FALSE(batch.resolved.contains("lag"));
    CHECK(birth_schedule(batch.params).width == 8);

    // Reading the resolved section again gives it back.
    CHECK(read_params(batch.resolved).resolved == batch.resolved);

    const ReadParams named = read_params(json{{"schedule", "batch"}});
    CHECK(named.params.batch == GaParams{}.batch);
    CHECK_FALSE(named.resolved.contains("lag"));
}

TEST_CASE("evolution: every problem with its key path", "[evolution][config]") {
    const ReadParams r = read_params(json::parse(R"({"population": 1, "tournamnet": 3, "algorithm": "map_elite",
        "schedule": "pipeline", "batch": 4})"));
    const std::string text = messages(r.issues);
    CHECK_THAT(text, Catch::Contains("evolution.population"));
    CHECK_THAT(text, Catch::Contains("evolution.tournamnet") && Catch::Contains("did you mean \"tournament\""));
    CHECK_THAT(text, Catch::Contains("evolution.algorithm") && Catch::Contains("did you mean \"map_elites\""));
    CHECK_THAT(text, Catch::Contains("evolution.batch: applies to schedule \"batch\" only"));
    CHECK_THAT(messages(read_params(json{{"batch", 4}, {"lag", 2}}).issues),
               Catch::Contains("evolution.lag: applies to schedule \"pipeline\" only"));
}
