// Levels of detail: the bounds docs/file-formats.md promises ("Levels of
// detail") on random genomes at two growth settings, their wind data, and
// the LOD nodes of the GLB.
#include "base/config_reader.hpp"
#include "base/errors.hpp"
#include "engine/birth_steps.hpp"
#include "engine/plant_export.hpp"
#include "engine/plant_frame.hpp"
#include "engine/plant_lods.hpp"
#include "engine/plant_wind.hpp"
#include "growth/genome_grower.hpp"
#include "growth/growth_params.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <nlohmann/json.hpp>

using namespace morphogen;

namespace {

double diagonal(MeshView mesh) {
    Vec3 lo = mesh.positions[0], hi = mesh.positions[0];
    for (const Vec3& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    return (hi - lo).norm();
}

// Branching growth at tree sizes (150 steps, at most 1,000 vertices), with
// collisions allowed: fixed here, so that the counted figures do not move
// when configs/tree.json does.
GenomeGrower tree_grower() {
    nlohmann::json config = nlohmann::json::parse(
        R"({"network": {"outputs": 15, "hidden": [30]},
            "growth": {"steps": 150, "max_vertices": 1000, "mode": "branching", "collisions": "allow"}})");
    ConfigIssues issues;
    ObjectReader network(&config["network"], "network", issues);
    ObjectReader growth(&config["growth"], "growth", issues);
    const NetworkParams network_params = read_network_params(network);
    const GrowthParams growth_params = read_growth_params(growth);
    return GenomeGrower(network_params, growth_params);
}

// What the genomes seen did against the bounds of docs/file-formats.md.
struct LodStats {
    int plants = 0;
    int too_small = 0;                 // refused three levels (< 32 triangles)
    double worst_halving = 0;          // largest |faces(i) / faces(i-1) - 1/2| / (1/2)
    double worst_hausdorff[3] = {};    // largest distance / LOD0's diagonal, per level
    int over_bound[3] = {};            // plants over 1 % (LOD1) and 2 % (LOD2)
    int large = 0;                     // plants of at least kLarge triangles
    int large_over_bound[3] = {};
    double large_worst[3] = {};
};
constexpr std::size_t kLarge = 1000;


// Grows genomes first .. first + count - 1 and checks their three levels:
// each closed and manifold, about half the triangles of the one before
// (every plant), and their distances from LOD0 (counted, see the tests).
void check_lods(const GenomeGrower& grower, std::uint64_t first, int count, LodStats& stats) {
    for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(count); ++seed) {
        const GrowthState state = grower.grow(testing::random_test_genome(grower.layers(), seed).params);
        const PlacedPlant placed = place_plant(state.mesh.view(), std::nullopt);
        const MeshView lod0 = placed.mesh.view();
        INFO("genome " << seed << ", " << lod0.faces.size() << " triangles");
        ++stats.plants;
        if (lod0.faces.size() < kMinLodFaces << 2) {
            CHECK_THROWS_AS(simplify_lods(lod0, 3), MeshError);
            ++stats.too_small;
            continue;
        }
        const std::vector<MeshArrays> levels = simplify_lods(lod0, 3);
        REQUIRE(levels.size() == 3);
        CHECK(levels[0].positions == placed.mesh.positions);
        const double diag = diagonal(lod0);
        const bool large = lod0.faces.size() >= kLarge;
        stats.large += large;
        for (std::size_t i = 1; i < levels.size(); ++i) {
            const MeshView level = levels[i].view();
            INFO("LOD" << i << ": " << level.faces.size() << " triangles");
            CHECK(is_closed_manifold(level));
            const double ratio = static_cast<double>(level.faces.size()) / static_cast<double>(levels[i - 1].faces.size());
            stats.worst_halving = std::max(stats.worst_halving, std::abs(ratio - 0.5) / 0.5);
            CHECK(std::abs(ratio - 0.5) <= 0.05);
            const double distance = hausdorff_distance(lod0, level) / diag;
            stats.worst_hausdorff[i] = std::max(stats.worst_hausdorff[i], distance);
            const bool over = distance > 0.01 * static_cast<double>(i);
            stats.over_bound[i] += over;
            stats.large_over_bound[i] += over && large;
            if (large) stats.large_worst[i] = std::max(stats.large_worst[i], distance);
        }
    }
}

std::ostream& operator<<(std::ostream& out, const LodStats& s) {
    return out << s.plants << " plants (" << s.too_small << " under 32 triangles, " << s.large << " of 1000 or more): "
               << "triangles off half by at most " << 100 * s.worst_halving << " %; Hausdorff / diagonal LOD1 at most "
               << 100 * s.worst_hausdorff[1] << " % (" << s.over_bound[1] << " over 1 %, " << s.large_over_bound[1]
               << " of them large), LOD2 at most " << 100 * s.worst_hausdorff[2] << " % (" << s.over_bound[2]
               << " over 2 %, " << s.large_over_bound[2] << " of them large); large plants at most "
               << 100 * s.large_worst[1] << " % and " << 100 * s.large_worst[2] << " %";
}

}  // namespace

TEST_CASE("LOD0 is closed and manifold as grown", "[engine][lods]") {
    GrowthParams growth;
    const GenomeGrower grower(NetworkParams{}, growth);
    const GrowthState state = grower.grow(testing::random_test_genome(grower.layers(), 1).params);
    CHECK(is_closed_manifold(state.mesh.view()));
    MeshArrays open{state.mesh.positions(), state.mesh.faces()};
    open.faces.pop_back();
    CHECK_FALSE(is_closed_manifold(open.view()));
}

// The bounds of docs/file-formats.md on two trees the earlier method
// (Garland-Heckbert's quadric cost alone) took past them (genome 8: LOD1
// 1.16 %, LOD2 2.05 %; genome 50: 1.98 % and 4.25 %), and the same levels
// twice. About 10 s of one core.
TEST_CASE("levels of detail of two trees stay within 1 % and 2 % of LOD0", "[engine][lods]") {
    const GenomeGrower grower = tree_grower();
    for (const std::uint64_t seed : {8, 50}) {
        const GrowthState state = grower.grow(testing::random_test_genome(grower.layers(), seed).params);
        const PlacedPlant placed = place_plant(state.mesh.view(), std::nullopt);
        const MeshView lod0 = placed.mesh.view();
        INFO("genome " << seed << ", " << lod0.faces.size() << " triangles");
        const std::vector<MeshArrays> levels = simplify_lods(lod0, 3);
        for (std::size_t i = 1; i < levels.size(); ++i) {
            const MeshView level = levels[i].view();
            INFO("LOD" << i);
            CHECK(is_closed_manifold(level));
            const double ratio = static_cast<double>(level.faces.size()) / static_cast<double>(levels[i - 1].faces.size());
            CHECK(std::abs(ratio - 0.5) <= 0.05);
            CHECK(hausdorff_distance(lod0, level) / diagonal(lod0) <= 0.01 * static_cast<double>(i));
        }
        if (seed != 50) continue;
        const std::vector<MeshArrays> again = simplify_lods(lod0, 3);
        for (std::size_t i = 0; i < levels.size(); ++i) {
            CHECK(again[i].positions == levels[i].positions);
            CHECK(again[i].faces == levels[i].faces);
        }
    }
}

// 100 genomes (slow: ctest -L slow, or test_engine "[lods-slow]"). Every
// level is closed, manifold and about half the one before; the distances
// are counted (experiments/2026-11-27-lod-bounds.md): plants of a few dozen
// triangles (the seed barely grown) lose whole lobes when halved by any
// method, and some trees at the 1,000-vertex cap stay over the bounds.
// The guards are the earlier method's figures, which this one must not lose to.
TEST_CASE("levels of detail of 100 random genomes halve, stay closed and are counted", "[.][lods-slow]") {
    LodStats stats;
    check_lods(GenomeGrower(NetworkParams{}, GrowthParams{}), 1, 50, stats);
    check_lods(tree_grower(), 1, 50, stats);
    WARN(stats);
    CHECK(stats.plants == 100);
    CHECK(stats.large >= 30);
    CHECK(stats.large_over_bound[1] <= 9);
    CHECK(stats.large_over_bound[2] <= 11);
    CHECK(stats.large_worst[1] < 0.0461);
    CHECK(stats.large_worst[2] < 0.0741);
}

TEST_CASE("too many levels for a small plant are refused, naming --lods", "[engine][lods]") {
    GrowthParams growth;
    growth.steps = 0;
    const GenomeGrower grower(NetworkParams{}, growth);
    const GrowthState seed = grower.grow(testing::random_test_genome(grower.layers(), 1).params);
    CHECK_THROWS_WITH(simplify_lods(seed.mesh.view(), 8), Catch::Contains("--lods 8"));
    CHECK_THROWS_AS(simplify_lods(seed.mesh.view(), 0), std::invalid_argument);
}

TEST_CASE("each level is a child node plant_<id>_LOD<i> with its own wind data", "[engine][lods]") {
    GrowthParams growth;
    growth.steps = 80;
    const GenomeGrower grower(NetworkParams{}, growth);
    const Network network(testing::random_test_genome(grower.layers(), 4));
    BirthSteps births(grower.seed().mesh.num_vertices());
    GrowthWorkspace workspace;
    const GrowthState state = grower.grow(network, workspace, births.observer());
    PlantRecord record;
    record.id = "l";
    record.genome_hash = "0123456789abcdef";
    const GrownPlant plant{.mesh = state.mesh.view(), .birth_steps = births.steps(), .steps = 80};
    const PlantExportOptions options{.height_m = 2.0, .lods = 3, .wind = true};
    const std::string bytes = plant_glb_bytes(plant, record, options, "test");
    CHECK(bytes == plant_glb_bytes(plant, record, options, "test"));  // same plant, same bytes
    const tinygltf::Model model = test::parse_glb(bytes);
    REQUIRE(model.nodes.size() == 4);
    CHECK(model.nodes[0].name == "plant_l");
    CHECK(model.nodes[0].mesh == -1);
    REQUIRE(model.nodes[0].children == std::vector<int>{1, 2, 3});
    std::size_t previous = 0;
    for (int i = 0; i < 3; ++i) {
        const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(i + 1)];
        CHECK(node.name == "plant_l_LOD" + std::to_string(i));
        const tinygltf::Primitive& primitive = model.meshes.at(static_cast<std::size_t>(node.mesh)).primitives.at(0);
        const std::size_t triangles = model.accessors.at(static_cast<std::size_t>(primitive.indices)).count / 3;
        CHECK(node.extras.Get("triangles").GetNumberAsInt() == static_cast<int>(triangles));
        if (i == 0) CHECK(triangles == static_cast<std::size_t>(state.mesh.num_faces()));
        if (i > 0) CHECK(triangles < previous);
        previous = triangles;
        const std::vector<float> wind = test::accessor_floats(model, primitive.attributes.at("_WIND"));
        CHECK(wind.size() == 4 * model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("POSITION"))).count);
        CHECK(*std::max_element(wind.begin(), wind.end()) <= 1.0f);
        CHECK(*std::min_element(wind.begin(), wind.end()) >= 0.0f);
    }
}

TEST_CASE("a level's vertices take the wind of LOD0's nearest vertex", "[engine][lods][wind]") {
    const MeshArrays lod0{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {}};
    const std::vector<float> wind{0.1f, 0.1f, 0.1f, 0.1f, 0.2f, 0.2f, 0.2f, 0.2f, 0.3f, 0.3f, 0.3f, 0.3f};
    const MeshArrays level{{Vec3(0.9, 0.1, 0), Vec3(0.1, 0.05, 0)}, {}};
    CHECK(transfer_wind(lod0.view(), wind, level.view()) ==
          std::vector<float>{0.2f, 0.2f, 0.2f, 0.2f, 0.1f, 0.1f, 0.1f, 0.1f});
}
