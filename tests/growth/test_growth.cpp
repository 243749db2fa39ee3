#include "base/errors.hpp"
#include "growth/growth.hpp"
#include "tests/support/reference_compare.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <cstring>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

const std::vector<int> default_layers{45, 30, 15};

bool same_bits(const TriMesh& a, const TriMesh& b) {
    if (a.faces() != b.faces() || a.num_vertices() != b.num_vertices()) return false;
    return std::memcmp(a.positions().data(), b.positions().data(), sizeof(Vec3) * a.num_vertices()) == 0;
}

}  // namespace

TEST_CASE("growth keeps every invariant after every step of 200 random genomes", "[growth]") {
    // Shorter runs than the default keep the suite fast; every step is checked.
    GrowthParams params;
    params.steps = 60;
    params.max_vertices = 1500;
    const Seed seed = make_seed("icosahedron", 1.0);
    GrowthWorkspace workspace;
    int grew = 0;
    const auto first = static_cast<std::uint64_t>(GENERATE(0, 1, 2, 3));
    for (std::uint64_t g = first * 50 + 1; g <= first * 50 + 50; ++g) {
        const Network network(random_test_genome(default_layers, g));
        const Grower grower(network, params);
        const GrowthState state = grower.grow(seed, workspace, nullptr, [&](const GrowthState& s, int t) {
            INFO("genome " << g << " step " << t);
            const auto defects = s.mesh.check();
            REQUIRE(defects.empty());
            REQUIRE(s.directions.size() == static_cast<std::size_t>(s.mesh.num_vertices()));
            REQUIRE(s.outputs.size() == static_cast<std::size_t>(s.mesh.num_vertices()) * 15);
            REQUIRE(s.mesh.num_vertices() <= params.max_vertices);
            for (int v = 0; v < s.mesh.num_vertices(); ++v) {
                REQUIRE(s.mesh.position(v).z() >= 0.0);
                REQUIRE(std::abs(s.directions[v].norm() - 1.0) < 1e-9);
            }
            for (double w : s.outputs) REQUIRE((w > 0.0 && w <= 1.0));
        });
        grew += state.mesh.num_vertices() > seed.mesh.num_vertices();
    }
    CHECK(grew > 10);
}

TEST_CASE("growth matches the plain reference implementation of the spec", "[growth]") {
    GrowthParams params;
    params.steps = 40;
    params.max_vertices = 700;
    require_same_as_reference(params, 101);
}

TEST_CASE("the same genome grows the same mesh bit for bit, timed or not", "[growth]") {
    GrowthParams params;
    params.steps = 80;
    const Seed seed = make_seed("icosahedron", 1.0);
    for (std::uint64_t g = 1; g <= 5; ++g) {
        INFO("genome " << g);
        const Network network(random_test_genome(default_layers, g));
        GrowthWorkspace shared_workspace, fresh_workspace;
        const GrowthState a = Grower(network, params).grow(seed, shared_workspace);
        PhaseTimes times;
        const auto start = std::chrono::steady_clock::now();
        const GrowthState b = Grower(network, params).grow(seed, fresh_workspace, &times);  // timed
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const GrowthState c = Grower(network, params).grow(seed, shared_workspace);  // reused buffers
        CHECK(same_bits(a.mesh, b.mesh));
        CHECK(same_bits(a.mesh, c.mesh));
        CHECK(a.outputs == b.outputs);
        // The gather's share is estimated from a sample of its blocks; every
        // phase still gets a non-negative time, and they fit in the wall time.
        for (double phase : {times.gather, times.think, times.move, times.split, times.flip}) CHECK(phase >= 0.0);
        CHECK(times.think > 0.0);
        CHECK(times.gather > 0.0);
        CHECK(times.total() <= wall);
        CHECK(times.vertex_steps >= static_cast<std::uint64_t>(params.steps) * 12);
    }
}

TEST_CASE("movement respects speed and budget; ground and max_vertices hold", "[growth]") {
    GrowthParams params;
    params.split_area = 1e9;  // no splits: vertices keep their identity
    params.speed = 0.05;
    params.budget = 0.3;
    const Seed seed = make_seed("icosahedron", 1.0);
    for (std::uint64_t g = 1; g <= 20; ++g) {
        const Network network(random_test_genome(default_layers, g));
        const Grower grower(network, params);
        GrowthWorkspace workspace;
        GrowthState state = grower.start(seed);
        for (int t = 0; t < 30; ++t) {
            const std::vector<Vec3> before = state.mesh.positions();
            grower.step(state, workspace);
            double total = 0;
            for (int v = 0; v < state.mesh.num_vertices(); ++v) {
                const Vec3 moved = state.mesh.position(v) - before[v];
                REQUIRE(moved.norm() <= params.speed * 0.5 + 1e-12);  // d <= 0.5, k <= speed
                total += moved.norm();
            }
            REQUIRE(total <= params.budget + 1e-9);
        }
    }
}

TEST_CASE("growth refuses a network that does not fit", "[growth]") {
    const Network small(random_test_genome({10, 4}, 1));  // inputs != 3 * outputs
    CHECK_THROWS_AS(Grower(small, GrowthParams{}), ConfigError);
    const Network tiny(random_test_genome({6, 2}, 1));  // N < 3
    CHECK_THROWS_AS(Grower(tiny, GrowthParams{}), ConfigError);
}
