// Novelty search with local competition end to end (evolve / resume with
// evolution.algorithm "nslc", docs/algorithm.md §14): the same bytes for 1
// and 2 threads, after a stop between sessions and after Ctrl-C; the novelty
// archive grows; its config keys checked with clear messages.
#include "core/base/errors.hpp"
#include "run/config/experiment_config.hpp"
#include "run/persistence/checkpoint.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <string>

using namespace morphogen;
using namespace morphogen::test;

namespace {

// A small NSLC run: the pipeline with lag 4 keeps pending births at every stop.
std::string nslc_config(int generations, const std::string& evolution_extra = "") {
    return R"({"network": {"outputs": 4, "hidden": [5]},
 "growth": {"steps": 12, "max_vertices": 300},
 "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
 "evolution": {"algorithm": "nslc", "population": 12, "lag": 4, "mutation_rate": 0.2,
               "novelty_k": 5, "novelty_archive": 20, "novelty_archive_rate": 0.2)" +
           evolution_extra + R"(},
 "descriptors": [{"measure": "height", "min": 0, "max": 3}, {"measure": "footprint", "min": 0, "max": 10}],
 "run": {"seed": 3, "generations": )" +
           std::to_string(generations) + R"(, "export_every": 2}})";
}

nlohmann::json nslc_state_of(const fs::path& run) {
    return checkpoint_content(read_text(run / "checkpoint.json"), run.string())["nslc"];
}

// What reading `document` says ("" if it is valid).
std::string nslc_config_errors(const nlohmann::json& document) {
    try {
        read_experiment_config(document, "n.json");
        return "";
    } catch (const ConfigError& e) {
        return e.what();
    }
}
}  // namespace

TEST_CASE("an NSLC run gives the same files for 1 and 2 threads and after a resume", "[app][nslc][evolve]") {
    TempDir tmp("nslc-run");
    write_text(tmp.path / "n.json", nslc_config(6));
    const std::string config = q(tmp.path / "n.json");
    REQUIRE(run_morphogen("evolve " + config + " --out " + q(tmp.path / "one") + " --threads 1 --no-report").code == 0);
    REQUIRE(run_morphogen("evolve " + config + " --out " + q(tmp.path / "two") + " --threads 2 --no-report").code == 0);
    check_same_results(tmp.path / "one", tmp.path / "two");
    CHECK(read_text(tmp.path / "one" / "best" / "gen_0006.obj") == read_text(tmp.path / "two" / "best" / "gen_0006.obj"));

    // Stopped after generation 2 (pending births in the checkpoint), resumed in two sessions.
    const fs::path split = tmp.path / "split";
    REQUIRE(run_morphogen("evolve " + config + " --out " + q(split) + " --threads 2 --generations 2 --no-report").code ==
            0);
    const nlohmann::json at_2 = nslc_state_of(split);
    REQUIRE(checkpoint_content(read_text(split / "checkpoint.json"), "t").contains("pending"));
    REQUIRE(run_morphogen("resume " + q(split) + " --generations 4 --threads 1 --no-report").code == 0);
    REQUIRE(run_morphogen("resume " + q(split) + " --generations 6 --threads 2 --no-report").code == 0);
    check_same_results(tmp.path / "one", split);

    // The archive grew after generation 2, in birth order, within its bound;
    // the population holds valid members with their descriptors.
    const nlohmann::json at_6 = nslc_state_of(tmp.path / "one");
    CHECK(at_2["archive"].size() > 0);
    CHECK(at_6["archive"].size() > at_2["archive"].size());
    CHECK(at_6["archive"].size() <= 20);
    CHECK(at_6["population"].size() == 12);
    for (const nlohmann::json& member : at_6["population"]) {
        CHECK(member["fitness"].is_number());
        CHECK(member["descriptors"].size() == 2);
    }
    const std::string lineage = read_text(tmp.path / "one" / "lineage.csv");
    CHECK(lineage.rfind("id,birth,parent1,parent2,fitness,height,footprint\n", 0) == 0);
    const std::string history = read_text(tmp.path / "one" / "history.csv");
    CHECK(history.rfind("generation,births,best,mean,median,worst,mean_vertices,invalid,births_per_s,elapsed_s\n", 0) == 0);
    // And it is not the GA: the same config as a GA run breeds other children.
    nlohmann::json ga = nlohmann::json::parse(nslc_config(6));
    for (const char* key : {"novelty_k", "novelty_archive", "novelty_archive_rate"}) ga["evolution"].erase(key);
    ga["evolution"]["algorithm"] = "steady_state";
    write_text(tmp.path / "ga.json", ga.dump());
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "ga.json") + " --out " + q(tmp.path / "ga") + " --no-report").code == 0);
    CHECK(read_text(tmp.path / "ga" / "lineage.csv") != lineage);
}

TEST_CASE("an NSLC run stopped by Ctrl-C resumes to the bytes of an uninterrupted run", "[app][nslc][resume][signals]") {
    TempDir tmp("nslc-signal");
    write_text(tmp.path / "long.json", nslc_config(100000));  // far more than it reaches before the signal
    const fs::path stopped = tmp.path / "stopped";
    const int pid = spawn_morphogen({"evolve", (tmp.path / "long.json").string(), "--out", stopped.string(),
                                     "--threads", "2", "--no-report"},
                                    tmp.path / "spawn.log", true);
    wait_for_rows(stopped, 3);
    ::kill(pid, SIGINT);
    REQUIRE(wait_for(pid) == 130);
    const std::uint64_t births = nslc_state_of(stopped)["births"].get<std::uint64_t>();
    const std::string target = std::to_string(births / 12 + 2);
    REQUIRE(run_morphogen("resume " + q(stopped) + " --generations " + target + " --threads 1 --no-report").code == 0);
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "long.json") + " --out " + q(tmp.path / "whole") +
                          " --generations " + target + " --threads 2 --no-report")
                .code == 0);
    check_same_results(tmp.path / "whole", stopped);
}

TEST_CASE("NSLC's config keys are checked with clear messages", "[app][nslc][config]") {
    const nlohmann::json good = nlohmann::json::parse(nslc_config(2));
    CHECK(nslc_config_errors(good) == "");
    const ExperimentConfig read = read_experiment_config(good, "n.json");
    CHECK(read.algorithm == Algorithm::nslc);
    CHECK(read.novelty.k == 5);
    CHECK(read.novelty.archive == 20);
    CHECK(read.novelty.archive_rate == 0.2);
    CHECK_FALSE(read.resolved["descriptors"][0].contains("bins"));
    // A GA config resolves without the novelty keys (its bytes are unchanged).
    CHECK_FALSE(read_experiment_config(nlohmann::json::object(), "{}").resolved["evolution"].contains("novelty_k"));

    const auto refused = [&](nlohmann::json document, const std::string& why) {
        INFO(document.dump());
        CHECK_THAT(nslc_config_errors(document), Catch::Contains(why));
    };
    nlohmann::json bad = good;
    bad.erase("descriptors");
    refused(bad, "descriptors: required when evolution.algorithm is \"nslc\"");
    bad = good;
    bad["descriptors"][0]["bins"] = 4;
    refused(bad, "descriptors[0].bins: not used by evolution.algorithm \"nslc\"");
    bad = good;
    bad["evolution"]["novelty_k"] = 0;
    refused(bad, "evolution.novelty_k: 0 is out of range");
    bad = good;
    bad["evolution"]["novelty_archive_rate"] = 1.5;
    refused(bad, "evolution.novelty_archive_rate: 1.5 is out of range [0, 1]");
    bad = good;
    bad["evolution"]["novelty_kk"] = 3;
    refused(bad, "evolution.novelty_kk: unknown key \"novelty_kk\" (did you mean \"novelty_k\"?)");
    bad = good;
    bad["archive"] = {{"type", "grid"}};
    refused(bad, "archive: used only when evolution.algorithm is \"map_elites\"");
    bad = good;
    bad["evolution"]["algorithm"] = "steady_state";
    refused(bad, "evolution.novelty_k: used only when evolution.algorithm is \"nslc\"");
    bad["evolution"]["algorithm"] = "novelty";
    refused(bad, "evolution.algorithm");

    // `validate` says so and exits 2.
    TempDir tmp("nslc-config");
    bad = good;
    bad.erase("descriptors");
    write_text(tmp.path / "bad.json", bad.dump());
    const CliResult validated = run_morphogen("validate " + q(tmp.path / "bad.json"));
    CHECK(validated.code == 2);
    CHECK_THAT(validated.output, Catch::Contains("descriptors: required when evolution.algorithm is \"nslc\""));
}
