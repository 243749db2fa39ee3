#include "core/growth/growth_phase_timer.hpp"

#include "core/growth/network/gather_kernel.hpp"
#include "core/growth/growth.hpp"
#include "core/growth/network/network_kernel.hpp"

#include <algorithm>

namespace morphogen {

namespace {
double seconds_between(std::chrono::steady_clock::time_point start, std::chrono::steady_clock::time_point stop) {
    return std::chrono::duration<double>(stop - start).count();
}
}  // namespace

void GrowthPhaseTimer::begin(GrowthPhase phase, const GrowthState& state, const GrowthWorkspace&) {
    if (phase == GrowthPhase::think) times_.vertex_steps += static_cast<std::uint64_t>(state.mesh.num_vertices());
    if (phase == GrowthPhase::flip) guard_seconds_in_flip_ = 0;
    // Last: nothing above counts in the phase.
    (phase == GrowthPhase::flip_guard ? guard_start_ : phase_start_) = Clock::now();
}

void GrowthPhaseTimer::end(GrowthPhase phase, const GrowthState& state, const GrowthWorkspace& workspace) {
    const Clock::time_point now = Clock::now();  // first: nothing below counts in the phase
    if (phase == GrowthPhase::flip_guard) {
        const double seconds = seconds_between(guard_start_, now);
        times_.collide += seconds;
        guard_seconds_in_flip_ += seconds;
        return;
    }
    const double seconds = seconds_between(phase_start_, now);
    switch (phase) {
    case GrowthPhase::neighbours: times_.gather += seconds; break;
    case GrowthPhase::think: {
        const double gather = std::min(seconds, time_gather_alone(state, workspace));
        times_.gather += gather;
        times_.think += seconds - gather;
        break;
    }
    case GrowthPhase::branch:
    case GrowthPhase::move: times_.move += seconds; break;
    case GrowthPhase::settle: times_.collide += seconds; break;
    case GrowthPhase::split: times_.split += seconds; break;
    case GrowthPhase::flip: times_.flip += seconds - guard_seconds_in_flip_; break;
    case GrowthPhase::flip_guard: break;  // handled above
    }
}

double GrowthPhaseTimer::time_gather_alone(const GrowthState& state, const GrowthWorkspace& workspace) {
    const kernel::GatherInput input = gather_input(state, workspace, height_scale_);
    const int vertices = state.mesh.num_vertices();
    rows_.resize(static_cast<std::size_t>(3 * input.outputs * kernel::block));
    const Clock::time_point start = Clock::now();
    for (int first = 0; first < vertices; first += kernel::block)
        kernel::gather_inputs(input, first, std::min(kernel::block, vertices - first), rows_.data());
    const double seconds = seconds_between(start, Clock::now());
    own_seconds_ += seconds;
    return seconds;
}

}  // namespace morphogen
