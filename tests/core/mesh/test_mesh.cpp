// TriMesh: building and checking a mesh, its topology operations (split,
// can_flip, flip) and queries. When an edge flips (docs/algorithm.md §5.4):
// tests/core/growth/test_flip_pass.cpp.
#include "core/mesh/mesh.hpp"
#include "tests/fitness/mesh_builders.hpp"
#include "tests/support/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace morphogen;
using namespace morphogen::test;
using namespace morphogen::testing;

namespace {

// Base case: a flat rhombus base whose long diagonal Q0-Q2 may flip.
MeshArrays flippable() { return pyramid({-2, 0, 0}, {0, -1, 0}, {2, 0, 0}, {0, 1, 0}); }

// The regular tetrahedron: every two of its vertices are joined.
MeshArrays tetrahedron() {
    return {{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
}

// The faces, each as its sorted vertices, in sorted order.
std::vector<Face> face_sets(std::vector<Face> faces) {
    for (Face& t : faces) std::sort(t.begin(), t.end());
    std::sort(faces.begin(), faces.end());
    return faces;
}

}  // namespace

TEST_CASE("from_arrays accepts closed oriented spheres and rejects defects", "[mesh]") {
    CHECK_NOTHROW(TriMesh::from_arrays(flippable()));
    MeshArrays open = flippable();
    open.faces.pop_back();
    CHECK_THROWS_WITH(TriMesh::from_arrays(open, "open.obj"), Catch::Contains("open.obj") && Catch::Contains("open"));
    MeshArrays flipped = flippable();
    std::swap(flipped.faces[0][0], flipped.faces[0][1]);
    CHECK_THROWS_WITH(TriMesh::from_arrays(flipped), Catch::Contains("same direction"));
    MeshArrays degenerate = flippable();
    degenerate.faces[0] = {0, 0, 4};
    CHECK_THROWS_WITH(TriMesh::from_arrays(degenerate), Catch::Contains("degenerate"));
    MeshArrays out_of_range = flippable();
    out_of_range.faces[0][2] = 9;
    CHECK_THROWS_WITH(TriMesh::from_arrays(out_of_range), Catch::Contains("out of range"));
    // Two disjoint tetrahedra: closed and oriented, but not one sphere.
    MeshArrays two;
    const MeshArrays tet = tetrahedron();
    for (int copy = 0; copy < 2; ++copy) {
        for (const Vec3& p : tet.positions) two.positions.push_back(p + Vec3(5.0 * copy, 0, 0));
        for (Face f : tet.faces) two.faces.push_back({f[0] + 4 * copy, f[1] + 4 * copy, f[2] + 4 * copy});
    }
    CHECK_THROWS_WITH(TriMesh::from_arrays(two), Catch::Contains("not connected"));
    MeshArrays nan = flippable();
    nan.positions[1].x() = std::nan("");
    CHECK_THROWS_WITH(TriMesh::from_arrays(nan), Catch::Contains("non-finite"));
}

TEST_CASE("split keeps every invariant and wires the new faces as specified", "[mesh]") {
    TriMesh mesh = TriMesh::from_arrays(make_icosphere(0));  // the icosahedron
    const Face before = mesh.face(3);
    const int v = mesh.split_face(3, mesh.face_centroid(3));
    CHECK(v == 12);
    CHECK(mesh.face(3) == Face{before[0], before[1], v});
    CHECK(mesh.face(20) == Face{before[1], before[2], v});
    CHECK(mesh.face(21) == Face{before[2], before[0], v});
    CHECK(mesh.valence(v) == 3);
    CHECK(mesh.check().empty());
    // Split every face repeatedly, checking after each split.
    for (int round = 0; round < 3; ++round) {
        const int F = mesh.num_faces();
        for (int f = 0; f < F; f += 2) {
            mesh.split_face(f, mesh.face_centroid(f));
            INFO("round " << round << " face " << f);
            REQUIRE(mesh.check().empty());
        }
    }
}

TEST_CASE("flip rewrites f and g, and flipping the new edge brings the old one back", "[mesh][flip]") {
    TriMesh mesh = TriMesh::from_arrays(flippable());
    const std::vector<Face> before = mesh.faces();
    const auto [f, e] = find_half_edge(mesh, 0, 2);  // B = Q0, D = Q2, A = Q1; across it C = Q3
    REQUIRE(mesh.can_flip(f, e));
    mesh.flip(f, e);
    CHECK(mesh.face(f) == Face{1, 0, 3});  // (A,B,C)
    CHECK(mesh.adjacent(1, 3));
    CHECK_FALSE(mesh.adjacent(0, 2));
    CHECK(mesh.check().empty());
    const auto [f2, e2] = find_half_edge(mesh, 3, 1);  // the new edge, C -> A
    REQUIRE(mesh.can_flip(f2, e2));
    mesh.flip(f2, e2);
    CHECK(mesh.check().empty());
    CHECK(face_sets(mesh.faces()) == face_sets(before));
}

TEST_CASE("can_flip refuses a flip whose new edge is there already", "[mesh][flip]") {
    const TriMesh tet = TriMesh::from_arrays(tetrahedron());
    for (int f = 0; f < tet.num_faces(); ++f)
        for (int e = 0; e < 3; ++e) CHECK_FALSE(tet.can_flip(f, e));
}

TEST_CASE("random splits and flips keep every invariant", "[mesh][flip]") {
    const MeshArrays starts[] = {make_icosphere(0), make_box({0, 0, 0}, {1, 2, 3}), tetrahedron()};
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        std::mt19937 rng(seed);
        TriMesh mesh = TriMesh::from_arrays(starts[seed % 3]);
        int flips = 0;
        for (int op = 0; op < 150; ++op) {
            const int f = static_cast<int>(rng() % static_cast<std::uint32_t>(mesh.num_faces()));
            if (rng() % 5 < 2) {
                mesh.split_face(f, mesh.face_centroid(f) + 0.05 * mesh.face_cross(f).normalized());
            } else if (const int e = static_cast<int>(rng() % 3); mesh.can_flip(f, e)) {
                mesh.flip(f, e);
                ++flips;
            }
            INFO("seed " << seed << " op " << op);
            REQUIRE(mesh.check().empty());
        }
        CHECK(flips > 0);
    }
}

TEST_CASE("neighbour queries agree with the faces", "[mesh]") {
    TriMesh mesh = TriMesh::from_arrays(make_icosphere(0));
    for (int f = 0; f < 20; f += 3) mesh.split_face(f, mesh.face_centroid(f));
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        std::vector<int> around;
        mesh.for_each_neighbour(v, [&](int u) { around.push_back(u); });
        std::vector<int> expected;
        for (const Face& f : mesh.faces())
            for (int k = 0; k < 3; ++k)
                if (f[k] == v) expected.push_back(f[(k + 1) % 3]);
        std::sort(around.begin(), around.end());
        std::sort(expected.begin(), expected.end());
        CHECK(around == expected);
        CHECK(mesh.valence(v) == static_cast<int>(expected.size()));
        for (int u = 0; u < mesh.num_vertices(); ++u)
            CHECK(mesh.adjacent(v, u) == std::binary_search(expected.begin(), expected.end(), u));
    }
}
