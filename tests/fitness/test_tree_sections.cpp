// The tree measures (fitness/architecture/tree_sections.hpp, docs/fitness-measures.md "Tree
// measures") on meshes with known answers, and as fitness terms and
// descriptors.
#include "fitness/descriptors.hpp"
#include "fitness/architecture/tree_sections.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace morphogen;
using namespace morphogen::test;

TEST_CASE("tree sections: a trunk under three crowns, a box, a sphere", "[fitness][tree]") {
    // Lowest quarter: the trunk alone, width sqrt(2). Upper half: the plane
    // at z = 10 counts the crowns' bottoms as above it (z >= h), so it cuts
    // the trunk; every higher plane cuts three crowns, width sqrt(14^2 + 2^2).
    const MeshArrays tree = three_crowned_tree();
    const TreeSections t = tree_sections(tree.view());
    CHECK(t.trunk_ratio == Approx(std::sqrt(2.0) / std::sqrt(200.0)));
    CHECK(t.upper_loops == 3);
    const MeshArrays split = unwelded(tree);
    const TreeSections u = tree_sections(split.view());
    CHECK(u.trunk_ratio == t.trunk_ratio);
    CHECK(u.upper_loops == 3);

    const MeshArrays box = make_box({0, 0, 0}, {3, 1, 7});
    CHECK(tree_sections(box.view()).trunk_ratio == 1.0);
    CHECK(tree_sections(box.view()).upper_loops == 1);

    // A unit sphere: the lowest quarter is widest at its top plane (i = 15),
    // z = -1 + 31/128 * 2, where the chord is 2 sqrt(1 - z^2); the upper half's
    // widest is the equator (i = 32, z = 0), 2. One loop everywhere.
    const MeshArrays sphere = make_icosphere(4);
    const TreeSections s = tree_sections(sphere.view());
    const double z = -1.0 + 31.0 / 128.0 * 2.0;
    CHECK(s.trunk_ratio == Approx(std::sqrt(1.0 - z * z)).epsilon(0.01));
    CHECK(s.upper_loops == 1);
}

TEST_CASE("tree sections: undefined for a flat mesh, refused for no faces", "[fitness][tree]") {
    const MeshArrays flat = make_square(0, 0, 1, 1, 2.0);
    CHECK(std::isnan(tree_sections(flat.view()).trunk_ratio));
    CHECK(tree_sections(flat.view()).upper_loops == 0);
    MeshArrays none;
    none.positions = {{0, 0, 0}};
    CHECK_THROWS_AS(tree_sections(none.view()), std::invalid_argument);
    CHECK_THROWS_AS(tree_sections(flat.view(), 0), std::invalid_argument);
}

TEST_CASE("tree sections are descriptors: trunk_ratio and upper_loops", "[fitness][tree][descriptors]") {
    const MeshArrays tree = three_crowned_tree();
    const DescriptorSet set({"trunk_ratio", "upper_loops"}, CanopyParams{});
    const std::vector<double> values = set(tree.view());
    CHECK(values[0] == Approx(0.1));
    CHECK(values[1] == 3.0);
}
