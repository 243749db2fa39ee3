#include "core/growth/genome_grower.hpp"

#include "core/growth/contact/self_intersection_check.hpp"

namespace morphogen {

namespace {

// growth.collisions "touch" (docs/algorithm.md §5.7.1, the fail-safe): steps
// from the seed, checking every step exactly, until the first mesh that
// self-intersects, and returns the state before it: the growth stopped at
// its last clean step k. Called for a genome whose final mesh self-intersects
// (from a clean seed), so such a step exists.
GrowthState last_clean_state(const Grower& grower, const Seed& seed, int steps, GrowthWorkspace& workspace,
                             SelfIntersectionCheck& check) {
    GrowthState state = grower.start(seed), previous;
    for (int t = 0; t < steps; ++t) {
        previous = state;  // reuses its buffers from the step before
        grower.step(state, workspace);
        if (check.intersects(state.mesh)) return previous;
    }
    return state;
}

// The state after `steps` steps, `after_step` and `phases` seeing each
// (Grower::grow's loop, for a number of steps of our choosing).
GrowthState grow_steps(const Grower& grower, const Seed& seed, int steps, GrowthWorkspace& workspace,
                       const StepObserver& after_step, GrowthObserver* phases) {
    GrowthState state = grower.start(seed);
    for (int t = 0; t < steps; ++t) {
        grower.step(state, workspace, phases);
        if (after_step) after_step(state, t);
    }
    return state;
}

}  // namespace

GenomeGrower::GenomeGrower(const NetworkParams& network, const GrowthParams& growth)
    : layers_(network.layers()), growth_(growth), seed_(make_seed(growth)) {
    // A seed that already self-intersects has no clean step to go back to:
    // the fail-safe stays off, as "prevent" lets such a seed grow (§5.7).
    SelfIntersectionCheck check;
    fail_safe_ = growth_.collisions == Collisions::touch && !check.intersects(seed_.mesh);
}

GrowthState GenomeGrower::grow(const Network& network, GrowthWorkspace& workspace, const StepObserver& after_step,
                               GrowthObserver* phases) const {
    const Grower grower(network, growth_);
    if (!fail_safe_) return grower.grow(seed_, workspace, after_step, phases);
    // The common case: one growth and one check. A phases observer alone
    // (bench's clock) sees the work as it is done: every step of this growth,
    // then the check, and the search for k where it fails, as one settle
    // phase outside the steps (collision work).
    SelfIntersectionCheck check;
    GrowthState state = grower.grow(seed_, workspace, {}, after_step ? nullptr : phases);
    if (!after_step && phases != nullptr) phases->begin(GrowthPhase::settle, state, workspace);
    if (check.intersects(state.mesh)) state = last_clean_state(grower, seed_, growth_.steps, workspace, check);
    if (!after_step) {
        if (phases != nullptr) phases->end(GrowthPhase::settle, state, workspace);
        return state;
    }
    // A step observer (wind data's birth steps, an animation) sees exactly
    // the steps of the growth returned: it is grown again, now that its
    // length is known, with both observers.
    return grow_steps(grower, seed_, state.steps_done, workspace, after_step, phases);
}

GrowthState GenomeGrower::grow_dated(const Network& network, GrowthWorkspace& workspace,
                                     std::vector<int>& births) const {
    births.assign(static_cast<std::size_t>(seed_.mesh.num_vertices()), 0);
    const StepObserver dating = [&births](const GrowthState& state, int step) {
        births.resize(static_cast<std::size_t>(state.mesh.num_vertices()), step + 1);
    };
    const Grower grower(network, growth_);
    GrowthState state = grower.grow(seed_, workspace, dating, nullptr);
    if (fail_safe_) {
        SelfIntersectionCheck check;
        if (check.intersects(state.mesh)) state = last_clean_state(grower, seed_, growth_.steps, workspace, check);
    }
    births.resize(static_cast<std::size_t>(state.mesh.num_vertices()));
    return state;
}

GrowthState GenomeGrower::grow(std::span<const double> genome, GrowthWorkspace& workspace) const {
    return grow(Network(Genome{layers_, std::vector<double>(genome.begin(), genome.end())}), workspace);
}

GrowthState GenomeGrower::grow(std::span<const double> genome) const {
    GrowthWorkspace workspace;
    return grow(genome, workspace);
}

}  // namespace morphogen
