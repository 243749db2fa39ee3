// growth.collisions "prevent" (docs/algorithm.md §5.7) and "touch" with its
// fail-safe (§5.7.1) against the fitness side's own check, CGAL's
// does_self_intersect (mesh_self_intersects): grown meshes never
// self-intersect, where "allow" grows many that do.
#include "fitness/geometry/cgal_geometry.hpp"
#include "core/growth/random_genome_centre.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/growth/contact/self_intersection_check.hpp"
#include "tests/support/sanitizers.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

const std::vector<int> default_layers{45, 30, 15};

GrowthParams with(GrowthParams params, Collisions collisions) {
    params.collisions = collisions;
    return params;
}

// The same settings in the branching mode (docs/algorithm.md §5.8).
GrowthParams branching(GrowthParams params) {
    params.mode = GrowthMode::branching;
    return params;
}

bool grows_self_intersecting(const Network& network, const GrowthParams& params, GrowthWorkspace& workspace) {
    return mesh_self_intersects(GenomeGrower(NetworkParams{}, params).grow(network, workspace).mesh.view());
}

// The 60-step tests' genomes per block of four: 1000 in all, a fifth of them
// under the sanitizers (tests/support/sanitizers.hpp).
constexpr int kBlock = morphogen::testing::whole_or_under_sanitizers(250, 50);
// Hostile genomes (wide weights) grow their full 200 steps to the vertex
// budget, the slowest growth there is: 8 (32 with "touch") in the optimised
// build, a quarter of them under the sanitizers.
constexpr int kHostile = morphogen::testing::whole_or_under_sanitizers(8, 2);
constexpr int kTouchHostile = morphogen::testing::whole_or_under_sanitizers(32, 8);

// Genomes [first, first + count) of random_test_genome (init range 2, as
// evolution's default): how many grow self-intersecting meshes.
int count_self_intersecting(const GrowthParams& params, std::uint64_t first, int count, double range = 2.0) {
    GrowthWorkspace workspace;
    int bad = 0;
    for (std::uint64_t g = first; g < first + count; ++g) {
        const Network network(random_test_genome(default_layers, g, range));
        if (grows_self_intersecting(network, params, workspace)) {
            ++bad;
            UNSCOPED_INFO("genome " << g << " (range " << range << ") self-intersects");
        }
    }
    return bad;
}

// Every output saturated at 1 (weights 0, output thresholds -40): every
// vertex moves as far as speed and budget allow, every step.
Network saturated_genome() {
    Genome genome = random_test_genome(default_layers, 1);
    std::fill(genome.params.begin(), genome.params.end(), 0.0);
    const std::size_t output_layer = 30 * (45 + 1);
    for (int j = 0; j < 15; ++j) genome.params[output_layer + j * 31 + 30] = -40.0;
    return Network(genome);
}

}  // namespace

TEST_CASE("1000 random genomes grown with collisions prevented never self-intersect", "[collision]") {
    // Shorter growth than the default (60 steps, at most 1500 vertices; the
    // rest as the paper's) keeps this in the ordinary suite, some 25 s; the
    // default settings run under the CTest label "slow" (below).
    GrowthParams params;
    params.steps = 60;
    params.max_vertices = 1500;
    const auto block = static_cast<std::uint64_t>(GENERATE(0, 1, 2, 3));
    CHECK(count_self_intersecting(with(params, Collisions::prevent), 1 + 250 * block, kBlock) == 0);
}

TEST_CASE("the check can fail: growth that allows collisions self-intersects", "[collision]") {
    // The same 1000 genomes and settings as above, allowed to collide.
    GrowthParams params;
    params.steps = 60;
    params.max_vertices = 1500;
    const int allowed = count_self_intersecting(with(params, Collisions::allow), 1, 4 * kBlock);
    WARN(allowed << " of " << 4 * kBlock << " genomes self-intersect when collisions are allowed (60 steps)");
    CHECK(allowed > 0);
}

TEST_CASE("hostile genomes (saturated outputs or wide weights) grown with collisions prevented never self-intersect", "[collision]") {
    const GrowthParams params;  // the paper's defaults: 200 steps, 4000 vertices
    GrowthWorkspace workspace;
    const Network saturated = saturated_genome();
    CHECK_FALSE(grows_self_intersecting(saturated, with(params, Collisions::prevent), workspace));
    // Weights 10x the usual range: outputs flip between 0 and 1 from vertex
    // to vertex, the most folded growth random genomes show.
    CHECK(count_self_intersecting(with(params, Collisions::prevent), 1, kHostile, 20.0) == 0);
}

TEST_CASE("hostile genomes self-intersect when collisions are allowed", "[collision]") {
    const GrowthParams params;
    GrowthWorkspace workspace;
    CHECK(grows_self_intersecting(saturated_genome(), with(params, Collisions::allow), workspace));
    const int allowed = count_self_intersecting(with(params, Collisions::allow), 1, 8, 20.0);
    WARN(allowed << " of 8 wide-weight genomes self-intersect when collisions are allowed");
    CHECK(allowed > 0);
}

TEST_CASE("1000 random genomes at the default growth settings never self-intersect", "[.][collision-slow]") {
    const auto block = static_cast<std::uint64_t>(GENERATE(0, 1, 2, 3));
    CHECK(count_self_intersecting(with(GrowthParams{}, Collisions::prevent), 1 + 250 * block, 250) == 0);
}

TEST_CASE("the same 1000 genomes self-intersect when collisions are allowed", "[.][collision-slow]") {
    const int allowed = count_self_intersecting(with(GrowthParams{}, Collisions::allow), 1, 1000);
    WARN(allowed << " of 1000 genomes self-intersect at the default settings when collisions are allowed");
    CHECK(allowed > 0);
}

TEST_CASE("1000 random genomes in the branching mode, collisions prevented, never self-intersect", "[collision][branching]") {
    GrowthParams params;
    params.steps = 60;
    params.max_vertices = 1500;
    const auto block = static_cast<std::uint64_t>(GENERATE(0, 1, 2, 3));
    CHECK(count_self_intersecting(with(branching(params), Collisions::prevent), 1 + 250 * block, kBlock) == 0);
}

TEST_CASE("the check can fail in the branching mode too", "[collision][branching]") {
    GrowthParams params;
    params.steps = 60;
    params.max_vertices = 1500;
    const int allowed = count_self_intersecting(with(branching(params), Collisions::allow), 1, 4 * kBlock);
    WARN(allowed << " of " << 4 * kBlock << " genomes self-intersect in the branching mode when collisions are allowed (60 steps)");
    CHECK(allowed > 0);
}

TEST_CASE("hostile genomes in the branching mode, collisions prevented, never self-intersect", "[collision][branching]") {
    const GrowthParams params = branching(GrowthParams{});
    GrowthWorkspace workspace;
    // Saturated: every vertex grows (w3 = 1) and turns toward its normal, up
    // and apart at the full rate, as far as speed and budget allow.
    CHECK_FALSE(grows_self_intersecting(saturated_genome(), with(params, Collisions::prevent), workspace));
    CHECK(count_self_intersecting(with(params, Collisions::prevent), 1, kHostile, 20.0) == 0);
}

TEST_CASE("1000 random genomes in the branching mode at the default growth settings never self-intersect",
          "[.][collision-slow]") {
    const auto block = static_cast<std::uint64_t>(GENERATE(0, 1, 2, 3));
    CHECK(count_self_intersecting(with(branching(GrowthParams{}), Collisions::prevent), 1 + 250 * block, 250) == 0);
}

TEST_CASE("the same 1000 genomes in the branching mode self-intersect when collisions are allowed", "[.][collision-slow]") {
    const int allowed = count_self_intersecting(with(branching(GrowthParams{}), Collisions::allow), 1, 1000);
    WARN(allowed << " of 1000 genomes self-intersect in the branching mode at the default settings when allowed");
    CHECK(allowed > 0);
}

// growth.collisions "touch" (docs/algorithm.md §5.7.1) is a cheap margin,
// and its fail-safe makes it clean by construction: a mesh that
// self-intersects goes back to its last clean step.

namespace {

// configs/tree_map.json's sizes (tree.json's until 2026-11-29; the paper's
// mode at the same sizes).
GrowthParams map_sizes(GrowthParams params) {
    params.steps = 150;
    params.max_vertices = 1000;
    return params;
}

// configs/tree.json's sizes.
GrowthParams tree_sizes(GrowthParams params) {
    params.steps = 300;
    params.max_vertices = 4000;
    return params;
}

// Genomes [first, first + count) grown with "touch": how many self-intersect
// by CGAL's check (none should); how many the fail-safe rewound is reported.
// With `centred`, genomes are drawn as the searches draw them
// (docs/algorithm.md §6.3: in the branching mode their shoots start growing).
int count_touch_self_intersecting(const GrowthParams& params, std::uint64_t first, int count, double range = 2.0,
                                  bool centred = false) {
    const GrowthParams touch = with(params, Collisions::touch);
    const GenomeGrower grower(NetworkParams{}, touch);
    const std::vector<double> centre = centred ? random_genome_centre(default_layers, touch.mode) : std::vector<double>{};
    GrowthWorkspace workspace;
    int bad = 0, rewound = 0;
    for (std::uint64_t g = first; g < first + count; ++g) {
        RandomStream stream(g, 0);
        const Genome genome{default_layers, random_parameters(parameter_count(default_layers), range, stream, centre)};
        const GrowthState state = grower.grow(Network(genome), workspace);
        rewound += state.steps_done < touch.steps ? 1 : 0;
        if (mesh_self_intersects(state.mesh.view())) {
            ++bad;
            UNSCOPED_INFO("genome " << g << " (range " << range << ") self-intersects");
        }
    }
    WARN(rewound << " of " << count << " genomes from " << first << " rewound by touch's fail-safe ("
                 << (touch.mode == GrowthMode::branching ? "branching" : "paper") << " mode, " << touch.steps
                 << " steps, range " << range << ")");
    return bad;
}

// A quarter of the genomes of the default-size blocks below, under the
// sanitizers a tenth of that.
constexpr int kTouchBlock = morphogen::testing::whole_or_under_sanitizers(25, 5);

}  // namespace

TEST_CASE("touch: 1000 random genomes never self-intersect (60 steps), both modes", "[collision][contact]") {
    GrowthParams params;
    params.steps = 60;
    params.max_vertices = 1500;
    const auto block = static_cast<std::uint64_t>(GENERATE(0, 1, 2, 3));
    for (const GrowthParams& mode : {params, branching(params)})
        CHECK(count_touch_self_intersecting(mode, 1 + 250 * block, kBlock) == 0);
}

TEST_CASE("touch: random genomes at the default settings and at tree_map.json's never self-intersect", "[collision][contact]") {
    // Genomes 51-150: 73 self-intersects without the fail-safe (branching
    // mode, default settings; tests/core/growth/test_contact_rule.cpp).
    const auto block = static_cast<std::uint64_t>(GENERATE(0, 1, 2, 3));
    for (const GrowthParams& settings : {GrowthParams{}, map_sizes(GrowthParams{})})
        for (const GrowthParams& mode : {settings, branching(settings)})
            CHECK(count_touch_self_intersecting(mode, 51 + 25 * block, kTouchBlock) == 0);
}

TEST_CASE("touch: random genomes drawn as the branching searches draw them never self-intersect at tree.json's "
          "and tree_map.json's sizes",
          "[collision][contact]") {
    const auto block = static_cast<std::uint64_t>(GENERATE(0, 1, 2, 3));
    for (const GrowthParams& sizes : {map_sizes(GrowthParams{}), tree_sizes(GrowthParams{})})
        CHECK(count_touch_self_intersecting(branching(sizes), 4242 + 25 * block, kTouchBlock, 2.0, true) == 0);
}

TEST_CASE("touch: hostile genomes (saturated outputs or wide weights) never self-intersect", "[collision][contact]") {
    for (const GrowthParams& mode : {GrowthParams{}, branching(GrowthParams{})}) {
        INFO((mode.mode == GrowthMode::branching ? "branching" : "paper") << " mode");
        GrowthWorkspace workspace;
        CHECK_FALSE(grows_self_intersecting(saturated_genome(), with(mode, Collisions::touch), workspace));
        // The most folded growth: outputs flip between 0 and 1 from vertex to
        // vertex (without the fail-safe, 2 of these 32 self-intersected in
        // the branching mode).
        CHECK(count_touch_self_intersecting(mode, 1, kTouchHostile, 20.0) == 0);
    }
}

TEST_CASE("the fail-safe's whole-mesh check agrees with CGAL's", "[collision][contact]") {
    // Meshes grown with "allow", many of them self-intersecting.
    GrowthParams params;
    params.steps = 60;
    params.max_vertices = 1500;
    SelfIntersectionCheck check;
    int intersecting = 0;
    const int count = morphogen::testing::whole_or_under_sanitizers(100, 20);
    for (const GrowthParams& mode : {params, branching(params)}) {
        const GenomeGrower grower(NetworkParams{}, with(mode, Collisions::allow));
        GrowthWorkspace workspace;
        for (std::uint64_t g = 1; g <= static_cast<std::uint64_t>(count); ++g) {
            const TriMesh mesh = grower.grow(Network(random_test_genome(default_layers, g)), workspace).mesh;
            const bool cgal = mesh_self_intersects(mesh.view());
            INFO("genome " << g);
            CHECK(check.intersects(mesh) == cgal);
            intersecting += cgal ? 1 : 0;
        }
    }
    CHECK(intersecting > 0);
    CHECK(intersecting < 2 * count);
}

TEST_CASE("touch: 1000 random genomes in the paper's mode never self-intersect, default settings and tree_map.json's",
          "[.][collision-slow]") {
    for (const GrowthParams& settings : {GrowthParams{}, map_sizes(GrowthParams{})})
        CHECK(count_touch_self_intersecting(settings, 1, 1000) == 0);
}

TEST_CASE("touch: 1000 random genomes in the branching mode never self-intersect, default settings, tree_map.json's "
          "and tree.json's",
          "[.][collision-slow]") {
    for (const GrowthParams& settings : {GrowthParams{}, map_sizes(GrowthParams{}), tree_sizes(GrowthParams{})})
        CHECK(count_touch_self_intersecting(branching(settings), 1, 1000) == 0);
}
