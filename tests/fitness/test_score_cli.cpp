// `morphogen score` end to end: runs the executable.
#include "core/growth/genome_io.hpp"
#include "core/growth/growth_params.hpp"
#include "core/io/mesh_io.hpp"
#include "tests/fitness/mesh_builders.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

using namespace morphogen;
using nlohmann::json;

using Result = testing::CliRun;
using testing::morphogen_run;

TEST_CASE("score --mesh prints the fitness and every metric", "[fitness][cli]") {
    const testing::TempDir tmp("score");
    const auto& dir = tmp.path;
    const std::string box = (dir / "box.obj").string();
    write_mesh(test::make_box({0, 0, 0}, {1, 1, 11}).view(), box);

    const Result text = morphogen_run("score --mesh " + box);
    INFO(text.out);
    CHECK(text.code == 0);
    for (const char* word : {"fitness", "canopy", "height", "footprint", "area", "volume", "vertices", "faces",
                             "self_intersecting", "architecture", "Strahler", "solidity"})
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
    // A box is one unbranched axis, its own convex hull.
    const json& architecture = report["architecture"];
    CHECK(architecture["tips"] == 1);
    CHECK(architecture["limbs"] == 0);
    CHECK(architecture["limb_lengths"] == json::array());
    CHECK(architecture["limb_thicknesses"] == json::array());
    CHECK(architecture["limb_tip_z"] == json::array());
    CHECK(architecture["forks"] == 0);
    CHECK(architecture["strahler"] == 1);
    CHECK(architecture["first_fork_height"].get<double>() == Approx(11.0));
    CHECK(architecture["solidity"].get<double>() == Approx(1.0));
    CHECK(architecture["band_width"].get<double>() > 0);

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

    // A fitness made of parts prints them: the plant's, which recombine to its score.
    CHECK_FALSE(report.contains("fitness_terms"));  // canopy has none
    const Result plant = morphogen_run("score --json --mesh " + box +
                                       " --fitness '{\"type\": \"plant\", \"volume_cost\": 0.1, \"spacing\": 0.05}'");
    REQUIRE(plant.code == 0);
    const json p = json::parse(plant.out);
    const json& terms = p["fitness_terms"];
    CHECK(terms["volume"].get<double>() == Approx(11.0));
    CHECK(terms["tips"] == 1.0);
    CHECK(terms["light"].get<double>() > 0.0);
    CHECK(terms["cost"].get<double>() == Approx(1.0 + 0.0002 * terms["moment"].get<double>() + 0.1 * 11.0));
    CHECK(p["fitness"].get<double>() ==
          Approx(std::sqrt(terms["light"].get<double>() * terms["reproduction"].get<double>()) / terms["cost"].get<double>()));
    const Result plant_text = morphogen_run("score --mesh " + box + " --fitness '{\"type\": \"plant\"}'");
    for (const char* word : {"light", "reproduction", "bearing_tips", "moment", "cost"})
        CHECK(plant_text.out.find(word) != std::string::npos);

    // An open mesh has no solidity: null in JSON, said in words in text.
    const std::string open = (dir / "open.obj").string();
    write_mesh(test::make_square(0, 0, 1, 1, 0).view(), open);
    const Result open_json = morphogen_run("score --json --mesh " + open);
    REQUIRE(open_json.code == 0);
    CHECK(json::parse(open_json.out)["architecture"]["solidity"].is_null());
    CHECK(morphogen_run("score --mesh " + open).out.find("solidity none (open mesh)") != std::string::npos);
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

TEST_CASE("score refuses hostile and invalid mesh files: one line naming the file, exit 3 or 4", "[fitness][cli]") {
    const std::filesystem::path corpus = std::filesystem::path(MORPHOGEN_SOURCE_DIR) / "tests" / "corpus" / "mesh";
    // Files that do not read are I/O errors (3); files that read but hold
    // nothing to score, or more than the canopy grid can hold, are invalid
    // meshes (4).
    const std::pair<const char*, int> cases[] = {
        {"lying_ply_header.ply", 3},          {"lying_ply_list_length.ply", 3},
        {"ply_second_face_element_nan_index.ply", 3}, {"obj_coordinates_1e200.obj", 3},
        {"off_lying_counts.off", 3},          {"stl_lying_triangle_count.stl", 3},
        {"stl_ascii_nan_coordinate.stl", 3},  {"invalid_mesh_empty.obj", 4},
        {"invalid_mesh_no_triangles.obj", 4}, {"invalid_mesh_canopy_grid_too_large.obj", 4},
    };
    for (const auto& [name, code] : cases) {
        const std::string path = (corpus / name).string();
        const auto start = std::chrono::steady_clock::now();
        const Result r = morphogen_run("score --mesh " + path);
        INFO(name << ": " << r.out);
        CHECK(r.code == code);
        CHECK(r.out.find(path) != std::string::npos);
        CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 1);
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
    }
    const Result empty = morphogen_run("score --mesh " + (corpus / "invalid_mesh_empty.obj").string());
    CHECK(empty.out.find("mesh error") != std::string::npos);
    CHECK(empty.out.find("no vertices") != std::string::npos);
    const Result grid = morphogen_run("score --mesh " + (corpus / "invalid_mesh_canopy_grid_too_large.obj").string());
    CHECK(grid.out.find("larger than the limit of 268435456 cells") != std::string::npos);

    // validate and evolve read a seed mesh through the same readers: refused at once.
    const testing::TempDir tmp("score-seed");
    const std::string config = (tmp.path / "config.json").string();
    std::ofstream(config) << R"({"growth": {"seed_mesh": ")" << (corpus / "lying_ply_header.ply").string() << R"("}})";
    for (const std::string& command : {"validate " + config, "evolve " + config + " --out " + (tmp.path / "run").string()}) {
        const auto start = std::chrono::steady_clock::now();
        const Result r = morphogen_run(command);
        INFO(command << ": " << r.out);
        CHECK(r.code != 0);
        CHECK(r.out.find("lying_ply_header.ply:3: element 'e0' declares 2147483647 entries") != std::string::npos);
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
    }
}

TEST_CASE("score reads STL, PLY and OFF files like the OBJ of the same mesh", "[fitness][cli]") {
    const testing::TempDir tmp("score-formats");
    const MeshArrays box = test::make_box({0, 0, 0}, {1, 1, 11});
    json first;
    for (const char* name : {"box.obj", "box.ply", "box.off", "box.stl"}) {
        const std::string path = (tmp.path / name).string();
        write_mesh(box.view(), path);
        const Result r = morphogen_run("score --json --mesh " + path);
        INFO(name << ": " << r.out);
        REQUIRE(r.code == 0);
        json report = json::parse(r.out);
        report.erase("source");
        if (first.is_null()) first = report;
        CHECK(report == first);  // the box's coordinates are floats: every format is exact
    }
}
