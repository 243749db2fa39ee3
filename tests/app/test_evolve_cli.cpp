// End-to-end `evolve` / `resume` through the executable, with a tiny config:
// the run directory, determinism across thread counts, exact resume after a
// stop, a Ctrl-C or a kill -9, refusal of damaged checkpoints and mismatched
// configs.
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

using namespace morphogen::test;

namespace {
std::string arg(const char* option, int value) {
    std::string text(option);
    text += ' ';
    text += std::to_string(value);
    return text;
}

// `path` with `number` appended to its last component ("t" -> "t2").
fs::path numbered(fs::path path, int number) {
    path += std::to_string(number);
    return path;
}

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

std::uint64_t checkpoint_births(const fs::path& dir) {
    return checkpoint_without_times(dir)["ga"]["births"].get<std::uint64_t>();
}

struct TinyRun {
    TempDir tmp;
    fs::path config;
    explicit TinyRun(const std::string& name, int generations = 6) : tmp(name), config(tmp.path / "tiny.json") {
        write_text(config, tiny_config(generations));
    }
    CliResult evolve(const fs::path& out, const std::string& extra = "") const {
        return run_morphogen("evolve " + q(config) + " --out " + q(out) + " " + extra);
    }
};
}  // namespace

TEST_CASE("evolve writes the run directory", "[app][evolve]") {
    TinyRun t("evolve-files", 3);
    const auto run = t.tmp.path / "run";
    const CliResult r = t.evolve(run, "--threads 1 --generations 2");
    REQUIRE(r.code == 0);
    const std::string history = read_text(run / "history.csv");
    CHECK(history.rfind("generation,births,best,mean,median,worst,mean_vertices,invalid,births_per_s,elapsed_s\n", 0) ==
          0);
    CHECK(lines(history) == 4);  // header + generations 0, 1, 2
    const std::string lineage = read_text(run / "lineage.csv");
    CHECK(lineage.rfind("id,birth,parent1,parent2,fitness\n0,0,,,", 0) == 0);
    CHECK(lines(lineage) == 1 + 24);
    const auto config = nlohmann::json::parse(read_text(run / "config.json"));
    CHECK(config["run"]["generations"] == 2);  // the override is recorded
    CHECK(config["run"]["name"] == "tiny");     // derived from the file name
    CHECK(config["growth"]["speed"] == 0.2);    // defaults filled in
    CHECK(fs::exists(run / "log.txt"));
    CHECK(fs::is_empty(run / "best"));  // export_every 0

    SECTION("an existing non-empty directory is refused unless --force") {
        const CliResult again = t.evolve(run);
        CHECK(again.code == 3);
        CHECK_THAT(again.output, Catch::Contains("exists"));
        CHECK(lines(read_text(run / "history.csv")) == 4);  // untouched
        CHECK(t.evolve(run, "--force --generations 1").code == 0);
        CHECK(lines(read_text(run / "history.csv")) == 3);
    }
    SECTION("best meshes and genomes are exported every export_every generations") {
        auto doc = nlohmann::json::parse(tiny_config(3));
        doc["run"]["export_every"] = 2;
        write_text(t.tmp.path / "export.json", doc.dump());
        const auto out = t.tmp.path / "exports";
        REQUIRE(run_morphogen("evolve " + q(t.tmp.path / "export.json") + " --out " + q(out)).code == 0);
        for (const char* stem : {"gen_0000", "gen_0002", "gen_0003"})  // every 2nd and the last
            for (const char* ext : {".glb", ".obj", ".genome.json"}) CHECK(fs::exists(out / "best" / (stem + std::string(ext))));
        CHECK_FALSE(fs::exists(out / "best" / "gen_0001.obj"));
    }
    SECTION("an invalid config is refused before anything is created") {
        write_text(t.tmp.path / "bad.json", R"({"evolution": {"populaton": 3}})");
        const CliResult bad = run_morphogen("evolve " + q(t.tmp.path / "bad.json") + " --out " + q(t.tmp.path / "x"));
        CHECK(bad.code == 2);
        CHECK_THAT(bad.output, Catch::Contains("evolution.populaton") && Catch::Contains("population"));
        CHECK_FALSE(fs::exists(t.tmp.path / "x"));
    }
}

TEST_CASE("evolve gives the same bytes for 1 or 2 or 8 threads", "[app][evolve][determinism]") {
    TinyRun t("evolve-threads", 4);
    for (int threads : {1, 2, 8}) REQUIRE(t.evolve(numbered(t.tmp.path / "t", threads), arg("--threads", threads)).code == 0);
    check_same_results(t.tmp.path / "t1", t.tmp.path / "t2");
    check_same_results(t.tmp.path / "t1", t.tmp.path / "t8");
    // and a different seed gives a different run
    REQUIRE(t.evolve(t.tmp.path / "s", "--seed 8").code == 0);
    CHECK(read_text(t.tmp.path / "s" / "lineage.csv") != read_text(t.tmp.path / "t1" / "lineage.csv"));

    // The pipeline schedule too; its lag changes the run, threads never do.
    write_text(t.config, tiny_pipeline_config(4, 8, 5));
    for (int threads : {1, 2, 8}) REQUIRE(t.evolve(numbered(t.tmp.path / "p", threads), arg("--threads", threads)).code == 0);
    check_same_results(t.tmp.path / "p1", t.tmp.path / "p2");
    check_same_results(t.tmp.path / "p1", t.tmp.path / "p8");
    CHECK(read_text(t.tmp.path / "p1" / "lineage.csv") != read_text(t.tmp.path / "t1" / "lineage.csv"));
    write_text(t.config, tiny_pipeline_config(4, 8, 6));
    REQUIRE(t.evolve(t.tmp.path / "lag6", "--threads 2").code == 0);
    CHECK(read_text(t.tmp.path / "lag6" / "lineage.csv") != read_text(t.tmp.path / "p1" / "lineage.csv"));
}

TEST_CASE("resume after a stop equals an uninterrupted run", "[app][resume]") {
    TinyRun t("resume-stop", 6);
    const auto whole = t.tmp.path / "whole", parts = t.tmp.path / "parts";
    REQUIRE(t.evolve(whole, "--threads 2").code == 0);
    REQUIRE(t.evolve(parts, "--threads 1 --generations 2").code == 0);
    REQUIRE(run_morphogen("resume " + q(parts) + " --generations 4 --threads 8").code == 0);
    REQUIRE(run_morphogen("resume " + q(parts) + " --generations 6").code == 0);
    check_same_results(whole, parts);

    SECTION("resuming a finished run does nothing and exits 0") {
        const std::string before = read_text(parts / "checkpoint.json") + read_text(parts / "lineage.csv");
        const CliResult r = run_morphogen("resume " + q(parts));
        CHECK(r.code == 0);
        CHECK_THAT(r.output, Catch::Contains("nothing to do"));
        CHECK(read_text(parts / "checkpoint.json") + read_text(parts / "lineage.csv") == before);
    }
    SECTION("rows written after the last checkpoint are cut off") {
        // As after a kill -9 between writing rows and the next checkpoint.
        REQUIRE(t.evolve(t.tmp.path / "cut", "--generations 3").code == 0);
        std::ofstream(t.tmp.path / "cut" / "lineage.csv", std::ios::app) << "999,999,1,,0.5\n1000,10";
        std::ofstream(t.tmp.path / "cut" / "history.csv", std::ios::app) << "4,40,1,1,1,1,1,0,1,1\n5,";
        REQUIRE(run_morphogen("resume " + q(t.tmp.path / "cut") + " --generations 6").code == 0);
        check_same_results(whole, t.tmp.path / "cut");
    }
    SECTION("run.generations in config.json may be raised between sessions") {
        auto config = nlohmann::json::parse(read_text(parts / "config.json"));
        config["run"]["generations"] = 7;
        config["run"]["threads"] = 2;
        write_text(parts / "config.json", config.dump(2));
        REQUIRE(run_morphogen("resume " + q(parts)).code == 0);
        CHECK(lines(read_text(parts / "history.csv")) == 1 + 8);
    }
}

TEST_CASE("resume after Ctrl-C or kill -9 equals an uninterrupted run", "[app][resume][signals]") {
    TinyRun t("resume-signal", 100000);  // far more than it will reach before the signal
    for (int signal : {SIGINT, SIGTERM, SIGKILL}) {
        CAPTURE(signal);
        const auto dir = t.tmp.path / ("sig" + std::to_string(signal));
        const int pid = spawn_morphogen({"evolve", t.config.string(), "--out", dir.string(), "--threads", "2"},
                                        t.tmp.path / "spawn.log");
        wait_for_rows(dir, 3);
        ::kill(pid, signal);
        const int code = wait_for(pid);
        if (signal == SIGKILL) {
            CHECK(code == 128 + SIGKILL);
        } else {
            CHECK(code == 130);
            CHECK_THAT(read_text(t.tmp.path / "spawn.log"), Catch::Contains("morphogen resume"));
        }
        // Continue to a few generations past where it stopped, then compare.
        const std::uint64_t stopped = checkpoint_births(dir) / 8;
        const std::string target = std::to_string(std::max<std::uint64_t>(stopped + 2, 4));
        REQUIRE(run_morphogen("resume " + q(dir) + " --generations " + target + " --threads 1").code == 0);
        const auto whole = t.tmp.path / ("whole" + std::to_string(signal));
        REQUIRE(t.evolve(whole, "--generations " + target + " --threads 1").code == 0);
        check_same_results(whole, dir);
    }
}

TEST_CASE("a damaged or mismatched checkpoint is refused and left as it was", "[app][resume][checkpoint]") {
    TinyRun t("resume-refuse", 2);
    const auto run = t.tmp.path / "run";
    REQUIRE(t.evolve(run, "--generations 1").code == 0);
    const std::string good = read_text(run / "checkpoint.json");
    const std::string config = read_text(run / "config.json");

    auto expect_refusal = [&](const std::string& checkpoint, const std::string& why) {
        write_text(run / "checkpoint.json", checkpoint);
        const CliResult r = run_morphogen("resume " + q(run) + " --generations 2");
        CHECK(r.code == 5);
        CHECK_THAT(r.output, Catch::Contains("checkpoint") && Catch::Contains(why));
        CHECK(read_text(run / "checkpoint.json") == checkpoint);
    };
    expect_refusal(good.substr(0, good.size() / 2), "truncated");
    expect_refusal("", "empty");
    std::string flipped = good;
    flipped[good.find('\n') + 12] ^= 1;  // a bit of a genome in the binary part
    expect_refusal(flipped, "hash");
    std::string version = good;
    version.replace(version.find("\"version\":3"), 11, "\"version\":4");
    expect_refusal(version, "version 4 was written by a newer morphogen");

    auto edited = nlohmann::json::parse(config);
    edited["evolution"]["mutation_sigma"] = 0.5;
    write_text(run / "config.json", edited.dump(2));
    write_text(run / "checkpoint.json", good);
    const CliResult r = run_morphogen("resume " + q(run) + " --generations 2");
    CHECK(r.code == 5);
    CHECK_THAT(r.output, Catch::Contains("checkpoint") && Catch::Contains("evolution.mutation_sigma"));
    CHECK(read_text(run / "checkpoint.json") == good);

    write_text(run / "config.json", config);
    write_text(run / "lineage.csv", "id,birth,parent1,parent2,fitness\n");
    CHECK(run_morphogen("resume " + q(run) + " --generations 2").code == 5);
    CHECK(read_text(run / "checkpoint.json") == good);
}

TEST_CASE("the branching mode with collisions prevented and the tree fitness: the same bytes for 1, 2 and 8 "
          "threads, and a resumed run equals an uninterrupted one",
          "[app][evolve][determinism][branching]") {
    TinyRun t("evolve-branching", 4);
    write_text(t.config, R"({"network": {"outputs": 7, "hidden": [6]},
 "growth": {"steps": 30, "max_vertices": 300, "mode": "branching", "turn_rate": 0.2, "collisions": "prevent"},
 "fitness": {"type": "tree", "min_height": 1, "spacing": 0.25, "trunk_power": 2},
 "evolution": {"population": 8, "lag": 5, "mutation_rate": 0.2},
 "run": {"generations": 4, "seed": 7, "export_every": 0}})");
    for (int threads : {1, 2, 8}) REQUIRE(t.evolve(numbered(t.tmp.path / "t", threads), arg("--threads", threads)).code == 0);
    check_same_results(t.tmp.path / "t1", t.tmp.path / "t2");
    check_same_results(t.tmp.path / "t1", t.tmp.path / "t8");
    const auto config = nlohmann::json::parse(read_text(t.tmp.path / "t1" / "config.json"));
    CHECK(config["growth"]["mode"] == "branching");
    CHECK(config["fitness"]["trunk_target"] == 0.25);
    CHECK(config["fitness"]["trunk_power"] == 2.0);
    // Not every genome scores the same: the search has something to select.
    std::istringstream lineage(read_text(t.tmp.path / "t1" / "lineage.csv"));
    std::set<std::string> scores;
    for (std::string line; std::getline(lineage, line);) scores.insert(line.substr(line.rfind(',') + 1));
    CHECK(scores.size() > 2);  // the header's "fitness" and at least two values

    const auto parts = t.tmp.path / "parts";
    REQUIRE(t.evolve(parts, "--threads 1 --generations 2").code == 0);
    REQUIRE(run_morphogen("resume " + q(parts) + " --threads 2 --generations 4").code == 0);
    check_same_results(t.tmp.path / "t1", parts);
}

TEST_CASE("validate and evolve agree about a key an option replaces", "[app][evolve][config]") {
    TempDir tmp("evolve-override");
    auto config = nlohmann::json::parse(tiny_config(2));
    config["run"]["generations"] = "x";
    config["run"]["threads"] = -3;
    write_text(tmp.path / "bad.json", config.dump());
    const CliResult validated = run_morphogen("validate " + q(tmp.path / "bad.json"));
    CHECK(validated.code == 2);
    for (const char* options : {"--generations 1", "--threads 1", "--generations 1 --threads 1 --seed 2"}) {
        CAPTURE(options);
        const CliResult r =
            run_morphogen("evolve " + q(tmp.path / "bad.json") + " --out " + q(tmp.path / "r") + " " + options);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains("run.generations") && Catch::Contains("run.threads"));
        CHECK_FALSE(fs::exists(tmp.path / "r"));
    }
}

TEST_CASE("command-line numbers: a sign in an unsigned option and a non-finite number are refused, naming them",
          "[app][cli]") {
    TempDir tmp("cli-numbers");
    write_text(tmp.path / "c.json", tiny_config(1));
    const std::string config = q(tmp.path / "c.json");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"evolve " + config + " --seed -1", "--seed"},
        {"evolve " + config + " --generations -1", "--generations"},
        {"evolve " + config + " --max-eval-time nan", "--max-eval-time"},
        {"evolve " + config + " --max-eval-time inf", "--max-eval-time"},
        {"grow --random -5 -o " + q(tmp.path / "g.obj"), "--random"},
        {"gallery --count 2 --seed -2 --out " + q(tmp.path / "gal"), "--seed"},
        {"bench --seed -1 --genomes 1", "--seed"},
        {"grow --random 1 -o " + q(tmp.path / "a.glb") + " --animate " + q(tmp.path / "b.glb") +
             " --frame-seconds nan", "--frame-seconds"},
    };
    for (const auto& [args, option] : cases) {
        CAPTURE(args);
        const CliResult r = run_morphogen(args);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains(option));
        CHECK_THAT(r.output, !Catch::Contains("config error"));
    }
    CHECK_FALSE(fs::exists(tmp.path / "gal"));
    CHECK_FALSE(fs::exists(tmp.path / "g.obj"));
}

namespace {
// Runs a POSIX shell script (morphogen is $M in it); returns its exit status, output in `out`.
int run_script(const fs::path& dir, const std::string& body, std::string& out) {
    write_text(dir / "script.sh", "M=" + q(MORPHOGEN_EXE) + "\n" + body + "\n");
    const int status = std::system(("sh " + q(dir / "script.sh") + " > " + q(dir / "out.txt") + " 2>&1").c_str());
    out = read_text(dir / "out.txt");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

TEST_CASE("a file-size limit ends a run with exit 3 and the reason, nothing partial, then resumable",
          "[app][faults][resume]") {
    TempDir tmp("evolve-fsize");
    auto config = nlohmann::json::parse(tiny_config(4));
    config["run"]["export_every"] = 1;
    write_text(tmp.path / "c.json", config.dump());
    const std::string path = q(tmp.path / "c.json");
    REQUIRE(run_morphogen("evolve " + path + " --out " + q(tmp.path / "whole")).code == 0);
    int limited = 0;
    for (int blocks : {1, 4, 16, 64}) {  // ulimit -f counts 1 KiB blocks in dash and bash
        CAPTURE(blocks);
        const fs::path dir = tmp.path / ("f" + std::to_string(blocks));
        std::string output;
        const int code = run_script(tmp.path, "ulimit -f " + std::to_string(blocks) + "\nexec \"$M\" evolve " + path +
                                                  " --out " + q(dir), output);
        INFO(output);
        CHECK((code == 0 || code == 3));
        if (code == 3) {
            ++limited;
            CHECK_THAT(output, Catch::Contains("File too large"));
        }
        bool temporary = false;
        for (const auto& entry : fs::recursive_directory_iterator(dir))
            temporary = temporary || entry.path().extension() == ".tmp";
        CHECK_FALSE(temporary);
        const CliResult finished = fs::exists(dir / "checkpoint.json")
                                       ? run_morphogen("resume " + q(dir))
                                       : run_morphogen("evolve " + path + " --out " + q(dir));
        INFO(finished.output);
        REQUIRE(finished.code == 0);
        check_same_results(tmp.path / "whole", dir);
    }
    CHECK(limited >= 2);
}

TEST_CASE("a SIGINT the run was started with ignored stays ignored (nohup, background jobs)", "[app][signals]") {
    TempDir tmp("evolve-sigint-ignored");
    write_text(tmp.path / "c.json", tiny_config(60));
    // trap '' INT: what the shell starts has SIGINT ignored. SIGINT every
    // 10 ms for half a second (a zombie takes them too) must change nothing.
    std::string output;
    const int code = run_script(tmp.path, "trap '' INT\n\"$M\" evolve " + q(tmp.path / "c.json") + " --out " +
                                              q(tmp.path / "r") + " &\npid=$!\n"
                                              "for i in $(seq 1 50); do kill -INT $pid 2>/dev/null || break; sleep 0.01; done\n"
                                              "wait $pid",
                                output);
    INFO(output);
    CHECK(code == 0);
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "c.json") + " --out " + q(tmp.path / "whole")).code == 0);
    check_same_results(tmp.path / "whole", tmp.path / "r");
}
