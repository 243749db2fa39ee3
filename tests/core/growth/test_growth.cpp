#include "core/base/errors.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/growth/growth.hpp"
#include "tests/support/phase_recorder.hpp"
#include "tests/support/reference_compare.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

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
        const GrowthState state = grower.grow(seed, workspace, [&](const GrowthState& s, int t) {
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

TEST_CASE("the same genome grows the same mesh bit for bit, observed or not", "[growth]") {
    GrowthParams params;
    params.steps = 80;
    const Seed seed = make_seed("icosahedron", 1.0);
    for (std::uint64_t g = 1; g <= 5; ++g) {
        INFO("genome " << g);
        const Network network(random_test_genome(default_layers, g));
        GrowthWorkspace shared_workspace, fresh_workspace;
        const GrowthState a = Grower(network, params).grow(seed, shared_workspace);
        PhaseRecorder phases;
        const GrowthState b = Grower(network, params).grow(seed, fresh_workspace, {}, &phases);
        const GrowthState c = Grower(network, params).grow(seed, shared_workspace);  // reused buffers
        CHECK(same_bits(a.mesh, b.mesh));
        CHECK(same_bits(a.mesh, c.mesh));
        CHECK(a.outputs == b.outputs);
        CHECK(phases.count(PhaseRecorder::Hook::end, GrowthPhase::think) == params.steps);
    }
}

TEST_CASE("a step reports the phases of docs/algorithm.md §5 in order, each begun and ended", "[growth]") {
    using enum GrowthPhase;
    using Hook = PhaseRecorder::Hook;
    const Network network(random_test_genome(default_layers, 3));
    const Seed seed = make_seed("icosahedron", 1.0);
    GrowthWorkspace workspace;
    // The paper's mode, collisions allowed: the four phases of §5 (think's
    // neighbour lists apart), a flip every step.
    GrowthParams params;
    const Grower grower(network, params);
    GrowthState state = grower.start(seed);
    PhaseRecorder phases;
    grower.step(state, workspace, &phases);
    std::vector<std::pair<Hook, GrowthPhase>> expected;
    for (const GrowthPhase p : {neighbours, think, move, split, flip}) {
        expected.emplace_back(Hook::begin, p);
        expected.emplace_back(Hook::end, p);
    }
    CHECK(phases.calls == expected);
    CHECK(state.steps_done == 1);

    SECTION("branching adds its phase before the move; a skipped flip is not reported") {
        params.mode = GrowthMode::branching;
        params.flip_every = 2;
        const Grower branching(network, params);
        state = branching.start(seed);
        phases.calls.clear();
        branching.step(state, workspace, &phases);  // t = 0: no flip
        expected.clear();
        for (const GrowthPhase p : {neighbours, think, branch, move, split}) {
            expected.emplace_back(Hook::begin, p);
            expected.emplace_back(Hook::end, p);
        }
        CHECK(phases.calls == expected);
        branching.step(state, workspace, &phases);  // t = 1: flips
        CHECK(phases.count(Hook::begin, flip) == 1);
    }
    SECTION("collisions prevented: the settle after the move, the guard's tests inside the flip") {
        params.collisions = Collisions::prevent;
        const Grower guarded(network, params);
        state = guarded.start(seed);
        PhaseRecorder many;
        for (int t = 0; t < 20; ++t) guarded.step(state, workspace, &many);
        CHECK(many.count(Hook::end, settle) == 20);
        CHECK(many.count(Hook::begin, flip_guard) > 0);
        CHECK(many.count(Hook::begin, flip_guard) == many.count(Hook::end, flip_guard));
        // Hooks pair up, and every guard test lies directly inside a flip.
        std::vector<GrowthPhase> open;
        for (const auto& [hook, phase] : many.calls) {
            if (hook == Hook::begin) {
                if (phase == flip_guard) CHECK((!open.empty() && open.back() == flip));
                open.push_back(phase);
            } else {
                REQUIRE_FALSE(open.empty());
                CHECK(open.back() == phase);
                open.pop_back();
            }
        }
        CHECK(open.empty());
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

TEST_CASE("GenomeGrower grows a genome from the config's seed as Grower does, bit for bit", "[growth]") {
    NetworkParams network;
    network.outputs = 7;
    network.hidden = {9};
    GrowthParams params;
    params.steps = 30;
    params.seed_mesh = "octahedron";
    params.seed_radius = 2.0;
    const GenomeGrower grower(network, params);
    CHECK(grower.layers() == network.layers());
    CHECK(grower.seed().mesh.positions() == make_seed("octahedron", 2.0).mesh.positions());
    GrowthWorkspace workspace;
    for (std::uint64_t g = 1; g <= 3; ++g) {
        INFO("genome " << g);
        const Genome genome = random_test_genome(network.layers(), g);
        const Network net(genome);
        const GrowthState expected = Grower(net, params).grow(make_seed("octahedron", 2.0), workspace);
        for (const GrowthState& got : {grower.grow(genome.params, workspace), grower.grow(genome.params),
                                       grower.grow(net, workspace)}) {
            CHECK(same_bits(got.mesh, expected.mesh));
            CHECK(got.outputs == expected.outputs);
            CHECK(got.steps_done == 30);
        }
    }
    // A genome laid out for other layers is refused, as Network refuses it.
    CHECK_THROWS_AS(grower.grow(random_test_genome(default_layers, 1).params), ConfigError);
    params.seed_mesh = "no-such-seed.obj";
    CHECK_THROWS(GenomeGrower(network, params));
}
