// GrowthPhaseTimer, `morphogen bench`'s clock, on real growths.
#include "core/growth/growth_phase_timer.hpp"
#include "core/growth/genome_grower.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <chrono>

using namespace morphogen;
using namespace morphogen::testing;

namespace {
struct Timed {
    PhaseTimes times;
    double own_seconds = 0, wall = 0;
    std::uint64_t vertex_steps = 0;  // counted apart, from the meshes
};

Timed grow_timed(const GrowthParams& params) {
    const GenomeGrower grower(NetworkParams{}, params);
    GrowthPhaseTimer timer(params.height_scale);
    GrowthWorkspace workspace;
    Timed out;
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t g = 1; g <= 3; ++g) {
        std::uint64_t before_step = static_cast<std::uint64_t>(grower.seed().mesh.num_vertices());
        grower.grow(Network(random_test_genome(grower.layers(), g)), workspace,
                    [&](const GrowthState& state, int) {
                        out.vertex_steps += before_step;  // step t thinks over the mesh of step t - 1
                        before_step = static_cast<std::uint64_t>(state.mesh.num_vertices());
                    },
                    &timer);
    }
    out.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.times = timer.times();
    out.own_seconds = timer.own_seconds();
    return out;
}
}  // namespace

TEST_CASE("the phase timer splits growth into bench's columns, within the wall time", "[app][phase-timer]") {
    GrowthParams params;
    params.steps = 40;
    for (const Collisions collisions : {Collisions::allow, Collisions::prevent}) {
        params.collisions = collisions;
        INFO("collisions prevented: " << (collisions == Collisions::prevent));
        const Timed t = grow_timed(params);
        const PhaseTimes& p = t.times;
        CHECK(p.vertex_steps == t.vertex_steps);
        for (double phase : {p.gather, p.think, p.move, p.split, p.flip, p.collide}) CHECK(phase >= 0.0);
        CHECK(p.think > 0.0);
        CHECK(p.gather > 0.0);
        CHECK(p.split > 0.0);
        CHECK(p.flip > 0.0);
        // Only the guard of §5.7 collides.
        CHECK((p.collide > 0.0) == (collisions == Collisions::prevent));
        // The gather timed apart is the timer's own work, outside every phase.
        CHECK(t.own_seconds > 0.0);
        CHECK(p.total() + t.own_seconds <= t.wall);
    }
}
