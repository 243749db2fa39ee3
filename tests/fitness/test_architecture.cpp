// The architecture measures (fitness/architecture/architecture.hpp) on implicit shapes
// with known answers, and on hostile meshes.
#include "fitness/architecture/architecture.hpp"
#include "fitness/descriptors.hpp"
#include "fitness/architecture/skeleton.hpp"
#include "tests/fitness/limb_controls.hpp"
#include "tests/fitness/mesh_builders.hpp"
#include "tests/support/implicit_mesh.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace morphogen;
using namespace morphogen::testing;
using morphogen::test::unwelded;

namespace {

constexpr double kGrid = 0.1;  // grid spacing of the implicit meshes: edges ~0.05-0.15

// Upright cylinder, radius 0.5, height 8, flat bottom on z = 0.
MeshArrays cylinder() {
    return implicit_mesh([](const Vec3& p) { return cylinder_field(p, {0, 0, 0}, 0.5, 8.0); }, {-1, -1, -0.5},
                         {1, 1, 8.5}, kGrid);
}

// A labelled control's solid (tests/fitness/limb_controls.hpp) on the grid.
MeshArrays on_grid(const std::string& name) {
    const LimbControlSolid solid = limb_control_solid(name);
    return implicit_mesh(solid.field, solid.lo, solid.hi, kGrid);
}

// A trunk (radius 0.5, flat bottom, to z = 4) and two arms (radius 0.4) to (+-2.5, 0, 8).
MeshArrays y_shape() { return on_grid("y"); }

// A trunk to z = 4 under a bar along x at z = 4 carrying 3 candles 2 apart
// or 5 candles 1.5 apart (radius 0.4) up to z = 9.
MeshArrays candelabra(int arms) { return on_grid(arms == 3 ? "candelabra3" : "candelabra5"); }

// A lobed dome (a flattened ellipsoid with 19 small spheres on its top) on a short thick stalk.
MeshArrays broccoli() { return on_grid("broccoli"); }

// A cap (a flattened ellipsoid) on a thin stem.
MeshArrays mushroom() { return on_grid("mushroom"); }

// The limbs' thicknesses are the arms' diameter within 20 % (a marching-
// tetrahedra surface zigzags: its level curves are a few % longer than a
// circle, more where a limb bends or a fillet joins).
void check_limb_thickness(const Architecture& a, double diameter) {
    for (const Limb& limb : a.limbs) CHECK(limb.thickness == Approx(diameter).epsilon(0.2));
}

}  // namespace

TEST_CASE("architecture: a cylinder is one unbranched axis", "[fitness][architecture]") {
    const MeshArrays mesh = cylinder();
    CHECK_NOTHROW(TriMesh::from_arrays(mesh, "cylinder"));  // the builder's mesh is closed and manifold
    const Architecture a = measure_architecture(mesh.view());
    CHECK(a.tips == 1);
    CHECK(a.forks == 0);
    CHECK(a.limbs.empty());
    CHECK(a.strahler == 1);
    CHECK(a.first_fork_height == Approx(8.0).margin(kGrid));  // no fork: the height
    REQUIRE(a.tip_points.size() == 1);
    CHECK((a.tip_points[0] - Vec3(0, 0, 8)).norm() < 0.3);
    CHECK(a.solidity == Approx(1.0).margin(0.01));

    // Its skeleton: one node per band, each a ring of the cylinder's diameter.
    const Skeleton skeleton = level_set_skeleton(mesh.view());
    CHECK(skeleton.zmin == Approx(0.0).margin(1e-9));
    CHECK(skeleton.base_height == Approx(0.5 * skeleton.band_width));
    int middle = 0;
    for (const SkeletonNode& node : skeleton.nodes) {
        CHECK(node.children.size() <= 1);
        if (node.centroid.z() < 1.0 || node.centroid.z() > 7.0) continue;
        ++middle;
        CHECK(node.diameter == Approx(1.0).epsilon(0.05));  // the zigzag of the level curves
        CHECK(std::hypot(node.centroid.x(), node.centroid.y()) < 0.01);
    }
    CHECK(middle == Approx(6.0 / skeleton.band_width).margin(2));
}

TEST_CASE("architecture: a Y forks once into two limbs", "[fitness][architecture]") {
    const MeshArrays mesh = y_shape();
    const Architecture a = measure_architecture(mesh.view());
    CHECK(a.tips == 2);
    CHECK(a.forks == 1);
    REQUIRE(a.limbs.size() == 2);
    CHECK(a.strahler == 2);
    // Between where the axes meet (z = 4) and where the arms' surfaces part (z ~ 4.75).
    CHECK(a.first_fork_height > 4.0);
    CHECK(a.first_fork_height < 4.75 + 2 * a.band_width);
    check_limb_thickness(a, 0.8);
    for (const Limb& limb : a.limbs) {
        CHECK(limb.length > 3.5);  // the arm from the crotch: about 4 of its 4.7
        CHECK(limb.length < 5.0);
        CHECK(limb.tube_length == Approx(limb.length).epsilon(0.25));
        CHECK(std::abs(limb.tip.x()) > 2.0);
    }
    for (const Vec3& tip : a.tip_points) CHECK((tip - Vec3(tip.x() > 0 ? 2.5 : -2.5, 0, 8)).norm() < 0.5);

    // The factors: no limb is 10 thicknesses long; a tip must stand 6 thicknesses clear.
    CHECK(measure_architecture(mesh.view(), {.limb_slenderness = 10}).limbs.empty());
    const Architecture strict = measure_architecture(mesh.view(), {.tip_slenderness = 6});
    CHECK(strict.tips == 1);
    CHECK(strict.strahler == 1);
    CHECK(std::isnan(measure_architecture(mesh.view(), {.with_solidity = false}).solidity));
}

TEST_CASE("architecture: candelabras of 3 and 5 arms have 3 and 5 limbs", "[fitness][architecture]") {
    const Architecture three = measure_architecture(candelabra(3).view());
    CHECK(three.tips == 3);
    CHECK(three.limbs.size() == 3);
    CHECK(three.strahler == 2);
    // The bar's axis is at z = 4; the fork's piece lies within its radius.
    CHECK(three.first_fork_height == Approx(4.0).margin(0.4));
    check_limb_thickness(three, 0.8);

    // Five candles 1.5 apart: the bar forks at x = 0 and x = +-1.5, and the
    // bar's pieces between forks (1.5 long, 0.8 thick) are no limbs.
    const Architecture five = measure_architecture(candelabra(5).view());
    CHECK(five.tips == 5);
    CHECK(five.forks >= 3);  // the middle fork may resolve into two bands' forks
    CHECK(five.forks <= 4);
    CHECK(five.limbs.size() == 5);
    CHECK(five.strahler == 3);
    CHECK(five.first_fork_height == Approx(4.0).margin(0.4));
    check_limb_thickness(five, 0.8);
    for (const Limb& limb : five.limbs) CHECK(limb.tip.z() > 8.0);
}

TEST_CASE("architecture: a broccoli's lobes and a mushroom's cap are no limbs", "[fitness][architecture]") {
    const Architecture broccoli_architecture = measure_architecture(broccoli().view());
    CHECK(broccoli_architecture.limbs.empty());
    CHECK(broccoli_architecture.tips == 1);
    CHECK(broccoli_architecture.strahler == 1);

    const MeshArrays cap_on_stem = mushroom();
    const Architecture mushroom_architecture = measure_architecture(cap_on_stem.view());
    CHECK(mushroom_architecture.limbs.empty());
    CHECK(mushroom_architecture.tips == 1);
    CHECK(mushroom_architecture.strahler == 1);
    CHECK(mushroom_architecture.first_fork_height == Approx(5.1).margin(kGrid));
    // Far from convex: the space under the cap.
    CHECK(mushroom_architecture.solidity < 0.6);
}

TEST_CASE("architecture: the same shape moved, or with split vertices, measures the same", "[fitness][architecture]") {
    const MeshArrays mesh = y_shape();
    const Architecture a = measure_architecture(mesh.view());
    MeshArrays moved = mesh;
    for (Vec3& p : moved.positions) p += Vec3(10, -5, 3);
    const Architecture b = measure_architecture(moved.view());
    CHECK(b.tips == a.tips);
    CHECK(b.limbs.size() == a.limbs.size());
    CHECK(b.first_fork_height == Approx(a.first_fork_height).margin(1e-6));
    CHECK(b.solidity == Approx(a.solidity).epsilon(1e-9));

    const Architecture split = measure_architecture(unwelded(mesh).view());
    CHECK(split.tips == a.tips);
    CHECK(split.nodes == a.nodes);
    CHECK(split.first_fork_height == a.first_fork_height);
    CHECK(split.solidity == Approx(a.solidity).epsilon(1e-12));
}

TEST_CASE("solidity: volume over convex-hull volume", "[fitness][architecture]") {
    CHECK(mesh_solidity(test::make_box({0, 0, 0}, {1, 2, 3}).view()) == Approx(1.0).epsilon(1e-12));
    const MeshArrays ball = implicit_mesh([](const Vec3& p) { return sphere_field(p, {0, 0, 0}, 1.0); },
                                          {-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}, kGrid);
    CHECK(mesh_solidity(ball.view()) > 0.99);
    CHECK(mesh_solidity(ball.view()) <= 1.0);
    // An L of two unit-thick bars (two closed boxes sharing part of a face):
    // volume 3 + 2, hull 7 (the L's xz outline with its notch filled).
    const MeshArrays l_shape = test::merge(test::make_box({0, 0, 0}, {3, 1, 1}), test::make_box({0, 0, 1}, {1, 1, 3}));
    CHECK(mesh_solidity(l_shape.view()) == Approx(5.0 / 7.0).epsilon(1e-12));
    // Open, or flat: no volume to compare.
    CHECK(std::isnan(mesh_solidity(test::make_square(0, 0, 1, 1, 0).view())));
    CHECK(std::isnan(mesh_solidity(test::make_box({0, 0, 0}, {1, 1, 0}).view())));
    MeshArrays holed = test::make_box({0, 0, 0}, {1, 1, 1});
    holed.faces.pop_back();
    CHECK(std::isnan(mesh_solidity(holed.view())));
}

TEST_CASE("architecture of hostile meshes: clear errors or the documented values", "[fitness][architecture]") {
    CHECK_THROWS_WITH(measure_architecture(MeshArrays{}.view()), Catch::Contains("without vertices"));
    MeshArrays bad_index = test::make_box({0, 0, 0}, {1, 1, 1});
    bad_index.faces[3][1] = 8;
    CHECK_THROWS_WITH(measure_architecture(bad_index.view()), Catch::Contains("refers to vertex 8"));
    MeshArrays not_finite = test::make_box({0, 0, 0}, {1, 1, 1});
    not_finite.positions[2].x() = std::nan("");
    CHECK_THROWS_AS(measure_architecture(not_finite.view()), std::invalid_argument);
    const MeshArrays box = test::make_box({0, 0, 0}, {1, 1, 1});
    CHECK_THROWS_WITH(measure_architecture(box.view(), {.limb_slenderness = 0}), Catch::Contains("limb_slenderness"));
    CHECK_THROWS_WITH(measure_architecture(box.view(), {.skeleton = {.band_edges = 0}}), Catch::Contains("band_edges"));

    // One vertex, or only triangles with a repeated vertex: a lone root.
    for (const MeshArrays& lone : {MeshArrays{{{1, 2, 3}}, {}}, MeshArrays{{{0, 0, 1}, {1, 0, 1}}, {{0, 0, 1}, {1, 1, 0}}}}) {
        const Architecture a = measure_architecture(lone.view());
        CHECK(a.tips == 0);
        CHECK(a.limbs.empty());
        CHECK(a.nodes == 1);
        CHECK(a.strahler == 1);
        CHECK(a.first_fork_height == 0.0);
        CHECK(std::isnan(a.solidity));
    }
    // An open mesh has a skeleton but no solidity.
    const Architecture open = measure_architecture(test::make_square(0, 0, 1, 1, 0).view());
    CHECK(open.nodes >= 1);
    CHECK(std::isnan(open.solidity));
}

TEST_CASE("architecture descriptors: the measures by name; an open mesh's solidity refused", "[fitness][architecture]") {
    const MeshArrays mesh = y_shape();
    const Architecture a = measure_architecture(mesh.view());
    const DescriptorSet set({"tips", "limbs", "first_fork_height", "strahler", "solidity"}, {});
    const std::vector<double> values = set(mesh.view());
    CHECK(values == std::vector<double>{2.0, 2.0, a.first_fork_height, 2.0, a.solidity});
    CHECK_THROWS_WITH(set(test::make_square(0, 0, 1, 1, 0).view()), Catch::Contains("(solidity = nan)"));
}
