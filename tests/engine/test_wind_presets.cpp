// Wind presets (engine/plant_wind.hpp): each preset's attributes hold _WIND's
// own values per vertex, on every level of detail; without presets the GLB
// keeps only POSITION, NORMAL and _WIND; presets without wind are refused.
#include "core/base/errors.hpp"
#include "engine/birth_steps.hpp"
#include "engine/plant_export.hpp"
#include "engine/plant_scatter.hpp"
#include "engine/plant_wind.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/io/plant_glb.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/engine/grow_dated.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <set>

using namespace morphogen;

namespace {

using testing::Grown;
using testing::grow_dated;

PlantRecord record_w() {
    PlantRecord record;
    record.id.assign(1, 'w');  // (GCC 12 misreads assigning a one-letter literal here: -Wrestrict)
    record.genome_hash = "0123456789abcdef";
    return record;
}

// Where each preset puts each _WIND channel (0 bend, 1 flutter, 2 phase,
// 3 stiffness), written out from docs/game-engines.md's table, not from the code.
struct Channel {
    const char* attribute;
    int component;
};
const std::map<std::string, std::vector<std::pair<int, Channel>>> kLayout = {
    {"color", {{1, {"COLOR_0", 0}}, {2, {"COLOR_0", 1}}, {0, {"COLOR_0", 2}}, {3, {"COLOR_0", 3}}}},
    {"uv", {{0, {"TEXCOORD_0", 0}}, {1, {"TEXCOORD_0", 1}}, {2, {"TEXCOORD_1", 0}}, {3, {"TEXCOORD_1", 1}}}},
    {"godot", {{0, {"_CUSTOM0", 0}}, {1, {"_CUSTOM0", 1}}, {2, {"_CUSTOM0", 2}}, {3, {"_CUSTOM0", 3}}}},
};

std::set<std::string> attribute_names(const tinygltf::Primitive& primitive) {
    std::set<std::string> names;
    for (const auto& [name, accessor] : primitive.attributes) names.insert(name);
    return names;
}

}  // namespace

TEST_CASE("wind presets are named color, uv and godot, and nothing else", "[engine][wind]") {
    for (const std::string_view name : kWindPresetNames) {
        REQUIRE(wind_preset_named(name).has_value());
        CHECK(wind_preset_name(*wind_preset_named(name)) == name);
    }
    CHECK_FALSE(wind_preset_named("Color").has_value());
    CHECK_FALSE(wind_preset_named("unity").has_value());
    CHECK_FALSE(wind_preset_named("").has_value());
    CHECK_THROWS_AS(wind_preset_attributes(std::vector<float>(6, 0.5f), std::vector{WindPreset::uv}),
                    std::invalid_argument);
}

TEST_CASE("each preset copies _WIND's values per vertex on every level", "[engine][wind][lods]") {
    const Grown grown = grow_dated(12, 120);
    const GrownPlant plant{.mesh = grown.state.mesh.view(), .birth_steps = grown.births, .steps = 120};
    for (const auto& [preset_name, layout] : kLayout) {
        INFO(preset_name);
        const PlantExportOptions options{.height_m = 2.0, .lods = 2, .wind = true,
                                         .wind_presets = {*wind_preset_named(preset_name)}};
        const tinygltf::Model model = test::parse_glb(plant_glb_bytes(plant, record_w(), options, "test"));
        REQUIRE(model.meshes.size() == 2);
        for (const tinygltf::Mesh& mesh : model.meshes) {
            const tinygltf::Primitive& primitive = mesh.primitives.at(0);
            const std::size_t vertices = model.accessors.at(primitive.attributes.at("POSITION")).count;
            const std::vector<float> wind = test::accessor_floats(model, primitive.attributes.at("_WIND"));
            REQUIRE(wind.size() == 4 * vertices);
            std::map<std::string, std::vector<float>> copies;
            for (const auto& [channel, where] : layout) {
                REQUIRE(primitive.attributes.count(where.attribute) == 1);
                const tinygltf::Accessor& acc = model.accessors.at(primitive.attributes.at(where.attribute));
                CHECK(acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
                CHECK(acc.count == vertices);
                copies.try_emplace(where.attribute, test::accessor_floats(model, primitive.attributes.at(where.attribute)));
            }
            CHECK(attribute_names(primitive).size() == 3 + copies.size());  // POSITION, NORMAL, _WIND and the copies
            for (const auto& [channel, where] : layout) {
                const std::vector<float>& copy = copies.at(where.attribute);
                const std::size_t width = copy.size() / vertices;
                std::size_t differ = 0;
                for (std::size_t v = 0; v < vertices; ++v)
                    differ += copy[width * v + static_cast<std::size_t>(where.component)] != wind[4 * v + static_cast<std::size_t>(channel)];
                CHECK(differ == 0);
            }
        }
        const tinygltf::Value& names = model.nodes.at(0).extras.Get("wind_presets");
        REQUIRE(names.IsArray());
        CHECK(names.Get(0).Get<std::string>() == preset_name);
    }
}

TEST_CASE("presets are written in one order whatever the order asked, once each", "[engine][wind]") {
    const Grown grown = grow_dated(5, 60);
    const GrownPlant plant{.mesh = grown.state.mesh.view(), .birth_steps = grown.births, .steps = 60};
    const PlantExportOptions forward{.height_m = std::nullopt, .lods = 0, .wind = true,
                                     .wind_presets = {WindPreset::color, WindPreset::uv, WindPreset::godot}};
    const PlantExportOptions backward{.height_m = std::nullopt, .lods = 0, .wind = true,
                                      .wind_presets = {WindPreset::godot, WindPreset::uv, WindPreset::uv,
                                                       WindPreset::color}};
    const std::string bytes = plant_glb_bytes(plant, record_w(), forward, "test");
    CHECK(bytes == plant_glb_bytes(plant, record_w(), backward, "test"));
    const tinygltf::Model model = test::parse_glb(bytes);
    CHECK(attribute_names(model.meshes.at(0).primitives.at(0)) ==
          std::set<std::string>{"POSITION", "NORMAL", "_WIND", "COLOR_0", "TEXCOORD_0", "TEXCOORD_1", "_CUSTOM0"});
}

TEST_CASE("without presets the GLB holds _WIND alone, and presets only append to its buffer", "[engine][wind]") {
    const Grown grown = grow_dated(9, 60);
    const GrownPlant plant{.mesh = grown.state.mesh.view(), .birth_steps = grown.births, .steps = 60};
    const PlantExportOptions plain{.height_m = 3.0, .lods = 0, .wind = true};
    const PlantExportOptions all{.height_m = 3.0, .lods = 0, .wind = true,
                                 .wind_presets = {WindPreset::color, WindPreset::uv, WindPreset::godot}};
    const tinygltf::Model without = test::parse_glb(plant_glb_bytes(plant, record_w(), plain, "test"));
    const tinygltf::Model with = test::parse_glb(plant_glb_bytes(plant, record_w(), all, "test"));
    CHECK(attribute_names(without.meshes.at(0).primitives.at(0)) == std::set<std::string>{"POSITION", "NORMAL", "_WIND"});
    CHECK_FALSE(without.nodes.at(0).extras.Has("wind_presets"));
    const std::vector<unsigned char>& before = without.buffers.at(0).data;
    const std::vector<unsigned char>& after = with.buffers.at(0).data;
    REQUIRE(after.size() > before.size());
    CHECK(std::equal(before.begin(), before.end(), after.begin()));
}

TEST_CASE("presets without wind are refused, naming the option", "[engine][wind]") {
    const PlantExportOptions options{.height_m = std::nullopt, .lods = 0, .wind = false,
                                     .wind_presets = {WindPreset::uv}};
    CHECK_THAT(plant_export_problem(options), Catch::StartsWith("--wind-preset uv") && Catch::Contains("--wind"));
    const Grown grown = grow_dated(3, 20);
    CHECK_THROWS_AS(plant_glb_bytes({.mesh = grown.state.mesh.view(), .birth_steps = grown.births, .steps = 20},
                                    record_w(), options, "test"),
                    ConfigError);
}

TEST_CASE("a level's further attribute must fit its vertices and take a free name", "[io][wind]") {
    const Grown grown = grow_dated(3, 20);
    const MeshView mesh = grown.state.mesh.view();
    const std::size_t n = mesh.positions.size();
    const auto glb = [&](std::vector<VertexAttribute> attributes) {
        PlantGlb plant{.name = "plant_w", .extras = nlohmann::json::object(), .levels = {}, .lod_nodes = false};
        plant.levels.push_back(PlantLevel{.mesh = mesh, .wind = {}, .attributes = std::move(attributes), .extras = {}});
        return plant_glb_bytes(plant, "test");
    };
    CHECK_NOTHROW(glb({{.name = "TEXCOORD_0", .components = 2, .values = std::vector<float>(2 * n, 0.5f)}}));
    CHECK_THROWS_AS(glb({{.name = "TEXCOORD_0", .components = 2, .values = std::vector<float>(2 * n + 2, 0.5f)}}),
                    std::invalid_argument);
    CHECK_THROWS_AS(glb({{.name = "POSITION", .components = 3, .values = std::vector<float>(3 * n, 0.5f)}}),
                    std::invalid_argument);
    CHECK_THROWS_AS(glb({{.name = "_X", .components = 5, .values = std::vector<float>(5 * n, 0.5f)}}),
                    std::invalid_argument);
}

TEST_CASE("a species pack's scatter carries the presets of its plants", "[engine][wind][pack]") {
    const Grown grown = grow_dated(13, 60);
    const GrownPlant plant{.mesh = grown.state.mesh.view(), .birth_steps = grown.births, .steps = 60};
    const PlantExportOptions options{.height_m = std::nullopt, .lods = 0, .wind = true,
                                     .wind_presets = {WindPreset::color}};
    const std::vector<EnginePlant> plants{make_engine_plant(plant, record_w(), options)};
    const tinygltf::Model model = test::parse_glb(plant_scatter_bytes(plants, "run", "test"));
    const tinygltf::Primitive& primitive = model.meshes.at(0).primitives.at(0);
    REQUIRE(primitive.attributes.count("COLOR_0") == 1);
    const std::vector<float> wind = test::accessor_floats(model, primitive.attributes.at("_WIND"));
    const std::vector<float> color = test::accessor_floats(model, primitive.attributes.at("COLOR_0"));
    REQUIRE(color.size() == wind.size());
    for (std::size_t v = 0; v < wind.size() / 4; ++v) {
        CHECK(color[4 * v] == wind[4 * v + 1]);
        CHECK(color[4 * v + 2] == wind[4 * v]);
    }
}
