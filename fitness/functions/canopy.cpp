// Canopy by z-buffer rasterisation (docs/algorithm.md §10.1). Point-in-triangle uses
// Shewchuk's filtered orientation: the double determinant's sign is trusted
// when it clears the error bound, else CGAL decides exactly (rare). So the
// edge rule is exact: a centre on a shared edge is inside both triangles, no
// centre falls through a crack, and the result equals ray shooting on CGAL's
// exact predicates (canopy_reference.cpp).
#include "fitness/functions/canopy.hpp"

#include "fitness/geometry/cgal_geometry.hpp"
#include "fitness/measures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {

constexpr double kEpsilon = 1.1102230246251565e-16;  // 2^-53, half an ulp of 1
constexpr double kOrientBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr std::int64_t kMaxCells = canopy_max_cells;
constexpr double kMaxIndex = 1e12;  // |coordinate / cell| beyond this: refuse

struct Orientation {
    double det;  // approximately twice the signed area of (a, b, c)
    int sign;    // exact sign of det
};

inline Orientation orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    const double left = (ax - cx) * (by - cy);
    const double right = (ay - cy) * (bx - cx);
    const double det = left - right;
    const auto sign_of = [](double v) { return (v > 0) - (v < 0); };
    double sum;
    if (left > 0) {
        if (right <= 0) return {det, sign_of(det)};
        sum = left + right;
    } else if (left < 0) {
        if (right >= 0) return {det, sign_of(det)};
        sum = -left - right;
    } else {
        return {det, sign_of(det)};
    }
    const double bound = kOrientBound * sum;
    if (det >= bound || -det >= bound) return {det, sign_of(det)};
    return {det, orient2d_exact(ax, ay, bx, by, cx, cy)};
}

// Smallest i with cell_centre(i) >= x / largest with cell_centre(i) <= x,
// exact with respect to the rounded centres that are tested.
std::int64_t first_centre_from(double x, double cell) {
    auto i = static_cast<std::int64_t>(std::floor(x / cell - 0.5));
    while (cell_centre(i, cell) < x) ++i;
    while (cell_centre(i - 1, cell) >= x) --i;
    return i;
}
std::int64_t last_centre_to(double x, double cell) {
    auto i = static_cast<std::int64_t>(std::ceil(x / cell - 0.5));
    while (cell_centre(i, cell) > x) --i;
    while (cell_centre(i + 1, cell) <= x) ++i;
    return i;
}

// A triangle above the height with its projection counter-clockwise.
struct Candidate {
    double x[3], y[3], z[3];
};

// Unnormalised barycentric weights of a point in a candidate's projection.
struct Weights {
    double a, b, c;
    // The candidate's height at the point.
    double z(const Candidate& t) const { return (a * t.z[0] + b * t.z[1] + c * t.z[2]) / (a + b + c); }
};

// Whether (px, py) lies in t's projection (a point on an edge counts as
// inside); if so `w` gets its weights. Exact signs, so the canopy and its tops
// agree on every cell.
inline bool covers(const Candidate& t, double px, double py, Weights& w) {
    const Orientation wa = orient2d(t.x[1], t.y[1], t.x[2], t.y[2], px, py);
    if (wa.sign < 0) return false;
    const Orientation wb = orient2d(t.x[2], t.y[2], t.x[0], t.y[0], px, py);
    if (wb.sign < 0) return false;
    const Orientation wc = orient2d(t.x[0], t.y[0], t.x[1], t.y[1], px, py);
    if (wc.sign < 0) return false;
    w = {wa.det, wb.det, wc.det};
    return true;
}

struct Grid {
    std::int64_t i0 = 0, j0 = 0, width = 0, rows = 0;
    std::vector<std::uint8_t> marked;  // row-major, width x rows
};

std::vector<Candidate> candidates(MeshView mesh, double height) {
    std::vector<Candidate> out;
    for (const Face& f : mesh.faces) {
        const Vec3& a = mesh.positions[f[0]];
        const Vec3& b = mesh.positions[f[1]];
        const Vec3& c = mesh.positions[f[2]];
        if (!(std::max({a.z(), b.z(), c.z()}) > height)) continue;
        const int sign = orient2d(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()).sign;
        if (sign == 0) continue;  // zero-area projection
        const Vec3& second = sign > 0 ? b : c;
        const Vec3& third = sign > 0 ? c : b;
        out.push_back({{a.x(), second.x(), third.x()}, {a.y(), second.y(), third.y()}, {a.z(), second.z(), third.z()}});
    }
    return out;
}

void mark_triangle(const Candidate& t, double height, double cell, Grid& grid) {
    const double xmin = std::min({t.x[0], t.x[1], t.x[2]}), xmax = std::max({t.x[0], t.x[1], t.x[2]});
    const double ymin = std::min({t.y[0], t.y[1], t.y[2]}), ymax = std::max({t.y[0], t.y[1], t.y[2]});
    const std::int64_t ia = first_centre_from(xmin, cell), ib = last_centre_to(xmax, cell);
    const std::int64_t ja = first_centre_from(ymin, cell), jb = last_centre_to(ymax, cell);
    // Every centre of a triangle wholly above the height counts: no interpolation.
    const bool all_above = std::min({t.z[0], t.z[1], t.z[2]}) > height;
    for (std::int64_t j = ja; j <= jb; ++j) {
        const double py = cell_centre(j, cell);
        std::uint8_t* row = grid.marked.data() + (j - grid.j0) * grid.width;
        for (std::int64_t i = ia; i <= ib; ++i) {
            if (row[i - grid.i0]) continue;
            const double px = cell_centre(i, cell);
            Weights w;
            if (!covers(t, px, py, w)) continue;
            if (!all_above && !(w.z(t) > height)) continue;
            row[i - grid.i0] = 1;
        }
    }
}

// The grid covering every cell centre in the candidates' bounding box
// (`marked` left empty); throws for a grid too large to hold.
Grid grid_for(const std::vector<Candidate>& above, double cell) {
    Grid grid;
    if (above.empty()) return grid;
    double xmin = above[0].x[0], xmax = xmin, ymin = above[0].y[0], ymax = ymin;
    for (const Candidate& t : above) {
        for (int k = 0; k < 3; ++k) {
            xmin = std::min(xmin, t.x[k]), xmax = std::max(xmax, t.x[k]);
            ymin = std::min(ymin, t.y[k]), ymax = std::max(ymax, t.y[k]);
        }
    }
    const double reach = std::max({std::abs(xmin), std::abs(xmax), std::abs(ymin), std::abs(ymax)}) / cell;
    if (!(reach < kMaxIndex)) {
        char text[160];
        std::snprintf(text, sizeof text, "canopy grid index out of range: coordinates / cell reach %g (limit %g); "
                      "increase fitness.cell", reach, kMaxIndex);
        throw std::length_error(text);
    }
    grid.i0 = first_centre_from(xmin, cell);
    grid.j0 = first_centre_from(ymin, cell);
    grid.width = std::max<std::int64_t>(0, last_centre_to(xmax, cell) - grid.i0 + 1);
    grid.rows = std::max<std::int64_t>(0, last_centre_to(ymax, cell) - grid.j0 + 1);
    if (grid.width > kMaxCells || grid.rows > kMaxCells || grid.width * grid.rows > kMaxCells)
        throw std::length_error("canopy grid of " + std::to_string(grid.width) + " x " + std::to_string(grid.rows) +
                                " cells is larger than the limit of " + std::to_string(kMaxCells) +
                                " cells; increase fitness.cell");
    return grid;
}

void check_params(MeshView mesh, const CanopyParams& params) {
    check_mesh_view(mesh);
    if (!(params.cell > 0) || !std::isfinite(params.cell) || !std::isfinite(params.height))
        throw std::invalid_argument("canopy needs a finite height and a positive cell");
}

Grid rasterise(MeshView mesh, const CanopyParams& params) {
    check_params(mesh, params);
    const std::vector<Candidate> above = candidates(mesh, params.height);
    Grid grid = grid_for(above, params.cell);
    grid.marked.assign(static_cast<std::size_t>(grid.width * grid.rows), 0);
    for (const Candidate& t : above) mark_triangle(t, params.height, params.cell, grid);
    return grid;
}

// H at every centre of the grid: the highest interpolated z of the triangles
// covering it, each clamped to its triangle's z range (interpolation is a
// convex combination, so the clamp only removes rounding; it makes "H > height"
// agree exactly with mark_triangle's test). -infinity where no candidate covers.
void top_triangle(const Candidate& t, double cell, const Grid& grid, std::vector<double>& tops) {
    const double xmin = std::min({t.x[0], t.x[1], t.x[2]}), xmax = std::max({t.x[0], t.x[1], t.x[2]});
    const double ymin = std::min({t.y[0], t.y[1], t.y[2]}), ymax = std::max({t.y[0], t.y[1], t.y[2]});
    const double zmin = std::min({t.z[0], t.z[1], t.z[2]}), zmax = std::max({t.z[0], t.z[1], t.z[2]});
    const std::int64_t ia = first_centre_from(xmin, cell), ib = last_centre_to(xmax, cell);
    const std::int64_t ja = first_centre_from(ymin, cell), jb = last_centre_to(ymax, cell);
    for (std::int64_t j = ja; j <= jb; ++j) {
        const double py = cell_centre(j, cell);
        double* row = tops.data() + (j - grid.j0) * grid.width;
        for (std::int64_t i = ia; i <= ib; ++i) {
            double& top = row[i - grid.i0];
            if (top >= zmax) continue;  // this triangle cannot raise it
            const double px = cell_centre(i, cell);
            Weights w;
            if (!covers(t, px, py, w)) continue;
            top = std::max(top, std::clamp(w.z(t), zmin, zmax));
        }
    }
}

}  // namespace

double canopy_area(MeshView mesh, const CanopyParams& params) {
    const Grid grid = rasterise(mesh, params);
    const auto count = std::count(grid.marked.begin(), grid.marked.end(), std::uint8_t{1});
    return static_cast<double>(count) * params.cell * params.cell;
}

std::vector<CellIndex> canopy_cells(MeshView mesh, const CanopyParams& params) {
    const Grid grid = rasterise(mesh, params);
    std::vector<CellIndex> cells;
    for (std::int64_t r = 0; r < grid.rows; ++r)
        for (std::int64_t c = 0; c < grid.width; ++c)
            if (grid.marked[r * grid.width + c]) cells.emplace_back(grid.i0 + c, grid.j0 + r);
    std::sort(cells.begin(), cells.end());
    return cells;
}

std::vector<CanopyTop> canopy_tops(MeshView mesh, const CanopyParams& params) {
    check_params(mesh, params);
    std::vector<Candidate> above = candidates(mesh, params.height);
    // Highest triangles first, so most lower ones are skipped cell by cell
    // (a maximum does not depend on the order).
    const auto zmax = [](const Candidate& t) { return std::max({t.z[0], t.z[1], t.z[2]}); };
    std::sort(above.begin(), above.end(), [&](const Candidate& a, const Candidate& b) { return zmax(a) > zmax(b); });
    const Grid grid = grid_for(above, params.cell);
    std::vector<double> tops(static_cast<std::size_t>(grid.width * grid.rows),
                             -std::numeric_limits<double>::infinity());
    for (const Candidate& t : above) top_triangle(t, params.cell, grid, tops);
    std::vector<CanopyTop> out;
    for (std::int64_t r = 0; r < grid.rows; ++r)
        for (std::int64_t c = 0; c < grid.width; ++c)
            if (const double top = tops[r * grid.width + c]; top > params.height)
                out.push_back({{grid.i0 + c, grid.j0 + r}, top});
    std::sort(out.begin(), out.end(), [](const CanopyTop& a, const CanopyTop& b) { return a.cell < b.cell; });
    return out;
}

}  // namespace morphogen
