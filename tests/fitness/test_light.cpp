// Light captured from parallel sun rays, with self-shading.
#include "fitness/light.hpp"
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
