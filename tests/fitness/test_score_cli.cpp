// `morphogen score` end to end: runs the executable.
#include "genome_io.hpp"
#include "growth_params.hpp"
#include "mesh_builders.hpp"
#include "mesh_io.hpp"
#include "support/temp_dir.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sys/wait.h>

using namespace morphogen;
using nlohmann::json;

namespace {
struct Result {
    int code;
    std::string out;
};

// Runs the morphogen executable with `arguments` (shell syntax); stderr joins stdout.
Result morphogen_run(const std::string& arguments) {
    const std::string command = std::string("\"") + MORPHOGEN_EXE + "\" " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::string out;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace

TEST_CASE("score --mesh prints the fitness and every metric", "[fitness][cli]") {
    const testing::TempDir tmp("score");
    const auto& dir = tmp.path;
    const std::string box = (dir / "box.obj").string();
    write_mesh(test::make_box({0, 0, 0}, {1, 1, 11}).view(), box);

    const Result text = morphogen_run("score --mesh " + box);
    INFO(text.out);
    CHECK(text.code == 0);
    for (const char* word : {"fitness", "canopy", "height", "footprint", "area", "volume", "vertices", "faces",
                             "self_intersecting"})
        CHECK(text.out.find(word) != std::string::npos);

    const Result js = morphogen_run("score --mesh " + box + " --json");
    REQUIRE(js.code == 0);
    const json report = json::parse(js.out);
    CHECK(report["fitness"] == 1.0);
    CHECK(report["fitness_valid"] == true);
    CHECK(report["canopy"] == 1.0);
    CHECK(report["height"] == 11.0);
    CHECK(report["area"].get<double>() == Approx(46.0));
    CHECK(report["volume"].get<double>() == Approx(11.0));
    CHECK(report["vertices"] == 8);
    CHECK(report["faces"] == 12);
    CHECK(report["self_intersecting"] == false);

    // --fitness replaces the config's section; canopy metrics follow its height.
    const Result height = morphogen_run("score --mesh " + box +
                                        " --json --fitness '{\"type\": \"sum\", \"terms\": [{\"type\": \"height\"},"
                                        " {\"type\": \"canopy\", \"height\": 20, \"weight\": 5}]}'");
    REQUIRE(height.code == 0);
    CHECK(json::parse(height.out)["fitness"] == 11.0);
    CHECK(json::parse(height.out)["canopy"] == 0.0);

    // A config file's fitness section is used; --fitness overrides it.
    const std::string config = (dir / "config.json").string();
    std::ofstream(config) << R"({"fitness": {"type": "volume"}})";
    CHECK(json::parse(morphogen_run("score --json --mesh " + box + " --config " + config).out)["fitness"] == Approx(11.0));
    CHECK(json::parse(morphogen_run("score --json --mesh " + box + " --config " + config +
                                    " --fitness '{\"type\": \"vertices\"}'")
                          .out)["fitness"] == 8.0);

    // Invalid scores are reported, not fatal.
    const std::string crossing = (dir / "crossing.obj").string();
    write_mesh(test::merge(test::make_box({0, 0, 0}, {1, 1, 11}), test::make_box({0.5, 0.5, 0.5}, {2, 2, 2})).view(),
               crossing);
    const Result rejected = morphogen_run("score --json --mesh " + crossing +
                                          " --fitness '{\"reject_self_intersecting\": true}'");
    REQUIRE(rejected.code == 0);
    const json r = json::parse(rejected.out);
    CHECK(r["fitness"].is_null());
    CHECK(r["fitness_valid"] == false);
    CHECK(r["self_intersecting"] == true);
    std::filesystem::remove_all(dir);
}

TEST_CASE("score reports usage and config errors", "[fitness][cli]") {
    const testing::TempDir tmp("score");
    const auto& dir = tmp.path;
    const std::string box = (dir / "box.obj").string();
    write_mesh(test::make_box({0, 0, 0}, {1, 1, 11}).view(), box);
    CHECK(morphogen_run("score").code == 2);
    CHECK(morphogen_run("score --mesh " + box + " --genome " + box).code == 2);
    const Result typo = morphogen_run("score --mesh " + box + " --fitness '{\"type\": \"canopi\"}'");
    CHECK(typo.code == 2);
    CHECK(typo.out.find("fitness.type") != std::string::npos);
    CHECK(typo.out.find("did you mean \"canopy\"") != std::string::npos);
    const Result syntax = morphogen_run("score --mesh " + box + " --fitness '{\"type\": '");
    CHECK(syntax.code == 2);
    CHECK(syntax.out.find("--fitness") != std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST_CASE("score --genome grows the genome and scores the mesh", "[fitness][cli]") {
    const testing::TempDir tmp("score");
    const auto& dir = tmp.path;
    const std::string config = (dir / "config.json").string();
    std::ofstream(config) << R"({"growth": {"steps": 30}, "fitness": {"type": "height"}})";
    NetworkParams network;
    Genome genome{network.layers(), {}};
    genome.params.resize(parameter_count(genome.layers));
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uniform(-2.0, 2.0);
    for (double& p : genome.params) p = uniform(rng);
    const std::string path = (dir / "genome.json").string();
    save_genome(genome, path);
    const Result result = morphogen_run("score --json --genome " + path + " --config " + config);
    INFO(result.out);
    REQUIRE(result.code == 0);
    const json report = json::parse(result.out);
    CHECK(report["fitness_valid"] == true);
    CHECK(report["fitness"] == report["height"]);
    CHECK(report["vertices"].get<int>() >= 12);
    std::filesystem::remove_all(dir);
}
