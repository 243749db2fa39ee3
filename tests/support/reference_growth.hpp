#pragma once
// A second, deliberately plain implementation of docs/algorithm.md §4-§5, written
// straight from the text with different data structures (maps and sets, the
// per-vertex pseudocode network). The growth tests check that the engine and
// this agree to rounding error.
#include "core/growth/growth_params.hpp"
#include "core/growth/network/network.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "core/mesh/face_pair.hpp"
#include "core/mesh/fan_certificate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <vector>

namespace morphogen::testing {

struct ReferenceGrowth {
    std::vector<Vec3> x, h;
    std::vector<Face> faces;
    std::vector<std::vector<double>> w;
    std::vector<int> active;  // growth.mode "branching" (§5.8): every seed vertex grows

    ReferenceGrowth(const Seed& seed, int outputs, bool branching = false)
        : x(seed.mesh.positions()), h(seed.directions), faces(seed.mesh.faces()),
          w(x.size(), std::vector<double>(outputs, 0.5)) {
        if (branching) active.assign(x.size(), 1);
    }

    // §5.8: switch growth on channel 3 (stop below 1/3, start above 2/3), then
    // turn every direction by channels 4-6, all from the old directions.
    void branch(const std::vector<std::set<int>>& nb, double turn_rate) {
        const int V = static_cast<int>(x.size());
        for (int i = 0; i < V; ++i) {
            if (active[i] == 1 && w[i][3] < 1.0 / 3.0) active[i] = 0;
            else if (active[i] == 0 && w[i][3] > 2.0 / 3.0) active[i] = 1;
        }
        const auto unit = [](const Vec3& v) { return v.norm() > 1e-12 ? Vec3(v.normalized()) : Vec3(Vec3::Zero()); };
        std::vector<Vec3> normal(V, Vec3::Zero());
        for (const Face& f : faces)
            for (int a : f) normal[a] += (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]);
        std::vector<Vec3> turned(V);
        for (int i = 0; i < V; ++i) {
            const Vec3 n = normal[i].norm() > 0 ? Vec3(normal[i].normalized()) : Vec3(Vec3::Zero());
            Vec3 mean = Vec3::Zero();
            for (int j : nb[i]) mean += h[j];
            mean /= static_cast<double>(nb[i].size());
            const Vec3 target = (2 * w[i][4] - 1) * n + (2 * w[i][5] - 1) * Vec3(0, 0, 1) + (2 * w[i][6] - 1) * unit(h[i] - mean);
            const Vec3 sum = h[i] + turn_rate * target;
            turned[i] = sum.norm() > 1e-12 ? Vec3(sum.normalized()) : h[i];
        }
        h = turned;
    }

    // §5.9 exposure, as Palubicki et al. describe it: every vertex adds shadow
    // 2^-d to the voxels (I + dx, J + dy, K − d), |dx|, |dy| ≤ d, for d = 0 ..
    // depth; a vertex's exposure is clamp((C − s + 1) / C, 0, 1), s the shadow
    // of its voxel.
    std::vector<double> exposure(const GrowthParams& p) const {
        const auto voxel = [&](const Vec3& q) {
            std::array<long long, 3> v{};
            for (int axis = 0; axis < 3; ++axis)
                v[axis] = static_cast<long long>(std::clamp(std::floor(q[axis] / p.exposure_cell), -1099511627776.0, 1099511627776.0));
            return v;
        };
        std::map<std::array<long long, 3>, double> shadow;
        for (const Vec3& q : x) {
            const auto [I, J, K] = voxel(q);
            for (int d = 0; d <= p.exposure_depth; ++d)
                for (int dx = -d; dx <= d; ++dx)
                    for (int dy = -d; dy <= d; ++dy) shadow[{I + dx, J + dy, K - d}] += std::pow(2.0, -d);
        }
        std::vector<double> e;
        for (const Vec3& q : x)
            e.push_back(std::clamp((p.exposure_full_shade - shadow[voxel(q)] + 1.0) / p.exposure_full_shade, 0.0, 1.0));
        return e;
    }

    // §5.9 diffusion: `iterations` Jacobi steps of u := u + D (mean_nb(u) − u)
    // on channel 7, every vertex from the previous iterate.
    void diffuse(const std::vector<std::set<int>>& nb, int iterations, double rate) {
        const int V = static_cast<int>(x.size());
        for (int it = 0; it < iterations; ++it) {
            std::vector<double> u(V);
            for (int i = 0; i < V; ++i) {
                double mean = 0;
                for (int j : nb[i]) mean += w[j][7];
                mean /= static_cast<double>(nb[i].size());
                u[i] = w[i][7] + rate * (mean - w[i][7]);
            }
            for (int i = 0; i < V; ++i) w[i][7] = u[i];
        }
    }

    // ---- growth.collisions "touch" (§5.7.1), by brute force over every vertex and face ----
    // Paper mode: 1 where a vertex touched and stopped for good (empty until
    // the first settle, and in the branching mode, which uses `active`).
    std::vector<int> touched;

    bool touched_at(int i) const { return !touched.empty() && touched[i] == 1; }

    // Distance from q to the closed triangle (a, b, c), and the corners its
    // nearest point lies between (bit k: corner k): the plane where q projects
    // inside, else the nearest of the three sides, or one end of it.
    struct Nearest {
        double distance;
        unsigned corners;
    };
    static Nearest nearest_on_triangle(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
        Nearest best{std::numeric_limits<double>::infinity(), 0};
        const Vec3 corner[3] = {a, b, c};
        for (int k = 0; k < 3; ++k) {
            const Vec3 &s = corner[k], &e = corner[(k + 1) % 3];
            const double length2 = (e - s).squaredNorm();
            const double u = length2 > 0 ? std::clamp((q - s).dot(e - s) / length2, 0.0, 1.0) : 0.0;
            const double distance = (q - (s + u * (e - s))).norm();
            const unsigned ends = u == 0 ? 1U << k : u == 1 ? 1U << (k + 1) % 3 : (1U << k) | (1U << (k + 1) % 3);
            if (distance < best.distance) best = {distance, ends};
        }
        const Vec3 n = (b - a).cross(c - a);
        if (n.norm() > 0 && projects_inside(q, a, b, c)) return {std::abs(n.normalized().dot(q - a)), 0b111};
        return best;
    }
    static bool projects_inside(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 n = (b - a).cross(c - a);
        return (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 && (a - c).cross(q - c).dot(n) >= 0;
    }
    // Near by §5.7.1's measure (within r): the corners of the nearest point,
    // 0 if not near.
    static unsigned contact_near(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, double r) {
        const Nearest nearest = nearest_on_triangle(q, a, b, c);
        return nearest.distance < r ? nearest.corners : 0;
    }

    // §5.7.1: contact pairs at the proposed positions, then tangled fans;
    // the refused go back, the fans around them are checked once more; every
    // refused vertex goes dormant.
    void settle_contacts(const std::vector<Vec3>& before, const std::vector<std::set<int>>& nb, double r) {
        const int V = static_cast<int>(x.size());
        if (active.empty() && touched.empty()) touched.assign(V, 0);
        std::vector<bool> moving(V);
        for (int i = 0; i < V; ++i) moving[i] = x[i] != before[i];
        std::set<int> refuse;
        for (int v = 0; v < V; ++v)
            for (const Face& f : faces) {
                const auto [a, b, c] = f;
                if (v == a || v == b || v == c) continue;
                if (!moving[v] && !moving[a] && !moving[b] && !moving[c]) continue;
                unsigned corners = contact_near(x[v], x[a], x[b], x[c], r);
                const double s0 = (before[b] - before[a]).cross(before[c] - before[a]).dot(before[v] - before[a]);
                const double s1 = (x[b] - x[a]).cross(x[c] - x[a]).dot(x[v] - x[a]);
                if (corners == 0 && ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0))) {
                    const double t = s0 / (s0 - s1);
                    const auto at = [&](int u) { return Vec3(before[u] + t * (x[u] - before[u])); };
                    corners = contact_near(at(v), at(a), at(b), at(c), r);
                }
                if (corners == 0) continue;
                if (moving[v]) refuse.insert(v);
                for (int k = 0; k < 3; ++k)
                    if ((corners >> k & 1U) != 0 && moving[f[k]]) refuse.insert(f[k]);
            }
        // A fan not certified at the positions now: its moving vertices stay.
        const auto refuse_tangled = [&](const std::set<int>& check) {
            const TriMesh mesh = TriMesh::from_arrays({x, faces}, "reference");
            std::vector<Vec3> spokes;
            std::set<int> more;
            for (const int v : check) {
                if (fan_certified(mesh, v, spokes)) continue;
                if (moving[v]) more.insert(v);
                for (const int u : nb[v])
                    if (moving[u]) more.insert(u);
            }
            refuse.insert(more.begin(), more.end());
        };
        std::set<int> changed_fans;
        for (int v = 0; v < V; ++v)
            if (moving[v] || std::any_of(nb[v].begin(), nb[v].end(), [&](int u) { return moving[u]; }))
                changed_fans.insert(v);
        refuse_tangled(changed_fans);
        std::set<int> around_refused;
        for (const int u : refuse) {
            x[u] = before[u];
            around_refused.insert(u);
            around_refused.insert(nb[u].begin(), nb[u].end());
        }
        refuse_tangled(around_refused);
        for (const int u : refuse) {
            x[u] = before[u];
            if (!active.empty()) active[u] = 0;
            else touched[u] = 1;
        }
    }

    // The flip guard: the new faces are not degenerate and intersect neither
    // each other nor any face but the two they replace (core/mesh/face_pair.hpp).
    bool contact_flip_allowed(int f, int g, const Face& new_f, const Face& new_g) const {
        const IndexedTriangle tf = IndexedTriangle::of(x, new_f), tg = IndexedTriangle::of(x, new_g);
        if (triangle_degenerate(x[new_f[0]], x[new_f[1]], x[new_f[2]])) return false;
        if (triangle_degenerate(x[new_g[0]], x[new_g[1]], x[new_g[2]])) return false;
        if (faces_intersect(tf, tg)) return false;
        for (int j = 0; j < static_cast<int>(faces.size()); ++j) {
            if (j == f || j == g) continue;
            const IndexedTriangle tj = IndexedTriangle::of(x, faces[j]);
            if (faces_intersect(tf, tj) || faces_intersect(tg, tj)) return false;
        }
        return true;
    }
    // ---- end of "touch" ----

    void step(int t, const Network& net, const GrowthParams& p) {
        const int V = static_cast<int>(x.size());
        const int N = net.outputs();
        // 1. Think.
        std::vector<std::set<int>> nb(V);
        for (const Face& f : faces)
            for (int a : f)
                for (int b : f)
                    if (a != b) nb[a].insert(b);
        std::vector<std::vector<double>> next(V);
        const bool signals = !active.empty();  // §5.9's signals exist only in the branching mode
        const std::vector<double> light = signals && p.exposure ? exposure(p) : std::vector<double>{};
        for (int i = 0; i < V; ++i) {
            std::vector<double> in(3 * N);
            for (int c = 0; c < N; ++c) {
                double mean = 0;
                for (int j : nb[i]) mean += w[j][c];
                mean /= static_cast<double>(nb[i].size());
                double var = 0;
                for (int j : nb[i]) var += (w[j][c] - mean) * (w[j][c] - mean);
                var /= static_cast<double>(nb[i].size());
                in[c] = w[i][c];
                in[N + c] = mean;
                in[2 * N + c] = std::sqrt(var);
            }
            in[3 * N - 4] = 0.5 + 0.5 * h[i].x();
            in[3 * N - 3] = 0.5 + 0.5 * h[i].y();
            in[3 * N - 2] = 0.5 + 0.5 * h[i].z();
            in[3 * N - 1] = x[i].z() / p.height_scale;
            if (!active.empty()) in[3 * N - 5] = active[i];
            if (!light.empty()) in[3 * N - 6] = light[i];
            next[i] = net.evaluate_reference(in);
        }
        w = next;
        if (signals && p.signal_diffusion > 0) diffuse(nb, p.signal_diffusion, p.signal_rate);
        if (!active.empty()) branch(nb, p.turn_rate);
        // 2. Move (a dormant vertex does not move, nor one that touched: §5.7.1).
        const std::vector<Vec3> before_move = x;
        const auto d = [&](int i) {
            if (!active.empty() && active[i] == 0) return 0.0;
            if (touched_at(i)) return 0.0;
            return std::max(0.0, w[i][0] - 0.5);
        };
        double S = 0;
        for (int i = 0; i < V; ++i) S += d(i);
        if (S > 0) {
            const double k = std::min(p.speed, p.budget / S);
            for (int i = 0; i < V; ++i) x[i] += k * d(i) * h[i];
        }
        if (p.ground)
            for (Vec3& q : x) q.z() = std::max(q.z(), 0.0);
        if (p.collisions == Collisions::touch) settle_contacts(before_move, nb, p.contact_distance);
        // 3. Split.
        const int F0 = static_cast<int>(faces.size());
        for (int f = 0; f < F0; ++f) {
            const auto [a, b, c] = faces[f];
            const Vec3 n = (x[b] - x[a]).cross(x[c] - x[a]);
            const double area = 0.5 * n.norm();
            if (!(static_cast<int>(x.size()) < p.max_vertices &&
                  area > p.split_area * (0.5 + (w[a][1] + w[b][1] + w[c][1]) / 3.0)))
                continue;
            const int v = static_cast<int>(x.size());
            x.push_back((x[a] + x[b] + x[c]) / 3.0);
            std::vector<double> wv(N);
            for (int k = 0; k < N; ++k) wv[k] = (w[a][k] + w[b][k] + w[c][k]) / 3.0;
            w.push_back(wv);
            const Vec3 nf = n.normalized();
            const Vec3 sum = nf + w[a][2] * h[a] + w[b][2] * h[b] + w[c][2] * h[c];
            h.push_back(sum.norm() < 1e-12 ? nf : Vec3(sum.normalized()));
            if (!active.empty()) active.push_back(active[a] && active[b] && active[c] ? 1 : 0);
            if (!touched.empty()) touched.push_back(touched[a] || touched[b] || touched[c] ? 1 : 0);
            faces[f] = {a, b, v};
            faces.push_back({b, c, v});
            faces.push_back({c, a, v});
        }
        // 4. Flip.
        if ((t + 1) % p.flip_every != 0) return;
        const double min_dot = std::cos(p.flip_max_angle_deg * std::numbers::pi / 180.0);
        std::map<std::pair<int, int>, int> edge_face;  // directed edge -> face
        std::vector<int> valence(x.size(), 0);
        for (int f = 0; f < static_cast<int>(faces.size()); ++f)
            for (int k = 0; k < 3; ++k) {
                edge_face[{faces[f][k], faces[f][(k + 1) % 3]}] = f;
                ++valence[faces[f][k]];
            }
        for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
            for (int e = 0; e < 3; ++e) {
                const int B = faces[f][e], D = faces[f][(e + 1) % 3], A = faces[f][(e + 2) % 3];
                const int g = edge_face.at({D, B});
                int C = -1;
                for (int k = 0; k < 3; ++k)
                    if (faces[g][k] != D && faces[g][k] != B) C = faces[g][k];
                if (!(f < g)) continue;
                if (!((x[A] - x[C]).norm() < (x[B] - x[D]).norm())) continue;
                const Vec3 c1 = (x[B] - x[A]).cross(x[D] - x[A]);
                const Vec3 c2 = (x[C] - x[B]).cross(x[D] - x[B]);
                if (c1.norm() == 0 || c2.norm() == 0) continue;
                const Vec3 n1 = c1.normalized(), n2 = c2.normalized();
                if (!(n1.dot(n2) >= min_dot)) continue;
                if (!((x[B] - x[A]).cross(x[C] - x[A]).dot(n1 + n2) > 0)) continue;
                if (!((x[D] - x[C]).cross(x[A] - x[C]).dot(n1 + n2) > 0)) continue;
                if (!(valence[B] > p.min_valence && valence[D] > p.min_valence)) continue;
                if (edge_face.count({A, C}) || edge_face.count({C, A})) continue;
                if (p.collisions == Collisions::touch && !contact_flip_allowed(f, g, {A, B, C}, {C, D, A})) continue;
                for (int k = 0; k < 3; ++k) {
                    edge_face.erase({faces[f][k], faces[f][(k + 1) % 3]});
                    edge_face.erase({faces[g][k], faces[g][(k + 1) % 3]});
                }
                faces[f] = {A, B, C};
                faces[g] = {C, D, A};
                for (int k = 0; k < 3; ++k) {
                    edge_face[{faces[f][k], faces[f][(k + 1) % 3]}] = f;
                    edge_face[{faces[g][k], faces[g][(k + 1) % 3]}] = g;
                }
                --valence[B];
                --valence[D];
                ++valence[A];
                ++valence[C];
            }
        }
    }
};

}  // namespace morphogen::testing
