#include "growth/growth.hpp"

#include "base/errors.hpp"
#include "growth/branching.hpp"
#include "growth/gather_kernel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace morphogen {

namespace {

using Clock = std::chrono::steady_clock;

// Adds the seconds since `start` to `slot` (when timing is on) and restarts.
class PhaseClock {
public:
    explicit PhaseClock(PhaseTimes* times) : times_(times), start_(times ? Clock::now() : Clock::time_point{}) {}
    // Returns the seconds added.
    double lap(double PhaseTimes::*slot) {
        if (times_ == nullptr) return 0.0;
        const auto now = Clock::now();
        const double seconds = std::chrono::duration<double>(now - start_).count();
        times_->*slot += seconds;
        start_ = now;
        return seconds;
    }

private:
    PhaseTimes* times_;
    Clock::time_point start_;
};

}  // namespace

PhaseTimes& PhaseTimes::operator+=(const PhaseTimes& o) {
    gather += o.gather;
    think += o.think;
    move += o.move;
    split += o.split;
    flip += o.flip;
    collide += o.collide;
    vertex_steps += o.vertex_steps;
    return *this;
}

Grower::Grower(const Network& network, const GrowthParams& params) : network_(network), params_(params) {
    const int N = network.outputs();
    if (N < 3) throw ConfigError("network.outputs: growth needs at least 3 outputs, the network has " + std::to_string(N));
    if (network.inputs() != 3 * N)
        throw ConfigError("network: the input layer must have 3 * outputs = " + std::to_string(3 * N) +
                          " neurons, it has " + std::to_string(network.inputs()));
    if (params.mode == GrowthMode::branching && N < kBranchingOutputs)
        throw ConfigError("network.outputs: growth.mode \"branching\" needs at least " +
                          std::to_string(kBranchingOutputs) + " outputs, the network has " + std::to_string(N));
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

namespace {

// A tick counter to split the fused gather+network time: the gather runs
// once per block of 8 vertices, too often for clock_gettime. Fenced on both
// sides: a bare rdtsc may execute before the code ahead of it has finished,
// or after code behind it has started, so an interval would take in part of
// its neighbours' work (here, the kernel's).
std::uint64_t ticks() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_lfence();
    const std::uint64_t t = __rdtsc();
    _mm_lfence();
    return t;
#else
    return static_cast<std::uint64_t>(Clock::now().time_since_epoch().count());
#endif
}

// What a pair of back-to-back ticks() reads on top of the code between them
// (the smallest of 64 tries; 49 ticks = 20 ns on the development VM): a
// timed interval is that much too long.
std::uint64_t tick_overhead() {
    static const std::uint64_t overhead = [] {
        std::uint64_t least = ~std::uint64_t{0};
        for (int i = 0; i < 64; ++i) {
            const std::uint64_t a = ticks();
            least = std::min(least, ticks() - a);
        }
        return least;
    }();
    return overhead;
}

// What the network's input source needs: the gather of docs/algorithm.md §4.2 for a block of
// vertices, and (when timing) an estimate of the ticks it took. Only one
// block in `sample_every` is timed: a fenced read costs about 27 ns here and
// drains the pipeline, and two per block of 8 vertices would slow the timed
// pass itself. The timed blocks' ticks, less the reads' own overhead, are
// scaled up to all blocks. The sampling phase runs on across calls and
// genomes (per thread), so the timed blocks rotate.
struct BlockGather {
    static constexpr std::uint64_t sample_every = 8;
    kernel::GatherInput input;
    bool timed = false;
    mutable std::uint64_t gather_ticks = 0, blocks = 0, timed_blocks = 0;

    static void fill(const void* context, std::ptrdiff_t first, int count, double* rows) {
        thread_local std::uint64_t phase = 0;
        const auto& self = *static_cast<const BlockGather*>(context);
        if (self.timed) ++self.blocks;
        if (!self.timed || phase++ % sample_every != 0) {
            kernel::gather_inputs(self.input, static_cast<int>(first), count, rows);
            return;
        }
        const std::uint64_t start = ticks();
        kernel::gather_inputs(self.input, static_cast<int>(first), count, rows);
        const std::uint64_t elapsed = ticks() - start, overhead = tick_overhead();
        self.gather_ticks += elapsed > overhead ? elapsed - overhead : 0;
        ++self.timed_blocks;
    }

    // The estimated share of `total` ticks spent gathering.
    double share_of(std::uint64_t total) const {
        if (total == 0 || timed_blocks == 0) return 0.0;
        const double estimate = static_cast<double>(gather_ticks) * static_cast<double>(blocks) /
                                static_cast<double>(timed_blocks);
        return std::min(1.0, estimate / static_cast<double>(total));
    }
};

}  // namespace

double Grower::think(GrowthState& state, GrowthWorkspace& workspace, bool timed) const {
    const TriMesh& mesh = state.mesh;
    BlockGather gather;
    gather.timed = timed;
    kernel::GatherInput& in = gather.input;
    in.outputs = network_.outputs();
    in.previous = state.outputs.data();
    in.neighbour_offsets = workspace.neighbour_offsets.data();
    in.neighbours = workspace.neighbours.data();
    in.directions = state.directions.data();
    in.positions = mesh.positions().data();
    in.height_scale = params_.height_scale;
    in.active = state.active.empty() ? nullptr : state.active.data();
    workspace.next_outputs.resize(static_cast<std::size_t>(network_.outputs()) * mesh.num_vertices());
    if (timed) tick_overhead();  // calibrated once, outside the timed interval
    const std::uint64_t start = timed ? ticks() : 0;
    network_.evaluate(kernel::InputSource{&BlockGather::fill, &gather}, workspace.next_outputs, workspace.network);
    const std::uint64_t total = timed ? ticks() - start : 0;
    state.outputs.swap(workspace.next_outputs);
    return gather.share_of(total);
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
    // d_i (§5.2); a dormant vertex (branching mode, §5.8) does not move.
    const std::uint8_t* active = state.active.empty() ? nullptr : state.active.data();
    const auto step_of = [&](int i) { return active != nullptr && active[i] == 0 ? 0.0 : std::max(0.0, w[N * i] - 0.5); };
    double total = 0.0;
    for (int i = 0; i < V; ++i) total += step_of(i);
    if (total > 0.0) {
        const double k = std::min(params_.speed, params_.budget / total);
        for (int i = 0; i < V; ++i) x[i] += (k * step_of(i)) * state.directions[i];
    }
    if (params_.ground)
        for (Vec3& p : x) p.z() = std::max(p.z(), 0.0);
}

void Grower::split(GrowthState& state, GrowthWorkspace& workspace, CollisionGuard* guard) const {
    TriMesh& mesh = state.mesh;
    const int N = state.outputs_per_vertex;
    const int F0 = mesh.num_faces();
    std::vector<double>& outputs = state.outputs;
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

        const double* wa = outputs.data() + static_cast<std::ptrdiff_t>(N) * a;
        const double* wb = outputs.data() + static_cast<std::ptrdiff_t>(N) * b;
        const double* wc = outputs.data() + static_cast<std::ptrdiff_t>(N) * c;
        const Vec3 normal = cross / twice_area;
        const std::vector<Vec3>& h = state.directions;
        const Vec3 sum = normal + wa[2] * h[a] + wb[2] * h[b] + wc[2] * h[c];
        const double length = sum.norm();
        const Vec3 direction = length < 1e-12 ? normal : Vec3(sum / length);
        // a, b, c are older vertices (faces appended in this phase are not
        // visited), so w_v averages this step's outputs. Grow first: the
        // pointers above may not survive the reallocation.
        const std::size_t end = outputs.size();
        outputs.resize(end + N);
        for (int k = 0; k < N; ++k)
            outputs[end + k] = (outputs[static_cast<std::size_t>(N) * a + k] + outputs[static_cast<std::size_t>(N) * b + k] +
                                outputs[static_cast<std::size_t>(N) * c + k]) /
                               3.0;
        mesh.split_face(f, mesh.face_centroid(f));
        state.directions.push_back(direction);
        // Branching mode (§5.8): a new vertex grows only between three that grow.
        if (!state.active.empty()) state.active.push_back(state.active[a] & state.active[b] & state.active[c]);
        if (guard != nullptr)
            for (const int written : {f, mesh.num_faces() - 2, mesh.num_faces() - 1}) guard->face_changed(mesh, written);
    }
}

void Grower::flip(GrowthState& state, FlipGuard* guard) const {
    if (guard == nullptr) {
        flip_pass(state.mesh, flip_criteria_);
        return;
    }
    FlipCriteria criteria = flip_criteria_;
    criteria.guard = guard;
    flip_pass(state.mesh, criteria);
}

void Grower::step(GrowthState& state, GrowthWorkspace& workspace, PhaseTimes* times) const {
    const int t = state.steps_done;
    PhaseClock clock(times);
    if (times != nullptr) times->vertex_steps += static_cast<std::uint64_t>(state.mesh.num_vertices());
    build_neighbours(state.mesh, workspace);
    clock.lap(&PhaseTimes::gather);
    // Gather and network run together, a block of vertices at a time (the
    // inputs never leave the L1 cache); the gather's share is counted inside.
    const double gather_share = think(state, workspace, times != nullptr);
    const double fused = clock.lap(&PhaseTimes::think);
    if (times != nullptr) {
        times->think -= gather_share * fused;
        times->gather += gather_share * fused;
    }
    if (params_.mode == GrowthMode::branching) {
        branch(state, workspace);
        clock.lap(&PhaseTimes::move);  // counted with the move it steers (bench's "move")
    }
    // growth.collisions "prevent" (docs/algorithm.md §5.7): the move is
    // settled, splits are listed and flips guarded, so no two faces intersect.
    CollisionGuard* guard = params_.collisions == Collisions::prevent ? &workspace.collision : nullptr;
    if (guard != nullptr) {
        workspace.before_move.assign(state.mesh.positions().begin(), state.mesh.positions().end());
        clock.lap(&PhaseTimes::collide);
    }
    move(state);
    clock.lap(&PhaseTimes::move);
    if (guard != nullptr) {
        guard->settle_move(state.mesh, workspace.before_move);
        clock.lap(&PhaseTimes::collide);
    }
    split(state, workspace, guard);
    clock.lap(&PhaseTimes::split);
    const double guard_before = guard != nullptr ? guard->flip_seconds : 0.0;
    if (guard != nullptr) guard->timed = times != nullptr;
    if ((t + 1) % params_.flip_every == 0) flip(state, guard);
    clock.lap(&PhaseTimes::flip);
    if (guard != nullptr && times != nullptr) {
        times->flip -= guard->flip_seconds - guard_before;
        times->collide += guard->flip_seconds - guard_before;
    }
    state.steps_done = t + 1;
}

GrowthState Grower::grow(const Seed& seed, GrowthWorkspace& workspace, PhaseTimes* times,
                         const StepObserver& observer) const {
    GrowthState state = start(seed);
    for (int t = 0; t < params_.steps; ++t) {
        step(state, workspace, times);
        if (observer) observer(state, t);
    }
    return state;
}

}  // namespace morphogen
