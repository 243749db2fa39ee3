// Points inside a plant's body (see body_inside.hpp).
#include "engine/body_inside.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace morphogen {

namespace {

struct Entry {
    std::pair<long long, long long> column;
    int face;
};

// In order of column, then face. A counting sort over the grid of columns
// the faces touch where that grid is not much larger than the list (a plant:
// about 5 entries a face over some 1,000 columns); a comparison sort else.
void sort_by_column(std::vector<Entry>& entries) {
    if (entries.empty()) return;
    long long lo_i = entries[0].column.first, hi_i = lo_i, lo_j = entries[0].column.second, hi_j = lo_j;
    for (const Entry& e : entries) {
        lo_i = std::min(lo_i, e.column.first), hi_i = std::max(hi_i, e.column.first);
        lo_j = std::min(lo_j, e.column.second), hi_j = std::max(hi_j, e.column.second);
    }
    const double cells = (static_cast<double>(hi_i) - lo_i + 1) * (static_cast<double>(hi_j) - lo_j + 1);
    if (!(cells <= 8.0 * static_cast<double>(entries.size()) + 4096)) {
        std::ranges::sort(entries, [](const Entry& a, const Entry& b) {
            return std::tie(a.column, a.face) < std::tie(b.column, b.face);
        });
        return;
    }
    const long long rows = hi_j - lo_j + 1;
    const auto index = [&](const Entry& e) {
        return static_cast<std::size_t>((e.column.first - lo_i) * rows + (e.column.second - lo_j));
    };
    std::vector<std::size_t> start(static_cast<std::size_t>(cells) + 1, 0);
    for (const Entry& e : entries) ++start[index(e) + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<Entry> sorted(entries.size());
    for (const Entry& e : entries) sorted[start[index(e)]++] = e;  // entries come in face order: kept within a column
    entries = std::move(sorted);
}

}  // namespace

BodyInside::BodyInside(MeshView mesh, double column) : column_(column) {
    if (!(column > 0.0) || !std::isfinite(column)) throw std::invalid_argument("BodyInside: column must be positive");
    std::vector<Entry> entries;
    entries.reserve(2 * mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
        for (const int v : mesh.faces[f]) {
            const Vec3& p = mesh.positions[static_cast<std::size_t>(v)];
            lo_x = std::min(lo_x, p.x()), hi_x = std::max(hi_x, p.x());
            lo_y = std::min(lo_y, p.y()), hi_y = std::max(hi_y, p.y());
        }
        for (long long i = cell(lo_x); i <= cell(hi_x); ++i)
            for (long long j = cell(lo_y); j <= cell(hi_y); ++j) entries.push_back({{i, j}, static_cast<int>(f)});
    }
    sort_by_column(entries);
    columns_.reserve(entries.size());
    triangles_.reserve(entries.size());
    for (const Entry& e : entries) {
        const Face& face = mesh.faces[static_cast<std::size_t>(e.face)];
        const Vec3 &a = mesh.positions[static_cast<std::size_t>(face[0])],
                   &b = mesh.positions[static_cast<std::size_t>(face[1])],
                   &c = mesh.positions[static_cast<std::size_t>(face[2])];
        // Twice the signed area of the face's x-y projection; a vertical face
        // (0) is grazed by every vertical ray and never counts, so it is left out.
        const double area = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
        if (area == 0.0) continue;
        columns_.push_back(e.column);
        triangles_.push_back({a, b, c, area});
    }
}

long long BodyInside::cell(double x) const { return static_cast<long long>(std::floor(x / column_)); }

int BodyInside::winding(const Vec3& p) const {
    const auto [first, last] = std::equal_range(columns_.begin(), columns_.end(), Column{cell(p.x()), cell(p.y())});
    int winding = 0;
    for (auto it = first; it != last; ++it) {
        const auto& [a, b, c, area] = triangles_[static_cast<std::size_t>(it - columns_.begin())];
        // Barycentric coordinates of (p.x, p.y) in the face's x-y projection.
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
