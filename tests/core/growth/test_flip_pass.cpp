// The flip criteria and pass of docs/algorithm.md §5.4 (core/growth/contact/flip_pass.hpp):
// the canonical flip, each criterion alone, the pass against the plain loop.
// The flip itself (topology): tests/core/mesh/test_mesh.cpp.
#include "evolution/rng.hpp"
#include "core/growth/contact/flip_pass.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "core/mesh/mesh.hpp"
#include "tests/support/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

// Base case: a flat rhombus base whose long diagonal Q0-Q2 may flip.
MeshArrays flippable() { return pyramid({-2, 0, 0}, {0, -1, 0}, {2, 0, 0}, {0, 1, 0}); }

// Flip the base diagonal Q0 -> Q2 (half-edge in face (Q0,Q2,Q1)).
bool flip_base(TriMesh& mesh, const FlipCriteria& criteria) {
    const auto [f, e] = find_half_edge(mesh, 0, 2);
    REQUIRE(f >= 0);
    return try_flip(mesh, f, e, criteria);
}

FlipCriteria lenient() {
    FlipCriteria c;
    c.min_valence = 3;
    return c;
}

}  // namespace

TEST_CASE("the canonical flip rewrites f and g as specified", "[flip]") {
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

TEST_CASE("each flip condition alone blocks the flip", "[flip]") {
    SECTION("f < g: the pair is only flipped from its lower face") {
        TriMesh mesh = TriMesh::from_arrays(flippable());
        const auto [g, e] = find_half_edge(mesh, 2, 0);  // the same edge seen from face 5
        REQUIRE(g == 5);
        CHECK_FALSE(try_flip(mesh, g, e, lenient()));
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

TEST_CASE("a flip pass flips what try_flip on every edge in order flips", "[flip]") {
    int total = 0;
    for (const std::string& name : builtin_seed_names()) {
        RandomStream rng(11, 3);
        TriMesh mesh = builtin_seed_mesh(name, 1.0);
        // Splits at points off the surface, in and out, so that many edges may flip.
        for (int k = 0; k < 300; ++k) {
            const int f = static_cast<int>(rng.below(mesh.num_faces()));
            mesh.split_face(f, mesh.face_centroid(f) + rng.uniform(-0.05, 0.1) * mesh.face_cross(f).normalized());
        }
        FlipCriteria criteria;
        criteria.min_valence = 3;
        for (int pass = 0; pass < 3; ++pass) {
            TriMesh loop = mesh;
            int loop_flips = 0;
            for (int f = 0; f < loop.num_faces(); ++f)
                for (int e = 0; e < 3; ++e) loop_flips += try_flip(loop, f, e, criteria);
            const int flips = flip_pass(mesh, criteria);
            INFO(name << " pass " << pass);
            CHECK(flips == loop_flips);
            REQUIRE(mesh.faces() == loop.faces());
            REQUIRE(mesh.check().empty());
            total += flips;
        }
    }
    CHECK(total > 0);
}
