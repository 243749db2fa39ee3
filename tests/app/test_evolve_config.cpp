// The experiment config: every error at once with its path, nearest-key
// suggestions, invalid JSON with line and column, overrides, and
// configs/schema.json kept in step with the reader (validation of the
// shipped configs, defaults and ranges compared key by key).
#include "core/base/errors.hpp"
#include "fitness/descriptors.hpp"
#include "run/config/experiment_config.hpp"
#include "run/limits/resource_estimate.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include <cmath>
#include <functional>
#include <limits>

using namespace morphogen;
using namespace morphogen::test;
using nlohmann::json;

namespace {
const fs::path source_dir = MORPHOGEN_SOURCE_DIR;

json schema_document() { return json::parse(read_text(source_dir / "configs" / "schema.json")); }

// "" if `document` is valid under configs/schema.json, else the errors.
std::string schema_errors(const json& document) {
    static const json schema_json = schema_document();
    static const auto schema = [] {
        auto s = std::make_unique<valijson::Schema>();
        valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
        valijson::adapters::NlohmannJsonAdapter adapter(schema_json);
        parser.populateSchema(adapter, *s);
        return s;
    }();
    valijson::Validator validator;
    valijson::ValidationResults results;
    valijson::adapters::NlohmannJsonAdapter target(document);
    if (validator.validate(*schema, target, &results)) return "";
    std::string out;
    valijson::ValidationResults::Error error;
    while (results.popError(error)) {
        std::string context;
        for (const auto& c : error.context) context += c;
        out += context + ": " + error.description + "\n";
    }
    return out.empty() ? "invalid" : out;
}

std::string config_errors(const json& document) {
    try {
        read_experiment_config(document, "test.json");
        return "";
    } catch (const ConfigError& e) {
        return e.what();
    }
}

// Every fitness type with the smallest section that makes it valid.
std::vector<json> fitness_sections() {
    return {json{{"type", "canopy"}},
            json{{"type", "light"}},
            json{{"type", "tree"}},
            json{{"type", "plant"}},
            json{{"type", "height"}},
            json{{"type", "sum"}, {"terms", json::array({json{{"type", "canopy"}}, json{{"type", "light"}}})}}};
}

// Calls `visit(path, schema_of_key, resolved_value)` for every leaf key of a
// resolved config, following the schema (fitness terms through $ref).
void walk(const json& schema_root, const json& schema, const json& value, const std::string& path,
          const std::function<void(const std::string&, const json&, const json&)>& visit) {
    const json* s = &schema;
    if (s->contains("$ref")) s = &schema_root["definitions"][(*s)["$ref"].get<std::string>().substr(14)];
    if (value.is_object() && s->contains("properties")) {
        for (const auto& [key, item] : value.items()) {
            INFO(path + "." + key);
            REQUIRE((*s)["properties"].contains(key));
            walk(schema_root, (*s)["properties"][key], item, path.empty() ? key : path + "." + key, visit);
        }
        return;
    }
    if (value.is_array() && s->contains("items") && s->at("items").contains("$ref")) {
        for (std::size_t i = 0; i < value.size(); ++i)
            walk(schema_root, (*s)["items"], value[i], path + "[" + std::to_string(i) + "]", visit);
        return;
    }
    visit(path, *s, value);
}
}  // namespace

TEST_CASE("{} is valid and every default is filled in", "[app][config]") {
    const ExperimentConfig config = read_experiment_config(json::object(), "empty");
    CHECK(config.evolution.population == 100);
    CHECK(config.evolution.tournament == 3);
    CHECK(config.evolution.crossover == 0.3);
    CHECK(config.evolution.mutation_rate == 0.05);
    CHECK(config.evolution.mutation_sigma == 0.3);
    CHECK(config.evolution.batch == 32);
    CHECK(config.evolution.init_range == 2.0);
    CHECK(config.run.seed == 1);
    CHECK(config.run.generations == 100);
    CHECK(config.run.checkpoint_every == 1);
    CHECK(config.run.export_every == 1);
    CHECK(config.run.threads == 0);
    CHECK(config.run.name.empty());
    for (const char* section : {"network", "growth", "fitness", "evolution", "run"})
        CHECK(config.resolved.contains(section));
    // the resolved config reads back to itself
    CHECK(read_experiment_config(config.resolved, "resolved").resolved == config.resolved);
}

TEST_CASE("config errors are reported all at once and each with its path", "[app][config]") {
    const json document = json::parse(R"({
        "network": {"outputs": 2, "hiden": [3]},
        "growth": {"steps": "many"},
        "evolution": {"populaton": 10, "crossover": 1.5, "batch": 0, "tournament": 2.5},
        "run": {"seed": -1, "threads": 5000, "name": "a/b", "generatons": 3},
        "fitnes": {}
    })");
    const std::string errors = config_errors(document);
    for (const char* expected : {"test.json: network.outputs: 2 is out of range",
                                 "network.hiden: unknown key \"hiden\" (did you mean \"hidden\"?)",
                                 "growth.steps: expected an integer", "evolution.populaton: unknown key",
                                 "(did you mean \"population\"?)", "evolution.crossover: 1.5 is out of range [0, 1]",
                                 "evolution.batch: 0 is out of range", "evolution.tournament: expected an integer",
                                 "run.seed: -1 is out of range", "run.threads: 5000 is out of range",
                                 "run.name: \"a/b\" is not a usable directory name",
                                 "run.generatons: unknown key \"generatons\" (did you mean \"generations\"?)",
                                 "fitnes: unknown key \"fitnes\" (did you mean \"fitness\"?)"})
        CHECK_THAT(errors, Catch::Contains(expected));
    CHECK(std::count(errors.begin(), errors.end(), '\n') == 11);  // 12 issues, one line each
}

TEST_CASE("invalid JSON is reported with line and column", "[app][config]") {
    TempDir tmp("config-syntax");
    write_text(tmp.path / "broken.json", "{\n  \"run\": {\"seed\": 1,}\n}\n");
    CHECK_THROWS_WITH(load_experiment_config((tmp.path / "broken.json").string()),
                      Catch::Contains("broken.json: invalid JSON at line 2, column"));
}

TEST_CASE("command-line overrides are checked like keys and recorded", "[app][config]") {
    ConfigOverrides overrides;
    overrides.seed = 42;
    overrides.generations = 3;
    overrides.threads = 2;
    const auto config = read_experiment_config(json{{"run", {{"seed", 5}}}}, "x", overrides);
    CHECK(config.run.seed == 42);
    CHECK(config.resolved["run"]["generations"] == 3);
    CHECK(config.resolved["run"]["threads"] == 2);
    overrides.threads = -1;
    CHECK_THROWS_WITH(read_experiment_config(json::object(), "x", overrides), Catch::Contains("run.threads"));
    CHECK(run_name_from_path("some/dir/my run.v2.json") == "my_run.v2");
}

TEST_CASE("shipped configs and the default config are valid under schema.json", "[app][config][schema]") {
    for (const char* name : {"canopy.json", "quick.json", "map_elites.json", "tree.json", "tree_nslc.json"}) {
        INFO(name);
        const auto path = source_dir / "configs" / name;
        const json document = json::parse(read_text(path));
        CHECK(schema_errors(document) == "");
        const ExperimentConfig config = load_experiment_config(path.string());
        CHECK(schema_errors(config.resolved) == "");
    }
    CHECK(schema_errors(read_experiment_config(json::object(), "{}").resolved) == "");
    CHECK(schema_errors(json::object()) == "");
    for (const json& fitness : fitness_sections()) {
        INFO(fitness.dump());
        CHECK(schema_errors(read_experiment_config(json{{"fitness", fitness}}, "f").resolved) == "");
    }
    // and the schema rejects what the reader rejects
    for (const char* bad : {R"({"evolution": {"populaton": 3}})", R"({"run": {"seed": -1}})",
                            R"({"growth": {"steps": 1.5}})", R"({"fitness": {"type": "light", "height": 3}})",
                            R"({"fitness": {"type": "sum"}})", R"({"run": {"name": "a/b"}})", R"({"network": []})",
                            R"({"evolution": {"novelty_k": 3}})", R"({"evolution": {"algorithm": "nslc"}})"}) {
        INFO(bad);
        CHECK(schema_errors(json::parse(bad)) != "");
        CHECK(config_errors(json::parse(bad)) != "");
    }
}

TEST_CASE("schema.json defaults equal the reader's defaults", "[app][config][schema]") {
    const json schema = schema_document();
    std::size_t compared = 0;
    auto compare = [&](const std::string& path, const json& key_schema, const json& value) {
        INFO(path);
        REQUIRE(key_schema.contains("default"));
        REQUIRE(key_schema.contains("description"));
        CHECK(key_schema["default"] == value);
        ++compared;
    };
    walk(schema, schema, read_experiment_config(json::object(), "{}").resolved, "", compare);
    // The other fitness types: every key but the ones given (type, terms) has its default.
    auto compare_defaults = [&](const std::string& path, const json& key_schema, const json& value) {
        const std::string key = path.substr(path.rfind('.') + 1);
        if (key != "type" && key != "terms") compare(path, key_schema, value);
    };
    for (const json& fitness : fitness_sections())
        walk(schema, schema, read_experiment_config(json{{"fitness", fitness}}, "f").resolved, "", compare_defaults);
    // The branching mode's own key (turn_rate), resolved only in that mode.
    walk(schema, schema, read_experiment_config(json{{"growth", {{"mode", "branching"}}}}, "g").resolved, "",
         [&](const std::string& path, const json& key_schema, const json& value) {
             if (path != "growth.mode") compare(path, key_schema, value);
         });
    // run.export_glb, absent unless given: its keys' defaults.
    walk(schema, schema, read_experiment_config(json{{"run", {{"export_glb", json::object()}}}}, "r").resolved, "",
         [&](const std::string& path, const json& key_schema, const json& value) {
             if (path.rfind("run.export_glb.", 0) == 0) compare(path, key_schema, value);
         });
    // The contact rule's own key (contact_distance), resolved only with it.
    walk(schema, schema, read_experiment_config(json{{"growth", {{"collisions", "touch"}}}}, "c").resolved, "",
         [&](const std::string& path, const json& key_schema, const json& value) {
             if (path != "growth.collisions") compare(path, key_schema, value);
         });
    CHECK(compared > 40);
    // every section's default is {} (all of its keys default)
    for (const char* section : {"network", "growth", "fitness", "evolution", "run"})
        CHECK(schema["properties"][section]["default"] == json::object());
}

TEST_CASE("schema.json ranges equal the reader's ranges", "[app][config][schema]") {
    // For every numeric key: the bounds are accepted, just beyond them refused,
    // by both the schema and the reader.
    const json schema = schema_document();
    std::size_t probed = 0;
    auto probe = [&](const std::string& path, const json& key_schema, const json&) {
        if (key_schema.value("type", "") != "integer" && key_schema.value("type", "") != "number") return;
        // Build {"section": {..., "key": value}} (fitness keys of a type need that type).
        const std::string section = path.substr(0, path.find('.'));
        const std::string key = path.substr(path.find('.') + 1);
        if (key.find('.') != std::string::npos || key.find('[') != std::string::npos) return;
        auto document_with = [&](const json& value) {
            json document = json::object();
            document[section][key] = value;
            if (section == "fitness" && (key == "spacing" || key == "min_height" || key == "stand_spacing"))
                document[section]["type"] = "light";
            if (section == "fitness" && (key == "trunk_target" || key == "trunk_power" || key == "loops_target" ||
                                         key == "material_cost" || key == "root_height"))
                document[section]["type"] = "tree";
            if (section == "fitness" && (key == "half_saturation" || key == "moment_cost" || key == "shoot_radius" ||
                                         key == "shoot_half_light" || key == "volume_cost" || key == "leaf_size" ||
                                         key == "shoot_band_edges"))
                document[section]["type"] = "plant";
            if (section == "growth" && key == "turn_rate") document[section]["mode"] = "branching";
            if (section == "growth" && key == "signal_diffusion") {  // resolved (off) in the branching mode
                document[section]["mode"] = "branching";
                document["network"]["outputs"] = 8;  // the signal's channel
            }
            if (section == "growth" && key == "contact_distance") document[section]["collisions"] = "touch";
            return document;
        };
        const bool integer = key_schema["type"] == "integer";
        auto beyond = [&](double bound, double direction) {
            if (integer) return json(static_cast<long long>(bound) + static_cast<long long>(direction));
            return json(std::nextafter(bound, direction * std::numeric_limits<double>::infinity()));
        };
        INFO(path);
        for (const char* name : {"minimum", "maximum"}) {
            if (!key_schema.contains(name)) continue;
            const double bound = key_schema[name].get<double>();
            const double outward = std::string(name) == "minimum" ? -1.0 : 1.0;
            const json at = integer ? json(key_schema[name].get<long long>()) : json(bound);
            CHECK(config_errors(document_with(at)) == "");
            CHECK(schema_errors(document_with(at)) == "");
            CHECK_THAT(config_errors(document_with(beyond(bound, outward))), Catch::Contains(path));
            CHECK(schema_errors(document_with(beyond(bound, outward))) != "");
            ++probed;
        }
        if (key_schema.contains("exclusiveMinimum")) {
            const double bound = key_schema["exclusiveMinimum"].get<double>();
            CHECK_THAT(config_errors(document_with(bound)), Catch::Contains(path));
            CHECK(schema_errors(document_with(bound)) != "");
            CHECK(config_errors(document_with(beyond(bound, 1.0))) == "");
            CHECK(schema_errors(document_with(beyond(bound, 1.0))) == "");
            ++probed;
        }
        if (!key_schema.contains("maximum")) {  // unbounded above in both
            CHECK(config_errors(document_with(integer ? json(1LL << 40) : json(1e300))) == "");
        }
    };
    walk(schema, schema, read_experiment_config(json::object(), "{}").resolved, "", probe);
    walk(schema, schema, read_experiment_config(json{{"fitness", {{"type", "light"}}}}, "f").resolved, "", probe);
    walk(schema, schema,
         read_experiment_config(json{{"growth", {{"mode", "branching"}}}, {"fitness", {{"type", "tree"}}}}, "t").resolved,
         "", probe);
    walk(schema, schema, read_experiment_config(json{{"growth", {{"collisions", "touch"}}}}, "c").resolved, "", probe);
    CHECK(probed > 25);
}

TEST_CASE("map_elites configs: descriptors and archive are read, defaulted and checked", "[app][config][map_elites]") {
    const json document = json::parse(R"({
        "evolution": {"algorithm": "map_elites"},
        "descriptors": [{"measure": "height", "min": 0, "max": 20, "bins": 20},
                        {"measure": "footprint", "min": 0, "max": 400}]
    })");
    const ExperimentConfig config = read_experiment_config(document, "me.json");
    CHECK(config.algorithm == Algorithm::map_elites);
    REQUIRE(config.qd.descriptors.size() == 2);
    CHECK(config.qd.descriptors[0].name == "height");
    CHECK(config.qd.descriptors[0].bins == 20);
    CHECK(config.qd.descriptors[1].max == 400.0);
    CHECK(config.qd.descriptors[1].bins == 10);  // default
    CHECK(config.qd.archive == ArchiveKind::grid);
    CHECK(config.qd.cells() == 200);
    CHECK(config.qd.qd_offset == 0.0);
    CHECK(config.resolved["evolution"]["algorithm"] == "map_elites");
    CHECK(config.resolved["descriptors"][1]["bins"] == 10);
    CHECK(config.resolved["archive"] == json{{"type", "grid"}, {"qd_offset", 0.0}});
    CHECK(schema_errors(document) == "");
    CHECK(schema_errors(config.resolved) == "");
    CHECK(read_experiment_config(config.resolved, "resolved").resolved == config.resolved);

    const json cvt = json::parse(R"({"evolution": {"algorithm": "map_elites"},
        "descriptors": [{"measure": "height", "min": 0, "max": 20}, {"measure": "spread", "min": 0, "max": 4},
                        {"measure": "lean", "min": 0, "max": 5}, {"measure": "crown_height", "min": 0, "max": 20}],
        "archive": {"type": "cvt", "cells": 50, "qd_offset": -10}})");
    const ExperimentConfig c = read_experiment_config(cvt, "cvt.json");
    CHECK(c.qd.archive == ArchiveKind::cvt);
    CHECK(c.qd.cells() == 50);
    CHECK(c.qd.qd_offset == -10.0);
    CHECK(c.resolved["archive"]["cells"] == 50);
    CHECK(schema_errors(c.resolved) == "");
    // the schema's defaults for the archive are the reader's
    const json schema = schema_document();
    CHECK(schema["properties"]["archive"]["properties"]["type"]["default"] == config.resolved["archive"]["type"]);
    for (const char* key : {"cells", "qd_offset"}) {
        INFO(key);
        CHECK(schema["properties"]["archive"]["properties"][key]["default"] ==
              read_experiment_config(json::parse(R"({"evolution": {"algorithm": "map_elites"},
                  "descriptors": [{"measure": "height", "min": 0, "max": 1}], "archive": {"type": "cvt"}})"), "d")
                  .resolved["archive"][key]);
    }
    // the schema's measures are the library's
    std::vector<std::string> schema_measures;
    for (const json& m : schema["definitions"]["descriptor"]["properties"]["measure"]["enum"])
        schema_measures.push_back(m.get<std::string>());
    CHECK(schema_measures == descriptor_measure_names());
}

TEST_CASE("steady_state configs resolve the algorithm and no MAP-Elites keys", "[app][config][map_elites]") {
    const ExperimentConfig plain = read_experiment_config(json::object(), "{}");
    CHECK(plain.algorithm == Algorithm::steady_state);
    CHECK(plain.resolved["evolution"]["algorithm"] == "steady_state");
    CHECK_FALSE(plain.resolved.contains("descriptors"));
    CHECK_FALSE(plain.resolved.contains("archive"));
    const ExperimentConfig named = read_experiment_config(json{{"evolution", {{"algorithm", "steady_state"}}}}, "x");
    CHECK(named.resolved == plain.resolved);
    CHECK(named.resolved.dump(2) == plain.resolved.dump(2));
    // an archive without map_elites would be silently ignored: refused
    const std::string errors = config_errors(json::parse(
        R"({"descriptors": [{"measure": "height", "min": 0, "max": 1}], "archive": {"type": "grid"}})"));
    CHECK_THAT(errors, Catch::Contains("test.json: archive: used only when"));
    CHECK_THAT(errors, !Catch::Contains("descriptors"));
    // schema.json refuses the same: archive or emitters without map_elites.
    for (const char* ga : {R"({"archive": {"type": "grid"}})", R"({"emitters": [{"kind": "gaussian"}]})",
                           R"({"evolution": {"algorithm": "steady_state"}, "emitters": []})"}) {
        CAPTURE(ga);
        CHECK_THAT(config_errors(json::parse(ga)), Catch::Contains("used only when"));
        CHECK(schema_errors(json::parse(ga)) != "");
    }
    CHECK(schema_errors(json::parse(R"({"evolution": {"algorithm": "map_elites"}, "archive": {"type": "grid"},
        "emitters": [{"kind": "gaussian"}], "descriptors": [{"measure": "height", "min": 0, "max": 1}]})")) == "");
    CHECK_THAT(config_errors(json{{"evolution", {{"algorithm", "map_elite"}}}}),
               Catch::Contains("evolution.algorithm: \"map_elite\" is not one of \"steady_state\", \"map_elites\", "
                               "\"nslc\" (did you mean \"map_elites\"?)"));
}

TEST_CASE("a steady-state config may declare descriptors, only to record them", "[app][config][map_elites]") {
    const ExperimentConfig ga = read_experiment_config(json::parse(R"({"descriptors": [
        {"measure": "height", "min": 0, "max": 20, "bins": 20}, {"measure": "footprint", "min": 0, "max": 800},
        {"measure": "width", "min": 0, "max": 1}, {"measure": "area", "min": 0, "max": 1}]})"), "ga");
    CHECK(ga.algorithm == Algorithm::steady_state);
    CHECK(ga.qd.measure_names() == std::vector<std::string>{"height", "footprint", "width", "area"});  // no grid limit
    CHECK(ga.resolved["descriptors"][1] == json::parse(R"({"measure": "footprint", "min": 0, "max": 800, "bins": 10})"));
    CHECK_FALSE(ga.resolved.contains("archive"));
    CHECK(ga.resolved["evolution"]["algorithm"] == "steady_state");
    // the same checks as for MAP-Elites, with key paths, all at once
    const std::string errors = config_errors(json::parse(R"({"descriptors": [
        {"measure": "heigth", "min": 0, "max": 1}, {"measure": "height", "min": 2, "max": 2}]})"));
    CHECK_THAT(errors, Catch::Contains("descriptors[0].measure: unknown measure \"heigth\" (did you mean \"height\"?)"));
    CHECK_THAT(errors, Catch::Contains("descriptors[1]: min (2.0) must be less than max (2.0)"));
    CHECK_THAT(config_errors(json::parse(R"({"descriptors": []})")), Catch::Contains("descriptors: expected a non-empty array"));
}

TEST_CASE("bad descriptor configs are refused all at once with their key paths", "[app][config][map_elites]") {
    const json document = json::parse(R"({
        "evolution": {"algorithm": "map_elites"},
        "descriptors": [{"measure": "heigth", "min": 0, "max": 20, "bins": 20},
                        {"measure": "footprint", "min": 5, "max": 5},
                        {"measure": "width", "min": 0, "max": 3, "bins": 0},
                        {"min": 0, "max": 1, "bins": 2},
                        {"measure": "area", "max": 1, "colour": 3},
                        7],
        "archive": {"type": "grid", "cells": 10, "qd_ofset": 1}
    })");
    const std::string errors = config_errors(document);
    for (const char* expected :
         {"test.json: descriptors[0].measure: unknown measure \"heigth\" (did you mean \"height\"?)",
          "test.json: descriptors[1]: min (5.0) must be less than max (5.0)",
          "test.json: descriptors[2].bins: 0 is out of range [1, 1000000]",
          "test.json: descriptors[3].measure: required", "test.json: descriptors[4].min: required",
          "test.json: descriptors[4].colour: unknown key", "test.json: descriptors[5]: expected an object",
          "test.json: archive.cells: only for a CVT archive",
          "test.json: archive.qd_ofset: unknown key \"qd_ofset\" (did you mean \"qd_offset\"?)",
          "test.json: descriptors: 6 descriptors: a grid archive takes 1 to 3"})
        CHECK_THAT(errors, Catch::Contains(expected));
    CHECK(schema_errors(document) != "");

    auto me = [](const std::string& rest) {
        return json::parse(R"({"evolution": {"algorithm": "map_elites"})" + rest + "}");
    };
    CHECK_THAT(config_errors(me("")), Catch::Contains("test.json: descriptors: required when evolution.algorithm"));
    CHECK_THAT(config_errors(me(R"(, "descriptors": [])")), Catch::Contains("descriptors: expected a non-empty array"));
    CHECK_THAT(config_errors(me(R"(, "descriptors": {"measure": "height"})")),
               Catch::Contains("descriptors: expected a non-empty array"));
    CHECK_THAT(config_errors(me(R"(, "descriptors": [{"measure": "height", "min": 0, "max": 1}],
                                   "archive": {"type": "cvt", "cells": 10001})")),
               Catch::Contains("archive.cells: 10001 cells is more than a CVT archive places (at most 10000"));
    CHECK_THAT(config_errors(me(R"(, "descriptors": [{"measure": "height", "min": 0, "max": 1}],
                                   "archive": {"type": "hexagonal"})")),
               Catch::Contains("archive.type: \"hexagonal\" is not one of"));
    // a grid beyond 2^40 cells, and a full archive beyond memory, with the estimate
    CHECK_THAT(config_errors(me(R"(, "descriptors": [{"measure": "height", "min": 0, "max": 1, "bins": 1000000},
        {"measure": "area", "min": 0, "max": 1, "bins": 1000000}, {"measure": "width", "min": 0, "max": 1, "bins": 2}])")),
               Catch::Contains("descriptors: the grid has 2000000000000.0 cells"));
    // a full archive beyond memory: the resource limits (search_genomes counts the cells)
    const ExperimentConfig big = read_experiment_config(me(R"(, "network": {"outputs": 15, "hidden": [30]},
        "descriptors": [{"measure": "height", "min": 0, "max": 1, "bins": 1000},
                        {"measure": "area", "min": 0, "max": 1, "bins": 1000}])"), "big.json");
    CHECK(search_genomes(big).checkpointed == 1'000'001.0 + 63);  // + the pipeline's lag - 1 kept births
    ResourceLimits limits;
    limits.max_memory_bytes = 32.0 * (1ULL << 30);  // the estimate is 43.5 GiB (27.7 GiB of genomes, 15.8 GiB for the checkpoint)
    std::string memory;
    try {
        check_resource_limits(big, evolution_workload(big), limits, "big.json");
    } catch (const ConfigError& e) {
        memory = e.what();
    }
    CHECK_THAT(memory, Catch::Contains("big.json: descriptors, "));
    CHECK_THAT(memory, Catch::Contains("genomes (a full archive of 1,000,000 cells twice, births in flight, best) x "));
    // the same archive in a GA-sized grid fits
    const ExperimentConfig small = read_experiment_config(me(R"(, "descriptors": [{"measure": "height", "min": 0, "max": 1, "bins": 20}])"), "s");
    CHECK_NOTHROW(check_resource_limits(small, evolution_workload(small), limits, "s.json"));
}

TEST_CASE("a section that is null is refused, not taken for its defaults", "[app][config]") {
    for (const char* section : {"network", "growth", "fitness", "evolution", "run", "descriptors", "archive"}) {
        INFO(section);
        json document = json::object();
        document[section] = nullptr;
        CHECK_THAT(config_errors(document), Catch::Contains("test.json: " + std::string(section) + ": "));
    }
    CHECK_THAT(config_errors(json(nullptr)), Catch::Contains("expected an object, got null"));
    // a command-line override does not turn a null run section into an object
    TempDir tmp("config-null-run");
    write_text(tmp.path / "c.json", R"({"run": null})");
    ConfigOverrides overrides;
    overrides.seed = 3;
    CHECK_THROWS_WITH(load_experiment_config((tmp.path / "c.json").string(), overrides),
                      Catch::Contains("run: expected an object, got null"));
}

TEST_CASE("growth.mode: the branching mode needs 7 outputs, and turn_rate only means something there", "[app][config]") {
    CHECK(config_errors(json{{"growth", {{"mode", "branching"}}}}) == "");
    CHECK_THAT(config_errors(json{{"growth", {{"mode", "branching"}}}, {"network", {{"outputs", 6}}}}),
               Catch::Contains("network.outputs: growth.mode \"branching\" needs at least 7 outputs, got 6"));
    CHECK_THAT(config_errors(json{{"growth", {{"turn_rate", 0.2}}}}),
               Catch::Contains("growth.turn_rate: is used only with growth.mode \"branching\""));
    CHECK_THAT(config_errors(json{{"growth", {{"mode", "branchy"}}}}), Catch::Contains("growth.mode"));
    // The paper's mode is recorded, without a turn rate.
    const json paper = read_experiment_config(json::object(), "p").resolved["growth"];
    CHECK(paper["mode"] == "paper");
    CHECK_FALSE(paper.contains("turn_rate"));
    const json branching = read_experiment_config(json{{"growth", {{"mode", "branching"}}}}, "b").resolved["growth"];
    CHECK(branching["mode"] == "branching");
    CHECK(branching["turn_rate"] == 0.1);
    // and the schema agrees
    CHECK(schema_errors(json{{"growth", {{"turn_rate", 0.2}}}}) != "");
    CHECK(schema_errors(json{{"growth", {{"mode", "branching"}, {"turn_rate", 0.2}}}}) == "");
}

TEST_CASE("growth.seed_radius beyond what a seed can be is a config error naming the key and range", "[app][config]") {
    for (double radius : {1e300, 1e308, 1e-300, 1e7, 1e-7}) {
        INFO(radius);
        json document = json::object();
        document["growth"]["seed_radius"] = radius;
        const std::string errors = config_errors(document);
        CHECK_THAT(errors, Catch::Contains("growth.seed_radius:"));
        CHECK_THAT(errors, Catch::Contains("out of range [1e-06, 1e+06]"));
    }
    TempDir tmp("config-seed-radius");
    write_text(tmp.path / "c.json", R"({"growth": {"seed_radius": 1e300}})");
    const CliResult result = run_morphogen("validate " + q(tmp.path / "c.json"));
    CHECK(result.code == 2);
    CHECK_THAT(result.output, Catch::Contains("growth.seed_radius"));
}

TEST_CASE("run.threads far beyond the machine and the batch is capped, with a warning, and the bytes stay",
          "[app][config]") {
    TempDir tmp("threads-cap");
    write_text(tmp.path / "c.json", tiny_config(2));
    const CliResult many = run_morphogen("evolve " + q(tmp.path / "c.json") + " --out " + q(tmp.path / "many") +
                                         " --no-report --threads 4096");
    INFO(many.output);
    REQUIRE(many.code == 0);
    CHECK_THAT(many.output, Catch::Contains("run.threads 4096 is more than can run at once here"));
    CHECK_THAT(many.output, Catch::Contains("batch 3): using "));
    const CliResult one = run_morphogen("evolve " + q(tmp.path / "c.json") + " --out " + q(tmp.path / "one") +
                                        " --no-report --threads 1");
    REQUIRE(one.code == 0);
    check_same_results(tmp.path / "many", tmp.path / "one");
}

TEST_CASE("the schedule: the pipeline by default, batch where a config sets batch, always resolved",
          "[app][config][pipeline]") {
    // A new config: the pipeline, lag 64; no batch key in the resolved config.
    const ExperimentConfig fresh = read_experiment_config(json::object(), "x");
    CHECK(fresh.evolution.schedule == ScheduleKind::pipeline);
    CHECK(fresh.evolution.lag == 64);
    CHECK(fresh.resolved["evolution"]["schedule"] == "pipeline");
    CHECK(fresh.resolved["evolution"]["lag"] == 64);
    CHECK_FALSE(fresh.resolved["evolution"].contains("batch"));
    // A config written for batches (every run made before the pipeline): batch,
    // recorded, no lag key, and stable when read again.
    const ExperimentConfig old = read_experiment_config(json{{"evolution", {{"batch", 8}}}}, "x");
    CHECK(old.evolution.schedule == ScheduleKind::batch);
    CHECK(old.evolution.batch == 8);
    CHECK(old.resolved["evolution"]["schedule"] == "batch");
    CHECK_FALSE(old.resolved["evolution"].contains("lag"));
    CHECK(read_experiment_config(old.resolved, "again").resolved == old.resolved);
    CHECK(read_experiment_config(fresh.resolved, "again").resolved == fresh.resolved);
    // Named explicitly.
    const ExperimentConfig named = read_experiment_config(json{{"evolution", {{"schedule", "batch"}}}}, "x");
    CHECK(named.evolution.schedule == ScheduleKind::batch);
    CHECK(named.resolved["evolution"]["schedule"] == "batch");
    CHECK(named.resolved["evolution"]["batch"] == 32);
    CHECK(read_experiment_config(named.resolved, "again").resolved == named.resolved);
    const ExperimentConfig lag = read_experiment_config(json{{"evolution", {{"lag", 5}}}}, "x");
    CHECK(birth_schedule(lag.evolution).describe() == "pipeline, lag 5");
    // Keys that do not apply, and out of range.
    CHECK_THAT(config_errors(json{{"evolution", {{"batch", 8}, {"lag", 4}}}}),
               Catch::Contains("evolution.lag") && Catch::Contains("pipeline\" only"));
    CHECK_THAT(config_errors(json{{"evolution", {{"schedule", "pipeline"}, {"batch", 8}}}}),
               Catch::Contains("evolution.batch") && Catch::Contains("batch\" only"));
    CHECK_THAT(config_errors(json{{"evolution", {{"lag", 0}}}}), Catch::Contains("evolution.lag"));
    CHECK_THAT(config_errors(json{{"evolution", {{"schedule", "waves"}}}}), Catch::Contains("evolution.schedule"));
}

TEST_CASE("MAP-Elites emitters: read, every default resolved, refused where they do not apply",
          "[app][config][emitters]") {
    const json base = json::parse(R"({"evolution": {"algorithm": "map_elites"},
        "descriptors": [{"measure": "height", "min": 0, "max": 10, "bins": 4}]})");
    // Without `emitters`: the default, two cma_me, written out.
    const ExperimentConfig plain = read_experiment_config(base, "x");
    REQUIRE(plain.qd.emitters.size() == 2);
    CHECK(plain.qd.emitters[0].emitter->kind() == "cma_me");
    CHECK(plain.resolved["emitters"] == json::parse(R"([
        {"kind": "cma_me", "share": 1.0, "selection": "uniform", "sigma0": 0.2, "parents": "filter",
         "restart": "no_improvement", "covariance": "diagonal"},
        {"kind": "cma_me", "share": 1.0, "selection": "uniform", "sigma0": 0.2, "parents": "filter",
         "restart": "no_improvement", "covariance": "diagonal"}])"));
    CHECK(read_experiment_config(plain.resolved, "again").resolved == plain.resolved);
    CHECK(schema_errors(plain.resolved) == "");
    json with = base;
    with["emitters"] = json::parse(R"([{"kind": "iso_line", "share": 3, "sigma_line": 0.5},
                                       {"selection": "fitness_proportional"},
                                       {"kind": "cma_mae", "share": 2, "learning_rate": 0.1, "covariance": "full"}])");
    const ExperimentConfig three = read_experiment_config(with, "x");
    REQUIRE(three.qd.emitters.size() == 3);
    CHECK(three.qd.emitters[0].emitter->kind() == "iso_line");
    CHECK(three.qd.emitters[0].share == 3);
    CHECK(three.qd.emitters[1].emitter->kind() == "gaussian");
    CHECK(three.qd.emitters[1].emitter->selection() == ParentSelection::fitness_proportional);
    CHECK(three.qd.emitters[2].emitter->square_matrices() == 1);
    CHECK(three.resolved["emitters"][0] ==
          json::parse(R"({"kind": "iso_line", "share": 3.0, "selection": "uniform", "sigma_iso": 0.05, "sigma_line": 0.5})"));
    CHECK(three.resolved["emitters"][1] ==
          json::parse(R"({"kind": "gaussian", "share": 1.0, "selection": "fitness_proportional"})"));
    CHECK(three.resolved["emitters"][2] == json::parse(R"({"kind": "cma_mae", "share": 2.0, "selection": "uniform",
        "sigma0": 0.5, "parents": "mu", "restart": "basic", "covariance": "full", "learning_rate": 0.1,
        "threshold_min": 0.0})"));
    CHECK(read_experiment_config(three.resolved, "again").resolved == three.resolved);
    CHECK(schema_errors(three.resolved) == "");

    // Each kind's keys and values are the registry's (tests/evolution/test_emitter_registry.cpp); here, that
    // its issues reach the config's.
    auto refused = [&](const json& emitters, const std::string& why) {
        json bad = base;
        bad["emitters"] = emitters;
        CHECK_THAT(config_errors(bad), Catch::Contains(why));
    };
    refused(json::array(), "non-empty array");
    refused(json::parse(R"([{"kind": "cma"}])"), "emitters[0].kind");
    refused(json::parse(R"([{"sigma_iso": 0.1}])"), "only for kind \"iso_line\"");
    refused(json::parse(R"([{"kind": "cma_mae"}, {"kind": "cma_mae", "threshold_min": -5}])"),
            "same learning_rate and threshold_min");
    CHECK_THAT(config_errors(json{{"emitters", json::array({json::object()})}}),
               Catch::Contains("emitters") && Catch::Contains("map_elites"));
}
