#include "measures.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace morphogen {

void check_mesh_view(MeshView mesh) {
    const auto n = static_cast<long long>(mesh.positions.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        for (int v : mesh.faces[f]) {
            if (v < 0 || v >= n)
                throw std::invalid_argument("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                            " of " + std::to_string(n));
        }
    }
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (!mesh.positions[v].allFinite())
            throw std::invalid_argument("vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
}

double mesh_height(MeshView mesh) {
    if (mesh.positions.empty()) throw std::invalid_argument("height of a mesh without vertices");
    double top = -std::numeric_limits<double>::infinity();
    for (const Vec3& p : mesh.positions) top = std::max(top, p.z());
    return top;
}

double mesh_footprint(MeshView mesh) {
    using P = std::pair<double, double>;
    std::vector<P> points;
    points.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x(), p.y());
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return 0.0;
    auto cross = [](const P& o, const P& a, const P& b) {
        return (a.first - o.first) * (b.second - o.second) - (a.second - o.second) * (b.first - o.first);
    };
    // Andrew's monotone chain: lower hull then upper hull, counter-clockwise.
    std::vector<P> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);  // the last point repeats the first
    double twice = 0.0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const P& a = hull[i];
        const P& b = hull[(i + 1) % hull.size()];
        twice += a.first * b.second - b.first * a.second;
    }
    return 0.5 * std::abs(twice);
}

double mesh_area(MeshView mesh) {
    double sum = 0.0;
    for (const Face& f : mesh.faces) {
        const Vec3& a = mesh.positions[f[0]];
        sum += 0.5 * (mesh.positions[f[1]] - a).cross(mesh.positions[f[2]] - a).norm();
    }
    return sum;
}

double mesh_volume(MeshView mesh) {
    double sum = 0.0;
    for (const Face& f : mesh.faces)
        sum += mesh.positions[f[0]].dot(mesh.positions[f[1]].cross(mesh.positions[f[2]]));
    return sum / 6.0;
}

}  // namespace morphogen
