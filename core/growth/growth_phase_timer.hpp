#pragma once
// `morphogen bench`'s clock: a GrowthObserver that adds up the seconds of
// each phase of growth (docs/algorithm.md §5) in the columns bench reports.
#include "core/growth/growth_observer.hpp"

#include <chrono>
#include <cstdint>
#include <vector>

namespace morphogen {

// Seconds spent in each of bench's columns, accumulated over steps and genomes.
struct PhaseTimes {
    double gather = 0;   // the neighbour lists, and the gather's share of think
    double think = 0;    // the network (think less the gather)
    double move = 0;     // the move, and the branching mode's steering before it
    double split = 0;
    double flip = 0;     // less the guard's tests
    double collide = 0;  // growth.collisions "prevent" or "touch" (§5.7): settling moves, guarding flips
    std::uint64_t vertex_steps = 0;  // sum over steps of the vertices that thought
    double total() const { return gather + think + move + split + flip + collide; }
};

class GrowthPhaseTimer final : public GrowthObserver {
public:
    // `height_scale`: growth.height_scale of the growth it watches.
    explicit GrowthPhaseTimer(double height_scale) : height_scale_(height_scale) {}

    void begin(GrowthPhase phase, const GrowthState& state, const GrowthWorkspace& workspace) override;
    void end(GrowthPhase phase, const GrowthState& state, const GrowthWorkspace& workspace) override;

    const PhaseTimes& times() const { return times_; }
    // Seconds the timer spent measuring on its own (the gather timed apart,
    // below): time that a growth it watches would not have spent.
    double own_seconds() const { return own_seconds_; }

private:
    using Clock = std::chrono::steady_clock;
    // Gather and network run fused a block of vertices at a time (§4.4), so
    // the gather's share of think cannot be timed from outside the phase:
    // after think, the gather alone runs over the same mesh and neighbour
    // lists (the new outputs: the same sizes, the same memory pattern), and
    // its seconds move from think to gather. Returns them.
    double time_gather_alone(const GrowthState& state, const GrowthWorkspace& workspace);

    double height_scale_;
    PhaseTimes times_;
    double own_seconds_ = 0;
    Clock::time_point phase_start_, guard_start_;
    double guard_seconds_in_flip_ = 0;
    std::vector<double> rows_;  // one block of gathered inputs
};

}  // namespace morphogen
