#include "fitness/measures.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
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

namespace {
using P = std::pair<double, double>;

double cross(const P& o, const P& a, const P& b) {
    return (a.first - o.first) * (b.second - o.second) - (a.second - o.second) * (b.first - o.first);
}

// Sorted, duplicate-free xy-projections.
std::vector<P> xy_points(std::span<const Vec3> positions) {
    std::vector<P> points;
    points.reserve(positions.size());
    for (const Vec3& p : positions) points.emplace_back(p.x(), p.y());
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

// Andrew's monotone chain over sorted distinct points (at least 3): lower
// hull then upper hull, counter-clockwise, collinear points dropped.
std::vector<P> hull_of(const std::vector<P>& points) {
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
    return hull;
}

double distance2(const P& a, const P& b) {
    const double dx = a.first - b.first, dy = a.second - b.second;
    return dx * dx + dy * dy;
}
}  // namespace

double mesh_footprint(MeshView mesh) {
    const std::vector<P> points = xy_points(mesh.positions);
    if (points.size() < 3) return 0.0;
    const std::vector<P> hull = hull_of(points);
    double twice = 0.0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const P& a = hull[i];
        const P& b = hull[(i + 1) % hull.size()];
        twice += a.first * b.second - b.first * a.second;
    }
    return 0.5 * std::abs(twice);
}

double xy_width(std::span<const Vec3> positions) {
    const std::vector<P> points = xy_points(positions);
    if (points.size() < 2) return 0.0;
    if (points.size() == 2) return std::sqrt(distance2(points[0], points[1]));
    const std::vector<P> hull = hull_of(points);
    const std::size_t m = hull.size();
    if (m == 2) return std::sqrt(distance2(hull[0], hull[1]));
    // Rotating calipers: for each edge (i, i+1) advance the antipodal vertex j
    // while it gets farther from the edge's line; the diameter is among the
    // antipodal pairs. The area only rises strictly, so j cannot cycle.
    double best = 0.0;
    std::size_t j = 1;
    for (std::size_t i = 0; i < m; ++i) {
        const std::size_t next = (i + 1) % m;
        for (std::size_t steps = 0; steps < m && cross(hull[i], hull[next], hull[(j + 1) % m]) >
                                                     cross(hull[i], hull[next], hull[j]);
             ++steps)
            j = (j + 1) % m;
        best = std::max({best, distance2(hull[i], hull[j]), distance2(hull[next], hull[j])});
    }
    return std::sqrt(best);
}

double mesh_width(MeshView mesh) { return xy_width(mesh.positions); }

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
