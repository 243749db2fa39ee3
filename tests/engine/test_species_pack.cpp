// The species pack: a GLB per plant, manifest.json true to the files,
// scatter.glb with EXT_mesh_gpu_instancing over plain nodes that stand
// apart, the same bytes for the same plants, and what it refuses.
#include "core/base/errors.hpp"
#include "engine/birth_steps.hpp"
#include "engine/plant_scatter.hpp"
#include "engine/species_pack.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/growth/network/network.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/engine/grow_dated.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

using namespace morphogen;
namespace fs = std::filesystem;

namespace {

using testing::Grown;

// A random genome grown 40 steps, with its vertices' birth steps.
Grown grow(std::uint64_t seed) { return testing::grow_dated(seed, 40); }

PlantRecord record_of(std::uint64_t id, std::optional<std::uint64_t> cell) {
    PlantRecord record;
    record.id = std::to_string(id);
    record.genome_hash = genome_hash(std::vector<double>{static_cast<double>(id)});
    record.fitness = 0.5 * static_cast<double>(id);
    record.measures = {{"height", 1.0 + static_cast<double>(id)}};
    record.run = "pack-test";
    record.birth = id;
    record.cell = cell;
    return record;
}

const PackSource kSource{.run = "pack-test", .algorithm = "map_elites", .measures = {"height"}};

// Writes a pack of the plants grown from seeds 1..n into `dir`.
void write_pack(const fs::path& dir, const std::vector<Grown>& plants, const PlantExportOptions& options) {
    SpeciesPack pack(dir, kSource, options);
    for (std::size_t i = 0; i < plants.size(); ++i)
        pack.add(plants[i].plant(), record_of(10 + i, i % 2 == 0 ? std::optional<std::uint64_t>(3 * i) : std::nullopt));
    pack.finish();
}

// The farthest a mesh's vertices reach from its node's up axis (glTF: Y-up, so x and z).
double reach(const tinygltf::Model& model, int mesh) {
    const std::vector<float> p = test::accessor_floats(model, model.meshes.at(mesh).primitives.at(0).attributes.at("POSITION"));
    double r = 0;
    for (std::size_t i = 0; i < p.size(); i += 3) r = std::max(r, std::hypot(double(p[i]), double(p[i + 2])));
    return r;
}

}  // namespace

TEST_CASE("a species pack writes a GLB per plant, a manifest true to them and the same bytes twice", "[engine]") {
    std::vector<Grown> plants;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) plants.push_back(grow(seed));
    const PlantExportOptions options{.height_m = 1.5, .lods = 2, .wind = true};
    testing::TempDir temp("pack");
    write_pack(temp.path / "a", plants, options);
    write_pack(temp.path / "b", plants, options);

    const nlohmann::json manifest = nlohmann::json::parse(testing::read_text(temp.path / "a" / "manifest.json"));
    CHECK(manifest["format"] == "morphogen species pack");
    CHECK(manifest["format_version"] == kPackFormatVersion);
    CHECK(manifest["run"] == "pack-test");
    CHECK(manifest["algorithm"] == "map_elites");
    CHECK(manifest["measures"] == nlohmann::json::array({"height"}));
    CHECK(manifest["options"] == nlohmann::json({{"height_m", 1.5}, {"lods", 2}, {"wind", true}}));
    CHECK(manifest["scatter"] == nlohmann::json({{"file", "scatter.glb"}, {"copies_per_species", kScatterCopies}}));
    REQUIRE(manifest["species"].size() == plants.size());
    std::size_t files = 0;
    int two_levels = 0;  // plants whose chain kept LOD1
    for (std::size_t i = 0; i < plants.size(); ++i) {
        const nlohmann::json& entry = manifest["species"][i];
        const std::string id = std::to_string(10 + i);
        CHECK(entry["id"] == id);
        CHECK(entry["file"] == "plant_" + id + ".glb");
        CHECK(entry["fitness"] == 0.5 * static_cast<double>(10 + i));
        CHECK(entry["measures"]["height"] == 1.0 + static_cast<double>(10 + i));
        CHECK(entry["height_m"].get<double>() == Approx(1.5).epsilon(1e-12));
        CHECK(entry.contains("cell") == (i % 2 == 0));
        CHECK_FALSE(entry.contains("run"));
        if (i % 2 == 0) CHECK(entry["cell"] == 3 * i);
        // Triangles per level: the GLB's LOD meshes, counted from their indices.
        const tinygltf::Model model = test::parse_glb(testing::read_text(temp.path / "a" / entry["file"].get<std::string>()));
        // Two levels asked; the chain stops where LOD1 cannot keep its bound (plant_lods.hpp).
        const int written = entry["lods_written"].get<int>();
        REQUIRE((written == 1 || written == 2));
        two_levels += written == 2;
        REQUIRE(entry["triangles"].size() == static_cast<std::size_t>(written));
        REQUIRE(model.nodes[0].children.size() == static_cast<std::size_t>(written));
        CHECK(model.nodes[0].extras.Get("lods_written").GetNumberAsInt() == written);
        for (int level = 0; level < written; ++level) {
            const tinygltf::Node& node = model.nodes.at(model.nodes[0].children.at(level));
            CHECK(node.name == "plant_" + id + "_LOD" + std::to_string(level));
            const auto& primitive = model.meshes.at(node.mesh).primitives.at(0);
            CHECK(model.accessors.at(primitive.indices).count == 3 * entry["triangles"][level].get<std::size_t>());
            CHECK(primitive.attributes.count("_WIND") == 1);
        }
        CHECK(model.nodes[0].extras.Get("cell").IsNumber() == (i % 2 == 0));
        ++files;
    }
    CHECK(two_levels >= 1);  // the LOD nodes are covered
    // Same plants, same bytes: every file of both packs.
    for (const auto& entry : fs::directory_iterator(temp.path / "a")) {
        INFO(entry.path().filename());
        CHECK(testing::read_text(entry.path()) == testing::read_text(temp.path / "b" / entry.path().filename()));
    }
    CHECK(files + 2 == static_cast<std::size_t>(std::distance(fs::directory_iterator(temp.path / "b"), {})));
}

TEST_CASE("scatter.glb instances every species over a plain node, the clusters apart", "[engine]") {
    std::vector<Grown> plants;
    for (std::uint64_t seed = 21; seed <= 27; ++seed) plants.push_back(grow(seed));
    testing::TempDir temp("scatter");
    write_pack(temp.path / "pack", plants, {.height_m = std::nullopt, .lods = 2, .wind = true});
    const tinygltf::Model model = test::parse_glb(testing::read_text(temp.path / "pack" / "scatter.glb"));

    CHECK(model.extensionsUsed == std::vector<std::string>{"EXT_mesh_gpu_instancing"});
    CHECK(model.extensionsRequired.empty());
    REQUIRE(model.scenes.size() == 1);
    const tinygltf::Node& root = model.nodes.at(model.scenes[0].nodes.at(0));
    CHECK(root.name == "scatter");
    REQUIRE(root.children.size() == plants.size());

    struct Copy {
        std::size_t species;
        double x, z, reach;
    };
    std::vector<Copy> copies;
    std::map<std::pair<double, double>, int> places;
    for (std::size_t i = 0; i < plants.size(); ++i) {
        const tinygltf::Node& node = model.nodes.at(root.children[i]);
        CHECK(node.name == "plant_" + std::to_string(10 + i));
        CHECK(model.meshes.at(node.mesh).primitives.at(0).attributes.count("_WIND") == 1);
        REQUIRE(node.translation.size() == 3);
        CHECK(node.translation[1] == 0.0);
        ++places[{node.translation[0], node.translation[2]}];
        const tinygltf::Value& attributes = node.extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
        const std::vector<float> t = test::accessor_floats(model, attributes.Get("TRANSLATION").GetNumberAsInt());
        const std::vector<float> r = test::accessor_floats(model, attributes.Get("ROTATION").GetNumberAsInt());
        const std::vector<float> s = test::accessor_floats(model, attributes.Get("SCALE").GetNumberAsInt());
        REQUIRE(t.size() == 3 * kScatterCopies);
        REQUIRE(r.size() == 4 * kScatterCopies);
        REQUIRE(s.size() == 3 * kScatterCopies);
        // The first copy is the plain node itself: what a client without the extension draws.
        CHECK(std::vector<float>(t.begin(), t.begin() + 3) == std::vector<float>{0, 0, 0});
        CHECK(std::vector<float>(r.begin(), r.begin() + 4) == std::vector<float>{0, 0, 0, 1});
        CHECK(std::vector<float>(s.begin(), s.begin() + 3) == std::vector<float>{1, 1, 1});
        const double plant_reach = reach(model, node.mesh);
        for (int k = 0; k < kScatterCopies; ++k) {
            CHECK(std::hypot(r[4 * k], r[4 * k + 1], r[4 * k + 2]) + r[4 * k + 3] * r[4 * k + 3] > 0);
            CHECK(r[4 * k] == 0.0f);  // turned about the up axis only: plants stay upright
            CHECK(r[4 * k + 2] == 0.0f);
            CHECK(t[3 * k + 1] == 0.0f);  // on the ground
            copies.push_back({i, node.translation[0] + t[3 * k], node.translation[2] + t[3 * k + 2],
                              plant_reach * s[3 * k]});
        }
    }
    CHECK(places.size() == plants.size());  // without the extension: one plant per species, each in its place
    for (const Copy& a : copies)
        for (const Copy& b : copies)
            if (a.species != b.species) {
                INFO("species " << a.species << " and " << b.species);
                CHECK(std::hypot(a.x - b.x, a.z - b.z) > a.reach + b.reach);  // clusters never overlap
            }
}

TEST_CASE("a species pack refuses a used directory, bad or repeated ids and an empty pack", "[engine]") {
    testing::TempDir temp("pack_refusals");
    const Grown plant = grow(7);
    fs::create_directories(temp.path / "used");
    testing::write_text(temp.path / "used" / "notes.txt", "mine");
    CHECK_THROWS_AS(SpeciesPack(temp.path / "used", kSource, {}), IoError);
    CHECK(testing::read_text(temp.path / "used" / "notes.txt") == "mine");  // nothing lost
    testing::write_text(temp.path / "file", "x");
    CHECK_THROWS_AS(SpeciesPack(temp.path / "file", kSource, {}), IoError);
    CHECK_THROWS_AS(SpeciesPack(temp.path / "bad_options", kSource, {.height_m = -1.0, .lods = 0, .wind = false}),
                    ConfigError);

    SpeciesPack pack(temp.path / "pack", kSource, {});
    CHECK_THROWS_AS(pack.finish(), std::invalid_argument);
    PlantRecord sneaky = record_of(1, std::nullopt);
    sneaky.id = "../1";
    CHECK_THROWS_AS(pack.add(plant.plant(), sneaky), std::invalid_argument);
    CHECK_FALSE(fs::exists(temp.path / "1.glb"));
    pack.add(plant.plant(), record_of(1, std::nullopt));
    CHECK_THROWS_AS(pack.add(plant.plant(), record_of(1, std::nullopt)), std::invalid_argument);
    pack.finish();
    CHECK(pack.size() == 1);
    CHECK(fs::exists(temp.path / "pack" / "plant_1.glb"));
    CHECK(fs::exists(temp.path / "pack" / "manifest.json"));
}
