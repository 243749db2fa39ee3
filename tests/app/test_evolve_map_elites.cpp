// MAP-Elites runs end to end (evolve / resume with evolution.algorithm
// "map_elites"): the same bytes for any thread count and after a resume,
// archive.csv against lineage.csv and the checkpoint, damaged archives
// refused, and CVT centroids carried by the checkpoint.
#include "run/persistence/checkpoint.hpp"
#include "core/base/fnv_hash.hpp"
#include "run/loop/run_records.hpp"
#include "tests/app/evolve_test_support.hpp"
#include "tests/run/search_states.hpp"
#include "tests/support/sanitizers.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <chrono>
#include <thread>

#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace morphogen;
using namespace morphogen::test;

namespace {

std::string me_config(int generations, const std::string& archive = R"({"type": "grid", "qd_offset": -1})",
                      const std::string& descriptors = R"([{"measure": "height", "min": 0, "max": 3, "bins": 6},
                                                           {"measure": "footprint", "min": 0, "max": 10, "bins": 5}])") {
    return R"({"network": {"outputs": 4, "hidden": [5]},
 "growth": {"steps": 12, "max_vertices": 300},
 "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
 "evolution": {"algorithm": "map_elites", "population": 12, "batch": 4, "mutation_rate": 0.2},
 "descriptors": )" + descriptors + R"(,
 "archive": )" + archive + R"(,
 "run": {"seed": 3, "generations": )" + std::to_string(generations) + R"(, "export_every": 2}})";
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> cells_of(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
}

void check_same_elite_runs(const fs::path& a, const fs::path& b) {
    check_same_results(a, b);
    CHECK(read_text(a / "archive.csv") == read_text(b / "archive.csv"));
    for (const char* name : {"gen_0000.obj", "gen_0004.genome.json", "gen_0005.glb"}) {
        INFO(name);
        CHECK(read_text(a / "best" / name) == read_text(b / "best" / name));
    }
}
}  // namespace

TEST_CASE("a MAP-Elites run gives the same files for 1 and 2 threads and after a resume", "[app][map_elites][evolve]") {
    TempDir tmp("me-run");
    write_text(tmp.path / "me.json", me_config(5));
    const std::string config = (tmp.path / "me.json").string();
    const CliResult one = run_morphogen("evolve " + config + " --out " + (tmp.path / "one").string() + " --threads 1");
    REQUIRE(one.code == 0);
    REQUIRE(run_morphogen("evolve " + config + " --out " + (tmp.path / "two").string() + " --threads 2").code == 0);
    check_same_elite_runs(tmp.path / "one", tmp.path / "two");

    // stop after generation 2 (a finished shorter run), then resume to 5 with another thread count
    REQUIRE(run_morphogen("evolve " + config + " --out " + (tmp.path / "split").string() +
                          " --threads 2 --generations 2")
                .code == 0);
    const std::string archive_at_2 = read_text(tmp.path / "split" / "archive.csv");
    CHECK(archive_at_2 != read_text(tmp.path / "one" / "archive.csv"));  // the archive grew after generation 2
    REQUIRE(run_morphogen("resume " + (tmp.path / "split").string() + " --generations 5 --threads 1").code == 0);
    check_same_elite_runs(tmp.path / "one", tmp.path / "split");

    // the history has the MAP-Elites columns; coverage and new cells add up
    const std::vector<std::string> history = lines_of(read_text(tmp.path / "one" / "history.csv"));
    REQUIRE(history.size() == 7);
    CHECK(history[0] ==
          "generation,births,best,mean,median,worst,mean_vertices,invalid,coverage,qd_score,new_cells,births_per_s,"
          "elapsed_s");
    std::uint64_t filled = 0;
    for (std::size_t g = 1; g < history.size(); ++g) filled += std::stoull(cells_of(history[g])[10]);
    const std::vector<std::string> archive = lines_of(read_text(tmp.path / "one" / "archive.csv"));
    CHECK(filled == archive.size() - 1);  // every occupied cell was first filled in some generation
    CHECK(std::stod(cells_of(history.back())[8]) == Approx(static_cast<double>(archive.size() - 1) / 30.0));
}

TEST_CASE("archive.csv agrees with lineage.csv and the checkpoint", "[app][map_elites][evolve]") {
    TempDir tmp("me-archive");
    write_text(tmp.path / "me.json", me_config(4));
    REQUIRE(run_morphogen("evolve " + (tmp.path / "me.json").string() + " --out " + (tmp.path / "run").string())
                .code == 0);
    const std::vector<std::string> archive = lines_of(read_text(tmp.path / "run" / "archive.csv"));
    const std::vector<std::string> lineage = lines_of(read_text(tmp.path / "run" / "lineage.csv"));
    REQUIRE(archive.size() > 2);
    CHECK(archive[0] == "cell,height,footprint,fitness,id");
    CHECK(lineage[0] == "id,birth,parent1,parent2,fitness,height,footprint");
    const RunState state = load_checkpoint(tmp.path / "run" / "checkpoint.json");
    REQUIRE(state.search);
    REQUIRE(elites_state(*state.search) != nullptr);
    CHECK(elites_of(state).archive.occupied() == archive.size() - 1);
    double best = -1e300;
    long previous = -1;
    for (std::size_t i = 1; i < archive.size(); ++i) {
        INFO(archive[i]);
        const std::vector<std::string> row = cells_of(archive[i]);
        REQUIRE(row.size() == 5);
        const long cell = std::stol(row[0]);
        CHECK(cell > previous);  // cell order
        previous = cell;
        const std::uint64_t id = std::stoull(row[4]);
        REQUIRE(id + 1 < lineage.size());
        const std::vector<std::string> birth = cells_of(lineage[id + 1]);
        CHECK(birth[0] == row[4]);
        CHECK(birth[4] == row[3]);  // the same fitness text as lineage.csv
        REQUIRE(birth.size() == 7);  // lineage.csv records the descriptors too, with the same text
        CHECK(birth[5] == row[1]);
        CHECK(birth[6] == row[2]);
        // the cell is where the descriptors fall: 6 height bins over [0,3] x 5 footprint bins over [0,10]
        const auto bin = [](double x, double max, int bins) {
            return std::clamp(static_cast<long>(x / max * bins), 0L, static_cast<long>(bins - 1));
        };
        CHECK(cell == bin(std::stod(row[1]), 3, 6) * 5 + bin(std::stod(row[2]), 10, 5));
        const Individual& elite = elites_of(state).archive.elites().at(static_cast<std::uint64_t>(cell));
        CHECK(elite.id == id);
        best = std::max(best, elite.fitness);
    }
    REQUIRE(elites_of(state).best);
    CHECK(elites_of(state).best->fitness == best);
}

TEST_CASE("a damaged or inconsistent MAP-Elites checkpoint is refused and left as it was", "[app][map_elites][checkpoint]") {
    TempDir tmp("me-damaged");
    write_text(tmp.path / "me.json", me_config(3));
    const fs::path run = tmp.path / "run";
    REQUIRE(run_morphogen("evolve " + (tmp.path / "me.json").string() + " --out " + run.string() + " --generations 1")
                .code == 0);
    const std::string original = read_text(run / "checkpoint.json");
    const nlohmann::json content = checkpoint_content(original, "test");
    REQUIRE(content["map_elites"]["archive"]["elites"].size() >= 2);

    const std::vector<std::pair<std::string, std::function<void(nlohmann::json&)>>> edits = {
        {"map to cell", [](nlohmann::json& c) {
             auto& e = c["map_elites"]["archive"]["elites"];
             e[0]["descriptors"][0] = 2.99;  // moves it to another height bin
         }},
        {"increasing order", [](nlohmann::json& c) {
             auto& e = c["map_elites"]["archive"]["elites"];
             std::swap(e[0], e[1]);
         }},
        {"fitter than the best", [](nlohmann::json& c) {
             c["map_elites"]["archive"]["elites"][0]["fitness"] = 1e9;
         }},
        {"parameters", [](nlohmann::json& c) { c["map_elites"]["archive"]["elites"][0]["params"].erase(0); }},
        {"holds no map_elites state", [](nlohmann::json& c) {
             c["ga"] = c["map_elites"];
             c.erase("map_elites");
         }},
        {"a grid archive has none", [](nlohmann::json& c) {
             c["map_elites"]["archive"]["centroids"] = nlohmann::json::array({0.5, 0.5});
         }},
        {"but the archive it holds gives", [](nlohmann::json& c) {
             auto& e = c["map_elites"]["archive"]["elites"][0];
             e["fitness"] = e["fitness"].get<double>() - 1e-3;
         }},
    };
    for (const auto& [expected, edit] : edits) {
        INFO(expected);
        nlohmann::json changed = content;
        edit(changed);
        const std::string text = checkpoint_text(changed);
        write_text(run / "checkpoint.json", text);
        const CliResult result = run_morphogen("resume " + run.string());
        CHECK(result.code == 5);
        CHECK_THAT(result.output, Catch::Contains(expected));
        CHECK(read_text(run / "checkpoint.json") == text);  // untouched
    }
    write_text(run / "checkpoint.json", original);
    CHECK(run_morphogen("resume " + run.string()).code == 0);
}

TEST_CASE("a CVT run keeps its centroids in the checkpoint and resumes to the same bytes", "[app][map_elites][evolve]") {
    TempDir tmp("me-cvt");
    write_text(tmp.path / "cvt.json",
               me_config(3, R"({"type": "cvt", "cells": 16})",
                         R"([{"measure": "height", "min": 0, "max": 3}, {"measure": "footprint", "min": 0, "max": 10},
                             {"measure": "spread", "min": 0, "max": 3}, {"measure": "vertices", "min": 0, "max": 300}])"));
    const std::string config = (tmp.path / "cvt.json").string();
    REQUIRE(run_morphogen("evolve " + config + " --out " + (tmp.path / "whole").string() + " --threads 2").code == 0);
    REQUIRE(run_morphogen("evolve " + config + " --out " + (tmp.path / "split").string() + " --generations 1").code ==
            0);
    REQUIRE(run_morphogen("resume " + (tmp.path / "split").string() + " --generations 3 --threads 2").code == 0);
    check_same_results(tmp.path / "whole", tmp.path / "split");
    CHECK(read_text(tmp.path / "whole" / "archive.csv") == read_text(tmp.path / "split" / "archive.csv"));
    const nlohmann::json content = checkpoint_content(read_text(tmp.path / "whole" / "checkpoint.json"), "t");
    CHECK(content["map_elites"]["archive"]["centroids"].size() == 16 * 4);
    CHECK(lines_of(read_text(tmp.path / "whole" / "archive.csv"))[0] == "cell,height,footprint,spread,vertices,fitness,id");
}

TEST_CASE("a steady-state run's files have no MAP-Elites columns", "[app][map_elites][evolve]") {
    TempDir tmp("me-ga");
    write_text(tmp.path / "ga.json", tiny_config(1));
    REQUIRE(run_morphogen("evolve " + (tmp.path / "ga.json").string() + " --out " + (tmp.path / "run").string()).code ==
            0);
    CHECK(lines_of(read_text(tmp.path / "run" / "history.csv"))[0] ==
          "generation,births,best,mean,median,worst,mean_vertices,invalid,births_per_s,elapsed_s");
    CHECK_FALSE(fs::exists(tmp.path / "run" / "archive.csv"));
    const nlohmann::json content = checkpoint_content(read_text(tmp.path / "run" / "checkpoint.json"), "t");
    CHECK(content.contains("ga"));
    CHECK_FALSE(content.contains("map_elites"));
    CHECK(content["config"]["evolution"]["algorithm"] == "steady_state");
    CHECK_FALSE(content["history"][0].contains("coverage"));
}

TEST_CASE("a GA run with descriptors records them in lineage.csv and computes what it computed without", "[app][map_elites][evolve]") {
    TempDir tmp("ga-descriptors");
    std::string with = me_config(4, "null");
    with.replace(with.find(R"("algorithm": "map_elites", )"), std::string(R"("algorithm": "map_elites", )").size(), "");
    with.replace(with.find(R"(,
 "archive": null)"), std::string(R"(,
 "archive": null)").size(), "");
    nlohmann::json without = nlohmann::json::parse(with);
    without.erase("descriptors");
    write_text(tmp.path / "with.json", with);
    write_text(tmp.path / "without.json", without.dump());
    for (const char* name : {"with", "without"})
        REQUIRE(run_morphogen("evolve " + (tmp.path / (std::string(name) + ".json")).string() + " --out " +
                              (tmp.path / name).string())
                    .code == 0);
    // the same search: lineage.csv's first five cells, the history, the GA's state and best meshes
    const std::vector<std::string> a = lines_of(read_text(tmp.path / "with" / "lineage.csv"));
    const std::vector<std::string> b = lines_of(read_text(tmp.path / "without" / "lineage.csv"));
    REQUIRE(a.size() == b.size());
    REQUIRE(a.size() == 5 * 12 + 1);
    CHECK(a[0] == "id,birth,parent1,parent2,fitness,height,footprint");
    CHECK(b[0] == "id,birth,parent1,parent2,fitness");
    for (std::size_t i = 1; i < a.size(); ++i) {
        INFO(a[i]);
        std::vector<std::string> cells = cells_of(a[i]);
        REQUIRE(cells.size() == 7);
        CHECK(cells[5].empty() == cells[4].empty());  // measured exactly when valid (no measure fails here)
        cells.resize(5);
        CHECK(cells == cells_of(b[i]));
    }
    CHECK(history_without_times(tmp.path / "with") == history_without_times(tmp.path / "without"));
    nlohmann::json ca = checkpoint_content(read_text(tmp.path / "with" / "checkpoint.json"), "t");
    nlohmann::json cb = checkpoint_content(read_text(tmp.path / "without" / "checkpoint.json"), "t");
    CHECK(ca["ga"] == cb["ga"]);
    CHECK(ca["config"]["descriptors"].size() == 2);
    CHECK_FALSE(cb["config"].contains("descriptors"));
    CHECK(read_text(tmp.path / "with" / "best" / "gen_0004.obj") == read_text(tmp.path / "without" / "best" / "gen_0004.obj"));
    CHECK_FALSE(fs::exists(tmp.path / "with" / "archive.csv"));
    // the recorded descriptors are those of the grown plant: the best regrows (morphogen score) to them
    const std::uint64_t best = ca["ga"]["best"]["id"].get<std::uint64_t>();
    const CliResult score = run_morphogen("score --genome " + (tmp.path / "with" / "best" / "gen_0004.genome.json").string() +
                                          " --config " + (tmp.path / "with" / "config.json").string() + " --json");
    REQUIRE(score.code == 0);
    const nlohmann::json scored = nlohmann::json::parse(score.output);
    const std::vector<std::string> row = cells_of(a[best + 1]);
    CHECK(format_number(scored["fitness"].get<double>()) == row[4]);
    CHECK(format_number(scored["height"].get<double>()) == row[5]);
    CHECK(format_number(scored["footprint"].get<double>()) == row[6]);

    // a resume (the GA's state holds no descriptors) continues the same lineage.csv
    REQUIRE(run_morphogen("evolve " + (tmp.path / "with.json").string() + " --out " + (tmp.path / "split").string() +
                          " --generations 2")
                .code == 0);
    REQUIRE(run_morphogen("resume " + (tmp.path / "split").string() + " --generations 4").code == 0);
    check_same_results(tmp.path / "with", tmp.path / "split");
}

TEST_CASE("a MAP-Elites run stopped by Ctrl-C or kill -9 resumes to the same bytes", "[app][map_elites][signals]") {
    TempDir tmp("me-signal");
    write_text(tmp.path / "me.json", me_config(100000));  // far more than it reaches before the signal
    const std::string config = (tmp.path / "me.json").string();
    for (int signal : {SIGINT, SIGKILL}) {
        CAPTURE(signal);
        const fs::path dir = tmp.path / ("sig" + std::to_string(signal));
        const int pid = spawn_morphogen({"evolve", config, "--out", dir.string(), "--threads", "2"}, tmp.path / "spawn.log");
        for (int i = 0; i < 2000 && lines_of(read_text(dir / "history.csv")).size() < 4; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        ::kill(pid, signal);
        const int code = wait_for(pid);
        CHECK(code == (signal == SIGKILL ? 128 + SIGKILL : 130));
        const std::uint64_t stopped =
            checkpoint_content(read_text(dir / "checkpoint.json"), "t")["map_elites"]["births"].get<std::uint64_t>() / 12;
        const std::string target = std::to_string(std::max<std::uint64_t>(stopped + 2, 4));
        REQUIRE(run_morphogen("resume " + dir.string() + " --generations " + target + " --threads 1").code == 0);
        const fs::path whole = tmp.path / ("whole" + std::to_string(signal));
        REQUIRE(run_morphogen("evolve " + config + " --out " + whole.string() + " --generations " + target +
                              " --threads 1")
                    .code == 0);
        check_same_results(whole, dir);
        CHECK(read_text(whole / "archive.csv") == read_text(dir / "archive.csv"));
    }
}

TEST_CASE("a MAP-Elites run with CMA emitters killed during generation 0 resumes from its first checkpoint",
          "[app][map_elites][emitters][signals]") {
    TempDir tmp("me-first-checkpoint");
    nlohmann::json config = nlohmann::json::parse(me_config(1));
    // A generation 0 of seconds (the sanitizers slow growth down): the kill lands inside it.
    config["growth"]["steps"] = morphogen::testing::whole_or_under_sanitizers(150, 60);
    config["growth"]["max_vertices"] = 3000;
    config["emitters"] = nlohmann::json::parse(R"([{"kind": "cma_mae", "share": 1, "sigma0": 0.3,
        "learning_rate": 0.2, "threshold_min": -1}, {"kind": "cma_me", "share": 1, "sigma0": 0.2}])");
    const fs::path path = tmp.path / "cma.json";
    write_text(path, config.dump());
    const fs::path dir = tmp.path / "killed";
    const int pid = spawn_morphogen({"evolve", path.string(), "--out", dir.string(), "--threads", "1"}, tmp.path / "spawn.log");
    for (int i = 0; i < 20000 && !fs::exists(dir / "checkpoint.json"); ++i)
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    ::kill(pid, SIGKILL);
    CHECK(wait_for(pid) == 128 + SIGKILL);
    const nlohmann::json first = checkpoint_content(read_text(dir / "checkpoint.json"), "t");
    REQUIRE(first["map_elites"]["births"] == 0);
    CHECK(first["map_elites"]["emitters"] == nlohmann::json::parse("[null, null]"));
    const CliResult resumed = run_morphogen("resume " + dir.string() + " --threads 1");
    INFO(resumed.output);
    REQUIRE(resumed.code == 0);
    REQUIRE(run_morphogen("evolve " + path.string() + " --out " + (tmp.path / "whole").string() + " --threads 1").code == 0);
    check_same_results(tmp.path / "whole", dir);
    CHECK(read_text(tmp.path / "whole" / "archive.csv") == read_text(dir / "archive.csv"));
}

TEST_CASE("a MAP-Elites run stopped before its first checkpoint is a stopped start", "[app][map_elites][faults]") {
    TempDir tmp("me-stopped-start");
    write_text(tmp.path / "me.json", me_config(2));
    const std::string config = (tmp.path / "me.json").string();
    REQUIRE(run_morphogen("evolve " + config + " --out " + (tmp.path / "whole").string()).code == 0);
    // What a kill -9 between the empty archive.csv and the first checkpoint leaves.
    const fs::path dir = tmp.path / "start";
    fs::create_directories(dir / "best");
    fs::copy_file(tmp.path / "whole" / "config.json", dir / "config.json");
    const std::string history = read_text(tmp.path / "whole" / "history.csv");
    const std::string lineage = read_text(tmp.path / "whole" / "lineage.csv");
    const std::string archive = read_text(tmp.path / "whole" / "archive.csv");
    write_text(dir / "history.csv", history.substr(0, history.find('\n') + 1));
    write_text(dir / "lineage.csv", lineage.substr(0, lineage.find('\n') + 1));
    write_text(dir / "archive.csv", archive.substr(0, archive.find('\n') + 1));
    write_text(dir / "log.txt", "");

    const CliResult refused = run_morphogen("resume " + dir.string());
    CHECK(refused.code == 3);  // no checkpoint to read; nothing refused (5)
    CHECK_THAT(refused.output, Catch::Contains("before its first checkpoint"));
    // An archive.csv holding an elite is a run's work: never taken for a stopped start.
    write_text(dir / "archive.csv", archive.substr(0, archive.find('\n', archive.find('\n') + 1) + 1));
    CHECK(run_morphogen("evolve " + config + " --out " + dir.string()).code == 3);
    write_text(dir / "archive.csv", archive.substr(0, archive.find('\n') + 1));
    const CliResult restarted = run_morphogen("evolve " + config + " --out " + dir.string());
    INFO(restarted.output);
    REQUIRE(restarted.code == 0);
    check_same_results(tmp.path / "whole", dir);
    CHECK(read_text(tmp.path / "whole" / "archive.csv") == read_text(dir / "archive.csv"));
}

TEST_CASE("morphogen archive exports elites that regrow to their stored fitness and cell", "[app][map_elites][archive]") {
    TempDir tmp("me-export");
    write_text(tmp.path / "me.json", me_config(3));
    const fs::path run = tmp.path / "run";
    REQUIRE(run_morphogen("evolve " + (tmp.path / "me.json").string() + " --out " + run.string()).code == 0);
    const fs::path out = tmp.path / "elites";
    const CliResult all = run_morphogen("archive " + run.string() + " --out " + out.string() + " --png " +
                                        (tmp.path / "map.png").string() + " --size 32");
    REQUIRE(all.code == 0);
    CHECK(fs::file_size(tmp.path / "map.png") > 1000);
    const std::vector<std::string> archive = lines_of(read_text(run / "archive.csv"));
    const std::vector<std::string> species = lines_of(read_text(out / "species.csv"));
    REQUIRE(species.size() == archive.size());
    CHECK(species[0] == "cell,height,footprint,fitness,file");
    for (std::size_t i = 1; i < species.size(); ++i) {
        INFO(species[i]);
        const std::vector<std::string> s = cells_of(species[i]), a = cells_of(archive[i]);
        CHECK(s[0] == a[0]);
        CHECK(s[3] == a[3]);
        for (const char* ext : {".glb", ".obj", ".genome.json"})
            CHECK(fs::exists(out / (s[4].substr(0, s[4].size() - 4) + ext)));
    }
    // the first elite regrows (morphogen score) to its stored fitness and descriptors
    const std::vector<std::string> first = cells_of(species[1]);
    const std::string genome = (out / (first[4].substr(0, first[4].size() - 4) + ".genome.json")).string();
    const CliResult score =
        run_morphogen("score --genome " + genome + " --config " + (run / "config.json").string() + " --json");
    REQUIRE(score.code == 0);
    const nlohmann::json scored = nlohmann::json::parse(score.output);
    CHECK(format_number(scored["fitness"].get<double>()) == first[3]);
    CHECK(format_number(scored["height"].get<double>()) == first[1]);
    CHECK(format_number(scored["footprint"].get<double>()) == first[2]);

    // --top keeps the N fittest
    REQUIRE(run_morphogen("archive " + run.string() + " --out " + (tmp.path / "top").string() + " --top 2").code == 0);
    CHECK(lines_of(read_text(tmp.path / "top" / "species.csv")).size() == 3);
    // a GA run has no archive: refused (exit 2)
    write_text(tmp.path / "ga.json", tiny_config(1));
    REQUIRE(run_morphogen("evolve " + (tmp.path / "ga.json").string() + " --out " + (tmp.path / "ga").string()).code ==
            0);
    const CliResult ga = run_morphogen("archive " + (tmp.path / "ga").string());
    CHECK(ga.code == 2);
    CHECK_THAT(ga.output, Catch::Contains("not a MAP-Elites run"));
}

TEST_CASE("a MAP-Elites run begun before lineage.csv had descriptor columns resumes with five columns",
          "[app][map_elites][evolve]") {
    TempDir tmp("me-old-lineage");
    write_text(tmp.path / "me.json", me_config(4));
    const std::string config = (tmp.path / "me.json").string();
    REQUIRE(run_morphogen("evolve " + config + " --out " + (tmp.path / "whole").string()).code == 0);
    const fs::path old = tmp.path / "old";
    REQUIRE(run_morphogen("evolve " + config + " --out " + old.string() + " --generations 2").code == 0);

    // What the previous version wrote: lineage.csv without the descriptor
    // columns, and a checkpoint sealing that file's length and hash.
    auto five_columns = [](const std::string& text) {
        std::string out;
        for (const std::string& line : lines_of(text)) {
            std::vector<std::string> cells = cells_of(line);
            cells.resize(5);
            out += cells[0] + "," + cells[1] + "," + cells[2] + "," + cells[3] + "," + cells[4] + "\n";
        }
        return out;
    };
    const std::string lineage = five_columns(read_text(old / "lineage.csv"));
    REQUIRE(lineage.starts_with(lineage_header));
    write_text(old / "lineage.csv", lineage);
    nlohmann::json content = checkpoint_content(read_text(old / "checkpoint.json"), old.string());
    content["lineage"] = {{"bytes", lineage.size()}, {"hash", fnv1a64_hex(lineage)}};
    write_text(old / "checkpoint.json", checkpoint_text(content));

    const CliResult resumed = run_morphogen("resume " + old.string() + " --generations 4");
    INFO(resumed.output);
    REQUIRE(resumed.code == 0);
    CHECK(read_text(old / "lineage.csv") == five_columns(read_text(tmp.path / "whole" / "lineage.csv")));
    CHECK(read_text(old / "archive.csv") == read_text(tmp.path / "whole" / "archive.csv"));
    CHECK(history_without_times(old) == history_without_times(tmp.path / "whole"));
    // and once more: the resumed run's own checkpoint resumes the same way
    REQUIRE(run_morphogen("resume " + old.string() + " --generations 5").code == 0);
    CHECK(lines_of(read_text(old / "lineage.csv")).back().find(',') != std::string::npos);
    CHECK(cells_of(lines_of(read_text(old / "lineage.csv")).back()).size() == 5);
}

namespace {
// Writes `config` to me.json in `tmp`, evolves it on 1 and on 2 threads (into
// one/ and two/) and checks the runs are the same; returns the config's path.
std::string evolve_on_1_and_2_threads(const TempDir& tmp, const nlohmann::json& config) {
    write_text(tmp.path / "me.json", config.dump());
    const std::string path = (tmp.path / "me.json").string();
    REQUIRE(run_morphogen("evolve " + path + " --out " + (tmp.path / "one").string() + " --threads 1").code == 0);
    REQUIRE(run_morphogen("evolve " + path + " --out " + (tmp.path / "two").string() + " --threads 2").code == 0);
    check_same_elite_runs(tmp.path / "one", tmp.path / "two");
    return path;
}
}  // namespace

TEST_CASE("MAP-Elites with CMA-ME and CMA-MAE emitters: the same files for any threads and after a resume; "
          "a damaged emitter state is refused",
          "[app][map_elites][emitters][checkpoint]") {
    TempDir tmp("me-cma");
    nlohmann::json config = nlohmann::json::parse(me_config(5));
    config["evolution"].erase("batch");  // the pipeline (lag 64 > a generation of 12)
    config["emitters"] = nlohmann::json::parse(R"([{"kind": "cma_me", "share": 1, "sigma0": 0.2},
        {"kind": "cma_mae", "share": 2, "sigma0": 0.3, "learning_rate": 0.2, "threshold_min": -1},
        {"kind": "iso_line", "share": 1}])");
    const std::string path = evolve_on_1_and_2_threads(tmp, config);
    const fs::path split = tmp.path / "split";
    REQUIRE(run_morphogen("evolve " + path + " --out " + split.string() + " --threads 2 --generations 2").code == 0);
    const fs::path damaged = tmp.path / "damaged";
    fs::copy(split, damaged, fs::copy_options::recursive);
    const std::string original = read_text(damaged / "checkpoint.json");
    REQUIRE(run_morphogen("resume " + split.string() + " --generations 5 --threads 1").code == 0);
    check_same_elite_runs(tmp.path / "one", split);

    // The state at generation 2: every CMA emitter started, thresholds kept.
    const nlohmann::json content = checkpoint_content(original, "test");
    const nlohmann::json& emitters = content["map_elites"]["emitters"];
    REQUIRE(emitters.size() == 3);
    CHECK(emitters[0].is_object());
    CHECK(emitters[1].is_object());
    CHECK(emitters[2].is_null());
    CHECK(emitters[1]["mean"]["params"].size() == content["map_elites"]["best"]["params"].size());
    const std::vector<std::pair<std::string, std::function<void(nlohmann::json&)>>> edits = {
        {"map_elites.emitters[1].sigma", [](nlohmann::json& c) { c["map_elites"]["emitters"][1]["sigma"] = 0.0; }},
        {"map_elites.emitters[0].children", [](nlohmann::json& c) {
             c["map_elites"]["emitters"][0]["children"].push_back(c["map_elites"]["emitters"][0]["mean"]);
         }},
        {"map_elites.emitters[1].variances", [](nlohmann::json& c) {
             c["map_elites"]["emitters"][1]["variances"]["params"][0] = -1.0;
         }},
        {"map_elites.emitters[2]", [](nlohmann::json& c) {
             c["map_elites"]["emitters"][2] = c["map_elites"]["emitters"][1];
         }},
    };
    for (const auto& [expected, edit] : edits) {
        INFO(expected);
        nlohmann::json changed = content;
        edit(changed);
        const std::string text = checkpoint_text(changed);
        write_text(damaged / "checkpoint.json", text);
        const CliResult result = run_morphogen("resume " + damaged.string() + " --generations 6");
        CHECK(result.code == 5);
        CHECK_THAT(result.output, Catch::Contains(expected));
        CHECK(read_text(damaged / "checkpoint.json") == text);  // untouched
    }
    write_text(damaged / "checkpoint.json", original);
    // Changing the emitters between sessions is refused, naming them.
    const std::string config_text = read_text(damaged / "config.json");
    nlohmann::json edited = nlohmann::json::parse(config_text);
    edited["emitters"][0]["sigma0"] = 0.25;
    write_text(damaged / "config.json", edited.dump());
    const CliResult changed = run_morphogen("resume " + damaged.string() + " --generations 3");
    CHECK(changed.code == 5);
    CHECK_THAT(changed.output, Catch::Contains("emitters.0.sigma0 differs"));
    write_text(damaged / "config.json", config_text);
    CHECK(run_morphogen("resume " + damaged.string() + " --generations 3").code == 0);
}

TEST_CASE("MAP-Elites with full-covariance CMA emitters: the same files for any threads and after a resume; "
          "a damaged covariance is refused and left as it was",
          "[app][map_elites][emitters][checkpoint]") {
    TempDir tmp("me-cma-full");
    nlohmann::json config = nlohmann::json::parse(me_config(5));
    config["evolution"].erase("batch");
    config["emitters"] = nlohmann::json::parse(R"([{"kind": "cma_me", "sigma0": 0.2, "covariance": "full"},
        {"kind": "cma_mae", "share": 2, "sigma0": 0.3, "learning_rate": 0.2, "covariance": "full"}])");
    const std::string path = evolve_on_1_and_2_threads(tmp, config);
    const fs::path split = tmp.path / "split";
    REQUIRE(run_morphogen("evolve " + path + " --out " + split.string() + " --threads 2 --generations 2").code == 0);
    const std::string original = read_text(split / "checkpoint.json");
    const nlohmann::json content = checkpoint_content(original, "test");
    const nlohmann::json& emitter = content["map_elites"]["emitters"][0];
    const std::size_t n = content["map_elites"]["best"]["params"].size();
    REQUIRE(emitter.contains("covariance"));
    CHECK_FALSE(emitter.contains("variances"));
    CHECK(emitter["covariance"].size() == n);

    // C made asymmetric in one entry: refused, exit 5, the file untouched.
    const fs::path damaged = tmp.path / "damaged";
    fs::copy(split, damaged, fs::copy_options::recursive);
    nlohmann::json changed = content;
    changed["map_elites"]["emitters"][0]["covariance"][0]["params"][1] = 0.125;
    changed["map_elites"]["emitters"][0]["covariance"][1]["params"][0] = 0.25;
    const std::string text = checkpoint_text(changed);
    write_text(damaged / "checkpoint.json", text);
    const CliResult refused = run_morphogen("resume " + damaged.string() + " --generations 5");
    CHECK(refused.code == 5);
    CHECK_THAT(refused.output, Catch::Contains("map_elites.emitters[0].covariance"));
    CHECK(read_text(damaged / "checkpoint.json") == text);

    REQUIRE(run_morphogen("resume " + split.string() + " --generations 5 --threads 1").code == 0);
    check_same_elite_runs(tmp.path / "one", split);
}

TEST_CASE("placing a large CVT archive shows its rounds and stops on SIGTERM within a second",
          "[app][map_elites][signals]") {
    TempDir tmp("me-cvt-stop");
    nlohmann::json config = nlohmann::json::parse(me_config(1));
    config["archive"] = nlohmann::json::parse(R"({"type": "cvt", "cells": 10000})");
    nlohmann::json descriptors = nlohmann::json::array();
    for (const char* measure : {"height", "footprint", "spread", "slenderness", "lean", "sphericity", "volume", "area"})
        descriptors.push_back({{"measure", measure}, {"min", 0}, {"max", 10}});
    config["descriptors"] = descriptors;
    write_text(tmp.path / "cvt.json", config.dump());
    const CliResult valid = run_morphogen("validate " + (tmp.path / "cvt.json").string());
    INFO(valid.output);
    REQUIRE(valid.code == 0);
    const fs::path dir = tmp.path / "run";
    const int pid = spawn_morphogen({"evolve", (tmp.path / "cvt.json").string(), "--out", dir.string(), "--threads", "2"},
                                    tmp.path / "spawn.log");
    for (int i = 0; i < 2000 && read_text(dir / "log.txt").find("placing 10000 CVT centroids") == std::string::npos; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const auto sent = std::chrono::steady_clock::now();
    ::kill(pid, SIGTERM);
    CHECK(wait_for(pid) == 130);
    CHECK(std::chrono::steady_clock::now() - sent < std::chrono::seconds(5));
    const std::string log = read_text(dir / "log.txt");
    CHECK_THAT(log, Catch::Contains("placing 10000 CVT centroids") && Catch::Contains("nothing was lost"));
    CHECK_FALSE(fs::exists(dir / "checkpoint.json"));
    const CliResult resumed = run_morphogen("resume " + dir.string());
    CHECK(resumed.code == 3);
    CHECK_THAT(resumed.output, Catch::Contains("before its first checkpoint"));
}
