// --leaves through the real executable: grow writes the same leafy GLB
// twice; archive, archive --pack and run.export_glb carry the cards; every
// refusal names its option or key and writes nothing.
#include "tests/app/evolve_test_support.hpp"
#include "tests/engine/glb_reader.hpp"

#include <catch2/catch.hpp>

// In the namespace rather than `using` it: this file shares a unity batch.
namespace morphogen::test {
namespace {

// The cards of a plant GLB's first mesh: its second primitive's vertices / 4.
int leaf_cards_of(const tinygltf::Model& model) {
    const auto& primitives = model.meshes.at(0).primitives;
    if (primitives.size() < 2) return 0;
    return static_cast<int>(model.accessors.at(static_cast<std::size_t>(primitives[1].attributes.at("POSITION"))).count / 4);
}

}  // namespace

TEST_CASE("grow --leaves writes the cards as a second primitive, the same bytes every time", "[cli][leaves]") {
    TempDir dir("leaves-grow");
    const std::string args = " --leaves --leaf-size 0.05 --leaf-density 0.8 --lods 2 --wind";
    const CliResult a = run_morphogen("grow --random 4 --steps 150 -o " + q(dir.path / "a.glb") + args);
    INFO(a.output);
    REQUIRE(a.code == 0);
    REQUIRE(run_morphogen("grow --random 4 --steps 150 -o " + q(dir.path / "b.glb") + args).code == 0);
    const std::string bytes = read_text(dir.path / "a.glb");
    CHECK(bytes == read_text(dir.path / "b.glb"));
    const tinygltf::Model model = parse_glb(bytes);
    const tinygltf::Value& extras = model.nodes.at(0).extras;
    CHECK(extras.Get("leaf_size").GetNumberAsDouble() == Approx(0.05));
    CHECK(extras.Get("leaf_density").GetNumberAsDouble() == Approx(0.8));
    const int cards = extras.Get("leaves").GetNumberAsInt();
    CHECK(cards > 0);
    CHECK(leaf_cards_of(model) == cards);
    CHECK(model.materials.at(1).alphaMode == "MASK");
    // Branching mode: exposure decides which vertices are lit.
    const CliResult tree = run_morphogen("grow --config " + q(std::string(MORPHOGEN_SOURCE_DIR) + "/configs/tree.json") +
                                         " --random 5 --steps 120 --leaves -o " + q(dir.path / "tree.glb"));
    INFO(tree.output);
    REQUIRE(tree.code == 0);
    CHECK(parse_glb(read_text(dir.path / "tree.glb")).nodes.at(0).extras.Get("leaves").IsNumber());
}

TEST_CASE("leaves: refusals of --leaves name the option and write nothing", "[cli][leaves]") {
    TempDir dir("leaves-refused");
    const std::string out = q(dir.path / "x.glb");
    const struct {
        std::string args, message;
    } refused[] = {
        {"--leaves -o " + q(dir.path / "x.obj"), "--leaves: writes an engine-ready GLB, so the output must be .glb"},
        {"--leaves --leaf-size 0 -o " + out, "--leaf-size 0: must be a fraction of the plant's height above 0 and at most 0.5"},
        {"--leaves --leaf-size 0.7 -o " + out, "--leaf-size 0.7: must be"},
        {"--leaves --leaf-size nan -o " + out, "--leaf-size"},
        {"--leaves --leaf-density 0 -o " + out, "--leaf-density 0: must be a fraction of the eligible vertices"},
        {"--leaves --leaf-density 1.5 -o " + out, "--leaf-density 1.5: must be"},
        {"--leaf-size 0.1 -o " + out, "--leaf-size 0.1: shapes the cards of --leaves, so it needs --leaves"},
        {"--leaf-density 0.3 -o " + out, "--leaf-density 0.3: shapes the cards of --leaves, so it needs --leaves"},
    };
    for (const auto& [args, message] : refused) {
        const CliResult r = run_morphogen("grow --random 3 --steps 20 " + args);
        INFO(args << "\n" << r.output);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains(message));
        CHECK(fs::is_empty(dir.path));
    }
    write_text(dir.path / "bad.json", R"({"run": {"export_glb": {"leaf_size": 0.1, "leaf_density": 2}}})");
    const CliResult bad = run_morphogen("validate " + q(dir.path / "bad.json"));
    INFO(bad.output);
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("run.export_glb.leaf_size") && Catch::Contains("needs it") &&
                               Catch::Contains("run.export_glb.leaf_density"));
}

TEST_CASE("archive --leaves, archive --pack --leaves and run.export_glb.leaves carry the cards", "[cli][leaves]") {
    TempDir dir("leaves-archive");
    const std::string elites = std::string(MORPHOGEN_SOURCE_DIR) + "/tests/app/fixtures/engine_elites.json";
    const fs::path run = dir.path / "run";
    REQUIRE(run_morphogen("evolve " + q(elites) + " --out " + q(run)).code == 0);
    const CliResult archived = run_morphogen("archive " + q(run) + " --out " + q(dir.path / "elites") + " --leaves");
    INFO(archived.output);
    REQUIRE(archived.code == 0);
    int with_cards = 0, files = 0;
    for (const auto& entry : fs::directory_iterator(dir.path / "elites")) {
        if (entry.path().extension() != ".glb") continue;
        const tinygltf::Model model = parse_glb(read_text(entry.path()));
        CHECK(leaf_cards_of(model) == model.nodes.at(0).extras.Get("leaves").GetNumberAsInt());
        with_cards += leaf_cards_of(model) > 0, ++files;
    }
    CHECK(files > 0);
    CHECK(with_cards > 0);
    const CliResult packed = run_morphogen("archive " + q(run) + " --pack " + q(dir.path / "pack") + " --leaves --lods 2");
    INFO(packed.output);
    REQUIRE(packed.code == 0);
    const nlohmann::json manifest = nlohmann::json::parse(read_text(dir.path / "pack" / "manifest.json"));
    bool leaves_listed = false;
    for (const auto& species : manifest.at("species")) leaves_listed = leaves_listed || species.contains("leaves");
    CHECK(leaves_listed);

    std::string config = read_text(elites);
    config.replace(config.find("\"export_every\": 1}"), 18, R"("export_every": 1, "export_glb": {"leaves": true, "leaf_size": 0.08}})");
    write_text(dir.path / "leafy.json", config);
    const CliResult best = run_morphogen("evolve " + q(dir.path / "leafy.json") + " --out " + q(dir.path / "leafy"));
    INFO(best.output);
    REQUIRE(best.code == 0);
    const tinygltf::Model model = parse_glb(read_text(dir.path / "leafy" / "best" / "gen_0000.glb"));
    CHECK(model.nodes.at(0).extras.Get("leaf_size").GetNumberAsDouble() == Approx(0.08));
}

}  // namespace morphogen::test
