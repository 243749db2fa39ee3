#include "core/growth/growth.hpp"

#include "core/base/errors.hpp"
#include "core/growth/branching.hpp"
#include "core/growth/network/gather_kernel.hpp"
#include "core/growth/signals/signal_diffusion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace morphogen {

Grower::Grower(const Network& network, const GrowthParams& params) : network_(network), params_(params) {
    const int N = network.outputs();
    if (N < 3) throw ConfigError("network.outputs: growth needs at least 3 outputs, the network has " + std::to_string(N));
    if (network.inputs() != 3 * N)
        throw ConfigError("network: the input layer must have 3 * outputs = " + std::to_string(3 * N) +
                          " neurons, it has " + std::to_string(network.inputs()));
    if (params.mode == GrowthMode::branching && N < kBranchingOutputs)
        throw ConfigError("network.outputs: growth.mode \"branching\" needs at least " +
                          std::to_string(kBranchingOutputs) + " outputs, the network has " + std::to_string(N));
    if (params.mode == GrowthMode::branching && params.signal_diffusion > 0 && N < kSignalOutputs)
        throw ConfigError("network.outputs: growth.signal_diffusion needs at least " + std::to_string(kSignalOutputs) +
                          " outputs, the network has " + std::to_string(N));
    flip_criteria_.min_normal_dot = std::cos(params.flip_max_angle_deg * std::numbers::pi / 180.0);
    flip_criteria_.min_valence = params.min_valence;
}

GrowthState Grower::start(const Seed& seed) const {
    GrowthState state;
    state.mesh = seed.mesh;
    state.directions = seed.directions;
    state.outputs_per_vertex = network_.outputs();
    state.outputs.assign(static_cast<std::size_t>(network_.outputs()) * seed.mesh.num_vertices(), 0.5);
    if (params_.mode == GrowthMode::branching) state.active.assign(static_cast<std::size_t>(seed.mesh.num_vertices()), 1);
    else if (params_.collisions == Collisions::touch)
        state.touched.assign(static_cast<std::size_t>(seed.mesh.num_vertices()), 0);
    return state;
}

void Grower::build_neighbours(const TriMesh& mesh, GrowthWorkspace& workspace) const {
    const int V = mesh.num_vertices();
    // Neighbour lists in CSR form, from one pass over the half-edges: each
    // neighbour of u is the head of exactly one half-edge leaving u.
    std::vector<int>& offsets = workspace.neighbour_offsets;
    std::vector<int>& neighbours = workspace.neighbours;
    offsets.resize(static_cast<std::size_t>(V) + 1);
    offsets[0] = 0;
    for (int v = 0; v < V; ++v) offsets[v + 1] = offsets[v] + mesh.valence(v);
    neighbours.resize(offsets[V]);
    std::vector<int>& cursor = workspace.cursor;
    cursor.assign(offsets.begin(), offsets.end() - 1);
    for (const Face& f : mesh.faces()) {
        neighbours[cursor[f[0]]++] = f[1];
        neighbours[cursor[f[1]]++] = f[2];
        neighbours[cursor[f[2]]++] = f[0];
    }
}

kernel::GatherInput gather_input(const GrowthState& state, const GrowthWorkspace& workspace, double height_scale) {
    kernel::GatherInput in;
    in.outputs = state.outputs_per_vertex;
    in.previous = state.outputs.data();
    in.neighbour_offsets = workspace.neighbour_offsets.data();
    in.neighbours = workspace.neighbours.data();
    in.directions = state.directions.data();
    in.positions = state.mesh.positions().data();
    in.height_scale = height_scale;
    in.active = state.active.empty() ? nullptr : state.active.data();
    in.exposure = workspace.exposure.empty() ? nullptr : workspace.exposure.data();
    return in;
}

namespace {
// The network's input source: the gather of docs/algorithm.md §4.2 for a block of vertices.
void gather_block(const void* input, std::ptrdiff_t first, int count, double* rows) {
    kernel::gather_inputs(*static_cast<const kernel::GatherInput*>(input), static_cast<int>(first), count, rows);
}
}  // namespace

void Grower::expose(const GrowthState& state, GrowthWorkspace& workspace) const {
    if (params_.mode != GrowthMode::branching || !params_.exposure) {
        workspace.exposure.clear();
        return;
    }
    const ExposureParams exposure{params_.exposure_cell, params_.exposure_depth, params_.exposure_full_shade};
    compute_exposure(state.mesh.positions(), exposure, workspace.exposure_grid, workspace.exposure);
}

void Grower::think(GrowthState& state, GrowthWorkspace& workspace) const {
    expose(state, workspace);
    const kernel::GatherInput input = gather_input(state, workspace, params_.height_scale);
    workspace.next_outputs.resize(static_cast<std::size_t>(network_.outputs()) * state.mesh.num_vertices());
    network_.evaluate(kernel::InputSource{&gather_block, &input}, workspace.next_outputs, workspace.network);
    state.outputs.swap(workspace.next_outputs);
    if (params_.mode == GrowthMode::branching && params_.signal_diffusion > 0)
        diffuse_signal(state.outputs, state.outputs_per_vertex, workspace.neighbour_offsets, workspace.neighbours,
                       params_.signal_diffusion, params_.signal_rate, workspace.diffusion);
}

void Grower::branch(GrowthState& state, GrowthWorkspace& workspace) const {
    update_activity(state.active, state.outputs, state.outputs_per_vertex);
    steer_directions(state.directions, state.mesh, state.outputs, state.outputs_per_vertex,
                     workspace.neighbour_offsets, workspace.neighbours, params_.turn_rate, workspace.steered);
}

void Grower::move(GrowthState& state) const {
    std::vector<Vec3>& x = state.mesh.positions();
    const int V = state.mesh.num_vertices();
    const double* w = state.outputs.data();
    const std::ptrdiff_t N = state.outputs_per_vertex;
    // d_i (§5.2); a dormant vertex (branching mode, §5.8) does not move, nor
    // one that touched in the paper's mode (§5.7.1).
    const std::uint8_t* active = state.active.empty() ? nullptr : state.active.data();
    const std::uint8_t* touched = state.touched.empty() ? nullptr : state.touched.data();
    const auto step_of = [&](int i) {
        const bool dormant = (active != nullptr && active[i] == 0) || (touched != nullptr && touched[i] != 0);
        return dormant ? 0.0 : std::max(0.0, w[N * i] - 0.5);
    };
    double total = 0.0;
    for (int i = 0; i < V; ++i) total += step_of(i);
    if (total > 0.0) {
        const double k = std::min(params_.speed, params_.budget / total);
        for (int i = 0; i < V; ++i) x[i] += (k * step_of(i)) * state.directions[i];
    }
    if (params_.ground)
        for (Vec3& p : x) p.z() = std::max(p.z(), 0.0);
}

void Grower::settle_contacts(GrowthState& state, GrowthWorkspace& workspace) const {
    workspace.contact.settle_move(state.mesh, workspace.before_move, workspace.neighbour_offsets, workspace.neighbours,
                                  params_.contact_distance, workspace.touching);
    // Touch stops growth: dormant in the branching mode (the network may wake
    // the vertex again, §5.8), stopped for good in the paper's.
    std::vector<std::uint8_t>& stopped = state.active.empty() ? state.touched : state.active;
    const std::uint8_t value = state.active.empty() ? 1 : 0;
    for (const int v : workspace.touching) stopped[v] = value;
}

namespace {

// §5.3: the direction of a vertex made inside face (a, b, c): the face's unit
// normal plus the corners' directions weighted by their w[2], normalised.
Vec3 split_direction(const void* context, int a, int b, int c) {
    const GrowthState& state = *static_cast<const GrowthState*>(context);
    const std::vector<Vec3>& x = state.mesh.positions();
    const Vec3 cross = (x[b] - x[a]).cross(x[c] - x[a]);  // = face_cross of the face (a, b, c)
    const Vec3 normal = cross / std::sqrt(cross.squaredNorm());
    const std::vector<Vec3>& h = state.directions;
    const Vec3 sum = normal + state.output(a, 2) * h[a] + state.output(b, 2) * h[b] + state.output(c, 2) * h[c];
    const double length = sum.norm();
    return length < 1e-12 ? normal : Vec3(sum / length);
}

}  // namespace

VertexChannels GrowthState::channels() {
    VertexChannels list;
    // w_v: the mean of the corners' outputs of this step.
    list.mean(outputs, outputs_per_vertex);
    list.computed(directions, &split_direction, this);
    // Branching mode (§5.8): a new vertex grows only between three that grow.
    list.all(active);
    // Likewise in the paper's mode with "touch" (§5.7.1): it grows only if
    // no corner touched.
    list.any(touched);
    return list;
}

void Grower::split(GrowthState& state, GrowthWorkspace& workspace, CollisionGuard* guard, ContactGuard* contact) const {
    TriMesh& mesh = state.mesh;
    const int N = state.outputs_per_vertex;
    const int F0 = mesh.num_faces();
    const std::vector<double>& outputs = state.outputs;
    const VertexChannels channels = state.channels();
    // Each vertex's w[1] in a compact array: the face loop reads it three times
    // per face from scattered vertices, and a whole output row per read would
    // pull N doubles into the cache for one. Only vertices older than this
    // phase are read (appended faces are not visited).
    std::vector<double>& w1 = workspace.split_w1;
    w1.resize(static_cast<std::size_t>(mesh.num_vertices()));
    for (std::size_t i = 0; i < w1.size(); ++i) w1[i] = outputs[i * N + 1];
    for (int f = 0; f < F0; ++f) {
        if (mesh.num_vertices() >= params_.max_vertices) break;
        const auto [a, b, c] = mesh.face(f);
        const Vec3 cross = mesh.face_cross(f);
        const double w1_sum = w1[a] + w1[b] + w1[c];
        const double twice_area_squared = cross.squaredNorm();
        // Most faces are far below their threshold: reject them without the
        // square root and the division (about half of this phase's time). The
        // margin dwarfs the rounding of `near_threshold`, so every face it
        // rejects also fails the exact test below, which decides the rest.
        const double near_threshold = params_.split_area * (0.5 + w1_sum * (1.0 / 3.0));
        if (twice_area_squared < 4.0 * near_threshold * near_threshold * (1.0 - 1e-9)) continue;
        const double twice_area = std::sqrt(twice_area_squared);  // = cross.norm()
        if (!(0.5 * twice_area > params_.split_area * (0.5 + w1_sum / 3.0))) continue;

        // a, b, c are older vertices (faces appended in this phase are not
        // visited), so the new vertex's values come from this step's.
        channels.add_vertex_in(a, b, c);
        mesh.split_face(f, mesh.face_centroid(f));
        if (guard != nullptr)
            for (const int written : {f, mesh.num_faces() - 2, mesh.num_faces() - 1}) guard->face_changed(mesh, written);
        if (contact != nullptr)
            for (const int written : {mesh.num_faces() - 2, mesh.num_faces() - 1}) contact->face_changed(mesh, written);
    }
}

namespace {

// Reports each flip the collision guard tests to an observer (§5.7's share
// of the flip phase).
class ObservedFlipGuard final : public FlipGuard {
public:
    ObservedFlipGuard(FlipGuard& guard, GrowthObserver& observer, const GrowthState& state,
                      const GrowthWorkspace& workspace)
        : guard_(guard), observer_(observer), state_(state), workspace_(workspace) {}
    bool allows(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) override {
        observer_.begin(GrowthPhase::flip_guard, state_, workspace_);
        const bool allowed = guard_.allows(mesh, f, g, new_f, new_g);
        observer_.end(GrowthPhase::flip_guard, state_, workspace_);
        return allowed;
    }

private:
    FlipGuard& guard_;
    GrowthObserver& observer_;
    const GrowthState& state_;
    const GrowthWorkspace& workspace_;
};

// Runs one phase of a step between the observer's hooks (when there is one).
template <class Phase>
void observed(GrowthPhase phase, GrowthObserver* observer, const GrowthState& state, const GrowthWorkspace& workspace,
              Phase&& run) {
    if (observer != nullptr) observer->begin(phase, state, workspace);
    run();
    if (observer != nullptr) observer->end(phase, state, workspace);
}

}  // namespace

void Grower::flip(GrowthState& state, GrowthWorkspace& workspace, FlipGuard* guard, GrowthObserver* phases) const {
    FlipCriteria criteria = flip_criteria_;
    std::optional<ObservedFlipGuard> observed_guard;
    if (guard != nullptr && phases != nullptr) guard = &observed_guard.emplace(*guard, *phases, state, workspace);
    criteria.guard = guard;
    flip_pass(state.mesh, criteria);
}

void Grower::step(GrowthState& state, GrowthWorkspace& workspace, GrowthObserver* phases) const {
    const auto phase = [&](GrowthPhase which, auto&& run) { observed(which, phases, state, workspace, run); };
    // growth.collisions "prevent" (docs/algorithm.md §5.7): the move is
    // settled, splits are listed and flips guarded, so no two faces intersect.
    CollisionGuard* guard = params_.collisions == Collisions::prevent ? &workspace.collision : nullptr;
    // growth.collisions "touch" (§5.7.1): touching vertices stay and go
    // dormant, flips are guarded; cheap, not a proof.
    ContactGuard* contact = params_.collisions == Collisions::touch ? &workspace.contact : nullptr;
    FlipGuard* flip_guard = guard != nullptr ? static_cast<FlipGuard*>(guard) : contact;
    phase(GrowthPhase::neighbours, [&] { build_neighbours(state.mesh, workspace); });
    phase(GrowthPhase::think, [&] { think(state, workspace); });
    if (params_.mode == GrowthMode::branching) phase(GrowthPhase::branch, [&] { branch(state, workspace); });
    phase(GrowthPhase::move, [&] {
        if (flip_guard != nullptr)
            workspace.before_move.assign(state.mesh.positions().begin(), state.mesh.positions().end());
        move(state);
    });
    if (guard != nullptr) phase(GrowthPhase::settle, [&] { guard->settle_move(state.mesh, workspace.before_move); });
    if (contact != nullptr) phase(GrowthPhase::settle, [&] { settle_contacts(state, workspace); });
    phase(GrowthPhase::split, [&] { split(state, workspace, guard, contact); });
    if ((state.steps_done + 1) % params_.flip_every == 0)
        phase(GrowthPhase::flip, [&] { flip(state, workspace, flip_guard, phases); });
    ++state.steps_done;
}

GrowthState Grower::grow(const Seed& seed, GrowthWorkspace& workspace, const StepObserver& after_step,
                         GrowthObserver* phases) const {
    GrowthState state = start(seed);
    for (int t = 0; t < params_.steps; ++t) {
        step(state, workspace, phases);
        if (after_step) after_step(state, t);
    }
    return state;
}

}  // namespace morphogen
