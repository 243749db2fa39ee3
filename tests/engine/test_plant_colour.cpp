// Colour from growth history (docs/algorithm.md §13) on random genomes in
// both growth modes: in range, deterministic, woodier at the foot than at
// the tips, and a tint that follows the genome.
#include "engine/birth_steps.hpp"
#include "engine/plant_colour.hpp"
#include "engine/plant_export.hpp"
#include "core/base/errors.hpp"
#include "core/io/mesh_io.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/engine/grow_dated.hpp"
#include "core/growth/genome_grower.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace morphogen {
namespace {

struct Coloured {
    std::vector<Rgb> colours;
    std::vector<Vec3> positions;
    double tint = 0.5;
};

Coloured grow_coloured(std::uint64_t seed, GrowthMode mode) {
    const testing::Grown grown = testing::grow_dated(seed, 60, mode);
    const GrowthState& state = grown.state;
    const ExposureParams exposure_params{};
    const std::vector<double> exposure =
        mode == GrowthMode::branching ? final_exposure(state.mesh, exposure_params) : std::vector<double>{};
    Coloured out;
    out.positions = state.mesh.positions();
    out.tint = genome_tint(state);
    out.colours = plant_colours({.positions = state.mesh.positions(),
                                 .birth_steps = grown.births,
                                 .steps = state.steps_done,
                                 .active = state.active,
                                 .exposure = exposure,
                                 .tint = out.tint});
    return out;
}

// How brown a colour is: red over green (bark ~1.9, greens < 1).
double brownness(const Rgb& c) { return c[0] / std::max(c[1], 1e-6f); }

}  // namespace

TEST_CASE("plant colours: in range, deterministic, wood at the foot and green at the tips", "[colour]") {
    for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching}) {
        int wood_below = 0, plants = 0;
        for (std::uint64_t seed = 1; seed <= 12; ++seed) {
            const Coloured a = grow_coloured(seed, mode);
            const Coloured b = grow_coloured(seed, mode);
            REQUIRE(a.colours == b.colours);
            REQUIRE(a.colours.size() == a.positions.size());
            for (const Rgb& c : a.colours)
                for (const float x : c) REQUIRE((x >= 0.0f && x <= 1.0f));
            REQUIRE((a.tint >= 0.0 && a.tint <= 1.0));
            // The lowest and highest tenth of the vertices by height.
            std::vector<int> order(a.positions.size());
            for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
            std::sort(order.begin(), order.end(),
                      [&](int x, int y) { return a.positions[x].z() < a.positions[y].z(); });
            const std::size_t tenth = std::max<std::size_t>(order.size() / 10, 1);
            double foot = 0.0, top = 0.0;
            for (std::size_t i = 0; i < tenth; ++i) {
                foot += brownness(a.colours[order[i]]);
                top += brownness(a.colours[order[order.size() - 1 - i]]);
            }
            ++plants;
            if (foot > top) ++wood_below;
        }
        INFO("mode " << (mode == GrowthMode::paper ? "paper" : "branching"));
        CHECK(wood_below == plants);
    }
}

TEST_CASE("plant colours: the tint shifts the hue, and bad sizes are refused", "[colour]") {
    const std::vector<Vec3> positions{Vec3(0, 0, 0), Vec3(0, 0, 1)};
    const std::vector<int> births{0, 10};
    ColourInputs in;
    in.positions = positions;
    in.birth_steps = births;
    in.steps = 10;
    in.tint = 0.0;
    const std::vector<Rgb> low = plant_colours(in);
    in.tint = 1.0;
    const std::vector<Rgb> high = plant_colours(in);
    CHECK(low[1] != high[1]);
    // The seed's vertex at the foot is bark; the newest at the top foliage.
    CHECK(brownness(low[0]) > 1.5);
    CHECK(brownness(high[1]) < 1.0);
    const std::vector<int> short_births{0};
    in.birth_steps = short_births;
    CHECK_THROWS_AS(plant_colours(in), std::invalid_argument);
}

TEST_CASE("colour (--colour) writes COLOR_0 on every level with a white material; the colour preset is refused with it",
          "[colour]") {
    const testing::Grown grown = grow_dated(7, 50);
    const GrowthState& state = grown.state;
    const std::vector<Rgb> colours = plant_colours(
        {.positions = state.mesh.positions(), .birth_steps = grown.births, .steps = 50, .active = state.active,
         .exposure = {}, .tint = genome_tint(state)});
    const std::vector<float> rgba = colour_rgba(colours);
    PlantRecord record;
    record.id = "c";
    record.genome_hash = "0123456789abcdef";
    const GrownPlant plant{.mesh = state.mesh.view(), .birth_steps = grown.births, .steps = 50, .colours = rgba};
    for (const int lods : {0, 3}) {
        PlantExportOptions options;
        options.lods = lods;
        options.colour = true;
        const tinygltf::Model model = test::parse_glb(plant_glb_bytes(plant, record, options, "test"));
        CHECK(model.materials.at(0).pbrMetallicRoughness.baseColorFactor == std::vector<double>{1, 1, 1, 1});
        REQUIRE(!model.meshes.empty());
        for (const tinygltf::Mesh& mesh : model.meshes) {
            const auto& attributes = mesh.primitives.at(0).attributes;
            REQUIRE(attributes.count("COLOR_0") == 1);
            const tinygltf::Accessor& acc = model.accessors.at(attributes.at("COLOR_0"));
            CHECK(acc.type == TINYGLTF_TYPE_VEC4);
            CHECK(acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
            CHECK(acc.count == model.accessors.at(attributes.at("POSITION")).count);
            const std::vector<float> values = test::accessor_floats(model, attributes.at("COLOR_0"));
            for (const float x : values) REQUIRE((x >= 0.0f && x <= 1.0f));
            if (lods == 0) CHECK(values == rgba);
        }
    }
    // Without --colour the material keeps its green and no COLOR_0 is written.
    PlantExportOptions plain;
    plain.lods = 2;
    const tinygltf::Model model = test::parse_glb(plant_glb_bytes(plant, record, plain, "test"));
    CHECK(model.materials.at(0).pbrMetallicRoughness.baseColorFactor[0] == 0.33);
    for (const tinygltf::Mesh& mesh : model.meshes) CHECK(mesh.primitives.at(0).attributes.count("COLOR_0") == 0);

    PlantExportOptions clash;
    clash.wind = true;
    clash.colour = true;
    clash.wind_presets = {WindPreset::color};
    CHECK(plant_export_problem(clash).starts_with("--colour and --wind-preset color both write COLOR_0"));
    CHECK_THROWS_AS(plant_glb_bytes(plant, record, clash, "test"), ConfigError);
    clash.wind_presets = {WindPreset::uv};
    CHECK(plant_export_problem(clash).empty());
    PlantExportOptions short_colours;
    short_colours.colour = true;
    const GrownPlant bad{.mesh = state.mesh.view(), .birth_steps = grown.births, .steps = 50,
                         .colours = std::span<const float>(rgba).first(8)};
    CHECK_THROWS_AS(plant_glb_bytes(bad, record, short_colours, "test"), std::invalid_argument);
}

TEST_CASE("OBJ and PLY carry the colours (sRGB) and still read back as the same mesh", "[colour]") {
    const testing::Grown grown = grow_dated(5, 40);
    const GrowthParams params{};
    const std::vector<float> rgba = growth_colours(grown.state, grown.births, params);
    const MeshView mesh = grown.state.mesh.view();
    MeshWriteOptions options;
    options.colours = rgba;
    const std::string obj = encode_mesh(mesh, mesh_format_from_path("x.obj"), options);
    std::istringstream lines(obj);
    std::string line;
    std::size_t v = 0;
    while (std::getline(lines, line)) {
        if (!line.starts_with("v ")) continue;
        std::istringstream fields(line.substr(2));
        double x[6];
        for (double& f : x) REQUIRE(static_cast<bool>(fields >> f));
        for (int k = 0; k < 3; ++k) CHECK(std::abs(x[3 + k] - srgb_encode(rgba[4 * v + k])) < 1e-6);
        ++v;
    }
    CHECK(v == mesh.positions.size());
    CHECK(parse_mesh(obj, mesh_format_from_path("x.obj"), "test.obj").positions.size() == mesh.positions.size());
    const std::string ply = encode_mesh(mesh, mesh_format_from_path("x.ply"), options);
    CHECK(ply.find("property uchar red\nproperty uchar green\nproperty uchar blue\n") != std::string::npos);
    const std::string plain = encode_mesh(mesh, mesh_format_from_path("x.ply"), {});
    const std::size_t header_lines = 60;  // the three "property uchar ..." lines
    CHECK(ply.size() == plain.size() + header_lines + 3 * mesh.positions.size());
    // The first vertex's colour bytes follow its 6 floats.
    const std::size_t body = ply.find("end_header\n") + 11;
    for (int k = 0; k < 3; ++k)
        CHECK(static_cast<unsigned char>(ply[body + 24 + k]) == std::lround(255.0 * srgb_encode(rgba[k])));
    const MeshArrays back = parse_mesh(ply, mesh_format_from_path("x.ply"), "test.ply");
    CHECK(back.positions.size() == mesh.positions.size());
    CHECK(back.faces.size() == mesh.faces.size());
    options.colours = std::span<const float>(rgba).first(4);
    CHECK_THROWS_AS(encode_mesh(mesh, mesh_format_from_path("x.obj"), options), std::invalid_argument);
}

}  // namespace morphogen
