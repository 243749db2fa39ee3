// grow and archive with --height (and the engine-ready GLB's other options)
// through the real executable: names, extras, placement, refusals.
#include "tests/app/evolve_test_support.hpp"
#include "tests/engine/glb_reader.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <sstream>

using namespace morphogen::test;

namespace {

const std::string kElitesConfig = std::string(MORPHOGEN_SOURCE_DIR) + "/tests/app/fixtures/engine_elites.json";

const tinygltf::Accessor& positions(const tinygltf::Model& model, int mesh) {
    return model.accessors.at(model.meshes.at(mesh).primitives.at(0).attributes.at("POSITION"));
}

}  // namespace

TEST_CASE("grow --height writes an engine-ready GLB, the same bytes every time", "[cli][engine]") {
    TempDir dir("engine-grow");
    const std::string a = q(dir.path / "a.glb"), b = q(dir.path / "b.glb");
    const CliResult r = run_morphogen("grow --random 3 --steps 40 --height 2.5 -o " + a);
    INFO(r.output);
    REQUIRE(r.code == 0);
    REQUIRE(run_morphogen("grow --random 3 --steps 40 --height 2.5 -o " + b).code == 0);
    const std::string bytes = read_text(dir.path / "a.glb");
    CHECK(bytes == read_text(dir.path / "b.glb"));

    const tinygltf::Model model = parse_glb(bytes);
    REQUIRE(model.nodes.size() == 1);
    const std::string name = model.nodes[0].name;
    CHECK(name.rfind("plant_", 0) == 0);
    CHECK(name.size() == 6 + 8);  // plant_ and the genome hash's first 8 hex digits
    CHECK(model.meshes.at(0).name == name);
    const tinygltf::Value& extras = model.nodes[0].extras;
    CHECK(extras.Get("genome_hash").Get<std::string>().rfind(name.substr(6), 0) == 0);
    CHECK(extras.Get("fitness").IsNumber());
    CHECK(!extras.Has("birth_id"));
    CHECK(positions(model, 0).minValues[1] == 0.0);
    CHECK(positions(model, 0).maxValues[1] == Approx(2.5).epsilon(1e-6));
}

TEST_CASE("grow refuses bad engine options, naming the option", "[cli][engine]") {
    TempDir dir("engine-refuse");
    const std::string glb = q(dir.path / "p.glb");
    for (const std::string bad : {"--height -1", "--height 0", "--height nan", "--height 20000"}) {
        const CliResult r = run_morphogen("grow --random 3 --steps 5 " + bad + " -o " + glb);
        INFO(bad << ": " << r.output);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains("--height"));
    }
    for (const std::string bad : {"--lods 0", "--lods 9", "--lods two"}) {
        const CliResult r = run_morphogen("grow --random 3 --steps 5 " + bad + " -o " + glb);
        INFO(bad << ": " << r.output);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains("--lods"));
    }
    // Too few triangles for 8 levels: the levels it can have, said on stderr.
    const CliResult small = run_morphogen("grow --random 3 --steps 0 --lods 8 -o " + glb);
    CHECK(small.code == 0);
    CHECK_THAT(small.output, Catch::Contains("--lods 8: wrote 1 level(s)"));
    fs::remove(dir.path / "p.glb");
    const CliResult obj = run_morphogen("grow --random 3 --steps 5 --height 2 -o " + q(dir.path / "p.obj"));
    CHECK(obj.code == 2);
    CHECK_THAT(obj.output, Catch::Contains("--height") && Catch::Contains(".glb"));
    CHECK(!fs::exists(dir.path / "p.glb"));
}

TEST_CASE("archive --height names each elite plant_<birth> and records its run, cell and parents", "[cli][engine]") {
    TempDir dir("engine-archive");
    const fs::path run = dir.path / "run", out = dir.path / "elites";
    REQUIRE(run_morphogen("evolve " + q(kElitesConfig) + " --out " + q(run)).code == 0);
    const CliResult r = run_morphogen("archive " + q(run) + " --out " + q(out) + " --height 1.5");
    INFO(r.output);
    REQUIRE(r.code == 0);
    std::istringstream species(read_text(out / "species.csv"));
    std::string line;
    std::getline(species, line);
    int elites = 0;
    while (std::getline(species, line)) {
        const std::string cell = line.substr(0, line.find(','));
        const std::string file = line.substr(line.rfind(',') + 1);
        const tinygltf::Model model = parse_glb(read_text(out / file));
        const tinygltf::Value& extras = model.nodes.at(0).extras;
        CHECK(model.nodes[0].name == "plant_" + std::to_string(extras.Get("birth_id").GetNumberAsInt()));
        CHECK(std::to_string(extras.Get("cell").GetNumberAsInt()) == cell);
        CHECK(extras.Get("run").Get<std::string>() == "engine");
        CHECK(extras.Get("measures").Has("height"));
        if (extras.Has("parents")) CHECK(extras.Get("parents").IsArray());  // left out for the first population
        CHECK(positions(model, 0).maxValues[1] == Approx(1.5).epsilon(1e-6));
        CHECK(fs::exists(out / (file.substr(0, file.size() - 4) + ".obj")));
        ++elites;
    }
    CHECK(elites > 0);
    CHECK(run_morphogen("archive " + q(run) + " --out " + q(out) + " --height -3").code == 2);
}

TEST_CASE("archive --colour alone writes each elite's GLB with COLOR_0 and a white material", "[cli][engine][colour]") {
    TempDir dir("engine-archive-colour");
    const fs::path run = dir.path / "run", out = dir.path / "elites";
    REQUIRE(run_morphogen("evolve " + q(kElitesConfig) + " --out " + q(run)).code == 0);
    const CliResult r = run_morphogen("archive " + q(run) + " --out " + q(out) + " --top 2 --colour");
    INFO(r.output);
    REQUIRE(r.code == 0);
    int elites = 0;
    for (const auto& entry : fs::directory_iterator(out)) {
        if (entry.path().extension() != ".glb") continue;
        const tinygltf::Model model = parse_glb(read_text(entry.path()));
        const tinygltf::Primitive& body = model.meshes.at(0).primitives.at(0);
        CHECK(body.attributes.count("COLOR_0") == 1);
        const std::vector<double>& base = model.materials.at(body.material).pbrMetallicRoughness.baseColorFactor;
        CHECK(base == std::vector<double>{1.0, 1.0, 1.0, 1.0});
        ++elites;
    }
    CHECK(elites == 2);
}

TEST_CASE("grow --wind adds _WIND without changing the mesh, also while animating", "[cli][engine][wind]") {
    TempDir dir("engine-wind");
    REQUIRE(run_morphogen("grow --random 4 --steps 60 --height 3 -o " + q(dir.path / "still.glb")).code == 0);
    const CliResult r = run_morphogen("grow --random 4 --steps 60 --height 3 --wind -o " + q(dir.path / "wind.glb") +
                                      " --animate " + q(dir.path / "growth.glb") + " --frames 5");
    INFO(r.output);
    REQUIRE(r.code == 0);
    const tinygltf::Model still = parse_glb(read_text(dir.path / "still.glb"));
    const tinygltf::Model wind = parse_glb(read_text(dir.path / "wind.glb"));
    const auto& attributes = wind.meshes.at(0).primitives.at(0).attributes;
    REQUIRE(attributes.count("_WIND") == 1);
    CHECK(attributes.count("COLOR_0") == 0);
    CHECK(accessor_floats(wind, attributes.at("POSITION")) ==
          accessor_floats(still, still.meshes.at(0).primitives.at(0).attributes.at("POSITION")));
    CHECK(accessor_floats(wind, attributes.at("_WIND")).size() == 4 * positions(wind, 0).count);
    CHECK(fs::exists(dir.path / "growth.glb"));
}

TEST_CASE("run.export_glb exports the best of generation engine-ready", "[cli][engine]") {
    TempDir dir("engine-best");
    const fs::path run = dir.path / "run";
    const CliResult r = run_morphogen("evolve " + q(std::string(MORPHOGEN_SOURCE_DIR) +
                                                   "/tests/app/fixtures/engine_best.json") + " --out " + q(run));
    INFO(r.output);
    REQUIRE(r.code == 0);
    int exported = 0;
    for (const auto& entry : fs::directory_iterator(run / "best")) {
        if (entry.path().extension() != ".glb") continue;
        const tinygltf::Model model = parse_glb(read_text(entry.path()));
        const tinygltf::Node& plant = model.nodes.at(0);
        const tinygltf::Value& extras = plant.extras;
        CHECK(plant.name == "plant_" + std::to_string(extras.Get("birth_id").GetNumberAsInt()));
        CHECK(extras.Get("run").Get<std::string>() == "engine-best");
        CHECK(extras.Get("height_m").GetNumberAsDouble() == Approx(2.0));
        CHECK(extras.Get("wind").Get<std::string>() == "_WIND");
        // Two levels asked; the chain stops where LOD1 cannot keep its bound (engine/plant_lods.hpp).
        REQUIRE(plant.children.size() == static_cast<std::size_t>(extras.Get("lods_written").GetNumberAsInt()));
        CHECK(extras.Get("lods_requested").GetNumberAsInt() == 2);
        if (plant.children.size() == 2)
            CHECK(model.nodes.at(static_cast<std::size_t>(plant.children[1])).name == plant.name + "_LOD1");
        CHECK(fs::exists(fs::path(entry.path()).replace_extension(".obj")));
        ++exported;
    }
    CHECK(exported == 3);  // generations 0, 1 and 2
    write_text(dir.path / "bad.json", R"({"run": {"export_glb": {"lods": 9, "size": 1}}})");
    const CliResult bad = run_morphogen("validate " + q(dir.path / "bad.json"));
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("run.export_glb.lods") && Catch::Contains("run.export_glb.size"));
}

// archive.csv's rows: birth id -> cell.
std::map<long, long> cells_by_birth(const fs::path& run) {
    std::istringstream rows(read_text(run / "archive.csv"));
    std::string line;
    std::getline(rows, line);
    std::map<long, long> cells;
    while (std::getline(rows, line)) cells[std::stol(line.substr(line.rfind(',') + 1))] = std::stol(line.substr(0, line.find(',')));
    return cells;
}

TEST_CASE("run.export_glb of a MAP-Elites run records the exported elite's cell", "[cli][engine]") {
    TempDir dir("engine-best-cell");
    std::string config = read_text(kElitesConfig);
    config.replace(config.find("\"export_every\": 1}"), 18, R"("export_every": 1, "export_glb": {"wind": true}})");
    write_text(dir.path / "elites.json", config);
    const CliResult r = run_morphogen("evolve " + q(dir.path / "elites.json") + " --out " + q(dir.path / "run"));
    INFO(r.output);
    REQUIRE(r.code == 0);
    // The last generation's best is in the final archive, in the cell its extras name.
    const tinygltf::Model model = parse_glb(read_text(dir.path / "run" / "best" / "gen_0002.glb"));
    const tinygltf::Value& extras = model.nodes.at(0).extras;
    const std::map<long, long> cells = cells_by_birth(dir.path / "run");
    REQUIRE(cells.count(extras.Get("birth_id").GetNumberAsInt()) == 1);
    CHECK(extras.Get("cell").GetNumberAsInt() == cells.at(extras.Get("birth_id").GetNumberAsInt()));
}

TEST_CASE("archive --pack packs a MAP-Elites run's elites and a GA run's population", "[cli][engine][pack]") {
    TempDir dir("engine-pack");
    const fs::path run = dir.path / "run", ga = dir.path / "ga";
    REQUIRE(run_morphogen("evolve " + q(kElitesConfig) + " --out " + q(run)).code == 0);
    REQUIRE(run_morphogen("evolve " + q(std::string(MORPHOGEN_SOURCE_DIR) + "/tests/app/fixtures/engine_best.json") +
                          " --out " + q(ga)).code == 0);
    const CliResult r = run_morphogen("archive " + q(run) + " --pack " + q(dir.path / "pack") + " --lods 2 --wind");
    INFO(r.output);
    REQUIRE(r.code == 0);
    const nlohmann::json manifest = nlohmann::json::parse(read_text(dir.path / "pack" / "manifest.json"));
    const std::map<long, long> cells = cells_by_birth(run);
    CHECK(manifest["species"].size() == cells.size());  // every elite
    CHECK(manifest["algorithm"] == "map_elites");
    long previous_cell = -1;
    for (const nlohmann::json& species : manifest["species"]) {
        const long birth = species["birth_id"].get<long>();
        CHECK(species["cell"].get<long>() == cells.at(birth));
        CHECK(species["cell"].get<long>() > previous_cell);  // cell order
        previous_cell = species["cell"].get<long>();
        const tinygltf::Model model = parse_glb(read_text(dir.path / "pack" / species["file"].get<std::string>()));
        CHECK(model.nodes.at(0).extras.Get("cell").GetNumberAsInt() == cells.at(birth));
        CHECK(model.nodes.at(0).children.size() == species["lods_written"].get<std::size_t>());  // <= 2: the chain may stop
        CHECK(species["triangles"].size() == species["lods_written"].get<std::size_t>());
    }

    REQUIRE(run_morphogen("archive " + q(ga) + " --pack " + q(dir.path / "ga_pack") + " --top 2").code == 0);
    const nlohmann::json ga_manifest = nlohmann::json::parse(read_text(dir.path / "ga_pack" / "manifest.json"));
    CHECK(ga_manifest["algorithm"] == "steady_state");
    REQUIRE(ga_manifest["species"].size() == 2);
    CHECK(ga_manifest["species"][0]["fitness"].get<double>() >= ga_manifest["species"][1]["fitness"].get<double>());
    CHECK_FALSE(ga_manifest["species"][0].contains("cell"));
    CHECK(ga_manifest["options"]["lods"] == 0);

    // --pack with --out is refused before anything is written (exit 2).
    CHECK(run_morphogen("archive " + q(run) + " --pack " + q(dir.path / "p3") + " --out " + q(dir.path / "o")).code == 2);
    CHECK_FALSE(fs::exists(dir.path / "p3"));
}

TEST_CASE("grow --wind-preset copies _WIND where engines read it; bad names and no --wind write nothing",
          "[cli][engine][wind]") {
    TempDir dir("engine-wind-presets");
    const fs::path out = dir.path / "presets.glb";
    const CliResult r =
        run_morphogen("grow --random 4 --steps 60 --wind --wind-preset uv,color --wind-preset godot -o " + q(out));
    INFO(r.output);
    REQUIRE(r.code == 0);
    const tinygltf::Model model = parse_glb(read_text(out));
    const auto& attributes = model.meshes.at(0).primitives.at(0).attributes;
    for (const char* name : {"_WIND", "COLOR_0", "TEXCOORD_0", "TEXCOORD_1", "_CUSTOM0"}) CHECK(attributes.count(name) == 1);
    CHECK(accessor_floats(model, attributes.at("_CUSTOM0")) == accessor_floats(model, attributes.at("_WIND")));

    REQUIRE(run_morphogen("grow --random 4 --steps 60 --wind -o " + q(dir.path / "plain.glb")).code == 0);
    const tinygltf::Model plain = parse_glb(read_text(dir.path / "plain.glb"));
    CHECK(plain.meshes.at(0).primitives.at(0).attributes.size() == 3);  // POSITION, NORMAL, _WIND: no COLOR_0

    const fs::path refused = dir.path / "refused.glb";
    const CliResult bad = run_morphogen("grow --random 4 --steps 60 --wind --wind-preset color,unity -o " + q(refused));
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("--wind-preset 'unity': not a preset; the presets are color, uv and godot"));
    const CliResult alone = run_morphogen("grow --random 4 --steps 60 --wind-preset uv -o " + q(refused));
    CHECK(alone.code == 2);
    CHECK_THAT(alone.output, Catch::Contains("--wind-preset uv: copies the wind data, so it needs --wind"));
    const CliResult archive = run_morphogen("archive " + q(dir.path / "no_run") + " --out " + q(dir.path / "elites") +
                                            " --wind-preset godot");
    CHECK(archive.code == 2);
    CHECK_THAT(archive.output, Catch::Contains("needs --wind"));
    CHECK_FALSE(fs::exists(refused));
    CHECK_FALSE(fs::exists(dir.path / "elites"));
}

TEST_CASE("run.export_glb.wind_presets is read as grow's --wind-preset, and refused without wind", "[cli][engine][wind]") {
    TempDir dir("engine-best-presets");
    std::string config = read_text(kElitesConfig);
    const std::size_t at = config.find("\"export_every\": 1}");
    config.replace(at, 18, R"("export_every": 1, "export_glb": {"wind": true, "wind_presets": ["color"]}})");
    write_text(dir.path / "elites.json", config);
    const CliResult r = run_morphogen("evolve " + q(dir.path / "elites.json") + " --out " + q(dir.path / "run"));
    INFO(r.output);
    REQUIRE(r.code == 0);
    const tinygltf::Model model = parse_glb(read_text(dir.path / "run" / "best" / "gen_0002.glb"));
    const auto& attributes = model.meshes.at(0).primitives.at(0).attributes;
    REQUIRE(attributes.count("COLOR_0") == 1);
    const std::vector<float> wind = accessor_floats(model, attributes.at("_WIND"));
    const std::vector<float> color = accessor_floats(model, attributes.at("COLOR_0"));
    REQUIRE(color.size() == wind.size());
    for (std::size_t v = 0; v < wind.size() / 4; ++v) CHECK(color[4 * v + 2] == wind[4 * v]);  // blue: the bend

    for (const char* bad : {R"({"wind_presets": ["uv"]})", R"({"wind": true, "wind_presets": ["unity"]})",
                            R"({"wind": true, "wind_presets": "uv"})"}) {
        std::string refused = read_text(kElitesConfig);
        refused.replace(refused.find("\"export_every\": 1}"), 18, std::string("\"export_every\": 1, \"export_glb\": ") + bad + "}");
        write_text(dir.path / "bad.json", refused);
        const CliResult no = run_morphogen("validate " + q(dir.path / "bad.json"));
        INFO(bad << "\n" << no.output);
        CHECK(no.code != 0);
        CHECK_THAT(no.output, Catch::Contains("run.export_glb.wind_presets"));
    }
}
