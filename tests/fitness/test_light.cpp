// Light captured from parallel sun rays, with self-shading.
#include "fitness/functions/light.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace morphogen;
using morphogen::test::make_box;
using morphogen::test::make_square;
using morphogen::test::merge;

namespace {
LightParams vertical_sun() {
    LightParams params;
    params.elevations_deg = {90.0};
    return params;
}
}  // namespace

TEST_CASE("a flat square under a vertical sun captures its area", "[fitness][light]") {
    const MeshArrays square = make_square(0, 0, 1, 1, 1);
    CHECK(light_captured(square.view(), vertical_sun()) == Approx(1.0));
    const MeshArrays big = make_square(-2, 1, 1, 3, 4);  // 3 x 2
    CHECK(light_captured(big.view(), vertical_sun()) == Approx(6.0));
    // Under an oblique sun it captures its projected area, area * sin(elevation).
    LightParams low = vertical_sun();
    low.elevations_deg = {30.0};
    low.azimuths_deg = {0.0, 90.0, 200.0};
    low.spacing = 0.02;
    CHECK(light_captured(big.view(), low) == Approx(3.0).epsilon(0.03));
}

TEST_CASE("a closed box under a vertical sun captures its top", "[fitness][light]") {
    const MeshArrays box = make_box({0, 0, 0}, {2, 1, 3});
    CHECK(light_captured(box.view(), vertical_sun()) == Approx(2.0));
}

TEST_CASE("a mesh shading another reduces the light", "[fitness][light]") {
    const MeshArrays low = make_square(0, 0, 1, 1, 1);
    const MeshArrays high = make_square(0, 0, 1, 1, 2);
    const MeshArrays both = merge(low, high);
    for (const LightParams& params : {vertical_sun(), LightParams{}}) {
        const double separate = light_captured(low.view(), params) + light_captured(high.view(), params);
        CHECK(light_captured(both.view(), params) < separate - 0.1);
    }
    // The vertical sun sees only the upper square.
    CHECK(light_captured(both.view(), vertical_sun()) == Approx(1.0));
    // A sun from +x at 45 degrees: the upper square at z=1.5 shades half of the lower one.
    const MeshArrays half = merge(low, make_square(0, 0, 1, 1, 1.5));
    const double alone = light_from(high.view(), {1, 0, 1}, 0.01, 0.0);
    CHECK(alone == Approx(std::sqrt(0.5)).epsilon(0.02));
    CHECK(light_from(half.view(), {1, 0, 1}, 0.01, 0.0) == Approx(1.5 * std::sqrt(0.5)).epsilon(0.02));
}

TEST_CASE("light: min_height and the sun set", "[fitness][light]") {
    const MeshArrays square = make_square(0, 0, 1, 1, 1);
    LightParams params = vertical_sun();
    params.min_height = 2.0;
    CHECK(light_captured(square.view(), params) == 0.0);
    CHECK(sun_directions(LightParams{}).size() == 5);  // 90 once, 45 at four azimuths
    for (const Vec3& sun : sun_directions(LightParams{})) CHECK(sun.norm() == Approx(1.0));
    CHECK(light_captured(MeshArrays{}.view(), params) == 0.0);
}

TEST_CASE("light: a stand of copies shades the plant's sides, not its top", "[fitness][light]") {
    // A box 0.2 deep (x), 0.4 wide (y), 1 high, under one sun from +x at 45 degrees.
    // Alone it catches its top and its +x side, (0.08 + 0.4) · cos 45.
    const MeshArrays box = make_box({0, 0, 0}, {0.2, 0.4, 1});
    LightParams params;
    params.elevations_deg = {45.0};
    params.azimuths_deg = {0.0};
    params.spacing = 0.004;
    const double alone = light_captured(box.view(), params);
    CHECK(alone == Approx(0.48 * std::sqrt(0.5)).epsilon(0.01));
    // Copies every 0.5: the one at x = 0.5 hides the +x side below z = 0.7 (a ray that reaches
    // the side at z passed x = 0.5 at z + 0.3), the top stays lit: (0.08 + 0.4 · 0.3) · cos 45.
    params.stand_spacing = 0.5;
    const double stand = light_captured(box.view(), params);
    CHECK(stand == Approx(0.2 * std::sqrt(0.5)).epsilon(0.02));
    const std::vector<double> per_face = light_per_face(box.view(), params);
    REQUIRE(per_face.size() == box.faces.size());
    double sum = 0.0;
    for (double light : per_face) sum += light;
    CHECK(sum == Approx(stand).epsilon(1e-12));
    // Neighbours farther than the shadow's reach change nothing.
    params.stand_spacing = 50.0;
    CHECK(light_captured(box.view(), params) == Approx(alone).epsilon(1e-3));
    // The stand itself: the plant's faces first, then eight copies on the lattice.
    const MeshArrays block = stand_of(box.view(), 0.5);
    REQUIRE(block.faces.size() == 9 * box.faces.size());
    CHECK(block.positions[box.positions.size()] == box.positions[0] + Vec3(-0.5, -0.5, 0));
    CHECK(stand_of(box.view(), 0.0).faces.size() == box.faces.size());
    params.stand_spacing = -1.0;
    CHECK_THROWS_AS(light_captured(box.view(), params), std::invalid_argument);
}
