#pragma once
// Closed, outward-oriented triangle meshes of implicit shapes (field < 0
// inside), by marching tetrahedra over a grid: each cube is cut into the six
// tetrahedra around its main diagonal (the same cut in every cube, so
// neighbours agree and the surface closes), each tetrahedron edge whose ends
// differ in sign gets one vertex (shared by every tetrahedron on that edge),
// and the tetrahedron's cut is one triangle or a quad of two. Plus signed
// distance functions of simple solids and a smooth union to compose plants.
#include "core/mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace morphogen::testing {

using Field = std::function<double(const Vec3&)>;

// The surface field = 0 sampled on a grid of spacing h over the box [lo, hi];
// the field must be positive on the box's boundary (throws otherwise), so the
// surface is closed. A node's value within 1e-9 of 0 is moved to +1e-9 so no
// vertex lands on a node and every triangle has three distinct vertices.
inline MeshArrays implicit_mesh(const Field& field, const Vec3& lo, const Vec3& hi, double h) {
    const int nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / h)) + 1;
    const int ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / h)) + 1;
    const int nz = static_cast<int>(std::ceil((hi.z() - lo.z()) / h)) + 1;
    auto id = [&](int i, int j, int k) { return (static_cast<std::int64_t>(k) * ny + j) * nx + i; };
    auto at = [&](std::int64_t n) {
        const std::int64_t i = n % nx, j = n / nx % ny, k = n / (static_cast<std::int64_t>(nx) * ny);
        return Vec3(lo.x() + static_cast<double>(i) * h, lo.y() + static_cast<double>(j) * h,
                    lo.z() + static_cast<double>(k) * h);
    };
    std::vector<double> value(static_cast<std::size_t>(nx) * ny * nz);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                double f = field(at(id(i, j, k)));
                if (std::abs(f) < 1e-9) f = 1e-9;
                const bool boundary = i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1;
                if (boundary && f < 0) throw std::invalid_argument("implicit_mesh: the shape reaches the box");
                value[id(i, j, k)] = f;
            }

    MeshArrays mesh;
    std::unordered_map<std::int64_t, int> edge_vertex;  // grid edge (a * nodes + b, a < b) -> vertex
    const std::int64_t nodes = static_cast<std::int64_t>(value.size());
    auto vertex_on = [&](std::int64_t a, std::int64_t b) {
        if (a > b) std::swap(a, b);
        const auto [it, fresh] = edge_vertex.emplace(a * nodes + b, static_cast<int>(mesh.positions.size()));
        if (fresh) {
            const double t = value[a] / (value[a] - value[b]);
            mesh.positions.push_back(at(a) + t * (at(b) - at(a)));
        }
        return it->second;
    };
    // Appends the polygon (3 or 4 vertices, in cyclic order) facing from `inside` towards `outside`.
    auto emit = [&](std::vector<int> polygon, const Vec3& inside, const Vec3& outside) {
        const Vec3& p0 = mesh.positions[polygon[0]];
        Vec3 normal = Vec3::Zero();
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
            normal += (mesh.positions[polygon[i]] - p0).cross(mesh.positions[polygon[i + 1]] - p0);
        if (normal.dot(outside - inside) < 0) std::reverse(polygon.begin(), polygon.end());
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i) mesh.faces.push_back({polygon[0], polygon[i], polygon[i + 1]});
    };
    static constexpr std::array<std::array<int, 4>, 6> kTets = {
        {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};
    for (int k = 0; k + 1 < nz; ++k)
        for (int j = 0; j + 1 < ny; ++j)
            for (int i = 0; i + 1 < nx; ++i)
                for (const auto& tet : kTets) {
                    std::vector<std::int64_t> in, out;
                    for (int corner : tet) {
                        const std::int64_t n = id(i + (corner & 1), j + (corner >> 1 & 1), k + (corner >> 2 & 1));
                        (value[n] < 0 ? in : out).push_back(n);
                    }
                    if (in.empty() || out.empty()) continue;
                    Vec3 inside = Vec3::Zero(), outside = Vec3::Zero();
                    for (auto n : in) inside += at(n) / static_cast<double>(in.size());
                    for (auto n : out) outside += at(n) / static_cast<double>(out.size());
                    if (in.size() == 2)
                        emit({vertex_on(in[0], out[0]), vertex_on(in[0], out[1]), vertex_on(in[1], out[1]),
                              vertex_on(in[1], out[0])},
                             inside, outside);
                    else if (in.size() == 1)
                        emit({vertex_on(in[0], out[0]), vertex_on(in[0], out[1]), vertex_on(in[0], out[2])}, inside,
                             outside);
                    else
                        emit({vertex_on(in[0], out[0]), vertex_on(in[1], out[0]), vertex_on(in[2], out[0])}, inside,
                             outside);
                }
    return mesh;
}

// Signed distances (negative inside).
inline double sphere_field(const Vec3& p, const Vec3& centre, double r) { return (p - centre).norm() - r; }

inline double capsule_field(const Vec3& p, const Vec3& a, const Vec3& b, double r) {
    const Vec3 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * ab)).norm() - r;
}

// An upright cylinder on its flat bottom at `base`, radius r, height `height`.
inline double cylinder_field(const Vec3& p, const Vec3& base, double r, double height) {
    const double radial = std::hypot(p.x() - base.x(), p.y() - base.y()) - r;
    const double axial = std::abs(p.z() - base.z() - 0.5 * height) - 0.5 * height;
    return std::max(radial, axial);
}

// An axis-aligned ellipsoid (a bound, not a distance: fine for its zero set).
inline double ellipsoid_field(const Vec3& p, const Vec3& centre, const Vec3& radii) {
    return ((p - centre).cwiseQuotient(radii).norm() - 1.0) * radii.minCoeff();
}

// The polynomial smooth minimum: the union of two shapes with a fillet of size ~k.
inline double smooth_union(double a, double b, double k) {
    const double s = std::clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return b + (a - b) * s - k * s * (1.0 - s);
}

}  // namespace morphogen::testing
