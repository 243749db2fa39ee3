// growth.collisions "prevent" (docs/algorithm.md §5.7): the face-pair rule,
// its float filter against the exact predicates, and the guard on a mesh.
#include "evolution/rng.hpp"
#include "core/growth/contact/collision.hpp"
#include "core/growth/growth.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "core/mesh/face_pair.hpp"
#include "tests/support/phase_recorder.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

IndexedTriangle tri(Face v, Vec3 a, Vec3 b, Vec3 c) {
    std::vector<Vec3> positions(static_cast<std::size_t>(std::max({v[0], v[1], v[2]})) + 1);
    positions[v[0]] = a;
    positions[v[1]] = b;
    positions[v[2]] = c;
    return IndexedTriangle::of(positions, v);
}

// Every pair of faces by brute force: what the guard must leave at zero.
int intersecting_pairs(const TriMesh& mesh) {
    int count = 0;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const IndexedTriangle a = IndexedTriangle::of(mesh.positions(), mesh.face(f));
        count += triangle_degenerate(a.p[0], a.p[1], a.p[2]);
        for (int g = f + 1; g < mesh.num_faces(); ++g)
            count += faces_intersect(a, IndexedTriangle::of(mesh.positions(), mesh.face(g)));
    }
    return count;
}

}  // namespace

TEST_CASE("face pairs follow CGAL's rule for shared vertices and edges", "[collision]") {
    const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    // No shared vertex: apart, crossing, touching at a point (contact counts).
    CHECK_FALSE(faces_intersect(tri({0, 1, 2}, o, x, y), tri({3, 4, 5}, z, z + x, z + y)));
    CHECK(faces_intersect(tri({0, 1, 2}, o, x, y), tri({3, 4, 5}, {0.2, 0.2, -1}, {0.2, 0.2, 1}, {2, 2, 0})));
    CHECK(faces_intersect(tri({0, 1, 2}, o, x, y), tri({3, 4, 5}, x, x + z, x + y + z)));
    // Coplanar, side by side (as on the ground), and overlapping.
    CHECK_FALSE(faces_intersect(tri({0, 1, 2}, o, x, y), tri({3, 4, 5}, {1, 1, 0}, {2, 1, 0}, {1, 2, 0})));
    CHECK(faces_intersect(tri({0, 1, 2}, o, x, y), tri({3, 4, 5}, {0.1, 0.1, 0}, {2, 0.1, 0}, {0.1, 2, 0})));
    // One shared vertex (0): a fan is fine; a face through the other is not,
    // nor one folded flat onto it.
    CHECK_FALSE(faces_intersect(tri({0, 1, 2}, o, x, y), tri({0, 3, 4}, o, -x, -y)));
    CHECK(faces_intersect(tri({0, 1, 2}, o, x, y), tri({0, 3, 4}, o, {0.3, 0.3, -1}, {0.3, 0.3, 1})));
    CHECK(faces_intersect(tri({0, 1, 2}, o, x, y), tri({0, 3, 4}, o, {0.5, 0.1, 0}, {0.1, 0.5, 0})));
    // A shared edge (0-1): open, flat, or folded onto each other.
    CHECK_FALSE(faces_intersect(tri({0, 1, 2}, o, x, y), tri({1, 0, 3}, x, o, z)));
    CHECK_FALSE(faces_intersect(tri({0, 1, 2}, o, x, y), tri({1, 0, 3}, x, o, -y)));
    CHECK(faces_intersect(tri({0, 1, 2}, o, x, y), tri({1, 0, 3}, x, o, {0.5, 0.5, 0})));
    // Degenerate faces.
    CHECK(triangle_degenerate(o, x, 2 * x));
    CHECK(triangle_degenerate(o, o, y));
    CHECK_FALSE(triangle_degenerate(o, x, {1e-9, 1e-9, 0}));
}

TEST_CASE("the float filter never contradicts the exact predicates", "[collision]") {
    // Small integer coordinates: coplanar, collinear and touching cases abound,
    // where a filter without sound error bounds would answer wrongly.
    RandomStream stream(7, 0);
    const auto point = [&] {
        Vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = std::floor(stream.uniform(-3.0, 3.0)) * 0.5 + 0.1;
        return p;
    };
    int intersecting = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Vec3 v = point(), a1 = point(), a2 = point(), b1 = point(), b2 = point(), b3 = point();
        if (triangle_degenerate(v, a1, a2) || triangle_degenerate(v, b1, b2) || triangle_degenerate(b1, b2, b3) ||
            triangle_degenerate(a1, v, b1))
            continue;
        INFO("trial " << trial);
        const bool none = faces_intersect(tri({0, 1, 2}, v, a1, a2), tri({3, 4, 5}, b1, b2, b3));
        REQUIRE(none == exact::triangles_intersect({v, a1, a2}, {b1, b2, b3}));
        const bool vertex = faces_intersect(tri({0, 1, 2}, v, a1, a2), tri({0, 4, 5}, v, b1, b2));
        REQUIRE(vertex == exact::shared_vertex_pair_intersects(v, a1, a2, b1, b2));
        const bool edge = faces_intersect(tri({0, 1, 2}, v, a1, a2), tri({1, 0, 5}, a1, v, b1));
        REQUIRE(edge == exact::shared_edge_pair_folds(v, a1, a2, b1));
        intersecting += none + vertex + edge;
    }
    CHECK(intersecting > 1000);
}

TEST_CASE("a move through the surface is shortened or refused", "[collision]") {
    // The top vertex of an octahedron (centre (0, 0, 1)) pulled sideways
    // into the equator's plane: its faces fold onto each other there.
    const Seed seed = make_seed("octahedron", 1.0);
    TriMesh mesh = seed.mesh;
    const std::vector<Vec3> before = mesh.positions();
    int side = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (before[v].z() > before[side].z()) side = v;
    mesh.positions()[side] = Vec3(3.0, 0.0, 1.0);
    REQUIRE(intersecting_pairs(mesh) > 0);
    CollisionGuard guard;
    guard.settle_move(mesh, before);
    CHECK(intersecting_pairs(mesh) == 0);
    CHECK(guard.shortened == 1);
    // A small move that hits nothing is taken whole.
    TriMesh free = seed.mesh;
    free.positions()[side].z() += 0.5;
    const Vec3 wanted = free.position(side);
    guard.settle_move(free, before);
    CHECK(free.position(side) == wanted);
}

TEST_CASE("grown with collisions prevented, no two faces intersect, the same bits in any workspace",
          "[collision]") {
    GrowthParams params;
    params.steps = 40;
    params.max_vertices = 600;
    params.collisions = Collisions::prevent;
    const Seed seed = make_seed("icosahedron", 1.0);
    GrowthWorkspace shared;  // reused across genomes: nothing of one may leak into the next
    long guarded_flips = 0;
    for (std::uint64_t g = 1; g <= 20; ++g) {
        INFO("genome " << g);
        const Network network(random_test_genome({45, 30, 15}, g));
        const GrowthState a = Grower(network, params).grow(seed, shared, [](const GrowthState& s, int) {
            REQUIRE(s.mesh.check().empty());
        });
        CHECK(intersecting_pairs(a.mesh) == 0);
        GrowthWorkspace fresh;
        PhaseRecorder phases;
        const GrowthState b = Grower(network, params).grow(seed, fresh, {}, &phases);  // observed
        CHECK(a.mesh.faces() == b.mesh.faces());
        CHECK(a.mesh.positions() == b.mesh.positions());
        CHECK(a.outputs == b.outputs);
        // Every move is settled; not every genome proposes a flip the guard must test.
        CHECK(phases.count(PhaseRecorder::Hook::end, GrowthPhase::settle) == params.steps);
        guarded_flips += phases.count(PhaseRecorder::Hook::end, GrowthPhase::flip_guard);
    }
    CHECK(guarded_flips > 0);
}
