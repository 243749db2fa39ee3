#pragma once
// One config's growth: its network shape, growth keys and seed mesh, and
// what turns a genome into a grown mesh with them (docs/algorithm.md §3-§6).
// Every command, the search's problem and the tests grow genomes here.
#include "core/growth/growth.hpp"
#include "core/growth/growth_params.hpp"
#include "core/growth/network/network.hpp"
#include "core/growth/seeds/seeds.hpp"

#include <span>
#include <vector>

namespace morphogen {

class GenomeGrower {
public:
    // Builds the seed mesh once (make_seed: IoError/MeshError for a bad seed file).
    GenomeGrower(const NetworkParams& network, const GrowthParams& growth);

    const std::vector<int>& layers() const { return layers_; }  // network.layers()
    const GrowthParams& params() const { return growth_; }
    const Seed& seed() const { return seed_; }

    // The state after growth.steps steps of `network` from the seed
    // (Grower::grow, with its ConfigError for a network that does not fit
    // the growth). `workspace` may be reused from genome to genome, one per
    // thread; `after_step` and `phases` as Grower::grow takes them.
    // With growth.collisions "touch" (from a seed that does not
    // self-intersect), the fail-safe of docs/algorithm.md §5.7.1: a grown
    // mesh that self-intersects (the exact rule of §5.7) is replaced by the
    // growth stopped at its last clean step k, before the first step that
    // self-intersects (steps_done == k); that is exactly the state growing
    // the genome for k steps gives. Observers see only the steps of the
    // growth returned (with `after_step` it is grown twice: first, unobserved,
    // to find k). `phases` alone (a clock) sees the work as it is done: every
    // step of the one growth, then the check and the search for k as one
    // settle phase.
    GrowthState grow(const Network& network, GrowthWorkspace& workspace, const StepObserver& after_step = {},
                     GrowthObserver* phases = nullptr) const;
    // The same for a genome's parameters laid out for layers() (§6.1);
    // ConfigError for a wrong count or a non-finite parameter (Network).
    GrowthState grow(std::span<const double> genome, GrowthWorkspace& workspace) const;
    // With a workspace of its own: one genome, e.g. to export it.
    GrowthState grow(std::span<const double> genome) const;

    // grow(network, workspace) once (no second growth, unlike a step
    // observer), and in `births` the step after which each vertex of the
    // returned state first existed (0: the seed's). Growth appends vertices
    // and never removes one, and the fail-safe's state is the same growth
    // stopped early, so the counts seen during the one growth date it.
    GrowthState grow_dated(const Network& network, GrowthWorkspace& workspace, std::vector<int>& births) const;

private:
    std::vector<int> layers_;
    GrowthParams growth_;
    Seed seed_;
    bool fail_safe_ = false;  // "touch" from a clean seed (§5.7.1)
};

}  // namespace morphogen
