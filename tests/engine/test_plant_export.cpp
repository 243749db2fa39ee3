// The engine-ready GLB: placed at the foot, scaled, named, its record in
// extras, the same bytes for the same plant, bad options refused.
#include "core/base/errors.hpp"
#include "engine/plant_export.hpp"
#include "engine/plant_frame.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/growth/network/network.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace morphogen;

namespace {

// A genome grown with the default growth, 40 steps: a real plant.
GrowthState grown_plant(std::uint64_t seed) {
    GrowthParams growth;
    growth.steps = 40;
    const GenomeGrower grower(NetworkParams{}, growth);
    return grower.grow(testing::random_test_genome(grower.layers(), seed).params);
}

PlantRecord sample_record() {
    PlantRecord record;
    record.id = "17";
    record.genome_hash = genome_hash(std::vector<double>{1.0, -2.5});
    record.fitness = 3.25;
    record.measures = {{"height", 1.5}, {"footprint", 0.75}};
    record.run = "tree";
    record.birth = 17;
    record.parents = {4, 9};
    record.cell = 12;
    return record;
}

}  // namespace

TEST_CASE("place_plant puts the centre of the foot at the origin and the lowest point at 0", "[engine]") {
    const GrowthState state = grown_plant(3);
    const PlacedPlant placed = place_plant(state.mesh.view(), std::nullopt);
    double lowest = std::numeric_limits<double>::infinity(), top = -lowest;
    for (const Vec3& p : placed.mesh.positions) lowest = std::min(lowest, p.z()), top = std::max(top, p.z());
    CHECK(lowest == 0.0);
    CHECK(placed.metres_per_unit == 1.0);
    CHECK(placed.height_m == Approx(top));
    Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const Vec3& p : placed.mesh.positions)
        if (p.z() <= kFootBand * top) lo = lo.cwiseMin(p.head<2>()), hi = hi.cwiseMax(p.head<2>());
    CHECK(((lo + hi) / 2).norm() < 1e-12);
    CHECK(placed.mesh.faces.size() == static_cast<std::size_t>(state.mesh.num_faces()));

    const PlacedPlant tall = place_plant(state.mesh.view(), 7.5);
    top = 0;
    for (const Vec3& p : tall.mesh.positions) top = std::max(top, p.z());
    CHECK(top == Approx(7.5).epsilon(1e-12));
    CHECK(tall.height_m == Approx(7.5).epsilon(1e-12));
    CHECK(tall.metres_per_unit == Approx(7.5 / placed.height_m));

    const MeshArrays flat{{Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)}, {Face{0, 1, 2}}};
    CHECK_THROWS_AS(place_plant(flat.view(), 2.0), MeshError);
    CHECK_NOTHROW(place_plant(flat.view(), std::nullopt));
}

TEST_CASE("the engine-ready GLB names the plant, carries its record and stands Y-up in metres", "[engine]") {
    const GrowthState state = grown_plant(5);
    const GrownPlant plant{.mesh = state.mesh.view(), .birth_steps = {}, .steps = state.steps_done};
    const PlantExportOptions options{.height_m = 2.0, .lods = 0, .wind = false};
    const std::string bytes = plant_glb_bytes(plant, sample_record(), options, "test");
    CHECK(bytes == plant_glb_bytes(plant, sample_record(), options, "test"));  // same plant, same bytes

    const tinygltf::Model model = test::parse_glb(bytes);
    REQUIRE(model.nodes.size() == 1);
    REQUIRE(model.meshes.size() == 1);
    CHECK(model.nodes[0].name == "plant_17");
    CHECK(model.meshes[0].name == "plant_17");
    const tinygltf::Value& extras = model.nodes[0].extras;
    CHECK(extras.Get("genome_hash").Get<std::string>() == sample_record().genome_hash);
    CHECK(extras.Get("fitness").GetNumberAsDouble() == 3.25);
    CHECK(extras.Get("measures").Get("footprint").GetNumberAsDouble() == 0.75);
    CHECK(extras.Get("run").Get<std::string>() == "tree");
    CHECK(extras.Get("birth_id").GetNumberAsInt() == 17);
    CHECK(extras.Get("parents").ArrayLen() == 2);
    CHECK(extras.Get("parents").Get(1).GetNumberAsInt() == 9);
    CHECK(extras.Get("cell").GetNumberAsInt() == 12);
    CHECK(extras.Get("height_m").GetNumberAsDouble() == Approx(2.0));

    const tinygltf::Accessor& pos = model.accessors.at(model.meshes[0].primitives[0].attributes.at("POSITION"));
    CHECK(pos.minValues[1] == 0.0);              // y = 0 at the lowest point
    CHECK(pos.maxValues[1] == Approx(2.0).epsilon(1e-6));  // Y-up, metres
    CHECK(pos.count == static_cast<std::size_t>(state.mesh.num_vertices()));
}

TEST_CASE("a plant without a run leaves out what it does not have", "[engine]") {
    PlantRecord record;
    record.id = "abc";
    record.genome_hash = genome_hash(std::vector<double>{0.5});
    const nlohmann::json json = record_json(record);
    CHECK(json.size() == 2);
    CHECK(json.at("genome_hash").get<std::string>().size() == 16);
    CHECK(genome_hash(std::vector<double>{0.5}) != genome_hash(std::vector<double>{-0.5}));
}

TEST_CASE("bad export options are refused, naming the option", "[engine]") {
    CHECK_THAT(plant_export_problem({.height_m = -1.0, .lods = 0, .wind = false}), Catch::StartsWith("--height"));
    CHECK_THAT(plant_export_problem({.height_m = 0.0, .lods = 0, .wind = false}), Catch::StartsWith("--height"));
    CHECK_THAT(plant_export_problem({.height_m = std::nan(""), .lods = 0, .wind = false}), Catch::StartsWith("--height"));
    CHECK(plant_export_problem({.height_m = 3.0, .lods = 0, .wind = false}).empty());
    CHECK_THAT(plant_export_problem({.height_m = std::nullopt, .lods = kMaxPlantLods + 1, .wind = false}),
               Catch::StartsWith("--lods"));
    const GrowthState state = grown_plant(5);
    CHECK_THROWS_AS(plant_glb_bytes({.mesh = state.mesh.view(), .birth_steps = {}, .steps = 40}, sample_record(),
                                    {.height_m = -2.0, .lods = 0, .wind = false}, "test"),
                    ConfigError);
}
