// Points inside a plant's body (see body_inside.hpp).
#include "engine/body_inside.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace morphogen {

BodyInside::BodyInside(MeshView mesh, double column) : mesh_(mesh), column_(column) {
    if (!(column > 0.0) || !std::isfinite(column)) throw std::invalid_argument("BodyInside: column must be positive");
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
        for (const int v : mesh.faces[f]) {
            const Vec3& p = mesh.positions[static_cast<std::size_t>(v)];
            lo_x = std::min(lo_x, p.x()), hi_x = std::max(hi_x, p.x());
            lo_y = std::min(lo_y, p.y()), hi_y = std::max(hi_y, p.y());
        }
        for (long long i = cell(lo_x); i <= cell(hi_x); ++i)
            for (long long j = cell(lo_y); j <= cell(hi_y); ++j) columns_[{i, j}].push_back(static_cast<int>(f));
    }
}

long long BodyInside::cell(double x) const { return static_cast<long long>(std::floor(x / column_)); }

std::size_t BodyInside::ColumnHash::operator()(const Column& c) const noexcept {
    return std::hash<long long>{}(c.first) * 0x9E3779B97F4A7C15ull + std::hash<long long>{}(c.second);
}

int BodyInside::winding(const Vec3& p) const {
    const auto found = columns_.find({cell(p.x()), cell(p.y())});
    if (found == columns_.end()) return 0;
    int winding = 0;
    for (const int f : found->second) {
        const Face& face = mesh_.faces[static_cast<std::size_t>(f)];
        const Vec3& a = mesh_.positions[static_cast<std::size_t>(face[0])];
        const Vec3& b = mesh_.positions[static_cast<std::size_t>(face[1])];
        const Vec3& c = mesh_.positions[static_cast<std::size_t>(face[2])];
        // Barycentric coordinates of (p.x, p.y) in the face's x-y projection.
        const double area = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
        if (area == 0.0) continue;  // a vertical face: the ray grazes it
        const double u = ((b.x() - p.x()) * (c.y() - p.y()) - (c.x() - p.x()) * (b.y() - p.y())) / area;
        const double v = ((c.x() - p.x()) * (a.y() - p.y()) - (a.x() - p.x()) * (c.y() - p.y())) / area;
        const double w = 1.0 - u - v;
        if (u < 0.0 || v < 0.0 || w < 0.0) continue;
        if (u * a.z() + v * b.z() + w * c.z() <= p.z()) continue;  // below the point
        winding += area > 0.0 ? 1 : -1;  // counter-clockwise seen from above: the normal points up
    }
    return winding;
}

}  // namespace morphogen
