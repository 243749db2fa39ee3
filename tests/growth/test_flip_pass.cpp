// The flip of docs/algorithm.md §5.4: the canonical flip, each criterion
// alone, and random splits and flips keeping every invariant.
#include "evolution/rng.hpp"
#include "growth/seeds.hpp"
#include "mesh/mesh.hpp"
#include "tests/support/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

// Base case: a flat rhombus base whose long diagonal Q0-Q2 may flip.
MeshArrays flippable() { return pyramid({-2, 0, 0}, {0, -1, 0}, {2, 0, 0}, {0, 1, 0}); }

// Flip the base diagonal Q0 -> Q2 (half-edge in face (Q0,Q2,Q1)).
bool flip_base(TriMesh& mesh, const FlipCriteria& criteria) {
    const auto [f, e] = find_half_edge(mesh, 0, 2);
    REQUIRE(f >= 0);
    return mesh.try_flip(f, e, criteria);
}

FlipCriteria lenient() {
    FlipCriteria c;
    c.min_valence = 3;
    return c;
}

}  // namespace

TEST_CASE("the canonical flip rewrites f and g as specified", "[mesh][flip]") {
    TriMesh mesh = TriMesh::from_arrays(flippable());
    REQUIRE(flip_base(mesh, lenient()));
    // f = (Q0,Q2,Q1): e = 0 -> B = Q0, D = Q2, A = Q1; g = (Q0,Q3,Q2), C = Q3.
    CHECK(mesh.face(4) == Face{1, 0, 3});  // (A,B,C)
    CHECK(mesh.face(5) == Face{3, 2, 1});  // (C,D,A)
    CHECK(mesh.valence(0) == 3);
    CHECK(mesh.valence(2) == 3);
    CHECK(mesh.valence(1) == 4);
    CHECK(mesh.valence(3) == 4);
    CHECK(mesh.check().empty());
}

TEST_CASE("each flip condition alone blocks the flip", "[mesh][flip]") {
    SECTION("f < g: the pair is only flipped from its lower face") {
        TriMesh mesh = TriMesh::from_arrays(flippable());
        const auto [g, e] = find_half_edge(mesh, 2, 0);  // the same edge seen from face 5
        REQUIRE(g == 5);
        CHECK_FALSE(mesh.try_flip(g, e, lenient()));
    }
    SECTION("|AC| < |BD|") {
        TriMesh mesh = TriMesh::from_arrays(pyramid({-0.5, 0, 0}, {0, -2, 0}, {0.5, 0, 0}, {0, 2, 0}));
        CHECK_FALSE(flip_base(mesh, lenient()));
        // Equal lengths block too (strict inequality).
        TriMesh square = TriMesh::from_arrays(pyramid({-1, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}));
        CHECK_FALSE(flip_base(square, lenient()));
    }
    SECTION("the normals' angle") {
        // Fold the base along Q0-Q2 by 2 * 10 degrees.
        const double drop = std::tan(10.0 * std::numbers::pi / 180.0);
        TriMesh folded = TriMesh::from_arrays(pyramid({-2, 0, 0}, {0, -1, -drop}, {2, 0, 0}, {0, 1, -drop}));
        FlipCriteria wide = lenient();
        wide.min_normal_dot = std::cos(25.0 * std::numbers::pi / 180.0);
        FlipCriteria narrow = lenient();
        narrow.min_normal_dot = std::cos(15.0 * std::numbers::pi / 180.0);
        CHECK_FALSE(flip_base(folded, narrow));
        CHECK(folded.check().empty());
        CHECK(flip_base(folded, wide));
    }
    SECTION("the new faces' orientation (a non-convex quad)") {
        TriMesh dart = TriMesh::from_arrays(pyramid({-2, 0, 0}, {-3, -0.1, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}));
        CHECK_FALSE(flip_base(dart, lenient()));
    }
    SECTION("valence of B and D") {
        TriMesh mesh = TriMesh::from_arrays(flippable());
        FlipCriteria strict = lenient();
        strict.min_valence = 4;  // Q0 and Q2 have valence 4: not > 4
        CHECK_FALSE(flip_base(mesh, strict));
    }
    SECTION("A and C already joined") {
        // A flat tetrahedron: its two lower faces share Q0-Q2 and lie almost in
        // one plane, but Q1-Q3 is already an edge (of the upper faces).
        MeshArrays tet;
        tet.positions = {{-2, 0, 0}, {0, -1, 0.01}, {2, 0, 0}, {0, 1, 0.01}};
        tet.faces = {{0, 2, 1}, {0, 3, 2}, {0, 1, 3}, {1, 2, 3}};
        TriMesh mesh = TriMesh::from_arrays(tet);
        FlipCriteria criteria = lenient();
        criteria.min_valence = 2;
        CHECK_FALSE(flip_base(mesh, criteria));
    }
    SECTION("a zero-area face has no normal") {
        TriMesh mesh = TriMesh::from_arrays(pyramid({-2, 0, 0}, {0, 0, 0}, {2, 0, 0}, {0, 1, 0}));
        CHECK_FALSE(flip_base(mesh, lenient()));
    }
}

TEST_CASE("random splits and flips keep every invariant", "[mesh]") {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        RandomStream rng(seed, 7);
        TriMesh mesh = builtin_seed_mesh(builtin_seed_names()[seed % 3], 1.0);
        FlipCriteria criteria;
        criteria.min_valence = 3;
        criteria.min_normal_dot = -1.0;
        int flips = 0;
        for (int op = 0; op < 150; ++op) {
            if (rng.uniform() < 0.4) {
                const int f = static_cast<int>(rng.below(mesh.num_faces()));
                Vec3 point = mesh.face_centroid(f) + 0.05 * mesh.face_cross(f).normalized();
                mesh.split_face(f, point);
            } else {
                flips += mesh.try_flip(static_cast<int>(rng.below(mesh.num_faces())), static_cast<int>(rng.below(3)),
                                       criteria);
            }
            INFO("seed " << seed << " op " << op);
            REQUIRE(mesh.check().empty());
        }
        CHECK(flips > 0);
    }
}
