// Wind data: birth steps seen through the grower's observer, the four
// channels of _WIND, and the attribute in the GLB (and nothing in COLOR_0).
#include "engine/birth_steps.hpp"
#include "engine/plant_export.hpp"
#include "engine/plant_frame.hpp"
#include "engine/plant_wind.hpp"
#include "core/growth/genome_grower.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/engine/grow_dated.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace morphogen;

using testing::Grown;
using testing::grow_dated;

TEST_CASE("birth steps date every vertex without changing growth", "[engine][wind]") {
    const Grown grown = grow_dated(3, 60);
    GrowthParams growth;
    growth.steps = 60;
    const GenomeGrower grower(NetworkParams{}, growth);
    const GrowthState plain = grower.grow(testing::random_test_genome(grower.layers(), 3).params);
    CHECK(plain.mesh.positions() == grown.state.mesh.positions());
    REQUIRE(grown.births.size() == static_cast<std::size_t>(grown.state.mesh.num_vertices()));
    CHECK(std::is_sorted(grown.births.begin(), grown.births.end()));
    CHECK(grown.births.front() == 0);
    CHECK(grown.births.back() >= 1);
    CHECK(grown.births.back() <= 60);
    CHECK(std::count(grown.births.begin(), grown.births.end(), 0) == grower.seed().mesh.num_vertices());
}

TEST_CASE("the four wind channels lie in [0, 1] and mean what the docs say", "[engine][wind]") {
    const Grown grown = grow_dated(5, 80);
    const PlacedPlant placed = place_plant(grown.state.mesh.view(), 3.0);
    const std::vector<float> wind = plant_wind(placed.mesh.view(), grown.births, 80);
    const std::size_t n = placed.mesh.positions.size();
    REQUIRE(wind.size() == 4 * n);
    float top_bend = 0;
    double foot_stiffness = 0, tip_stiffness = 0;
    int foot = 0, tips = 0;
    for (std::size_t v = 0; v < n; ++v) {
        for (int k = 0; k < 4; ++k) {
            CHECK(wind[4 * v + k] >= 0.0f);
            CHECK(wind[4 * v + k] <= 1.0f);
        }
        top_bend = std::max(top_bend, wind[4 * v]);
        CHECK(wind[4 * v + 1] == Approx(grown.births[v] / 80.0));
        if (placed.mesh.positions[v].z() <= kFootBand * placed.height_m) {
            CHECK(wind[4 * v] == 0.0f);  // the foot does not bend
            foot_stiffness += wind[4 * v + 3], ++foot;
        }
        if (wind[4 * v] > 0.8f) tip_stiffness += wind[4 * v + 3], ++tips;
    }
    CHECK(top_bend == 1.0f);
    REQUIRE(foot > 0);
    REQUIRE(tips > 0);
    CHECK(foot_stiffness / foot > tip_stiffness / tips);
    CHECK(plant_wind(placed.mesh.view(), grown.births, 80) == wind);  // reproducible
    CHECK_THROWS_AS(plant_wind(placed.mesh.view(), std::vector<int>(3, 0), 80), std::invalid_argument);
}

TEST_CASE("wind data is a _WIND VEC4 attribute, and COLOR_0 stays out", "[engine][wind]") {
    const Grown grown = grow_dated(7, 50);
    PlantRecord record;
    record.id = "w";
    record.genome_hash = "0123456789abcdef";
    const GrownPlant plant{.mesh = grown.state.mesh.view(), .birth_steps = grown.births, .steps = 50};
    const tinygltf::Model model =
        test::parse_glb(plant_glb_bytes(plant, record, {.height_m = std::nullopt, .lods = 0, .wind = true}, "test"));
    const auto& attributes = model.meshes.at(0).primitives.at(0).attributes;
    REQUIRE(attributes.count("_WIND") == 1);
    CHECK(attributes.count("COLOR_0") == 0);
    const tinygltf::Accessor& acc = model.accessors.at(attributes.at("_WIND"));
    CHECK(acc.type == TINYGLTF_TYPE_VEC4);
    CHECK(acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
    CHECK(acc.count == static_cast<std::size_t>(grown.state.mesh.num_vertices()));
    const std::vector<float> values = test::accessor_floats(model, attributes.at("_WIND"));
    CHECK(*std::max_element(values.begin(), values.end()) <= 1.0f);
    CHECK(*std::min_element(values.begin(), values.end()) >= 0.0f);
    CHECK(model.nodes.at(0).extras.Get("wind").Get<std::string>() == "_WIND");
    // Wind without birth steps cannot be made.
    CHECK_THROWS(plant_glb_bytes({.mesh = grown.state.mesh.view(), .birth_steps = {}, .steps = 50}, record,
                                 {.height_m = std::nullopt, .lods = 0, .wind = true}, "test"));
}
