// Run directories written by morphogen 0.1.0 (tests/app/fixtures/release-0.1.0,
// made as its README says): their configs and checkpoints are migrated on
// reading, a resume continues them to the same bytes as 0.1.0's own
// uninterrupted run, and files of a later version are refused with a reason.
#include "run/persistence/checkpoint.hpp"
#include "run/config/config_migration.hpp"
#include "run/config/experiment_config.hpp"
#include "core/base/fnv_hash.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace morphogen;
using namespace morphogen::test;
using nlohmann::json;

namespace {
const fs::path fixtures = fs::path(MORPHOGEN_SOURCE_DIR) / "tests/app/fixtures/release-0.1.0";

// A copy of a fixture's run directory (stopped at generation 1) to resume.
fs::path copy_run(const TempDir& tmp, const std::string& name) {
    const fs::path dir = tmp.path / name;
    fs::copy(fixtures / name / "run", dir, fs::copy_options::recursive);
    return dir;
}

// What 0.1.0 resolved, read by this build: migrated, defaults filled in.
json current_form(const json& v1) { return read_experiment_config(migrate_config(v1), "v1").resolved; }

void check_best_files(const fs::path& run, const fs::path& manifest) {
    std::istringstream lines(read_text(manifest));
    std::string hash, name;
    int files = 0;
    while (lines >> hash >> name) {
        INFO(name);
        CHECK(fnv1a64_hex(read_text(run / "best" / name)) == hash);
        ++files;
    }
    CHECK(files == 6);  // generations 2 and 3: .genome.json, .glb, .obj
}
}  // namespace

TEST_CASE("0.1.0's checkpoints load with their configs migrated", "[app][checkpoint][migration]") {
    for (const std::string name : {"ga", "map_elites"}) {
        INFO(name);
        const fs::path run = fixtures / name / "run";
        const RunState state = load_checkpoint(run / "checkpoint.json");
        const json v1 = json::parse(read_text(run / "config.json"));
        CHECK(state.config == current_form(v1));
        CHECK(state.config[config_format_key] == config_format_version);
        CHECK(state.births() == 8);
        CHECK(state.history.size() == 2);
        CHECK_FALSE(state.pending.empty());
        if (name == "map_elites")
            CHECK(state.config["emitters"] ==
                  json::parse(R"([{"kind": "gaussian", "selection": "uniform", "share": 1.0}])"));
        // Saved again: the current version, with the migrated config.
        const std::string bytes = checkpoint_bytes(state);
        CHECK(json::parse(bytes.substr(0, bytes.find('\n')))["version"] == checkpoint_version);
        CHECK(checkpoint_content(bytes, "saved")["config"] == state.config);
    }
}

TEST_CASE("resuming 0.1.0's runs gives the bytes of 0.1.0's uninterrupted runs", "[app][resume][migration]") {
    for (const std::string name : {"ga", "map_elites"}) {
        INFO(name);
        TempDir tmp("release-resume");
        const fs::path run = copy_run(tmp, name), expected = fixtures / name / "expected";
        const CliResult r = run_morphogen("resume " + q(run) + " --generations 3 --threads 2 --no-report");
        INFO(r.output);
        REQUIRE(r.code == 0);
        CHECK(read_text(run / "lineage.csv") == read_text(expected / "lineage.csv"));
        CHECK(history_without_times(run) == history_without_times(expected));
        if (name == "map_elites") CHECK(read_text(run / "archive.csv") == read_text(expected / "archive.csv"));
        check_best_files(run, expected / "best.fnv");
        // config.json and the checkpoint now hold the migrated config, the rest as 0.1.0 wrote it.
        const json expected_config = current_form(json::parse(read_text(expected / "config.json")));
        CHECK(read_text(run / "config.json") == expected_config.dump(2) + "\n");
        const std::string checkpoint = read_text(run / "checkpoint.json");
        CHECK(json::parse(checkpoint.substr(0, checkpoint.find('\n')))["version"] == checkpoint_version);
        CHECK(checkpoint_content(checkpoint, "resumed")["config"] == expected_config);
        json resumed = checkpoint_without_times(run), uninterrupted = checkpoint_without_times(expected);
        resumed.erase("config");
        uninterrupted.erase("config");
        CHECK(resumed == uninterrupted);
    }
}

TEST_CASE("a checkpoint or config.json of a later version is refused, naming the newer morphogen",
          "[app][resume][migration]") {
    TempDir tmp("release-later");
    const fs::path run = copy_run(tmp, "ga");
    const std::string checkpoint = read_text(run / "checkpoint.json"), config = read_text(run / "config.json");
    const std::string later_version = std::to_string(checkpoint_version + 1);

    std::string later = checkpoint;
    later.replace(later.find("\"version\":2}"), 12, "\"version\":" + later_version + "}");
    write_text(run / "checkpoint.json", later);
    CliResult r = run_morphogen("resume " + q(run) + " --generations 3 --no-report");
    CHECK(r.code == 5);
    CHECK_THAT(r.output, Catch::Contains("version " + later_version + " was written by a newer morphogen"));
    CHECK(read_text(run / "checkpoint.json") == later);  // untouched
    write_text(run / "checkpoint.json", checkpoint);

    json later_config = json::parse(config);
    later_config[config_format_key] = config_format_version + 1;
    write_text(run / "config.json", later_config.dump(2));
    r = run_morphogen("resume " + q(run) + " --generations 3 --no-report");
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("format_version: format " + std::to_string(config_format_version + 1) +
                                         " was written by a newer morphogen"));
    CHECK(read_text(run / "checkpoint.json") == checkpoint);
    r = run_morphogen("validate " + q(run / "config.json"));
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("was written by a newer morphogen"));
}

TEST_CASE("validate --resolved shows every default and the format version", "[app][config][migration]") {
    TempDir tmp("release-validate");
    const CliResult r = run_morphogen("validate --resolved " + q(fixtures / "ga" / "source.json"));
    REQUIRE(r.code == 0);
    const std::string text = r.output.substr(r.output.find('{'));
    const json shown = json::parse(text);
    CHECK(shown[config_format_key] == config_format_version);
    CHECK(shown["growth"]["collisions"] == "allow");
    CHECK(shown["growth"]["mode"] == "paper");
    CHECK(shown["evolution"]["algorithm"] == "steady_state");
    CHECK(shown["evolution"]["schedule"] == "pipeline");
}

TEST_CASE("checkpoint versions 2 and 3 differ by their config's format, and the version must tell it",
          "[app][checkpoint][migration]") {
    const std::string v2 = read_text(fixtures / "ga" / "run" / "checkpoint.json");
    std::string as_v3 = v2;
    as_v3.replace(as_v3.find("\"version\":2}"), 12, "\"version\":3}");
    CHECK_THROWS_WITH(checkpoint_content(as_v3, "v3"), Catch::Contains("version 3 with a config without format_version"));
    const std::string v3 = checkpoint_bytes(load_checkpoint(fixtures / "ga" / "run" / "checkpoint.json"));
    std::string as_v2 = v3;
    as_v2.replace(as_v2.find("\"version\":3}"), 12, "\"version\":2}");
    CHECK_THROWS_WITH(checkpoint_content(as_v2, "v2"), Catch::Contains("version 2 with a config with format_version"));
    CHECK_NOTHROW(checkpoint_content(v3, "v3"));
}
