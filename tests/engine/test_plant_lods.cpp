// Levels of detail: the bounds docs/file-formats.md promises ("Levels of
// detail") on random genomes at two growth settings, their wind data, and
// the LOD nodes of the GLB.
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "engine/birth_steps.hpp"
#include "engine/plant_export.hpp"
#include "engine/plant_frame.hpp"
#include "engine/plant_lods.hpp"
#include "engine/plant_wind.hpp"
#include "engine/species_pack.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/growth/growth_params.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/support/sanitizers.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <span>
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
    int short_chains = 0;              // fewer than three levels written
    int levels_written[3] = {};        // plants whose chain reached LOD i
    double worst_halving = 0;          // largest |faces(i) / faces(i-1) - 1/2| / (1/2)
    double worst_hausdorff[3] = {};    // largest distance / LOD0's diagonal, per level written
    int large = 0;                     // plants of at least kLarge triangles
    int large_short = 0;
};
constexpr std::size_t kLarge = 1000;

// Checks every written level against the LOD bounds: closed and
// manifold, within 10 % of half the triangles of the level before, within
// lod_distance_bound(i) of LOD0 by an independent measurement; that what
// simplify_lods reports matches; and that a short chain is one that stopped.
void check_chain(MeshView lod0, const PlantLods& lods, LodStats& stats) {
    const std::vector<MeshArrays>& levels = lods.levels;
    REQUIRE(!levels.empty());
    CHECK(levels.size() <= static_cast<std::size_t>(lods.requested));
    REQUIRE(lods.distances.size() == levels.size());
    CHECK(levels[0].positions == std::vector<Vec3>(lod0.positions.begin(), lod0.positions.end()));
    if (lods.short_chain()) CHECK(lods.refused_distance > lod_distance_bound(static_cast<int>(levels.size())));
    const double diag = diagonal(lod0);
    for (std::size_t i = 1; i < levels.size(); ++i) {
        const MeshView level = levels[i].view();
        INFO("LOD" << i << ": " << level.faces.size() << " triangles");
        CHECK(is_closed_manifold(level));
        const double ratio = static_cast<double>(level.faces.size()) / static_cast<double>(levels[i - 1].faces.size());
        stats.worst_halving = std::max(stats.worst_halving, std::abs(ratio - 0.5) / 0.5);
        CHECK(std::abs(ratio - 0.5) <= 0.05 + 1e-12);
        const double distance = hausdorff_distance(lod0, level) / diag;
        CHECK(distance == lods.distances[i]);
        CHECK(distance <= lod_distance_bound(static_cast<int>(i)));
        stats.worst_hausdorff[i] = std::max(stats.worst_hausdorff[i], distance);
    }
}

// Grows genomes first .. first + count - 1 and checks their chains of three
// levels (check_chain).
void check_lods(const GenomeGrower& grower, std::uint64_t first, int count, LodStats& stats) {
    for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(count); ++seed) {
        const GrowthState state = grower.grow(testing::random_test_genome(grower.layers(), seed).params);
        const PlacedPlant placed = place_plant(state.mesh.view(), std::nullopt);
        const MeshView lod0 = placed.mesh.view();
        INFO("genome " << seed << ", " << lod0.faces.size() << " triangles");
        ++stats.plants;
        if (lod0.faces.size() < kMinLodFaces << 2) {
            // The levels it can have: each of at least kMinLodFaces triangles.
            const PlantLods small = simplify_lods(lod0, 3);
            CHECK(small.short_chain());
            for (const MeshArrays& level : small.levels) CHECK(level.faces.size() >= std::min(kMinLodFaces, lod0.faces.size()));
            ++stats.too_small;
            continue;
        }
        const PlantLods lods = simplify_lods(lod0, 3);
        check_chain(lod0, lods, stats);
        const bool large = lod0.faces.size() >= kLarge;
        stats.large += large;
        stats.short_chains += lods.short_chain();
        stats.large_short += large && lods.short_chain();
        for (std::size_t i = 0; i < lods.levels.size(); ++i) ++stats.levels_written[i];
    }
}

std::ostream& operator<<(std::ostream& out, const LodStats& s) {
    return out << s.plants << " plants (" << s.too_small << " under 32 triangles, " << s.large << " of 1000 or more): "
               << s.short_chains << " short chains (" << s.large_short << " of them large); chains reaching LOD1 "
               << s.levels_written[1] << ", LOD2 " << s.levels_written[2] << "; triangles off half by at most "
               << 100 * s.worst_halving << " %; Hausdorff / diagonal LOD1 at most " << 100 * s.worst_hausdorff[1]
               << " %, LOD2 at most " << 100 * s.worst_hausdorff[2] << " %";
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

// The bounds of docs/file-formats.md on two trees the quadric cost alone
// took past them (genome 8: LOD1 1.16 %, LOD2 2.05 %; genome 50: 1.98 % and
// 4.25 %), and the same levels twice.
TEST_CASE("levels of detail of two trees stay within 1 % and 2 % of LOD0", "[engine][lods]") {
    const GenomeGrower grower = tree_grower();
    LodStats stats;
    for (const std::uint64_t seed : {8, 50}) {
        const GrowthState state = grower.grow(testing::random_test_genome(grower.layers(), seed).params);
        const PlacedPlant placed = place_plant(state.mesh.view(), std::nullopt);
        const MeshView lod0 = placed.mesh.view();
        INFO("genome " << seed << ", " << lod0.faces.size() << " triangles");
        const PlantLods lods = simplify_lods(lod0, 3);
        CHECK(lods.levels.size() == 3);
        check_chain(lod0, lods, stats);
        if (seed != 50) continue;
        const PlantLods again = simplify_lods(lod0, 3);
        REQUIRE(again.levels.size() == lods.levels.size());
        for (std::size_t i = 0; i < lods.levels.size(); ++i) {
            CHECK(again.levels[i].positions == lods.levels[i].positions);
            CHECK(again.levels[i].faces == lods.levels[i].faces);
        }
    }
}

// 100 genomes (slow: ctest -L slow, or test_engine "[lods-slow]"): every
// level written keeps the LOD bounds (check_chain); the chains that
// stopped short are counted (experiments/2026-11-27-lod-bounds.md).
TEST_CASE("levels of detail of 100 random genomes keep the bounds on every level written", "[.][lods-slow]") {
    LodStats stats;
    check_lods(GenomeGrower(NetworkParams{}, GrowthParams{}), 1, 50, stats);
    check_lods(tree_grower(), 1, 50, stats);
    WARN(stats);
    CHECK(stats.plants == 100);
    CHECK(stats.large >= 30);
}

// Named plants whose chain stops short (experiments/2026-11-27-lod-bounds.md):
// default genome 1 (40 triangles: halving LOD1's 20 to 10 leaves a hull
// 12 % away) and tree genome 19 (1,996 triangles of thin branches: LOD1 no
// nearer than 2.9 % by any try; its tubes pass through one another). The
// stop is recorded in the GLB's extras and in the pack's manifest; every
// level written keeps its bound. Under the sanitizers only genome 1: tree 19's
// four refused tries take minutes instrumented, on the same paths.
TEST_CASE("a chain that cannot keep its bound stops, and the GLB and the manifest say so", "[engine][lods]") {
    struct Named {
        const char* what;
        GenomeGrower grower;
        std::uint64_t seed;
    };
    const Named plants[] = {{"default genome 1", GenomeGrower(NetworkParams{}, GrowthParams{}), 1},
                            {"tree genome 19", tree_grower(), 19}};
    const int count = testing::whole_or_under_sanitizers(2, 1);
    for (const Named& named : std::span(plants, static_cast<std::size_t>(count))) {
        INFO(named.what);
        BirthSteps births(named.grower.seed().mesh.num_vertices());
        GrowthWorkspace workspace;
        const Network network(testing::random_test_genome(named.grower.layers(), named.seed));
        const GrowthState state = named.grower.grow(network, workspace, births.observer());
        const PlacedPlant placed = place_plant(state.mesh.view(), std::nullopt);
        LodStats stats;
        const PlantLods lods = simplify_lods(placed.mesh.view(), 3);
        check_chain(placed.mesh.view(), lods, stats);
        REQUIRE(lods.short_chain());
        const std::size_t written = lods.levels.size();

        const GrownPlant plant{.mesh = state.mesh.view(), .birth_steps = births.steps(), .steps = state.steps_done};
        PlantRecord record;
        record.id = "s";
        record.genome_hash = "0123456789abcdef";
        const PlantExportOptions options{.height_m = std::nullopt, .lods = 3, .wind = true};
        testing::TempDir temp("short-chain");
        SpeciesPack pack(temp.path / "pack", PackSource{.run = "r", .algorithm = "map_elites", .measures = {}}, options);
        pack.add(plant, record);  // writes plant_s.glb
        const tinygltf::Model model = test::parse_glb(testing::read_text(temp.path / "pack" / "plant_s.glb"));
        const tinygltf::Node& root = model.nodes.at(0);
        CHECK(root.children.size() == written);
        CHECK(root.extras.Get("lods_requested").GetNumberAsInt() == 3);
        CHECK(root.extras.Get("lods_written").GetNumberAsInt() == static_cast<int>(written));
        for (std::size_t i = 1; i < written; ++i)
            CHECK(model.nodes.at(static_cast<std::size_t>(root.children[i])).extras.Get("hausdorff_percent").GetNumberAsDouble() ==
                  Approx(100 * lods.distances[i]).margin(1e-3));
        const nlohmann::json entry = nlohmann::json::parse(pack.manifest_text())["species"][0];
        CHECK(entry["lods_written"] == written);
        CHECK(entry["triangles"].size() == written);
        REQUIRE(entry["hausdorff_percent"].size() == written);
        CHECK(entry["hausdorff_percent"][0] == 0.0);
    }
}

TEST_CASE("a small plant gets the levels it can have, each of at least kMinLodFaces triangles", "[engine][lods]") {
    GrowthParams growth;
    growth.steps = 0;
    const GenomeGrower grower(NetworkParams{}, growth);
    const GrowthState seed = grower.grow(testing::random_test_genome(grower.layers(), 1).params);  // 20 triangles
    const PlantLods lods = simplify_lods(seed.mesh.view(), 8);
    CHECK(lods.short_chain());
    REQUIRE(lods.levels.size() >= 1);  // LOD0 at least; none under 8 triangles
    CHECK(lods.levels[0].faces.size() == 20);
    for (const MeshArrays& level : lods.levels) CHECK(level.faces.size() >= kMinLodFaces);
    CHECK(lods.levels.size() == lods.distances.size());
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
