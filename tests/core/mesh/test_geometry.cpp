// mesh/'s geometry at its own level: vertex normals, the spatial hash, the
// face listing (against brute force over every pair) and fan certificates.
// The collision guard built on them is tested in tests/core/growth/.
#include "core/mesh/face_listing.hpp"
#include "core/mesh/fan_certificate.hpp"
#include "core/mesh/mesh.hpp"
#include "core/mesh/spatial_hash.hpp"
#include "core/mesh/vertex_normals.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace morphogen;
using morphogen::test::make_box;
using morphogen::test::make_icosphere;
using morphogen::test::make_square;

namespace {

// Random boxes of a few sizes in a 10-unit cube; some are points.
std::vector<Box3> random_boxes(int count, unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> where(-5.0, 5.0), size(0.0, 1.5);
    std::vector<Box3> boxes;
    for (int i = 0; i < count; ++i) {
        const Vec3 lo(where(random), where(random), where(random));
        const Vec3 extent = i % 7 == 0 ? Vec3::Zero() : Vec3(size(random), size(random), size(random));
        boxes.push_back({lo, lo + extent});
    }
    return boxes;
}

}  // namespace

TEST_CASE("vertex normals: unit, outward on a sphere, up on a square, zero where none", "[mesh][normals]") {
    const MeshArrays sphere = make_icosphere(2);
    const std::vector<Vec3> normals = vertex_normals(sphere.view());
    REQUIRE(normals.size() == sphere.positions.size());
    for (std::size_t v = 0; v < normals.size(); ++v) {
        CHECK(normals[v].norm() == Approx(1.0));
        CHECK(normals[v].dot(sphere.positions[v].normalized()) > 0.9);
    }
    MeshArrays square = make_square(0, 0, 1, 1, 0);
    square.positions.push_back({5, 5, 5});  // a vertex of no face
    std::vector<Vec3> reused(1, Vec3(9, 9, 9));
    vertex_normals(square.view(), reused);
    REQUIRE(reused.size() == square.positions.size());
    for (std::size_t v = 0; v + 1 < reused.size(); ++v) CHECK(reused[v] == Vec3(0, 0, 1));
    CHECK(reused.back() == Vec3::Zero());
}

TEST_CASE("spatial hash: every listed box that overlaps a query is a candidate", "[mesh][spatial_hash]") {
    const std::vector<Box3> boxes = random_boxes(300, 5);
    SpatialHash grid;
    grid.build(SpatialHash::cell_size_for(boxes), boxes);
    CHECK(grid.built_entries() >= boxes.size());
    const Box3 late{{-1, -1, -1}, {1, 1, 1}};
    grid.insert(1000, late);
    CHECK(grid.late_entries() >= 1);
    for (const Box3& query : random_boxes(100, 6)) {
        std::set<int> candidates;
        grid.for_each_candidate(query, [&](int id, const Box3&) { candidates.insert(id); });
        for (std::size_t i = 0; i < boxes.size(); ++i)
            if (boxes[i].overlaps(query)) CHECK(candidates.count(static_cast<int>(i)) == 1);
        if (late.overlaps(query)) CHECK(candidates.count(1000) == 1);
    }
    // Closed boxes: touching counts; a box inside another is contained.
    CHECK(Box3{{0, 0, 0}, {1, 1, 1}}.overlaps({{1, 1, 1}, {2, 2, 2}}));
    CHECK_FALSE(Box3{{0, 0, 0}, {1, 1, 1}}.overlaps({{1.5, 0, 0}, {2, 1, 1}}));
    CHECK(Box3{{0, 0, 0}, {1, 1, 1}}.inflated(0.5).contains({{-0.5, 0, 0}, {1.5, 1, 1}}));
}

TEST_CASE("face listing: partners are exactly the pairs whose boxes meet and the rule keeps", "[mesh][face_listing]") {
    std::vector<Box3> boxes = random_boxes(200, 7);
    FaceListing listing;
    for (int f = 0; f < static_cast<int>(boxes.size()); ++f) listing.relist(f, boxes[f]);
    const auto keep = [](int f, int g) { return (f + g) % 5 != 0; };
    const auto check_against_brute_force = [&] {
        listing.refresh(keep);
        for (int f = 0; f < listing.size(); ++f) {
            std::set<int> expected;
            for (int g = 0; g < listing.size(); ++g)
                if (g != f && boxes[f].overlaps(boxes[g]) && keep(f, g)) expected.insert(g);
            const std::span<const int> partners = listing.partners(f);
            CHECK(std::set<int>(partners.begin(), partners.end()) == expected);
            CHECK(partners.size() == expected.size());  // no repeats
        }
    };
    check_against_brute_force();
    // Some faces move and are listed again; a new face joins.
    for (int f = 0; f < 200; f += 9) {
        boxes[f] = {boxes[f].lo + Vec3(1, 0, 0), boxes[f].hi + Vec3(1, 0, 0)};
        listing.relist(f, boxes[f]);
    }
    boxes.push_back({{-2, -2, -2}, {2, 2, 2}});
    listing.relist(200, boxes.back());
    check_against_brute_force();
    int met = 0;
    listing.for_each_meeting({{-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}}, [&](int g) { met += g == 200; });
    CHECK(met == 1);
}

TEST_CASE("fan certificates: every fan of a convex solid, no fan with a degenerate face", "[mesh][fan]") {
    std::vector<Vec3> scratch;
    for (const MeshArrays& arrays : {make_icosphere(1), make_box({0, 0, 0}, {1, 2, 3})}) {
        const TriMesh mesh = TriMesh::from_arrays(arrays);
        for (int v = 0; v < mesh.num_vertices(); ++v) CHECK(fan_certified(mesh, v, scratch));
    }
    // A vertex moved onto its neighbour: the faces of that edge collapse.
    MeshArrays arrays = make_icosphere(1);
    TriMesh mesh = TriMesh::from_arrays(arrays);
    const Face first = mesh.face(0);
    mesh.positions()[first[0]] = mesh.positions()[first[1]];
    CHECK_FALSE(fan_certified(mesh, first[0], scratch));
    CHECK_FALSE(fan_certified(mesh, first[1], scratch));
}
