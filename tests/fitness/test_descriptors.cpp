// Descriptor measures on meshes with known answers, the canopy tops behind
// crown_height, and the lookup by name.
#include "fitness/functions/canopy.hpp"
#include "fitness/descriptors.hpp"
#include "fitness/measures.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

using namespace morphogen;
using morphogen::test::make_box;
using morphogen::test::make_bumpy;
using morphogen::test::make_icosphere;
using morphogen::test::make_square;
using morphogen::test::merge;

namespace {
double measure(const std::string& name, const MeshArrays& mesh, CanopyParams canopy = {}) {
    return find_descriptor_measure(name).measure(mesh.view(), canopy);
}

double brute_width(const MeshArrays& mesh) {
    double best = 0;
    for (const Vec3& a : mesh.positions)
        for (const Vec3& b : mesh.positions) best = std::max(best, std::hypot(a.x() - b.x(), a.y() - b.y()));
    return best;
}

// A plane z = 10 + x over [0,2] x [0,1] (two triangles, facing up).
MeshArrays ramp() {
    MeshArrays m;
    m.positions = {{0, 0, 10}, {2, 0, 12}, {2, 1, 12}, {0, 1, 10}};
    m.faces = {{0, 1, 2}, {0, 2, 3}};
    return m;
}
}  // namespace

TEST_CASE("descriptor measures of a box", "[fitness][descriptors]") {
    const MeshArrays box = make_box({1, -1, 2}, {3, 2, 6});  // 2 x 3 x 4, top at 6
    CHECK(measure("height", box) == 6.0);
    CHECK(measure("footprint", box) == Approx(6.0));
    CHECK(measure("width", box) == Approx(std::sqrt(13.0)));
    CHECK(measure("area", box) == Approx(52.0));
    CHECK(measure("volume", box) == Approx(24.0));
    CHECK(measure("vertices", box) == 8.0);
    CHECK(measure("faces", box) == 12.0);
    CHECK(measure("slenderness", box) == Approx(6.0 / std::sqrt(6.0)));
    CHECK(measure("canopy", box) == 0.0);  // below the default height 10
    CHECK(measure("canopy", box, {5.0, 0.1}) == Approx(6.0));
    CHECK(measure("lean", box) == Approx(0.0).margin(1e-12));
    CHECK(measure("spread", box) == Approx(1.0));
    // a unit cube's sphericity is (pi^(1/3) 6^(2/3)) / 6 = 0.806
    CHECK(measure("sphericity", make_box({0, 0, 0}, {1, 1, 1})) == Approx(0.805996).epsilon(1e-5));
}

TEST_CASE("width is the diameter of the xy-projection", "[fitness][descriptors]") {
    for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
        const MeshArrays blob = make_bumpy(seed, 2);
        CHECK(mesh_width(blob.view()) == Approx(brute_width(blob)).epsilon(1e-12));
    }
    const MeshArrays sphere = make_icosphere(3);
    CHECK(mesh_width(sphere.view()) == Approx(brute_width(sphere)).epsilon(1e-12));
    // collinear and single points
    const std::vector<Vec3> line{{0, 0, 0}, {1, 1, 5}, {3, 3, 1}, {2, 2, 2}};
    CHECK(xy_width(line) == Approx(3 * std::sqrt(2.0)));
    const std::vector<Vec3> stacked{{1, 2, 0}, {1, 2, 9}};
    CHECK(xy_width(stacked) == 0.0);
    CHECK(xy_width(std::vector<Vec3>{}) == 0.0);
}

TEST_CASE("crown_height is the mean top height over the canopy cells", "[fitness][descriptors]") {
    // A flat top at 11 over [0,1]^2: every top is exactly 11.
    const MeshArrays tower = make_box({0, 0, 0}, {1, 1, 11});
    CHECK(measure("crown_height", tower) == 11.0);
    // The ramp: H = 10 + x; above 10 every column counts (mean x = 1),
    // above 10.5 the columns with centres 0.55 .. 1.95 (mean x = 1.25).
    CHECK(measure("crown_height", ramp(), {10.0, 0.1}) == Approx(11.0));
    CHECK(measure("crown_height", ramp(), {10.5, 0.1}) == Approx(11.25));
    // Two stacked squares: H is the upper one.
    const MeshArrays stacked = merge(make_square(0, 0, 1, 1, 12), make_square(0, 0, 1, 1, 14));
    CHECK(measure("crown_height", stacked) == Approx(14.0));
    // No canopy: the canopy's height itself.
    CHECK(measure("crown_height", make_box({0, 0, 0}, {1, 1, 3}), {7.5, 0.1}) == 7.5);
}

TEST_CASE("canopy_tops has exactly the canopy's cells, each with its top", "[fitness][descriptors][canopy]") {
    for (unsigned seed : {11u, 12u, 13u}) {
        const MeshArrays blob = make_bumpy(seed);
        const CanopyParams params{10.0, 0.25};
        const std::vector<CanopyTop> tops = canopy_tops(blob.view(), params);
        const std::vector<CellIndex> cells = canopy_cells(blob.view(), params);
        REQUIRE(tops.size() == cells.size());
        REQUIRE_FALSE(tops.empty());
        const double high = mesh_height(blob.view());
        for (std::size_t i = 0; i < tops.size(); ++i) {
            CHECK(tops[i].cell == cells[i]);
            CHECK(tops[i].top > 10.0);
            CHECK(tops[i].top <= high);
        }
    }
}

TEST_CASE("spread and lean compare the top half with the bottom half", "[fitness][descriptors]") {
    // A tree: a 1x1 trunk from 0 to 5 under a 6x4 crown from 6 to 10. The
    // halves split at z = 5: the top half has the trunk's top and the crown
    // (width sqrt(52)), the bottom half only the trunk (width sqrt(2)).
    const MeshArrays trunk = make_box({-0.5, -0.5, 0}, {0.5, 0.5, 5});
    const MeshArrays tree = merge(trunk, make_box({-3, -2, 6}, {3, 2, 10}));
    CHECK(measure("spread", tree) == Approx(std::sqrt(26.0)));
    const MeshArrays upside_down = merge(make_box({-0.5, -0.5, 5}, {0.5, 0.5, 10}), make_box({-3, -2, 0}, {3, 2, 4}));
    CHECK(measure("spread", upside_down) == Approx(1.0 / std::sqrt(26.0)));
    CHECK(measure("lean", tree) == Approx(0.0).margin(1e-12));
    // A leaning shape: the top box is 3 units along x from the bottom one.
    const MeshArrays leaning = merge(make_box({0, 0, 0}, {1, 1, 1}), make_box({3, 0, 2}, {4, 1, 3}));
    CHECK(measure("lean", leaning) == Approx(3.0));
    CHECK(measure("slenderness", tree) == Approx(10.0 / std::sqrt(24.0)));
}

TEST_CASE("sphericity is near 1 for a sphere and small for a thin slab", "[fitness][descriptors]") {
    CHECK(measure("sphericity", make_icosphere(5)) == Approx(1.0).epsilon(0.01));
    CHECK(measure("sphericity", make_box({0, 0, 0}, {10, 10, 0.1})) < 0.3);
    // orientation does not matter
    MeshArrays inverted = make_icosphere(3);
    for (Face& f : inverted.faces) std::swap(f[1], f[2]);
    CHECK(measure("sphericity", inverted) == Approx(measure("sphericity", make_icosphere(3))));
}

TEST_CASE("degenerate meshes give non-finite measures or errors", "[fitness][descriptors]") {
    // a vertical wall has no footprint: slenderness is infinite (the search makes such a child invalid)
    MeshArrays wall;
    wall.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 5}};
    wall.faces = {{0, 1, 2}};
    CHECK_FALSE(std::isfinite(measure("slenderness", wall)));
    // A set refuses it, naming its place and measure: descriptors that reach a search are finite.
    const DescriptorSet slender({"height", "slenderness"}, {});
    CHECK_THROWS_WITH(slender(wall.view()), Catch::Contains("non-finite descriptor 1 (slenderness = inf)"));
    CHECK(DescriptorSet({"height"}, {})(wall.view()) == std::vector<double>{5.0});
    const MeshArrays empty;
    const DescriptorSet set({"height", "spread"}, {});
    CHECK_THROWS_AS(set(empty.view()), std::invalid_argument);
    MeshArrays broken = make_box({0, 0, 0}, {1, 1, 1});
    broken.positions[3].x() = std::nan("");
    CHECK_THROWS_AS(set(broken.view()), std::invalid_argument);
}

TEST_CASE("descriptor sets evaluate in order; unknown names suggest the nearest", "[fitness][descriptors]") {
    const MeshArrays box = make_box({0, 0, 0}, {2, 2, 12});
    const DescriptorSet set({"canopy", "height", "width", "crown_height"}, {10.0, 0.5});
    CHECK(set.names() == std::vector<std::string>{"canopy", "height", "width", "crown_height"});
    const std::vector<double> values = set(box.view());
    REQUIRE(values.size() == 4);
    CHECK(values[0] == Approx(4.0));
    CHECK(values[1] == 12.0);
    CHECK(values[2] == Approx(std::sqrt(8.0)));
    CHECK(values[3] == 12.0);
    CHECK_THROWS_WITH(find_descriptor_measure("heigth"), "unknown measure \"heigth\" (did you mean \"height\"?)");
    CHECK_THROWS_WITH(find_descriptor_measure("crownheight"), Catch::Contains("did you mean \"crown_height\""));
    CHECK_THROWS_WITH(find_descriptor_measure("Footprnt"), Catch::Contains("did you mean \"footprint\""));
    CHECK_THROWS_WITH(find_descriptor_measure("colour"), Catch::Contains("known: height footprint width"));
    CHECK_THROWS_AS(DescriptorSet({"height", "heigth"}, {}), std::invalid_argument);
    // every listed name resolves, names are unique
    const std::vector<std::string> names = descriptor_measure_names();
    CHECK(names.size() == descriptor_measures().size());
    for (const char* n : {"height", "footprint", "width", "area", "volume", "vertices", "canopy", "slenderness",
                                 "crown_height", "spread"})
        CHECK(std::find(names.begin(), names.end(), n) != names.end());
    for (const std::string& n : names) CHECK(find_descriptor_measure(n).name == n);
    CHECK(std::set<std::string>(names.begin(), names.end()).size() == names.size());
}

