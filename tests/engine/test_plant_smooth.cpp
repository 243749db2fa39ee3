// --smooth N (engine/plant_smooth.hpp): Loop subdivision of grown plants in
// both growth modes keeps them closed and free of self-intersections, makes
// 4^N times the triangles, carries colours and wind data in range, and
// refuses rounds outside 0..3; the engine-ready GLB's LOD0 is the smoothed mesh.
#include "engine/birth_steps.hpp"
#include "engine/plant_colour.hpp"
#include "engine/plant_export.hpp"
#include "engine/plant_lods.hpp"
#include "engine/plant_smooth.hpp"
#include "engine/plant_wind.hpp"
#include "core/growth/genome_grower.hpp"
#include "fitness/geometry/cgal_geometry.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/engine/grow_dated.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace morphogen {
namespace {

struct SmoothPlant {
    GrowthState state;
    std::vector<int> births;
    std::vector<float> colours;
};

SmoothPlant grow_for_smoothing(std::uint64_t seed, GrowthMode mode) {
    testing::Grown grown = testing::grow_dated(seed, 60, mode);
    GrowthParams growth;
    growth.steps = 60;
    growth.mode = mode;
    SmoothPlant out{std::move(grown.state), std::move(grown.births), {}};
    out.colours = growth_colours(out.state, out.births, growth);
    return out;
}

bool in_unit_range(const std::vector<float>& values) {
    return std::all_of(values.begin(), values.end(), [](float v) { return v >= 0.0f && v <= 1.0f; });
}

}  // namespace

TEST_CASE("smoothing grown plants keeps them closed and clean, 4^N triangles, attributes in range",
          "[smooth][engine]") {
    int checked = 0;
    for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching})
        for (std::uint64_t seed = 1; seed <= 12; ++seed) {
            const SmoothPlant plant = grow_for_smoothing(seed, mode);
            const MeshView mesh = plant.state.mesh.view();
            if (mesh_self_intersects(mesh)) continue;  // smoothing promises clean only of clean input
            ++checked;
            const std::vector<float> wind = plant_wind(mesh, plant.births, plant.state.steps_done);
            const std::span<const float> carried[] = {plant.colours, wind};
            for (int rounds = 1; rounds <= 2; ++rounds) {
                INFO("mode " << (mode == GrowthMode::paper ? "paper" : "branching") << ", seed " << seed << ", "
                             << rounds << " rounds");
                const SmoothedMesh smooth = smooth_mesh(mesh, rounds, carried);
                const std::size_t factor = std::size_t{1} << (2 * rounds);
                CHECK(smooth.mesh.faces.size() == factor * mesh.faces.size());
                // Euler: V - E + F = 2, E = 3F/2, so V = F/2 + 2.
                CHECK(smooth.mesh.positions.size() == smooth.mesh.faces.size() / 2 + 2);
                CHECK(is_closed_manifold(smooth.mesh.view()));
                CHECK_FALSE(mesh_self_intersects(smooth.mesh.view()));
                REQUIRE(smooth.attributes.size() == 2);
                CHECK(smooth.attributes[0].size() == 4 * smooth.mesh.positions.size());
                CHECK(smooth.attributes[1].size() == 4 * smooth.mesh.positions.size());
                CHECK(in_unit_range(smooth.attributes[0]));
                // Loop moves the old vertices' values too: a blend, not a copy.
                CHECK(smooth.attributes[0] != std::vector<float>(plant.colours.begin(), plant.colours.end()));
            }
        }
    CHECK(checked >= 16);  // of 24 plants; the others already touch themselves as grown
}

TEST_CASE("smoothing refuses rounds outside 0..3 and attributes of the wrong length", "[smooth][engine]") {
    const SmoothPlant plant = grow_for_smoothing(3, GrowthMode::paper);
    const MeshView mesh = plant.state.mesh.view();
    for (const int bad : {-1, 4, 100}) {
        CHECK_THROWS_WITH(smooth_mesh(mesh, bad), Catch::Contains("--smooth " + std::to_string(bad)) &&
                                                       Catch::Contains("0 to 3"));
        PlantExportOptions options;
        options.smooth = bad;
        CHECK_THAT(plant_export_problem(options), Catch::Contains("--smooth"));
    }
    const std::vector<float> short_colours(5, 0.5f);
    const std::span<const float> carried[] = {short_colours};
    CHECK_THROWS_WITH(smooth_mesh(mesh, 1, carried), Catch::Contains("5 floats"));
    const SmoothedMesh none = smooth_mesh(mesh, 0);
    CHECK(none.mesh.positions == plant.state.mesh.positions());
    CHECK(none.mesh.faces == plant.state.mesh.faces());
}

TEST_CASE("smooth: the GLB's LOD0 is the smoothed plant with its colours; the other levels are not",
          "[smooth][engine]") {
    const SmoothPlant plant = grow_for_smoothing(5, GrowthMode::branching);
    GrownPlant grown{.mesh = plant.state.mesh.view(), .birth_steps = plant.births, .steps = plant.state.steps_done};
    grown.colours = plant.colours;
    PlantRecord record;
    record.id = "1";
    PlantExportOptions options;
    options.colour = true;
    options.wind = true;
    options.lods = 2;
    const EnginePlant plain = make_engine_plant(grown, record, options);
    options.smooth = 2;
    const EnginePlant smooth = make_engine_plant(grown, record, options);
    REQUIRE(smooth.levels.size() == plain.levels.size());
    CHECK(smooth.levels[0].faces.size() == 16 * plain.levels[0].faces.size());
    CHECK(smooth.colours[0].size() == 4 * smooth.levels[0].positions.size());
    CHECK(smooth.wind[0].size() == 4 * smooth.levels[0].positions.size());
    for (std::size_t i = 1; i < smooth.levels.size(); ++i) CHECK(smooth.levels[i].faces == plain.levels[i].faces);
    CHECK(smooth.extras["smooth"] == 2);
    const tinygltf::Model model = test::parse_glb(plant_glb_bytes(smooth, "smooth"));
    CHECK(model.accessors.at(static_cast<std::size_t>(model.meshes.at(0).primitives.at(0).attributes.at("COLOR_0"))).count ==
          smooth.levels[0].positions.size());
}

}  // namespace morphogen

namespace morphogen {

TEST_CASE("grow_dated: one growth gives the step observer's state and birth steps", "[engine][colour][leaves]") {
    for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching})
        for (std::uint64_t seed = 1; seed <= 8; ++seed) {
            GrowthParams growth;
            growth.steps = 80;
            growth.mode = mode;
            growth.collisions = Collisions::touch;  // the fail-safe: its state is the growth stopped early
            const GenomeGrower grower(NetworkParams{}, growth);
            const Network network(testing::random_test_genome(grower.layers(), seed));
            BirthSteps observed(grower.seed().mesh.num_vertices());
            GrowthWorkspace workspace;
            const GrowthState twice = grower.grow(network, workspace, observed.observer());
            std::vector<int> births;
            const GrowthState once = grower.grow_dated(network, workspace, births);
            INFO("seed " << seed);
            CHECK(once.steps_done == twice.steps_done);
            CHECK(once.mesh.positions() == twice.mesh.positions());
            CHECK(once.mesh.faces() == twice.mesh.faces());
            CHECK(births == observed.steps());
        }
}

}  // namespace morphogen
