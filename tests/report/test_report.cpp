// `morphogen report`: what the report holds for small GA and MAP-Elites runs
// (data.js), runs with no exported meshes, runs in progress (locked, rows
// half-written), the run directory left untouched, and the exit codes and
// messages for non-run and damaged directories. The page itself is checked
// in headless Chromium by tests/report/ (CTest).
#include "core/base/errors.hpp"
#include "report/report.hpp"
#include "report/report_data.hpp"
#include "report/report_plants.hpp"
#include "run/persistence/run_directory.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <string>

using namespace morphogen;
using namespace morphogen::test;

namespace {

std::string exporting_config(int generations, int export_every) {
    std::string config = tiny_config(generations);
    const std::string from = "\"export_every\": 0";
    config.replace(config.find(from), from.size(), "\"export_every\": " + std::to_string(export_every));
    return config;
}

// A finished run in <tmp>/run made with `evolve --no-report`.
fs::path make_run(const TempDir& tmp, const std::string& config_text, const std::string& extra = "") {
    write_text(tmp.path / "c.json", config_text);
    const CliResult run = run_morphogen("evolve " + q(tmp.path / "c.json") + " --out " + q(tmp.path / "run") +
                                        " --no-report " + extra);
    INFO(run.output);
    REQUIRE(run.code == 0);
    return tmp.path / "run";
}

// data.js of a report as JSON.
nlohmann::json report_data(const fs::path& report) {
    const std::string text = read_text(report / "data.js");
    const std::string prefix = "window.MORPHOGEN_REPORT = ";
    REQUIRE(text.rfind(prefix, 0) == 0);
    REQUIRE(text.size() > prefix.size() + 2);
    return nlohmann::json::parse(text.substr(prefix.size(), text.size() - prefix.size() - 2));
}

// Every file under `dir` (report/ excluded) as path -> bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().string().find("/report/") == std::string::npos)
            files[fs::relative(entry.path(), dir).string()] = read_text(entry.path());
    return files;
}

// The glTF JSON of a mesh script the report wrote: morphogenMesh("key","BASE64");
nlohmann::json script_gltf(const fs::path& script) {
    const std::string text = read_text(script);
    const std::size_t from = text.find(",\"") + 2, to = text.rfind("\")");
    REQUIRE(from != std::string::npos);
    REQUIRE(to > from);
    static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string glb;
    unsigned bits = 0;
    int count = 0;
    for (std::size_t i = from; i < to && text[i] != '='; ++i) {
        bits = (bits << 6) | static_cast<unsigned>(alphabet.find(text[i]));
        if ((count += 6) >= 8) glb += static_cast<char>((bits >> (count -= 8)) & 0xff);
    }
    REQUIRE(glb.rfind("glTF", 0) == 0);  // GLB header, then the JSON chunk: length, "JSON", text
    std::uint32_t length = 0;
    for (int i = 0; i < 4; ++i) length |= static_cast<std::uint32_t>(static_cast<unsigned char>(glb[12 + i])) << (8 * i);
    REQUIRE(glb.compare(16, 4, "JSON") == 0);
    return nlohmann::json::parse(glb.substr(20, length));
}

// Pixels of a PNG in bark's hues (red to orange, 0-50 degrees, saturation
// above 0.15): never in the plain green, the grey plate or the captions.
int bark_pixels(const fs::path& png) {
    const std::string bytes = read_text(png);
    int w = 0, h = 0, channels = 0;
    unsigned char* rgb = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                               static_cast<int>(bytes.size()), &w, &h, &channels, 3);
    REQUIRE(rgb != nullptr);
    int bark = 0;
    for (int i = 0; i < w * h; ++i) {
        const double r = rgb[3 * i] / 255.0, g = rgb[3 * i + 1] / 255.0, b = rgb[3 * i + 2] / 255.0;
        const double hi = std::max({r, g, b}), lo = std::min({r, g, b});
        if (hi <= 0 || (hi - lo) / hi < 0.15 || hi != r) continue;
        const double hue = 60.0 * (g - b) / (hi - lo);
        bark += hue >= 0 && hue <= 50;
    }
    stbi_image_free(rgb);
    return bark;
}

}  // namespace

TEST_CASE("report of a small GA run: history, meshes, ancestry, pictures, three.js", "[app][report]") {
    TempDir tmp("report");
    const fs::path run = make_run(tmp, exporting_config(5, 2));
    CHECK_FALSE(fs::exists(run / "report"));  // --no-report
    const auto before = snapshot(run);
    const CliResult result = run_morphogen("report " + q(run) + " -o " + q(tmp.path / "out"));
    INFO(result.output);
    REQUIRE(result.code == 0);
    CHECK(snapshot(run) == before);  // the run directory is only read
    CHECK_FALSE(fs::exists(run / "report"));
    const fs::path out = tmp.path / "out";
    for (const char* file : {"index.html", "report.js", "report.css", "data.js", "lib/three.min.js",
                             "lib/GLTFLoader.js", "lib/OrbitControls.js", "contact.png", "best.js"})
        CHECK(fs::is_regular_file(out / file));
    CHECK(read_text(out / "index.html").find("<script src=\"lib/three.min.js\"></script>") != std::string::npos);

    const nlohmann::json d = report_data(out);
    CHECK(d["generations"] == 5);
    CHECK(d["history"]["columns"]["generation"].size() == 6);
    CHECK(d["history"]["columns"]["best"].size() == 6);
    CHECK(d["algorithm"] == "steady_state");
    CHECK(d["seed"] == 7);
    // generations 0, 2, 4 and the last (5) are exported
    std::vector<int> generations;
    for (const auto& m : d["meshes"]) {
        generations.push_back(m["generation"].get<int>());
        const std::string script = read_text(out / m["script"].get<std::string>());
        CHECK(script.rfind("morphogenMesh(\"" + m["key"].get<std::string>() + "\",\"Z2xURg", 0) == 0);  // "glTF"
    }
    CHECK(generations == std::vector<int>{0, 2, 4, 5});
    // the ancestry runs from the best back to the initial population, born in order
    const auto& line = d["ancestry"];
    REQUIRE(line.size() >= 1);
    CHECK(line[0]["id"] == d["best"]["id"]);
    CHECK(line.back()["parent1"].is_null());
    CHECK(line.back()["generation"] == 0);
    for (std::size_t i = 1; i < line.size(); ++i) {
        CHECK(line[i - 1]["parent1"] == line[i]["id"]);
        CHECK(line[i]["generation"] <= line[i - 1]["generation"]);
        const int g = line[i]["generation"];
        CHECK(line[i]["thumb"].is_null() == (g % 2 == 1 && g != 5));
    }
    CHECK(d["best"]["fitness"] == d["history"]["columns"]["best"].back());
    // the growth of the best: tiny_config grows 8 steps, so 9 frames (seed .. final)
    REQUIRE(d["animation"].is_object());
    CHECK(d["animation"]["frames"] == 9);
    const std::string glb = read_text(out / "growth.glb");
    CHECK(glb.rfind("glTF", 0) == 0);
    CHECK(read_text(out / "growth.js") == "morphogenMesh(\"growth\",\"" + base64(glb) + "\");\n");

    // written again without the animation and the sheet: their old files go
    const CliResult again = run_morphogen("report " + q(run) + " -o " + q(out) + " --frames 0 --sheet 0");
    REQUIRE(again.code == 0);
    CHECK(report_data(out)["animation"].is_null());
    CHECK(report_data(out)["sheet"].is_null());
    CHECK_FALSE(fs::exists(out / "growth.glb"));
    CHECK_FALSE(fs::exists(out / "contact.png"));
}

TEST_CASE("the report's thumbnails and contact sheet are in colours from growth history; --no-colour in green",
          "[app][report][colour]") {
    TempDir tmp("report_colour");
    const fs::path run = make_run(tmp, exporting_config(3, 1));
    const auto bark = [&](const fs::path& out, std::vector<int>& thumbs) {
        const nlohmann::json d = report_data(out);
        for (const auto& a : d["ancestry"])
            if (!a["thumb"].is_null()) thumbs.push_back(bark_pixels(out / a["thumb"].get<std::string>()));
        return bark_pixels(out / "contact.png");
    };
    std::vector<int> coloured, plain;
    REQUIRE(run_morphogen("report " + q(run) + " -o " + q(tmp.path / "c")).code == 0);
    const int sheet = bark(tmp.path / "c", coloured);
    REQUIRE(run_morphogen("report " + q(run) + " --no-colour -o " + q(tmp.path / "p")).code == 0);
    CHECK(bark(tmp.path / "p", plain) == 0);
    INFO("contact sheet: " << sheet << " bark pixels");
    CHECK(sheet > 100);
    REQUIRE(coloured.size() >= 2);
    REQUIRE(plain.size() == coloured.size());
    for (std::size_t i = 0; i < coloured.size(); ++i) {
        CHECK(coloured[i] > 10);
        CHECK(plain[i] == 0);
    }
    // An export whose genome file is gone: drawn in the plain green, with a note.
    fs::remove(run / "best/gen_0000.genome.json");
    const CliResult gone = run_morphogen("report " + q(run) + " -o " + q(tmp.path / "g"));
    REQUIRE(gone.code == 0);
    CHECK_THAT(gone.output, Catch::Contains("generation 0 drawn in plain green") && Catch::Contains("gen_0000.genome.json"));
}

TEST_CASE("without three.js the report has no viewer, says why, and loads nothing missing", "[app][report]") {
    TempDir tmp("report_nothree");
    const fs::path run = make_run(tmp, tiny_config(1));
    ::setenv("MORPHOGEN_THREE_DIR", (tmp.path / "no-three").c_str(), 1);
    const CliResult result = run_morphogen("report " + q(run));
    ::unsetenv("MORPHOGEN_THREE_DIR");
    INFO(result.output);
    REQUIRE(result.code == 0);
    CHECK_THAT(result.output, Catch::Contains("no 3-D viewer: " + (tmp.path / "no-three/three.min.js").string() +
                                              " is missing (install Debian's libjs-three)"));
    CHECK(report_data(run / "report")["three"] == false);
    CHECK(read_text(run / "report/index.html").find("three.min.js") == std::string::npos);
}

TEST_CASE("evolve writes the report at the end of a run unless --no-report; resume too", "[app][report]") {
    TempDir tmp("report_end");
    write_text(tmp.path / "c.json", exporting_config(2, 1));
    CliResult run = run_morphogen("evolve " + q(tmp.path / "c.json") + " --out " + q(tmp.path / "run"));
    INFO(run.output);
    REQUIRE(run.code == 0);
    CHECK(fs::is_regular_file(tmp.path / "run/report/index.html"));
    CHECK(report_data(tmp.path / "run/report")["generations"] == 2);
    fs::remove_all(tmp.path / "run/report");
    run = run_morphogen("resume " + q(tmp.path / "run") + " --generations 3 --no-report");
    REQUIRE(run.code == 0);
    CHECK_FALSE(fs::exists(tmp.path / "run/report"));
    run = run_morphogen("resume " + q(tmp.path / "run") + " --generations 4");
    REQUIRE(run.code == 0);
    CHECK(report_data(tmp.path / "run/report")["generations"] == 4);
}

TEST_CASE("a run with no exported meshes still reports: plots, ancestry, the best grown", "[app][report]") {
    TempDir tmp("report_nomesh");
    const fs::path run = make_run(tmp, tiny_config(3));  // export_every 0
    const CliResult result = run_morphogen("report " + q(run));
    INFO(result.output);
    REQUIRE(result.code == 0);
    CHECK_THAT(result.output, Catch::Contains("run.export_every is 0"));
    const nlohmann::json d = report_data(run / "report");
    CHECK(d["meshes"].empty());
    CHECK(d["sheet"].is_null());
    CHECK(d["best"]["script"] == "best.js");
    // The best grown: its architecture measures for the summary.
    const nlohmann::json& architecture = d["best"]["architecture"];
    CHECK(architecture["tips"].get<int>() >= 0);
    CHECK(architecture["strahler"].get<int>() >= 1);
    CHECK(architecture["limbs"] == architecture["limb_lengths"].size());
    CHECK(architecture["first_fork_height"].get<double>() >= 0);
    CHECK_FALSE(d["ancestry"].empty());
    for (const auto& a : d["ancestry"]) CHECK(a["thumb"].is_null());
    CHECK(fs::is_regular_file(run / "report/best.js"));
}

TEST_CASE("a run in progress is reported without its lock; half-written rows are left out", "[app][report]") {
    TempDir tmp("report_live");
    const fs::path run = make_run(tmp, exporting_config(3, 1));
    RunLock held(run);  // as the running process holds it
    // the writer is halfway through a row of each file
    std::ofstream(run / "history.csv", std::ios::app) << "4,99,1.";
    std::ofstream(run / "lineage.csv", std::ios::app) << "999,999,3";
    const auto before = snapshot(run);
    const CliResult result = run_morphogen("report " + q(run) + " -o " + q(tmp.path / "out"));
    INFO(result.output);
    REQUIRE(result.code == 0);
    CHECK(snapshot(run) == before);
    CHECK(report_data(tmp.path / "out")["generations"] == 3);
}

TEST_CASE("a MAP-Elites run: the archive's cells, the fittest elites grown for the viewer", "[app][report]") {
    TempDir tmp("report_me");
    const fs::path run = make_run(tmp, R"({"network": {"outputs": 4, "hidden": [5]},
 "growth": {"steps": 12, "max_vertices": 300},
 "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
 "evolution": {"algorithm": "map_elites", "population": 12, "batch": 4, "mutation_rate": 0.2},
 "descriptors": [{"measure": "height", "min": 0, "max": 3, "bins": 6}, {"measure": "footprint", "min": 0, "max": 10, "bins": 5}],
 "archive": {"type": "grid", "qd_offset": -1},
 "run": {"seed": 3, "generations": 3, "export_every": 1}})");
    const CliResult result = run_morphogen("report " + q(run) + " --elites 2");
    INFO(result.output);
    REQUIRE(result.code == 0);
    const nlohmann::json d = report_data(run / "report");
    CHECK(d["algorithm"] == "map_elites");
    const auto& e = d["elites"];
    REQUIRE(e.is_object());
    CHECK(e["kind"] == "grid");
    CHECK(e["descriptors"].size() == 2);
    CHECK(e["total_cells"] == 30);
    REQUIRE(e["cells"].size() >= 2);
    CHECK(e["grown"] == 2);
    std::vector<double> grown, not_grown;
    for (const auto& c : e["cells"]) {
        CHECK(c["bins"].size() == 2);
        CHECK(c["bins"][0] < 6);
        CHECK(c["bins"][1] < 5);
        (c["script"].is_null() ? not_grown : grown).push_back(c["fitness"]);
        if (!c["script"].is_null()) CHECK(fs::is_regular_file(run / "report" / c["script"].get<std::string>()));
    }
    REQUIRE(grown.size() == 2);
    for (double f : not_grown) CHECK(f <= std::min(grown[0], grown[1]));  // the fittest were grown
    CHECK(d["history"]["columns"].contains("coverage"));
}

TEST_CASE("the viewer's grown plants are engine-ready: named for their birth, wind data, colours, levels halving",
          "[app][report]") {
    TempDir tmp("report_engine");
    const fs::path run = make_run(tmp, R"({"network": {"outputs": 4, "hidden": [5]},
 "growth": {"steps": 20, "max_vertices": 300},
 "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
 "evolution": {"algorithm": "map_elites", "population": 12, "batch": 4, "mutation_rate": 0.2},
 "descriptors": [{"measure": "height", "min": 0, "max": 3, "bins": 6}, {"measure": "footprint", "min": 0, "max": 10, "bins": 5}],
 "archive": {"type": "grid", "qd_offset": -1},
 "run": {"seed": 3, "generations": 3, "export_every": 1}})");
    const CliResult result = run_morphogen("report " + q(run) + " --elites 3");
    INFO(result.output);
    REQUIRE(result.code == 0);
    const nlohmann::json d = report_data(run / "report");
    std::vector<std::pair<nlohmann::json, std::string>> plants = {{d["best"], "best.js"}};  // entry, script
    for (const auto& c : d["elites"]["cells"])
        if (!c["script"].is_null()) plants.emplace_back(c, c["script"].get<std::string>());
    REQUIRE(plants.size() == 4);
    for (const auto& [entry, script] : plants) {
        INFO(script);
        const nlohmann::json gltf = script_gltf(run / "report" / script);
        const std::string name = "plant_" + std::to_string(entry["id"].get<std::uint64_t>());
        const nlohmann::json& root = gltf["nodes"][0];
        CHECK(root["name"] == name);
        CHECK(root["extras"]["birth_id"] == entry["id"]);
        CHECK(root["extras"]["wind"] == "_WIND");
        if (entry.contains("cell")) CHECK(root["extras"]["cell"] == entry["cell"]);
        const int lods = entry["lods"];
        REQUIRE(lods >= 1);  // these plants have at least 8 triangles
        REQUIRE(root["children"].size() == static_cast<std::size_t>(lods));
        const nlohmann::json& lod0 = gltf["nodes"][root["children"][0].get<int>()];
        CHECK(lods <= report_lod_count(lod0["extras"]["triangles"].get<std::size_t>()));  // the chain may stop short
        CHECK(root["extras"]["lods_written"] == lods);
        for (int i = 0; i < lods; ++i) {
            const nlohmann::json& node = gltf["nodes"][root["children"][i].get<int>()];
            CHECK(node["name"] == name + "_LOD" + std::to_string(i));
            const nlohmann::json& primitive = gltf["meshes"][node["mesh"].get<int>()]["primitives"][0];
            CHECK(primitive["attributes"].contains("_WIND"));
            CHECK(primitive["attributes"].contains("COLOR_0"));  // colours from growth history, the viewer draws them
            // The white material (glTF's default base colour, so not written): the vertex colour is the colour.
            CHECK_FALSE(gltf["materials"][primitive["material"].get<int>()]["pbrMetallicRoughness"].contains("baseColorFactor"));
            if (i > 0) {  // about half the triangles of the level before
                const double ratio = node["extras"]["triangles"].get<double>() /
                                     gltf["nodes"][root["children"][i - 1].get<int>()]["extras"]["triangles"].get<double>();
                CHECK(ratio > 0.4);
                CHECK(ratio < 0.6);
            }
        }
    }
    // --no-colour: the plain green, no COLOR_0, in the viewer and the growth animation.
    REQUIRE(run_morphogen("report " + q(run) + " --elites 3 --no-colour -o " + q(tmp.path / "plain")).code == 0);
    const nlohmann::json plain = script_gltf(tmp.path / "plain" / "best.js");
    for (const auto& mesh : plain["meshes"]) CHECK_FALSE(mesh["primitives"][0]["attributes"].contains("COLOR_0"));
    for (const std::string& dir : {std::string("report"), std::string("plain")}) {
        const nlohmann::json growth = script_gltf(dir == "report" ? run / "report" / "growth.js" : tmp.path / dir / "growth.js");
        for (const auto& mesh : growth["meshes"])
            CHECK(mesh["primitives"][0]["attributes"].contains("COLOR_0") == (dir == "report"));
    }
}

TEST_CASE("a CVT archive: cells without bins, drawn at their descriptors", "[app][report]") {
    TempDir tmp("report_cvt");
    const fs::path run = make_run(tmp, R"({"network": {"outputs": 4, "hidden": [5]},
 "growth": {"steps": 12, "max_vertices": 300},
 "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
 "evolution": {"algorithm": "map_elites", "population": 12, "batch": 4, "mutation_rate": 0.2},
 "descriptors": [{"measure": "height", "min": 0, "max": 3}, {"measure": "footprint", "min": 0, "max": 10},
                 {"measure": "spread", "min": 0, "max": 3}],
 "archive": {"type": "cvt", "cells": 16},
 "run": {"seed": 3, "generations": 2, "export_every": 0}})");
    const CliResult result = run_morphogen("report " + q(run));
    INFO(result.output);
    REQUIRE(result.code == 0);
    const nlohmann::json e = report_data(run / "report")["elites"];
    CHECK(e["kind"] == "cvt");
    CHECK(e["total_cells"] == 16);
    REQUIRE_FALSE(e["cells"].empty());
    for (const auto& c : e["cells"]) {
        CHECK_FALSE(c.contains("bins"));
        CHECK(c["descriptors"].size() == 3);
        CHECK(c["cell"] < 16);
        CHECK_FALSE(c["script"].is_null());  // fewer elites than --elites: all grown
    }
}

TEST_CASE("report refuses non-run and damaged directories with the documented codes", "[app][report]") {
    TempDir tmp("report_bad");
    SECTION("no such directory: 3") {
        const CliResult r = run_morphogen("report " + q(tmp.path / "nowhere"));
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("nowhere does not exist"));
    }
    SECTION("a folder that is not a run: 3") {
        fs::create_directories(tmp.path / "plain");
        write_text(tmp.path / "plain/notes.txt", "hello");
        const CliResult r = run_morphogen("report " + q(tmp.path / "plain"));
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("is not a run directory"));
        CHECK_FALSE(fs::exists(tmp.path / "plain/report"));
    }
    const fs::path run = make_run(tmp, tiny_config(2));
    SECTION("history.csv missing: 3, named") {
        fs::remove(run / "history.csv");
        const CliResult r = run_morphogen("report " + q(run));
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("history.csv is missing"));
        CHECK_FALSE(fs::exists(run / "report"));
    }
    SECTION("lineage.csv missing: 3, named") {
        fs::remove(run / "lineage.csv");
        const CliResult r = run_morphogen("report " + q(run));
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("lineage.csv is missing"));
    }
    SECTION("checkpoint.json missing: 5") {
        fs::remove(run / "checkpoint.json");
        const CliResult r = run_morphogen("report " + q(run));
        CHECK(r.code == 5);
        CHECK_THAT(r.output, Catch::Contains("checkpoint.json is missing"));
    }
    SECTION("a refused checkpoint: 5, left byte-identical, nothing written") {
        std::string text = read_text(run / "checkpoint.json");
        text[text.size() / 2] = text[text.size() / 2] == '1' ? '2' : '1';
        write_text(run / "checkpoint.json", text);
        const CliResult r = run_morphogen("report " + q(run));
        CHECK(r.code == 5);
        CHECK_THAT(r.output, Catch::Contains("checkpoint"));
        CHECK(read_text(run / "checkpoint.json") == text);
        CHECK_FALSE(fs::exists(run / "report"));
    }
    SECTION("a history cell that is not a number: 3, with its line") {
        std::string text = read_text(run / "history.csv");
        text += "3,40,abc,1,1,1,1,0,1,1\n";
        write_text(run / "history.csv", text);
        const CliResult r = run_morphogen("report " + q(run));
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("history.csv: line 5: best is \"abc\", not a finite number"));
    }
    SECTION("absurd numbers in a history are shown, not trusted") {
        std::string text = read_text(run / "history.csv");
        text += "3,-1e300,1,1,1,1,1,0,1,1\n4,1e300,1,1,1,1,1,0,1,1\n";
        write_text(run / "history.csv", text);
        const CliResult r = run_morphogen("report " + q(run));
        INFO(r.output);
        CHECK(r.code == 0);
        CHECK(report_data(run / "report")["generations"] == 4);
    }
    SECTION("a history without its columns: 3") {
        write_text(run / "history.csv", "a,b\n1,2\n");
        const CliResult r = run_morphogen("report " + q(run));
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("history.csv: line 1: no generation column"));
    }
    SECTION("-o the run directory itself: 2") {
        const auto before = snapshot(run);
        const CliResult r = run_morphogen("report " + q(run) + " -o " + q(run));
        CHECK(r.code == 2);
        CHECK(snapshot(run) == before);
    }
    SECTION("an OUT_DIR that cannot be made: 3") {
        write_text(tmp.path / "file", "x");
        const CliResult r = run_morphogen("report " + q(run) + " -o " + q(tmp.path / "file/sub"));
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("cannot create"));
    }
}

TEST_CASE("lineage.csv is read by header name; hostile rows are refused with their line", "[app][report]") {
    TempDir tmp("report_lineage");
    const fs::path file = tmp.path / "lineage.csv";
    // columns in another order, and descriptor columns another writer added
    write_text(file, "birth,id,height,parent2,parent1,fitness,footprint\n0,0,1,,,1.5,2\n1,1,1,,,2,2\n"
                     "2,2,1,1,0,,3\n3,3,1,,2,4,1\n4,4");
    const Lineage lineage = read_lineage(file);
    REQUIRE(lineage.size() == 4);  // the half-written last row is left out
    CHECK(lineage.parent1[2] == 0u);
    CHECK(lineage.parent2[2] == 1u);
    CHECK_FALSE(lineage.fitness[2]);
    CHECK(ancestry(lineage, 3, file) == std::vector<std::uint64_t>{3, 2, 0});
    CHECK_THROWS_AS(ancestry(lineage, 4, file), IoError);

    auto refused = [&](const std::string& text, const std::string& message) {
        write_text(file, text);
        CHECK_THROWS_WITH(read_lineage(file), Catch::Contains(message));
    };
    refused("id,parent1,parent2,fitness\n1,,,1\n", "line 2: id 1 where 0 was expected");
    refused("id,parent1,parent2,fitness\n0,0,,1\n", "line 2: a parent born after its child");
    refused("id,parent1,parent2,fitness\n0,,,1\n1,-1,,1\n", "line 3: parent1 is not a birth index");
    refused("id,parent1,parent2,fitness\n0,,,1\n1,0.5,,1\n", "line 3: parent1 is not a birth index");
    refused("id,parent1,parent2,fitness\n0,,,1\n1,1e300,,1\n", "parent1 is not a birth index");
    refused("id,parent1,parent2,fitness\n0,,,nan\n", "fitness is \"nan\", not a finite number");
    refused("id,parent1,parent2,fitness\n0,,1\n", "line 2: 3 cells, the header has 4");
    refused("id,parent1,fitness\n0,,1\n", "no parent2 column");
    refused("id,id,parent1,parent2,fitness\n", "column id appears twice");
    refused("", "empty");
}

TEST_CASE("generation_of and base64", "[app][report]") {
    const std::vector<std::uint64_t> births{4, 8, 12};  // births so far after generations 0, 1, 2
    CHECK(generation_of(0, births) == 0);
    CHECK(generation_of(3, births) == 0);
    CHECK(generation_of(4, births) == 1);
    CHECK(generation_of(11, births) == 2);
    CHECK(generation_of(12, births) == 3);  // after the last row: the generation under way
    CHECK(base64("") == "");
    CHECK(base64("f") == "Zg==");
    CHECK(base64("fo") == "Zm8=");
    CHECK(base64("foo") == "Zm9v");
    CHECK(base64("foobar") == "Zm9vYmFy");
    CHECK(base64(std::string("\xff\x00\xfe", 3)) == "/wD+");
}

TEST_CASE("a report that cannot be written (a full disk) leaves no partial file; resume writes it later",
          "[app][report]") {
    TempDir tmp("report_full");
    const fs::path run = make_run(tmp, exporting_config(2, 1));
    // A file-size limit makes writes fail as a full disk does (EFBIG instead
    // of ENOSPC; SIGXFSZ ignored so that write() returns the error).
    const std::string limited = "sh -c 'trap \"\" XFSZ; ulimit -f 64; exec \"$0\" report \"$1\"' " +
                                q(MORPHOGEN_EXE) + " " + q(run);
    const int code = std::system(limited.c_str());
    CHECK(WEXITSTATUS(code) == 3);
    // Nothing half-written: no staging folder, no report folder with files in it.
    CHECK_FALSE(fs::exists(run / ".report.partial"));
    if (fs::exists(run / "report"))
        for (const auto& entry : fs::recursive_directory_iterator(run / "report")) CHECK_FALSE(entry.is_regular_file());
    // The run is complete: resume has nothing to run, but writes the missing report.
    const CliResult resumed = run_morphogen("resume " + q(run));
    INFO(resumed.output);
    CHECK(resumed.code == 0);
    CHECK_THAT(resumed.output, Catch::Contains("already reached"));
    CHECK(fs::is_regular_file(run / "report/index.html"));
    CHECK(report_data(run / "report")["generations"] == 2);
    // A report newer than the checkpoint is left alone.
    const auto written = fs::last_write_time(run / "report/index.html");
    CHECK(run_morphogen("resume " + q(run)).code == 0);
    CHECK(fs::last_write_time(run / "report/index.html") == written);
}
