#pragma once
// Watching growth from outside (e.g. `morphogen bench` timing each phase):
// Grower::step calls an observer's hooks around each phase of
// docs/algorithm.md §5. Growth itself keeps no clock; without an observer a
// step pays one null test per phase.
namespace morphogen {

struct GrowthState;
struct GrowthWorkspace;

// The phases of one step, in the order Grower::step runs them.
enum class GrowthPhase {
    neighbours,  // §5.1: the neighbour lists of the mesh as it stands
    think,       // §5.1, §4.4: gather and network, fused a block of vertices at a time
    branch,      // §5.8, growth.mode "branching" only: stop, start and steer
    move,        // §5.2 (with growth.collisions "prevent" or "touch", remembering the positions first)
    settle,      // §5.7, growth.collisions "prevent" or "touch" (§5.7.1) only: the move settled
    split,       // §5.3
    flip,        // §5.4, on the steps growth.flip_every picks
    flip_guard,  // §5.7, inside flip: the collision or contact guard testing one flip
};

class GrowthObserver {
public:
    virtual ~GrowthObserver() = default;
    // Called just before and just after `phase` runs on `state`; begin and
    // end pair up, and flip_guard nests inside flip. `workspace` holds the
    // step's buffers (after neighbours: the neighbour lists of state.mesh).
    virtual void begin(GrowthPhase phase, const GrowthState& state, const GrowthWorkspace& workspace) = 0;
    virtual void end(GrowthPhase phase, const GrowthState& state, const GrowthWorkspace& workspace) = 0;
};

}  // namespace morphogen
