// End-to-end tests of grow, gallery and bench through the real executable.
#include "core/io/mesh_io.hpp"
#include "core/mesh/mesh.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using namespace morphogen::test;

namespace {
const std::string small = "--steps 40";
}

TEST_CASE("grow writes every format and prints a summary", "[cli]") {
    TempDir dir("cli-grow");
    for (const std::string ext : {"obj", "ply", "off", "stl", "glb"}) {
        const auto out = (dir.path / ("tree." + ext)).string();
        const CliResult r = run_morphogen("grow --random 3 " + small + " -o " + out);
        INFO(r.output);
        CHECK(r.code == 0);
        CHECK(r.output.find("vertices") != std::string::npos);
        CHECK(fs::file_size(out) > 0);
    }
}

TEST_CASE("grow: PLY is float32 unless --ply-double, and every readable format reads back", "[cli]") {
    TempDir dir("cli-formats");
    const auto path = [&](const std::string& name) { return (dir.path / name).string(); };
    for (const std::string name : {"t.obj", "t.ply", "t.off", "t.stl"})
        REQUIRE(run_morphogen("grow --random 5 " + small + " -o " + path(name)).code == 0);
    REQUIRE(run_morphogen("grow --random 5 " + small + " --ply-double -o " + path("d.ply")).code == 0);
    CHECK(read_text(path("t.ply")).find("property float x\n") != std::string::npos);
    CHECK(read_text(path("d.ply")).find("property double x\n") != std::string::npos);
    CHECK(read_text(path("d.ply")).find("property double nz\n") != std::string::npos);
    CHECK(read_text(path("t.obj")).find("\nvn ") != std::string::npos);

    const morphogen::MeshArrays exact = morphogen::read_mesh(path("t.obj"));
    CHECK(morphogen::read_mesh(path("t.off")).positions == exact.positions);
    const morphogen::MeshArrays doubles = morphogen::read_mesh(path("d.ply"));
    CHECK(doubles.positions == exact.positions);
    CHECK(doubles.faces == exact.faces);
    const morphogen::MeshArrays floats = morphogen::read_mesh(path("t.ply"));
    REQUIRE(floats.positions.size() == exact.positions.size());
    for (std::size_t i = 0; i < exact.positions.size(); ++i)
        CHECK(floats.positions[i] == exact.positions[i].cast<float>().cast<double>());
    // STL: shared vertices welded back; the grown mesh is closed again.
    const morphogen::MeshArrays stl = morphogen::read_mesh(path("t.stl"));
    CHECK(stl.positions.size() == exact.positions.size());
    CHECK(stl.faces.size() == exact.faces.size());
    CHECK_NOTHROW(morphogen::TriMesh::from_arrays(stl, "t.stl"));

    // gallery takes the same flag for --format ply.
    REQUIRE(run_morphogen("gallery --count 1 --seed 5 --format ply --ply-double --out " + path("g")).code == 0);
    CHECK(read_text(path("g/0000.ply")).find("property double x\n") != std::string::npos);
}

TEST_CASE("grow is reproducible and a saved genome regrows the same mesh", "[cli]") {
    TempDir dir("cli-repro");
    const auto a = (dir.path / "a.obj").string(), b = (dir.path / "b.obj").string(),
               c = (dir.path / "c.obj").string(), genome = (dir.path / "g.json").string();
    REQUIRE(run_morphogen("grow --random 11 " + small + " -o " + a + " --save-genome " + genome).code == 0);
    REQUIRE(run_morphogen("grow --random 11 " + small + " -o " + b).code == 0);
    REQUIRE(run_morphogen("grow --genome " + genome + " " + small + " -o " + c).code == 0);
    CHECK(read_text(a) == read_text(b));
    CHECK(read_text(a) == read_text(c));
    REQUIRE(run_morphogen("grow --random 12 " + small + " -o " + b).code == 0);
    CHECK(read_text(a) != read_text(b));
}

TEST_CASE("grow refuses bad input with a reason and a meaningful exit code", "[cli]") {
    TempDir dir("cli-bad");
    const auto out = (dir.path / "x.obj").string();
    // Neither or both genome sources: usage error.
    CHECK(run_morphogen("grow -o " + out).code == 2);
    // Unknown output extension: I/O error before growing.
    CliResult r = run_morphogen("grow --random 1 -o " + (dir.path / "x.xyz").string());
    CHECK(r.code == 3);
    CHECK(r.output.find("x.xyz") != std::string::npos);
    // Bad config: every problem, with key paths.
    const auto config = (dir.path / "bad.json").string();
    write_text(config, R"({"growth": {"stpes": 3, "speed": -1}, "network": {"outputs": 2}})");
    r = run_morphogen("grow --config " + config + " --random 1 -o " + out);
    CHECK(r.code == 2);
    CHECK(r.output.find("growth.stpes") != std::string::npos);
    CHECK(r.output.find("did you mean \"steps\"") != std::string::npos);
    CHECK(r.output.find("growth.speed") != std::string::npos);
    CHECK(r.output.find("network.outputs") != std::string::npos);
    // Bad seed file: mesh error naming the file.
    const auto seed = (dir.path / "open.obj").string();
    write_text(seed, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n");
    const auto seed_config = (dir.path / "seed.json").string();
    write_text(seed_config, R"({"growth": {"seed_mesh": ")" + seed + R"("}})");
    r = run_morphogen("grow --config " + seed_config + " --random 1 -o " + out);
    CHECK(r.code == 4);
    CHECK(r.output.find("open.obj") != std::string::npos);
    // Genome that does not fit the network.
    const auto genome = (dir.path / "g.json").string();
    nlohmann::json small_genome{{"format", "morphogen-genome"}, {"version", 1}, {"layers", {9, 3}},
                                {"params", std::vector<double>(30, 0.0)}};
    write_text(genome, small_genome.dump());
    r = run_morphogen("grow --genome " + genome + " -o " + out);
    CHECK(r.code == 2);
    CHECK(r.output.find("do not match") != std::string::npos);
    write_text(genome, "{ not json");
    r = run_morphogen("grow --genome " + genome + " -o " + out);
    CHECK(r.code == 3);
    CHECK(r.output.find("g.json") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
}

TEST_CASE("gallery grows in parallel, reproducibly, with a summary and a contact sheet", "[cli]") {
    TempDir dir("cli-gallery");
    const auto one = (dir.path / "one").string(), two = (dir.path / "two").string();
    const auto config = (dir.path / "c.json").string();
    write_text(config, R"({"growth": {"steps": 40}})");
    CliResult r = run_morphogen("gallery --config " + config + " --count 6 --seed 5 --out " + one +
                                " --threads 1 --png " + one + "/sheet.png");
    INFO(r.output);
    REQUIRE(r.code == 0);
    REQUIRE(run_morphogen("gallery --config " + config + " --count 6 --seed 5 --out " + two + " --threads 2").code == 0);
    const std::string summary = read_text(fs::path(one) / "summary.csv");
    CHECK(summary.rfind("index,seed,vertices,faces,height,width,grew,time_ms,fitness\n", 0) == 0);
    CHECK(std::count(summary.begin(), summary.end(), '\n') == 7);
    CHECK(fs::file_size(fs::path(one) / "sheet.png") > 1000);
    for (int i = 0; i < 6; ++i) {
        const std::string name = "000" + std::to_string(i) + ".obj";
        CHECK(read_text(fs::path(one) / name) == read_text(fs::path(two) / name));
    }
    // Entry i is `grow --random seed+i`.
    const auto single = (dir.path / "single.obj").string();
    REQUIRE(run_morphogen("grow --config " + config + " --random 8 -o " + single).code == 0);
    CHECK(read_text(single) == read_text(fs::path(one) / "0003.obj"));
}

TEST_CASE("bench --json reports the documented fields", "[cli]") {
    TempDir dir("cli-bench");
    const auto config = (dir.path / "c.json").string();
    write_text(config, R"({"growth": {"steps": 20}})");
    const CliResult r = run_morphogen("bench --config " + config + " --genomes 2 --threads 2 --json");
    REQUIRE(r.code == 0);
    const auto report = nlohmann::json::parse(r.output);
    for (const char* key : {"vertex_steps", "think_s", "wall_s_1t", "wall_s_all", "genomes_per_s_1t",
                            "genomes_per_s_all", "vertex_steps_per_s_1t", "gather_s", "move_s", "split_s", "flip_s"})
        CHECK(report.contains(key));
    CHECK(report["vertex_steps"].get<double>() > 0);
}

