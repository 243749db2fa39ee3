// Measures and metrics: volume, area, footprint, height, self-intersection.
#include "fitness/geometry/cgal_geometry.hpp"
#include "fitness/fitness.hpp"
#include "fitness/measures.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using morphogen::test::make_box;
using morphogen::test::make_bumpy;
using morphogen::test::make_icosphere;
using morphogen::test::merge;

TEST_CASE("measures of a box", "[fitness][measures]") {
    const MeshArrays box = make_box({1, -1, 2}, {3, 2, 6});  // 2 x 3 x 4
    CHECK(mesh_volume(box.view()) == Approx(24.0));
    CHECK(mesh_area(box.view()) == Approx(2 * (6 + 8 + 12)));
    CHECK(mesh_footprint(box.view()) == Approx(6.0));
    CHECK(mesh_height(box.view()) == 6.0);
    // Inside-out orientation flips the sign of the volume only.
    MeshArrays inverted = box;
    for (Face& f : inverted.faces) std::swap(f[1], f[2]);
    CHECK(mesh_volume(inverted.view()) == Approx(-24.0));
    CHECK(mesh_area(inverted.view()) == Approx(52.0));
}

TEST_CASE("measures of a sphere approach the analytic values", "[fitness][measures]") {
    const MeshArrays sphere = make_icosphere(5);
    CHECK(mesh_volume(sphere.view()) == Approx(4.0 / 3.0 * M_PI).epsilon(0.01));
    CHECK(mesh_area(sphere.view()) == Approx(4.0 * M_PI).epsilon(0.01));
    CHECK(mesh_footprint(sphere.view()) == Approx(M_PI).epsilon(0.01));
}

TEST_CASE("footprint is the convex hull area of the xy projection", "[fitness][measures]") {
    MeshArrays l_shape;  // an L of three unit squares: hull area 3.5
    l_shape.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0.5, 0.5, 3}};
    CHECK(mesh_footprint(l_shape.view()) == Approx(3.5));
    MeshArrays line;
    line.positions = {{0, 0, 0}, {1, 1, 0}, {2, 2, 5}};
    CHECK(mesh_footprint(line.view()) == 0.0);
    CHECK_THROWS_AS(mesh_height(MeshArrays{}.view()), std::invalid_argument);
}

TEST_CASE("self-intersection", "[fitness][measures]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 1});
    CHECK_FALSE(mesh_self_intersects(box.view()));
    const MeshArrays crossing = merge(box, make_box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
    CHECK(mesh_self_intersects(crossing.view()));
    const MeshArrays apart = merge(box, make_box({2, 0, 0}, {3, 1, 1}));
    CHECK_FALSE(mesh_self_intersects(apart.view()));
    CHECK_FALSE(mesh_self_intersects(make_icosphere(3).view()));
    // A face soup that is not a half-edge mesh (a face repeated) is still answered.
    MeshArrays twice = box;
    twice.faces.push_back(twice.faces[0]);
    CHECK(mesh_self_intersects(twice.view()));
}

TEST_CASE("mesh_metrics reports every metric", "[fitness][measures]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 11});
    const nlohmann::json m = mesh_metrics(box.view());
    CHECK(m["canopy"].get<double>() == 1.0);
    CHECK(m["height"].get<double>() == 11.0);
    CHECK(m["footprint"].get<double>() == Approx(1.0));
    CHECK(m["area"].get<double>() == Approx(46.0));
    CHECK(m["volume"].get<double>() == Approx(11.0));
    CHECK(m["vertices"].get<int>() == 8);
    CHECK(m["faces"].get<int>() == 12);
    CHECK(m["self_intersecting"].is_boolean());
    CHECK(m["self_intersecting"].get<bool>() == false);
    CHECK(mesh_metrics(box.view(), {12.0, 0.1})["canopy"].get<double>() == 0.0);
    CHECK(mesh_metrics(make_bumpy(3).view()).size() == 8);
}
