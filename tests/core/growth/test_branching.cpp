// growth.mode "branching" (docs/algorithm.md §5.8): its arithmetic against
// cases computed by hand, and against the plain reference implementation.
#include "core/base/errors.hpp"
#include "core/growth/branching.hpp"
#include "core/growth/growth.hpp"
#include "tests/support/reference_compare.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

constexpr int N = kBranchingOutputs;  // 7 outputs, 21 inputs, no hidden layer

// A network without hidden layers whose output j is sigmoid(-threshold_j +
// Σ_k (in_k - 0.5) weight_jk): with zero weights, exactly value_j (to the
// kernel's 4e-16).
struct DirectNetwork {
    Genome genome{{3 * N, N}, std::vector<double>(static_cast<std::size_t>(N) * (3 * N + 1), 0.0)};
    double& weight(int output, int input) { return genome.params[static_cast<std::size_t>(output) * (3 * N + 1) + input]; }
    double& threshold(int output) { return genome.params[static_cast<std::size_t>(output) * (3 * N + 1) + 3 * N]; }
    void constant(int output, double value) { threshold(output) = std::log((1.0 - value) / value); }
};

GrowthParams branching_params() {
    GrowthParams p;
    p.mode = GrowthMode::branching;
    p.split_area = 1e6;  // no splits unless a case asks for them
    return p;
}

// The regular tetrahedron seed: vertices at c + h_i / ... with c its centre,
// and each h_i (= the vertex normal) pointing from c to the vertex.
const Seed& tetrahedron() {
    static const Seed seed = make_seed("tetrahedron", 1.0);
    return seed;
}

}  // namespace

TEST_CASE("a vertex stops below 1/3 and starts above 2/3; between them it holds", "[growth][branching]") {
    // Rows: (active before, w[3]) -> active after.
    const struct { std::uint8_t before; double w3; std::uint8_t after; } rows[] = {
        {1, 0.30, 0}, {1, 1.0 / 3.0, 1}, {1, 0.5, 1}, {1, 0.9, 1},
        {0, 0.1, 0},  {0, 0.5, 0},       {0, 2.0 / 3.0, 0}, {0, 0.7, 1},
    };
    std::vector<std::uint8_t> active;
    std::vector<double> outputs;
    for (const auto& row : rows) {
        active.push_back(row.before);
        std::vector<double> w(N, 0.5);
        w[kSwitchChannel] = row.w3;
        outputs.insert(outputs.end(), w.begin(), w.end());
    }
    update_activity(active, outputs, N);
    for (std::size_t i = 0; i < std::size(rows); ++i) {
        INFO("row " << i);
        CHECK(active[i] == rows[i].after);
    }
}

TEST_CASE("one branching step of the tetrahedron, computed by hand", "[growth][branching]") {
    // Outputs everywhere: w0 0.9 (d = 0.4), w3 0.5 (keeps growing), w4 0.75,
    // w5 0.25, w6 0.6: the turn target is 0.5 n_i - 0.5 z + 0.2 u_i.
    DirectNetwork direct;
    for (int c = 0; c < N; ++c) direct.constant(c, 0.5);
    direct.constant(0, 0.9);
    direct.constant(kTurnNormalChannel, 0.75);
    direct.constant(kTurnUpChannel, 0.25);
    direct.constant(kTurnApartChannel, 0.6);
    const Network network(direct.genome);
    const GrowthParams params = branching_params();
    const Grower grower(network, params);
    GrowthWorkspace workspace;
    const Seed& seed = tetrahedron();
    GrowthState state = grower.start(seed);
    REQUIRE(state.active == std::vector<std::uint8_t>(4, 1));
    grower.step(state, workspace);

    // In a regular tetrahedron the vertex normal n_i is h_i, and as the four
    // h sum to zero, h_i minus the mean of the other three is (4/3) h_i, so
    // u_i = h_i too: h'_i = normalize((1 + 0.1 (0.5 + 0.2)) h_i - 0.1 · 0.5 z).
    // Every vertex moves k d h'_i with S = 4 · 0.4, k = min(0.2, 20 / S) = 0.2,
    // and the ground clamps z at 0.
    REQUIRE(state.mesh.num_vertices() == 4);
    for (int i = 0; i < 4; ++i) {
        const Vec3 h = seed.directions[i];
        const Vec3 turned = (1.07 * h - Vec3(0, 0, 0.05)).normalized();
        Vec3 expected = seed.mesh.position(i) + 0.2 * 0.4 * turned;
        expected.z() = std::max(expected.z(), 0.0);
        INFO("vertex " << i);
        CHECK((state.directions[i] - turned).norm() < 1e-12);
        CHECK((state.mesh.position(i) - expected).norm() < 1e-12);
        CHECK(state.active[i] == 1);
    }
    // The two lower vertices (h.z < 0) end on the ground, the upper two above it.
    CHECK(state.mesh.position(1).z() == 0.0);
    CHECK(state.mesh.position(2).z() == 0.0);
    CHECK(state.mesh.position(0).z() > seed.mesh.position(0).z());
}

TEST_CASE("dormant vertices do not move, but still turn", "[growth][branching]") {
    DirectNetwork direct;
    for (int c = 0; c < N; ++c) direct.constant(c, 0.5);
    direct.constant(0, 0.9);
    direct.constant(kSwitchChannel, 0.2);  // every vertex stops at step 0
    direct.constant(kTurnUpChannel, 1.0 - 1e-9);
    const Network network(direct.genome);
    const Grower grower(network, branching_params());
    GrowthWorkspace workspace;
    const Seed& seed = tetrahedron();
    GrowthState state = grower.start(seed);
    grower.step(state, workspace);
    CHECK(state.active == std::vector<std::uint8_t>(4, 0));
    for (int i = 0; i < 4; ++i) {
        CHECK(state.mesh.position(i) == seed.mesh.position(i));
        // Turned toward +z by ~0.1 (w5 ≈ 1): h + 0.1 z, normalised.
        const Vec3 turned = (seed.directions[i] + Vec3(0, 0, 0.1 * (1.0 - 2e-9))).normalized();
        CHECK((state.directions[i] - turned).norm() < 1e-12);
    }
}

TEST_CASE("a new vertex grows only if all three corners of its face grow", "[growth][branching]") {
    // w3 = sigmoid(5 + 10 (h.x + h.y)): vertex 3 (h = (-1, -1, 1)/√3) stops,
    // 0, 1 and 2 grow. Every face splits at step 0 (tiny split_area), in face
    // order: (0,1,2) makes vertex 4 (grows), (0,3,1), (0,2,3) and (1,3,2) make
    // 5, 6 and 7 (dormant, each has corner 3).
    DirectNetwork direct;
    for (int c = 0; c < N; ++c) direct.constant(c, 0.5);
    direct.threshold(kSwitchChannel) = -5.0;
    direct.weight(kSwitchChannel, 3 * N - 4) = 20.0;  // in = 0.5 + 0.5 h.x
    direct.weight(kSwitchChannel, 3 * N - 3) = 20.0;  // in = 0.5 + 0.5 h.y
    const Network network(direct.genome);
    GrowthParams params = branching_params();
    params.split_area = 1e-3;
    const Grower grower(network, params);
    GrowthWorkspace workspace;
    GrowthState state = grower.start(tetrahedron());
    grower.step(state, workspace);
    REQUIRE(state.mesh.num_vertices() == 8);
    CHECK(state.active == std::vector<std::uint8_t>{1, 1, 1, 0, 1, 0, 0, 0});
    // The next step's input 3N-5 is each vertex's state: the gather writes it.
    REQUIRE(state.active.size() == state.directions.size());
}

TEST_CASE("branching growth matches the plain reference implementation", "[growth][branching]") {
    GrowthParams params;
    params.mode = GrowthMode::branching;
    params.steps = 40;
    params.max_vertices = 700;
    const std::vector<GrowthState> grown = require_same_as_reference(params, 301);
    // The 18 genomes exercise both states and the turning (else the test
    // would prove little).
    const Seed seed = make_seed("icosahedron", 1.0);
    int dormant_seen = 0;
    for (const GrowthState& state : grown) dormant_seen += std::count(state.active.begin(), state.active.end(), 0) > 0;
    CHECK(dormant_seen >= 3);
    int turned = 0;
    for (int i = 0; i < 6; ++i) turned += (grown[i].directions[0] - seed.directions[0]).norm() > 1e-6;
    CHECK(turned >= 3);
}

TEST_CASE("the paper's mode is untouched by the branching keys", "[growth][branching]") {
    // Same genome, paper mode: no activity state, and the turn rate is unused.
    const Network network(random_test_genome({45, 30, 15}, 7));
    GrowthParams a, b;
    b.turn_rate = 0.7;
    a.steps = b.steps = 30;
    GrowthWorkspace wa, wb;
    const Seed seed = make_seed("icosahedron", 1.0);
    const GrowthState sa = Grower(network, a).grow(seed, wa), sb = Grower(network, b).grow(seed, wb);
    CHECK(sa.active.empty());
    CHECK(sa.mesh.faces() == sb.mesh.faces());
    CHECK(std::memcmp(sa.mesh.positions().data(), sb.mesh.positions().data(), sizeof(Vec3) * sa.mesh.num_vertices()) == 0);
}

TEST_CASE("the branching mode refuses a network with fewer than 7 outputs", "[growth][branching]") {
    const Network small(random_test_genome({18, 6}, 1));
    CHECK_NOTHROW(Grower(small, GrowthParams{}));
    CHECK_THROWS_AS(Grower(small, branching_params()), ConfigError);
}
