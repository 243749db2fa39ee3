#pragma once
// Small meshes with known answers for the fitness tests, built in code.
#include "core/mesh/mesh.hpp"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>

namespace morphogen::test {

// Closed, outward-oriented axis-aligned box [lo, hi]: 8 vertices, 12 faces.
// Vertex index = x + 2y + 4z (0 = lo, 1 = hi per axis).
inline MeshArrays make_box(const Vec3& lo, const Vec3& hi) {
    MeshArrays box;
    for (int k = 0; k < 8; ++k)
        box.positions.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    box.faces = {{0, 2, 1}, {1, 2, 3},   // bottom, -z
                 {4, 5, 6}, {5, 7, 6},   // top, +z
                 {0, 1, 5}, {0, 5, 4},   // front, -y
                 {2, 7, 3}, {2, 6, 7},   // back, +y
                 {0, 4, 6}, {0, 6, 2},   // left, -x
                 {1, 3, 7}, {1, 7, 5}};  // right, +x
    return box;
}

// An open horizontal square [x0, x1] x [y0, y1] at height z, facing up.
inline MeshArrays make_square(double x0, double y0, double x1, double y1, double z) {
    MeshArrays square;
    square.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    square.faces = {{0, 1, 2}, {0, 2, 3}};
    return square;
}

// All of b's vertices and faces appended to a.
inline MeshArrays merge(MeshArrays a, const MeshArrays& b) {
    const int offset = static_cast<int>(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (const Face& f : b.faces) a.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
    return a;
}

// Unit icosphere: an icosahedron with each face split into 4, `levels` times
// (levels 4: 2562 vertices, 5120 faces), faces oriented outward.
inline MeshArrays make_icosphere(int levels) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    MeshArrays m;
    m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& p : m.positions) p.normalize();
    m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<int, int>, int> midpoints;
        auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            m.positions.push_back((m.positions[a] + m.positions[b]).normalized());
            const int v = static_cast<int>(m.positions.size()) - 1;
            midpoints.emplace(key, v);
            return v;
        };
        std::vector<Face> finer;
        for (const Face& f : m.faces) {
            const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        m.faces = std::move(finer);
    }
    for (Face& f : m.faces) {
        const Vec3& a = m.positions[f[0]];
        const Vec3 n = (m.positions[f[1]] - a).cross(m.positions[f[2]] - a);
        if (n.dot(a + m.positions[f[1]] + m.positions[f[2]]) < 0) std::swap(f[1], f[2]);
    }
    return m;
}

// A bumpy closed blob: an icosphere with random radial displacement, random
// anisotropic scale and rotation, standing on z = 0 with its top up to ~15,
// so that many triangles cross fitness height 10 and overlap in projection.
inline MeshArrays make_bumpy(unsigned seed, int levels = 3, double roughness = 0.35) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    MeshArrays m = make_icosphere(levels);
    for (Vec3& p : m.positions) p *= 1.0 + roughness * (unit(rng) - 0.5);
    const Vec3 scale(2.0 + 4.0 * unit(rng), 2.0 + 4.0 * unit(rng), 4.0 + 3.0 * unit(rng));
    const Eigen::Matrix3d rotation =
        (Eigen::AngleAxisd(6.3 * unit(rng), Vec3::UnitZ()) * Eigen::AngleAxisd(0.4 * unit(rng), Vec3::UnitX()))
            .toRotationMatrix();
    const Vec3 shift(10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0, 0.0);
    const double top = 11.0 + 4.0 * unit(rng);
    double low = INFINITY, high = -INFINITY;
    for (Vec3& p : m.positions) {
        p = rotation * scale.cwiseProduct(p) + shift;
        low = std::min(low, p.z());
        high = std::max(high, p.z());
    }
    for (Vec3& p : m.positions) p.z() = (p.z() - low) / (high - low) * top;
    return m;
}

// A trunk [-0.5, 0.5]^2 x [0, 10] and three crowns 2 x 2 x 10 above it at
// x = -6, 0, 6: trunk_ratio sqrt(2)/sqrt(200) = 0.1, upper_loops 3,
// volume 10 + 3 * 40 = 130; under a vertical sun the crowns' tops catch 12.
inline MeshArrays three_crowned_tree() {
    MeshArrays tree = make_box({-0.5, -0.5, 0}, {0.5, 0.5, 10});
    for (double x : {-6.0, 0.0, 6.0}) tree = merge(tree, make_box({x - 1, -1, 10}, {x + 1, 1, 20}));
    return tree;
}

// The same triangles, each with its own three vertices (as an STL file, or
// one that splits vertices by normal, holds them).
inline MeshArrays unwelded(const MeshArrays& mesh) {
    MeshArrays out;
    for (const Face& f : mesh.faces) {
        const int first = static_cast<int>(out.positions.size());
        for (int v : f) out.positions.push_back(mesh.positions[v]);
        out.faces.push_back({first, first + 1, first + 2});
    }
    return out;
}

}  // namespace morphogen::test
