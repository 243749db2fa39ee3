#pragma once
// Growth (docs/algorithm.md §4-§5): the network, copied at every vertex, grows a
// seed mesh step by step: think, move, split, flip. Deterministic: the same
// network, parameters and seed give the same mesh bit for bit.
#include "core/growth/contact/collision.hpp"
#include "core/growth/signals/exposure.hpp"
#include "core/growth/contact/contact_guard.hpp"
#include "core/growth/contact/flip_pass.hpp"
#include "core/growth/network/gather_kernel.hpp"
#include "core/growth/growth_observer.hpp"
#include "core/growth/growth_params.hpp"
#include "core/growth/network/network.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "core/growth/vertex_channels.hpp"
#include "core/mesh/mesh.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <vector>

namespace morphogen {

struct GrowthState {
    TriMesh mesh;
    std::vector<Vec3> directions;  // h_i, unit, fixed for the vertex's life
    std::vector<double> outputs;   // w: N per vertex, vertex after vertex, in (0, 1]
    int outputs_per_vertex = 0;    // N
    int steps_done = 0;
    // growth.mode "branching" (§5.8): 1 where the vertex grows, 0 where it is
    // dormant; empty in the paper's mode.
    std::vector<std::uint8_t> active;
    // growth.collisions "touch" in the paper's mode (§5.7.1): 1 where the
    // vertex touched and stopped for good; empty otherwise.
    std::vector<std::uint8_t> touched;

    double output(int vertex, int channel) const {
        return outputs[static_cast<std::size_t>(vertex) * outputs_per_vertex + channel];
    }

    // The per-vertex members above (the mesh's own aside), each with the
    // rule that gives a vertex made by a split its values (§5.3, §5.7.1,
    // §5.8): what the split phase grows. Valid while this state lives.
    VertexChannels channels();
};

// Reusable per-thread buffers, so growing many genomes does not reallocate.
struct GrowthWorkspace {
    // Plain vectors: they keep their capacity as the mesh grows, so steps do
    // not reallocate (and page-fault) fresh buffers.
    std::vector<double> next_outputs;  // N per vertex
    std::vector<int> neighbour_offsets, neighbours, cursor;  // CSR neighbour lists
    std::vector<double> split_w1;                            // w[1] of each vertex
    std::vector<Vec3> steered;                               // branching mode: new directions
    // growth.exposure (§5.9): this step's exposure of every vertex; empty when off.
    std::vector<double> exposure;
    ExposureWorkspace exposure_grid;
    std::vector<double> diffusion;  // growth.signal_diffusion (§5.9): the channel's iterates
    NetworkWorkspace network;
    // growth.collisions "prevent" only: positions before the move, the guard.
    std::vector<Vec3> before_move;
    CollisionGuard collision;
    // growth.collisions "touch" only: the contact rule, the vertices it refused.
    ContactGuard contact;
    std::vector<int> touching;
};

// Called after every step with the step index t; for tests and animation.
using StepObserver = std::function<void(const GrowthState&, int step)>;

// What the gather of docs/algorithm.md §4.2 reads for `state`: its outputs,
// directions and positions, and the neighbour lists and exposures in
// `workspace` (as the neighbours phase and think left them: valid until the
// mesh changes).
kernel::GatherInput gather_input(const GrowthState& state, const GrowthWorkspace& workspace, double height_scale);

class Grower {
public:
    // Throws ConfigError if the network does not fit (inputs != 3 * outputs, N < 3,
    // N < 7 in the branching mode, N < 8 with growth.signal_diffusion).
    Grower(const Network& network, const GrowthParams& params);

    // The state before step 0: the seed with every output 0.5.
    GrowthState start(const Seed& seed) const;
    // One timestep t (docs/algorithm.md §5) applied to `state`, its phases
    // reported to `phases` when there is one.
    void step(GrowthState& state, GrowthWorkspace& workspace, GrowthObserver* phases = nullptr) const;
    // start() then params.steps steps, `after_step` called after each.
    GrowthState grow(const Seed& seed, GrowthWorkspace& workspace, const StepObserver& after_step = {},
                     GrowthObserver* phases = nullptr) const;

private:
    // The neighbour lists (CSR) of the mesh as it stands.
    void build_neighbours(const TriMesh& mesh, GrowthWorkspace& workspace) const;
    // Gather (docs/algorithm.md §4.2) and network (§5.1), fused a block of
    // vertices at a time: new outputs for every vertex; with the signals of
    // §5.9, the exposures first and the diffusion after.
    void think(GrowthState& state, GrowthWorkspace& workspace) const;
    // §5.9: each vertex's exposure into workspace.exposure (emptied when off).
    void expose(const GrowthState& state, GrowthWorkspace& workspace) const;
    // Branching mode (§5.8): stop and start growth, turn the directions.
    void branch(GrowthState& state, GrowthWorkspace& workspace) const;
    void move(GrowthState& state) const;
    // growth.collisions "touch" (§5.7.1): refuses the touching vertices'
    // moves and makes them dormant.
    void settle_contacts(GrowthState& state, GrowthWorkspace& workspace) const;
    // With a guard, every face a split writes is reported to it (§5.7).
    void split(GrowthState& state, GrowthWorkspace& workspace, CollisionGuard* guard, ContactGuard* contact) const;
    // With a guard, each flip it tests is reported to `phases` as flip_guard.
    void flip(GrowthState& state, GrowthWorkspace& workspace, FlipGuard* guard, GrowthObserver* phases) const;

    const Network& network_;
    GrowthParams params_;
    FlipCriteria flip_criteria_;
};

}  // namespace morphogen
