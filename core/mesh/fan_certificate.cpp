#include "core/mesh/fan_certificate.hpp"

#include <span>

namespace morphogen {

namespace {

// u x v with every product taken in absolute value: the scale of the
// rounding error of u x v, component by component.
Vec3 cross_abs(const Vec3& u, const Vec3& v) {
    const Vec3 ua = u.cwiseAbs(), va = v.cwiseAbs();
    return {ua.y() * va.z() + ua.z() * va.y(), ua.z() * va.x() + ua.x() * va.z(), ua.x() * va.y() + ua.y() * va.x()};
}

// The sign of `value` when |value| > bound, else 0 (cannot tell).
int certain_sign(double value, double bound) { return value > bound ? 1 : value < -bound ? -1 : 0; }

// Where a spoke lies around v, in eighths of a turn counted from r
// (even: inside a quarter, odd: on the line between two), or -1 where the
// signs cannot tell or the spoke may lie along r itself. s1 is the side of r
// it lies on, s2 the side of r rotated by a quarter turn (both seen along N).
int octant(int s1, int s2) {
    if (s1 > 0) return s2 < 0 ? 0 : s2 == 0 ? 1 : 2;
    if (s1 < 0) return s2 > 0 ? 4 : s2 == 0 ? 5 : 6;
    return s2 > 0 ? 3 : -1;
}

}  // namespace

namespace {

// The certificate for one direction N (any vector: the proof holds for the
// exact N it is given).
bool certified_along(const Vec3& normal, std::span<const Vec3> spokes, std::span<const Vec3> crosses) {
    const std::size_t n = spokes.size();
    const Vec3 normal_abs = normal.cwiseAbs();
    // Every face positively oriented along N: N . (e_k x e_k+1) > 0. The
    // bound covers the rounding of the spokes (u - v), of the cross product
    // and of the dot product (about 8 epsilon; 45 allowed).
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3& a = spokes[k];
        const Vec3& b = spokes[k + 1 == n ? 0 : k + 1];
        if (certain_sign(normal.dot(crosses[k]), 1e-14 * normal_abs.dot(cross_abs(a, b))) <= 0) return false;
    }
    // Every turn from one spoke to the next is then in (0, pi); the ring winds
    // once iff, counted from a direction r inside face 0's angle, the spokes
    // e_1 .. e_n-1, e_0 go round without passing r again: their octants
    // never decrease. (Winding twice, some step would pass from octant >= 3
    // to one <= 3 past r, never both 3: that step would turn by a full pi.)
    // Sides are read as e . R1 and e . R2 with R1 = N x r, R2 = N x R1: for
    // the exact R1, R2 these are N . (r x e) and -|N|^2 (r_p . e_p). The
    // bound covers the rounding of R1 and R2 (a few epsilon of |N|_1 |r|_1
    // and |N|_1^2 |r|_1), of e and of the dot product, with a wide margin.
    const Vec3 r = spokes[0] + spokes[1];
    const Vec3 r1 = normal.cross(r), r2 = normal.cross(r1);
    const double scale1 = 1e-12 * normal.lpNorm<1>() * r.lpNorm<1>();
    const double scale2 = scale1 * normal.lpNorm<1>();
    const auto place = [&](const Vec3& e, int& s1) {
        const double e1 = e.lpNorm<1>();
        s1 = certain_sign(e.dot(r1), scale1 * e1);
        return octant(s1, certain_sign(e.dot(r2), scale2 * e1));
    };
    int s1 = 0;
    int last = place(spokes[1], s1);
    if (last < 0 || s1 <= 0) return false;  // e_1 to the left of r
    for (std::size_t k = 2; k <= n; ++k) {
        const int now = place(spokes[k == n ? 0 : k], s1);
        if (now < last) return false;  // also now == -1
        last = now;
    }
    return s1 < 0;  // e_0 to the right of r: r lies inside face 0's angle
}

}  // namespace

bool fan_certified(const TriMesh& mesh, int v, std::vector<Vec3>& scratch) {
    const std::vector<Vec3>& x = mesh.positions();
    const Vec3 centre = x[v];
    scratch.clear();
    mesh.for_each_neighbour(v, [&](int u) { scratch.push_back(x[u] - centre); });
    const std::size_t n = scratch.size();
    if (n < 3) return false;
    // The spokes, then each face's cross product e_k x e_k+1 (computed once).
    scratch.resize(2 * n);
    for (std::size_t k = 0; k < n; ++k) scratch[n + k] = scratch[k].cross(scratch[k + 1 == n ? 0 : k + 1]);
    const std::span<const Vec3> spokes(scratch.data(), n), crosses(scratch.data() + n, n);
    // N: the faces' cross products summed (their area-weighted normal), or,
    // where a large face outweighs a fold (a ridge between faces of unequal
    // size), their unit normals summed.
    Vec3 area_weighted = Vec3::Zero(), unit_sum = Vec3::Zero();
    for (std::size_t k = 0; k < n; ++k) area_weighted += crosses[k];
    if (certified_along(area_weighted, spokes, crosses)) return true;
    for (std::size_t k = 0; k < n; ++k) {
        const double length = crosses[k].norm();
        if (length > 0.0) unit_sum += crosses[k] / length;
    }
    return certified_along(unit_sum, spokes, crosses);
}

}  // namespace morphogen
