// Per-vertex channels (core/growth/vertex_channels.hpp): each rule gives a
// vertex made inside a face its values from the corners; a channel that is
// off (empty) stays empty; GrowthState lists every per-vertex member.
#include "core/growth/growth.hpp"
#include "core/growth/vertex_channels.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

using namespace morphogen;

namespace {
Vec3 corner_sum(const void* context, int a, int b, int c) {
    const auto& points = *static_cast<const std::vector<Vec3>*>(context);
    return points[a] + points[b] + points[c];
}
}  // namespace

TEST_CASE("vertex channels: mean, all, any and computed values of a new vertex", "[growth][channels]") {
    std::vector<double> outputs{0.0, 3.0,  // vertex 0
                                1.0, 6.0,  // vertex 1
                                2.0, 0.3,  // vertex 2
                                9.0, 9.0};
    std::vector<std::uint8_t> active{1, 1, 0, 1}, touched{0, 1, 0, 0};
    std::vector<std::uint8_t> off;  // a channel switched off
    const std::vector<Vec3> points{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}};
    std::vector<Vec3> made{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    VertexChannels channels;
    channels.mean(outputs, 2);
    channels.all(active);
    channels.any(touched);
    channels.any(off);
    channels.computed(made, &corner_sum, &points);

    channels.add_vertex_in(0, 1, 2);
    REQUIRE(outputs.size() == 10);
    CHECK(outputs[8] == (0.0 + 1.0 + 2.0) / 3.0);
    CHECK(outputs[9] == (3.0 + 6.0 + 0.3) / 3.0);  // the same rounding as the sum written out
    CHECK(active.back() == 0);
    CHECK(touched.back() == 1);
    CHECK(off.empty());
    CHECK(made.back() == Vec3(1, 1, 1));

    channels.add_vertex_in(0, 1, 3);
    CHECK(active.size() == 6);
    CHECK(active.back() == 1);
    CHECK(touched.back() == 1);
    CHECK(outputs.size() == 12);
    CHECK(made.size() == 6);
}

TEST_CASE("a growth state's channels grow every per-vertex member that is on", "[growth][channels]") {
    GrowthState state;
    state.outputs_per_vertex = 3;
    state.outputs = {0.5, 0.5, 1.0, 0.5, 0.5, 1.0, 0.5, 0.5, 1.0};
    state.directions = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
    state.mesh.positions() = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    state.active = {1, 1, 1};  // branching mode; touched stays off
    state.channels().add_vertex_in(0, 1, 2);
    CHECK(state.outputs.size() == 12);
    CHECK(state.active.size() == 4);
    CHECK(state.touched.empty());
    REQUIRE(state.directions.size() == 4);
    // The face's normal (+z) plus three +z directions weighted by w[2] = 1, normalised.
    CHECK(state.directions.back() == Vec3(0, 0, 1));
}
