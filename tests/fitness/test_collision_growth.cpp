// growth.collisions "prevent" (docs/algorithm.md §5.7) against the fitness
// side's own check, CGAL's does_self_intersect (mesh_self_intersects): grown
// meshes never self-intersect, where "allow" grows many that do.
#include "fitness/cgal_geometry.hpp"
#include "growth/genome_grower.hpp"
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
    CHECK(count_self_intersecting(with(params, Collisions::prevent), 1, 8, 20.0) == 0);
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
    CHECK(count_self_intersecting(with(params, Collisions::prevent), 1, 8, 20.0) == 0);
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

// growth.collisions "touch" (docs/algorithm.md §5.7.1) is a cheap margin, not
// a proof: a grown mesh is checked once at the end (fitness.reject_self_intersecting,
// §10.3). The rates are bounded and reported.
TEST_CASE("touch: at most 1 % of random genomes grow self-intersecting meshes (60 steps)", "[collision][contact]") {
    GrowthParams params;
    params.steps = 60;
    params.max_vertices = 1500;
    for (const GrowthParams& mode : {params, branching(params)}) {
        const int bad = count_self_intersecting(with(mode, Collisions::touch), 1, 250);
        WARN(bad << " of 250 genomes self-intersect with touch (60 steps, "
                 << (mode.mode == GrowthMode::branching ? "branching" : "paper") << " mode)");
        CHECK(bad <= 2);
    }
}

TEST_CASE("touch: hostile genomes (saturated outputs or wide weights), the check at the end", "[collision][contact]") {
    for (const GrowthParams& mode : {GrowthParams{}, branching(GrowthParams{})}) {
        const char* name = mode.mode == GrowthMode::branching ? "branching" : "paper";
        INFO(name << " mode");
        GrowthWorkspace workspace;
        CHECK_FALSE(grows_self_intersecting(saturated_genome(), with(mode, Collisions::touch), workspace));
        // The most folded growth: outputs flip between 0 and 1 from vertex to
        // vertex. Not a proof (§5.7.1): the rate is bounded, and reported.
        const int bad = count_self_intersecting(with(mode, Collisions::touch), 1, 32, 20.0);
        WARN(bad << " of 32 wide-weight genomes self-intersect with touch (" << name << " mode)");
        CHECK(bad <= 3);  // measured: 0 (paper), 2 (branching)
    }
}

TEST_CASE("touch: 1000 random genomes at the default settings, the self-intersection rate", "[.][collision-slow]") {
    // The paper's mode stays within 1 %; the branching mode does not (about
    // 2 %, experiments/2026-11-27-contact-rule.md): bounded here as measured.
    for (const auto& [mode, bound] : {std::pair{GrowthParams{}, 10}, std::pair{branching(GrowthParams{}), 30}}) {
        const int bad = count_self_intersecting(with(mode, Collisions::touch), 1, 1000);
        WARN(bad << " of 1000 genomes self-intersect with touch at the default settings ("
                 << (mode.mode == GrowthMode::branching ? "branching" : "paper") << " mode)");
        CHECK(bad <= bound);
    }
}
