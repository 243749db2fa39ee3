#include "growth.hpp"

#include "errors.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace morphogen {

namespace {

using Clock = std::chrono::steady_clock;

// Adds the seconds since `start` to `slot` (when timing is on) and restarts.
class PhaseClock {
public:
    explicit PhaseClock(PhaseTimes* times) : times_(times), start_(times ? Clock::now() : Clock::time_point{}) {}
    void lap(double PhaseTimes::*slot) {
        if (times_ == nullptr) return;
        const auto now = Clock::now();
        times_->*slot += std::chrono::duration<double>(now - start_).count();
        start_ = now;
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
    vertex_steps += o.vertex_steps;
    return *this;
}

Grower::Grower(const Network& network, const GrowthParams& params) : network_(network), params_(params) {
    const int N = network.outputs();
    if (N < 3) throw ConfigError("network.outputs: growth needs at least 3 outputs, the network has " + std::to_string(N));
    if (network.inputs() != 3 * N)
        throw ConfigError("network: the input layer must have 3 * outputs = " + std::to_string(3 * N) +
                          " neurons, it has " + std::to_string(network.inputs()));
    flip_criteria_.min_normal_dot = std::cos(params.flip_max_angle_deg * std::numbers::pi / 180.0);
    flip_criteria_.min_valence = params.min_valence;
}

GrowthState Grower::start(const Seed& seed) const {
    GrowthState state;
    state.mesh = seed.mesh;
    state.directions = seed.directions;
    state.outputs = Eigen::MatrixXd::Constant(network_.outputs(), seed.mesh.num_vertices(), 0.5);
    return state;
}

void Grower::gather(const GrowthState& state, GrowthWorkspace& workspace) const {
    const TriMesh& mesh = state.mesh;
    const int V = mesh.num_vertices();
    const int N = network_.outputs();
    Eigen::MatrixXd& inputs = workspace.inputs;
    inputs.resize(3 * N, V);
    const double* w = state.outputs.data();
    std::vector<int>& neighbours = workspace.neighbours;
    for (int i = 0; i < V; ++i) {
        double* in = inputs.data() + static_cast<std::ptrdiff_t>(3 * N) * i;
        double* mean = in + N;
        double* deviation = in + 2 * N;
        std::copy_n(w + static_cast<std::ptrdiff_t>(N) * i, N, in);

        neighbours.clear();
        mesh.for_each_neighbour(i, [&](int u) { neighbours.push_back(u); });
        const double inverse_count = 1.0 / static_cast<double>(neighbours.size());
        std::fill_n(mean, 2 * N, 0.0);
        for (int u : neighbours) {
            const double* wu = w + static_cast<std::ptrdiff_t>(N) * u;
            for (int c = 0; c < N; ++c) mean[c] += wu[c];
        }
        for (int c = 0; c < N; ++c) mean[c] *= inverse_count;
        // Two passes: the population deviation without cancellation.
        for (int u : neighbours) {
            const double* wu = w + static_cast<std::ptrdiff_t>(N) * u;
            for (int c = 0; c < N; ++c) {
                const double d = wu[c] - mean[c];
                deviation[c] += d * d;
            }
        }
        for (int c = 0; c < N; ++c) deviation[c] = std::sqrt(deviation[c] * inverse_count);

        const Vec3& h = state.directions[i];
        in[3 * N - 4] = 0.5 + 0.5 * h.x();
        in[3 * N - 3] = 0.5 + 0.5 * h.y();
        in[3 * N - 2] = 0.5 + 0.5 * h.z();
        in[3 * N - 1] = mesh.position(i).z() / params_.height_scale;
    }
}

void Grower::move(GrowthState& state) const {
    std::vector<Vec3>& x = state.mesh.positions();
    const int V = state.mesh.num_vertices();
    const double* w = state.outputs.data();
    const Eigen::Index N = state.outputs.rows();
    double total = 0.0;
    for (int i = 0; i < V; ++i) total += std::max(0.0, w[N * i] - 0.5);
    if (total > 0.0) {
        const double k = std::min(params_.speed, params_.budget / total);
        for (int i = 0; i < V; ++i) x[i] += (k * std::max(0.0, w[N * i] - 0.5)) * state.directions[i];
    }
    if (params_.ground)
        for (Vec3& p : x) p.z() = std::max(p.z(), 0.0);
}

void Grower::split(GrowthState& state) const {
    TriMesh& mesh = state.mesh;
    const int N = static_cast<int>(state.outputs.rows());
    const int F0 = mesh.num_faces();
    const int V0 = mesh.num_vertices();
    const double* w = state.outputs.data();
    std::vector<double> new_outputs;  // columns of the vertices added in this phase
    for (int f = 0; f < F0; ++f) {
        if (mesh.num_vertices() >= params_.max_vertices) break;
        const auto [a, b, c] = mesh.face(f);
        const double* wa = w + static_cast<std::ptrdiff_t>(N) * a;
        const double* wb = w + static_cast<std::ptrdiff_t>(N) * b;
        const double* wc = w + static_cast<std::ptrdiff_t>(N) * c;
        const Vec3 cross = mesh.face_cross(f);
        const double area = 0.5 * cross.norm();
        if (!(area > params_.split_area * (0.5 + (wa[1] + wb[1] + wc[1]) / 3.0))) continue;

        const Vec3 normal = cross / cross.norm();
        const std::vector<Vec3>& h = state.directions;
        const Vec3 sum = normal + wa[2] * h[a] + wb[2] * h[b] + wc[2] * h[c];
        const double length = sum.norm();
        const Vec3 direction = length < 1e-12 ? normal : Vec3(sum / length);
        for (int k = 0; k < N; ++k) new_outputs.push_back((wa[k] + wb[k] + wc[k]) / 3.0);
        mesh.split_face(f, mesh.face_centroid(f));
        state.directions.push_back(direction);
    }
    const int added = mesh.num_vertices() - V0;
    if (added > 0) {
        state.outputs.conservativeResize(Eigen::NoChange, V0 + added);
        std::copy(new_outputs.begin(), new_outputs.end(), state.outputs.data() + static_cast<std::ptrdiff_t>(N) * V0);
    }
}

void Grower::flip(GrowthState& state) const {
    TriMesh& mesh = state.mesh;
    const int F = mesh.num_faces();
    for (int f = 0; f < F; ++f)
        for (int e = 0; e < 3; ++e) mesh.try_flip(f, e, flip_criteria_);
}

void Grower::step(GrowthState& state, GrowthWorkspace& workspace, PhaseTimes* times) const {
    const int t = state.steps_done;
    PhaseClock clock(times);
    if (times != nullptr) times->vertex_steps += static_cast<std::uint64_t>(state.mesh.num_vertices());
    gather(state, workspace);
    clock.lap(&PhaseTimes::gather);
    workspace.next_outputs.resize(network_.outputs(), state.mesh.num_vertices());
    network_.evaluate(workspace.inputs, workspace.next_outputs, workspace.network);
    state.outputs.swap(workspace.next_outputs);
    clock.lap(&PhaseTimes::think);
    move(state);
    clock.lap(&PhaseTimes::move);
    split(state);
    clock.lap(&PhaseTimes::split);
    if ((t + 1) % params_.flip_every == 0) flip(state);
    clock.lap(&PhaseTimes::flip);
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
