// Foliage cards (engine/leaf_cards.hpp, --leaves) on random genomes in both
// growth modes: on the surface, facing out, mostly outside the body (the
// bound below), the same bytes from the same genome; their GLB primitive,
// material, texture and wind data; LOD thinning; refused options.
#include "engine/body_inside.hpp"
#include "engine/leaf_cards.hpp"
#include "engine/leaf_texture.hpp"
#include "engine/plant_export.hpp"
#include "engine/plant_frame.hpp"
#include "core/base/errors.hpp"
#include "core/mesh/vertex_normals.hpp"
#include "tests/engine/glb_reader.hpp"
#include "tests/engine/grow_dated.hpp"
#include "evolution/rng.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace morphogen {
namespace {

struct Leafy {
    testing::Grown grown;
    std::vector<double> light;
    PlacedPlant placed;
    std::vector<LeafCard> cards;
};

Leafy grow_leafy(std::uint64_t seed, GrowthMode mode, int steps, LeafParams params = {}) {
    GrowthParams growth;
    growth.steps = steps;
    growth.mode = mode;
    const GenomeGrower grower(NetworkParams{}, growth);
    const Network network(testing::random_test_genome(grower.layers(), seed));
    BirthSteps births(grower.seed().mesh.num_vertices());
    GrowthWorkspace workspace;
    Leafy out{.grown = {grower.grow(network, workspace, births.observer()), births.steps()}, .light = {},
              .placed = {}, .cards = {}};
    out.light = leaf_light(out.grown.state, growth);
    out.placed = place_plant(out.grown.state.mesh.view(), std::nullopt);
    out.cards = leaf_cards({.placed = out.placed.mesh.view(), .birth_steps = out.grown.births,
                            .steps = out.grown.state.steps_done, .light = out.light,
                            .seed = leaf_seed(std::to_string(seed))},
                           params);
    return out;
}

// The generalised winding number of `mesh` about `q` (Jacobson et al. 2013):
// about 1 inside a closed surface, 0 outside.
double winding_number(MeshView mesh, const Vec3& q) {
    double total = 0.0;
    for (const Face& f : mesh.faces) {
        const Vec3 a = mesh.positions[static_cast<std::size_t>(f[0])] - q;
        const Vec3 b = mesh.positions[static_cast<std::size_t>(f[1])] - q;
        const Vec3 c = mesh.positions[static_cast<std::size_t>(f[2])] - q;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        const double num = a.dot(b.cross(c));
        const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
        total += 2.0 * std::atan2(num, den);
    }
    return total / (4.0 * std::numbers::pi);
}

// The distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return (p - a).norm();
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return (p - b).norm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return (p - c).norm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
    const double denom = 1.0 / (va + vb + vc);
    return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

// A record named and hashed `id` (the cards' seed is leaf_seed(id)).
PlantRecord record_of(const std::string& id) {
    PlantRecord record;
    record.id = id;
    record.genome_hash = id;
    return record;
}

double surface_distance(MeshView mesh, const Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const Face& f : mesh.faces)
        best = std::min(best, point_triangle_distance(p, mesh.positions[static_cast<std::size_t>(f[0])],
                                                      mesh.positions[static_cast<std::size_t>(f[1])],
                                                      mesh.positions[static_cast<std::size_t>(f[2])]));
    return best;
}

}  // namespace

// The stated bound (docs/game-engines.md, "Leaves"): over the cards of 24
// random genomes, at most 0.5 % of the points of a 5 x 5 grid on each card
// lie inside the plant's body by its generalised winding number (an
// independent test of what BodyInside decides), and at most 2 % of the
// cards reach into it.
TEST_CASE("leaf cards stand on the surface, face outward and stay out of the body", "[leaves]") {
    std::size_t cards = 0, points = 0, inside = 0, cards_inside = 0;
    for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching}) {
        for (std::uint64_t seed = 1; seed <= 12; ++seed) {
            const Leafy leafy = grow_leafy(seed, mode, mode == GrowthMode::paper ? 120 : 60);
            const MeshView body = leafy.placed.mesh.view();
            const std::vector<Vec3> normals = vertex_normals(body);
            for (const LeafCard& card : leafy.cards) {
                INFO("mode " << static_cast<int>(mode) << " seed " << seed << " vertex " << card.vertex);
                const auto v = static_cast<std::size_t>(card.vertex);
                // Eligible: young and lit.
                CHECK(leafy.grown.births[v] * 2 >= leafy.grown.state.steps_done);
                // On the surface: the base is lifted a twentieth of the card from its vertex.
                CHECK(surface_distance(body, card.base) <= kLeafLiftOffset * card.length * (1 + 1e-9));
                // Facing out: within 50° of the surface normal, and its front side outside the body.
                CHECK(card.normal.dot(normals[v]) >= std::cos(50.0 * std::numbers::pi / 180.0) - 1e-9);
                CHECK(std::abs(card.axis.dot(card.across)) < 1e-9);
                CHECK(winding_number(body, card.base + card.normal * (0.01 * card.length)) < 0.5);
                std::size_t card_inside = 0;
                for (int i = 0; i < 5; ++i)
                    for (int j = 0; j < 5; ++j) {
                        const Vec3 p = card.base + card.axis * (card.length * (i + 0.5) / 5.0) +
                                       card.across * (kLeafAspect * card.length * ((j + 0.5) / 5.0 - 0.5));
                        card_inside += winding_number(body, p) > 0.5;
                    }
                ++cards, points += 25, inside += card_inside, cards_inside += card_inside > 0;
            }
        }
    }
    INFO(cards << " cards, " << inside << " of " << points << " points inside, " << cards_inside
               << " cards touch the body");
    CHECK(cards > 200);
    CHECK(static_cast<double>(inside) <= 0.005 * static_cast<double>(points));
    CHECK(static_cast<double>(cards_inside) <= 0.02 * static_cast<double>(cards));
}

TEST_CASE("BodyInside agrees with the generalised winding number", "[leaves]") {
    for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching}) {
        const Leafy leafy = grow_leafy(6, mode, mode == GrowthMode::paper ? 120 : 60);
        const MeshView body = leafy.placed.mesh.view();
        const BodyInside inside(body, 0.3);
        Vec3 lo = body.positions[0], hi = lo;
        for (const Vec3& p : body.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
        // Two copies far apart: the columns between them are empty, so
        // BodyInside sorts its list rather than counting into a grid.
        const Vec3 away(1000.0 * (hi - lo).maxCoeff(), 0.0, 0.0);
        MeshArrays twins = leafy.placed.mesh;
        const int n = static_cast<int>(twins.positions.size());
        for (int v = 0; v < n; ++v) twins.positions.push_back(twins.positions[static_cast<std::size_t>(v)] + away);
        for (std::size_t f = 0, faces = twins.faces.size(); f < faces; ++f)
            twins.faces.push_back({twins.faces[f][0] + n, twins.faces[f][1] + n, twins.faces[f][2] + n});
        const BodyInside both(twins.view(), 0.3);
        RandomStream stream(11, 0);
        std::size_t agree = 0, in = 0;
        constexpr int kPoints = 400;
        for (int i = 0; i < kPoints; ++i) {
            Vec3 r;
            for (int k = 0; k < 3; ++k) r[k] = stream.uniform();
            const Vec3 p = lo + (hi - lo).cwiseProduct(r);
            const int exact = static_cast<int>(std::lround(winding_number(body, p)));
            agree += inside.winding(p) == exact && both.winding(p) == exact && both.winding(p + away) == exact;
            in += exact > 0;
        }
        INFO("mode " << static_cast<int>(mode) << ": " << in << " of " << kPoints << " points inside");
        CHECK(in > 20);
        CHECK(agree == static_cast<std::size_t>(kPoints));
    }
}

TEST_CASE("leaf cards: the same genome gives the same cards, another genome others", "[leaves]") {
    const Leafy a = grow_leafy(5, GrowthMode::paper, 120), b = grow_leafy(5, GrowthMode::paper, 120);
    REQUIRE(!a.cards.empty());
    REQUIRE(a.cards.size() == b.cards.size());
    for (std::size_t i = 0; i < a.cards.size(); ++i) {
        CHECK(a.cards[i].vertex == b.cards[i].vertex);
        CHECK(a.cards[i].base == b.cards[i].base);
        CHECK(a.cards[i].normal == b.cards[i].normal);
    }
    // The same plant under another seed: other vertices carry cards.
    const std::vector<LeafCard> other =
        leaf_cards({.placed = a.placed.mesh.view(), .birth_steps = a.grown.births, .steps = a.grown.state.steps_done,
                    .light = a.light, .seed = leaf_seed("another genome")},
                   {});
    bool differs = other.size() != a.cards.size();
    for (std::size_t i = 0; !differs && i < other.size(); ++i) differs = other[i].vertex != a.cards[i].vertex;
    CHECK(differs);
    // Keys ascend; no two anchors closer than half a card.
    for (std::size_t i = 1; i < a.cards.size(); ++i) CHECK(a.cards[i - 1].key <= a.cards[i].key);
    for (std::size_t i = 0; i < a.cards.size(); ++i)
        for (std::size_t j = i + 1; j < a.cards.size(); ++j)
            CHECK((a.placed.mesh.positions[static_cast<std::size_t>(a.cards[i].vertex)] -
                   a.placed.mesh.positions[static_cast<std::size_t>(a.cards[j].vertex)])
                      .norm() >= a.cards[i].length / 2.0);
}

TEST_CASE("leaf cards: density and size scale them", "[leaves]") {
    const Leafy sparse = grow_leafy(5, GrowthMode::paper, 120, {.size = 0.03, .density = 0.2});
    const Leafy dense = grow_leafy(5, GrowthMode::paper, 120, {.size = 0.03, .density = 1.0});
    CHECK(sparse.cards.size() < dense.cards.size());
    REQUIRE(!dense.cards.empty());
    const Leafy large = grow_leafy(5, GrowthMode::paper, 120, {.size = 0.12, .density = 1.0});
    REQUIRE(!large.cards.empty());
    CHECK(large.cards.front().length == Approx(4.0 * dense.cards.front().length));
}

TEST_CASE("leaf cards: refused sizes and densities", "[leaves]") {
    for (const double size : {0.0, -0.1, 0.51, std::numeric_limits<double>::quiet_NaN()})
        CHECK_THAT(leaf_params_problem({.size = size, .density = 0.5}, "--leaf-size", "--leaf-density"),
                   Catch::StartsWith("--leaf-size"));
    for (const double density : {0.0, 1.01, -1.0, std::numeric_limits<double>::infinity()})
        CHECK_THAT(leaf_params_problem({.size = 0.1, .density = density}, "--leaf-size", "--leaf-density"),
                   Catch::StartsWith("--leaf-density"));
    CHECK(leaf_params_problem({.size = 0.5, .density = 1.0}, "s", "d").empty());
    PlantExportOptions options;
    options.leaf_size = 0.1;
    CHECK_THAT(plant_export_problem(options), Catch::Contains("--leaf-size 0.1: shapes the cards of --leaves"));
    options.leaves = true;
    CHECK(plant_export_problem(options).empty());
    options.leaf_density = 0.0;
    CHECK_THAT(plant_export_problem(options), Catch::StartsWith("--leaf-density 0: must be"));
    const testing::Grown grown = testing::grow_dated(3, 40);
    CHECK_THROWS_AS(plant_glb_bytes(grown.plant(), record_of("x"), options, "x.glb"), ConfigError);
    const std::vector<double> short_light(3, 1.0);
    CHECK_THROWS_AS(leaf_cards({.placed = grown.state.mesh.view(), .birth_steps = grown.births, .steps = 40,
                                .light = short_light, .seed = 1},
                               {}),
                    std::invalid_argument);
}

TEST_CASE("leaf texture: a leaf with alpha, and its embedded PNG decodes to it", "[leaves]") {
    const std::vector<std::uint8_t> rgba = leaf_texture_rgba();
    const int n = kLeafTextureSize;
    REQUIRE(rgba.size() == static_cast<std::size_t>(n * n * 4));
    auto alpha = [&](int row, int col) { return rgba[static_cast<std::size_t>((row * n + col) * 4 + 3)]; };
    CHECK(alpha(0, 0) == 0);
    CHECK(alpha(n - 1, 0) == 0);
    CHECK(alpha(n / 2, n / 2) == 255);     // the blade
    CHECK(alpha(n - 2, n / 2) == 255);     // the stalk at the base (bottom row)
    CHECK(alpha(n / 2, 1) == 0);           // beside the blade
    std::size_t opaque = 0;
    for (int i = 0; i < n * n; ++i) opaque += rgba[static_cast<std::size_t>(i * 4 + 3)] >= 128;
    CHECK(opaque > static_cast<std::size_t>(n * n / 4));
    CHECK(opaque < static_cast<std::size_t>(n * n * 3 / 4));
    const std::string png = leaf_texture_png();
    int w = 0, h = 0, channels = 0;
    unsigned char* decoded = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                                   static_cast<int>(png.size()), &w, &h, &channels, 4);
    REQUIRE(decoded != nullptr);
    CHECK(std::equal(rgba.begin(), rgba.end(), decoded));
    stbi_image_free(decoded);
    CHECK(png == encode_leaf_texture_png());  // the bytes the build embedded are the encoder's
}

TEST_CASE("leaf GLB: a second primitive with the leaf material, its texture and wind", "[leaves]") {
    const Leafy leafy = grow_leafy(4, GrowthMode::paper, 120);
    REQUIRE(!leafy.cards.empty());
    PlantExportOptions options;
    options.leaves = true;
    options.wind = true;
    GrownPlant plant = leafy.grown.plant();
    plant.light = leafy.light;
    const PlantRecord record = record_of("4");  // leaf_seed("4"), as grow_leafy's
    const std::string bytes = plant_glb_bytes(plant, record, options, "leafy.glb");
    CHECK(bytes == plant_glb_bytes(plant, record, options, "leafy.glb"));
    const tinygltf::Model model = test::parse_glb(bytes);
    REQUIRE(model.meshes.size() == 1);
    REQUIRE(model.meshes[0].primitives.size() == 2);
    REQUIRE(model.materials.size() == 2);
    const tinygltf::Primitive& leaves = model.meshes[0].primitives[1];
    const tinygltf::Material& leaf = model.materials.at(static_cast<std::size_t>(leaves.material));
    CHECK(leaf.alphaMode == "MASK");
    CHECK(leaf.doubleSided);
    CHECK(leaf.pbrMetallicRoughness.baseColorTexture.index == 0);
    CHECK(leaf.pbrMetallicRoughness.baseColorTexture.texCoord == 0);
    REQUIRE(model.images.size() == 1);
    CHECK(model.images[0].mimeType == "image/png");
    const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(model.images[0].bufferView));
    const std::string png = leaf_texture_png();
    REQUIRE(view.byteLength == png.size());
    const auto* embedded = reinterpret_cast<const char*>(model.buffers[0].data.data() + view.byteOffset);
    CHECK(std::string(embedded, view.byteLength) == png);
    CHECK(model.nodes[0].extras.Get("leaves").GetNumberAsInt() == static_cast<int>(leafy.cards.size()));

    const std::size_t vertices = 4 * leafy.cards.size();
    const std::vector<float> uv = test::accessor_floats(model, leaves.attributes.at("TEXCOORD_0"));
    const std::vector<float> wind = test::accessor_floats(model, leaves.attributes.at("_WIND"));
    REQUIRE(uv.size() == 2 * vertices);
    REQUIRE(wind.size() == 4 * vertices);
    const std::vector<float> body_wind =
        plant_wind(leafy.placed.mesh.view(), leafy.grown.births, leafy.grown.state.steps_done);
    for (std::size_t c = 0; c < leafy.cards.size(); ++c)
        for (int corner = 0; corner < 4; ++corner)
            for (int k = 0; k < 4; ++k) {
                const float got = wind[(4 * c + static_cast<std::size_t>(corner)) * 4 + static_cast<std::size_t>(k)];
                const float anchor = body_wind[4 * static_cast<std::size_t>(leafy.cards[c].vertex) + static_cast<std::size_t>(k)];
                CHECK(got == (corner >= 2 && k == 1 ? 1.0f : anchor));  // the tip flutters fully
            }
    // The body's primitive keeps what it had without leaves.
    options.leaves = false;
    const tinygltf::Model plain = test::parse_glb(plant_glb_bytes(plant, record, options, "plain.glb"));
    CHECK(plain.meshes[0].primitives.size() == 1);
    CHECK(plain.materials.size() == 1);
    CHECK(plain.images.empty());
}

TEST_CASE("leaf cards beside the uv wind preset: reads the texture from TEXCOORD_2", "[leaves]") {
    const Leafy leafy = grow_leafy(4, GrowthMode::paper, 120);
    PlantExportOptions options;
    options.leaves = true;
    options.wind = true;
    options.wind_presets = {WindPreset::uv};
    GrownPlant plant = leafy.grown.plant();
    plant.light = leafy.light;
    const tinygltf::Model model = test::parse_glb(plant_glb_bytes(plant, record_of("4"), options, "uv.glb"));
    const tinygltf::Primitive& leaves = model.meshes.at(0).primitives.at(1);
    CHECK(leaves.attributes.count("TEXCOORD_0") == 1);  // the wind copies
    CHECK(leaves.attributes.count("TEXCOORD_2") == 1);  // the leaf's
    CHECK(model.materials.at(1).pbrMetallicRoughness.baseColorTexture.texCoord == 2);
}

TEST_CASE("leaf cards with --lods: each level keeps the first cards, as many as its share of triangles", "[leaves]") {
    const Leafy leafy = grow_leafy(6, GrowthMode::paper, 200, {.size = 0.04, .density = 1.0});
    PlantExportOptions options;
    options.leaves = true;
    options.leaf_size = 0.04;
    options.leaf_density = 1.0;
    options.lods = 3;
    GrownPlant plant = leafy.grown.plant();
    plant.light = leafy.light;
    const EnginePlant ready = make_engine_plant(plant, record_of("6"), options);
    REQUIRE(ready.levels.size() == 3);
    REQUIRE(ready.leaves.size() == 3);
    const std::size_t total = leafy.cards.size();
    REQUIRE(total > 20);
    CHECK(ready.leaves[0].cards() == total);
    for (std::size_t i = 1; i < 3; ++i) {
        const double fraction =
            static_cast<double>(ready.levels[i].faces.size()) / static_cast<double>(ready.levels[0].faces.size());
        const LodLeaves lod = lod_leaves(total, fraction);
        CHECK(ready.leaves[i].cards() == lod.count);
        CHECK(ready.leaves[i].cards() < ready.leaves[i - 1].cards());
        CHECK(lod.scale == Approx(std::min(std::sqrt(1.0 / fraction), kMaxLodLeafScale)));
        // The same cards as LOD0's first ones: the same bases, drawn larger.
        for (std::size_t c = 0; c < ready.leaves[i].cards(); ++c) {
            const Vec3 base = (ready.leaves[i].mesh.positions[4 * c] + ready.leaves[i].mesh.positions[4 * c + 1]) / 2;
            const Vec3 base0 = (ready.leaves[0].mesh.positions[4 * c] + ready.leaves[0].mesh.positions[4 * c + 1]) / 2;
            CHECK((base - base0).norm() < 1e-9);
        }
    }
    const tinygltf::Model model = test::parse_glb(plant_glb_bytes(ready, "lods.glb"));
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(model.nodes.at(1 + i).extras.Get("leaves").GetNumberAsInt() == static_cast<int>(ready.leaves[i].cards()));
        CHECK(model.meshes.at(i).primitives.size() == 2);
    }
    CHECK(lod_leaves(0, 0.5).count == 0);
    CHECK(lod_leaves(10, 0.01).count == 1);
    CHECK(lod_leaves(10, 0.01).scale == kMaxLodLeafScale);
}

TEST_CASE("leaf cards: a plant without a young lit vertex writes no leaf primitive", "[leaves]") {
    const testing::Grown grown = testing::grow_dated(3, 0);  // the seed: every vertex born at step 0
    PlantExportOptions options;
    options.leaves = true;
    const tinygltf::Model model = test::parse_glb(plant_glb_bytes(grown.plant(), record_of("3"), options, "bare.glb"));
    CHECK(model.meshes.at(0).primitives.size() == 1);
    CHECK(model.materials.size() == 1);
    CHECK(model.nodes[0].extras.Get("leaves").GetNumberAsInt() == 0);
}

}  // namespace morphogen
