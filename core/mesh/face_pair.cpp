// The floating-point half of core/mesh/face_pair.hpp. Every "no" it gives is
// proven: a separating direction L is found such that the two triangles'
// projections onto L are apart by more than their rounding errors. Any L
// proves separation, so L itself may be rounded; only the projections need
// error bounds. Whatever it cannot prove goes to the exact predicates.
#include "core/mesh/face_pair.hpp"

#include <initializer_list>
#include <limits>

namespace morphogen {

namespace {

// |fl(L . fl(p - o)) - L . (p - o)| <= kProjectionError * sum_i |L_i| |fl(p - o)_i|:
// one rounding in each difference, three in the dot product (gamma_3 plus
// the difference's epsilon, about 4.5 epsilon); doubled for margin.
constexpr double kProjectionError = 10 * std::numeric_limits<double>::epsilon();

struct Interval {
    double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
    void add(const Vec3& axis, const Vec3& q) {
        const double value = axis.dot(q);
        const double error = kProjectionError * axis.cwiseAbs().dot(q.cwiseAbs());
        lo = std::min(lo, value - error);
        hi = std::max(hi, value + error);
    }
};

// u x v with every product taken in absolute value: the scale of the
// rounding error of u x v, component by component.
Vec3 cross_abs(const Vec3& u, const Vec3& v) {
    const Vec3 ua = u.cwiseAbs(), va = v.cwiseAbs();
    return {ua.y() * va.z() + ua.z() * va.y(), ua.z() * va.x() + ua.x() * va.z(), ua.x() * va.y() + ua.y() * va.x()};
}

// Corners relative to an origin o (rounded once each): keeps the products
// small where the triangles are far from the coordinate origin.
using Corners = std::array<Vec3, 3>;

// Proven: every corner of `a` lies strictly below every corner of `b` along
// `axis`, or the other way round.
bool apart(const Vec3& axis, const Corners& a, const Corners& b) {
    Interval ia, ib;
    for (const Vec3& q : a) ia.add(axis, q);
    for (const Vec3& q : b) ib.add(axis, q);
    return ia.hi < ib.lo || ib.hi < ia.lo;
}

// Proven: along `axis`, a's corners other than the origin (the shared vertex,
// projecting to exactly 0) lie strictly on one side of 0 and b's strictly on
// the other, so the triangles meet in the shared vertex alone.
bool apart_at_origin(const Vec3& axis, const Vec3& a1, const Vec3& a2, const Vec3& b1, const Vec3& b2) {
    Interval ia, ib;
    ia.add(axis, a1);
    ia.add(axis, a2);
    ib.add(axis, b1);
    ib.add(axis, b2);
    return (ia.hi < 0.0 && ib.lo > 0.0) || (ib.hi < 0.0 && ia.lo > 0.0);
}

// No shared vertex: the separating axis theorem's candidates, cheapest and
// likeliest first (the two planes, then the in-plane edge normals that part
// nearly coplanar neighbours, then the edge-edge directions).
bool disjoint_proven(const Corners& a, const Corners& b) {
    const Vec3 ea[3] = {a[1] - a[0], a[2] - a[1], a[0] - a[2]};
    const Vec3 eb[3] = {b[1] - b[0], b[2] - b[1], b[0] - b[2]};
    const Vec3 na = ea[0].cross(ea[1]), nb = eb[0].cross(eb[1]);
    if (apart(na, a, b) || apart(nb, a, b)) return true;
    for (const Vec3& e : ea)
        if (apart(na.cross(e), a, b)) return true;
    for (const Vec3& e : eb)
        if (apart(nb.cross(e), a, b)) return true;
    for (const Vec3& e : ea)
        for (const Vec3& f : eb)
            if (apart(e.cross(f), a, b)) return true;
    return false;
}

Vec3 unit(const Vec3& v) {
    const double length = v.norm();
    return length > 0.0 ? Vec3(v / length) : v;
}

// One shared vertex at the origin; (a1, a2) and (b1, b2) the other corners.
// Proven if a line through the origin in the mean plane, along the bisector
// of a gap between the two fans' edges, parts them (nearly flat fans, which
// no face's plane parts).
bool touch_only_proven(const Vec3& a1, const Vec3& a2, const Vec3& b1, const Vec3& b2) {
    const Vec3 normal = unit(a1.cross(a2)) + unit(b1.cross(b2));
    const Vec3 ua1 = unit(a1), ua2 = unit(a2), ub1 = unit(b1), ub2 = unit(b2);
    for (const Vec3 gap : {ua2 + ub1, ua1 + ub2, ua1 + ub1, ua2 + ub2})
        if (apart_at_origin(normal.cross(gap), a1, a2, b1, b2)) return true;
    return false;
}

// Edge p-q shared, r and s the third corners (all relative to p): proven
// not to fold onto each other because r and s lie on opposite sides of the
// edge in the faces' mean plane (for nearly coplanar faces).
bool no_fold_proven(const Vec3& q, const Vec3& r, const Vec3& s) {
    const Vec3 across = (unit(q.cross(r)) + unit(s.cross(q))).cross(q);
    Interval ir, is;
    ir.add(across, r);
    is.add(across, s);
    return (ir.hi < 0.0 && is.lo > 0.0) || (is.hi < 0.0 && ir.lo > 0.0);
}

// The proven side of `point` relative to t's plane (orient3d against its
// corners), or 0 if the filter cannot tell.
int plane_side(const IndexedTriangle& t, const Vec3& point) {
    const Vec3 w = point - t.p[0];
    const double det = w.dot(t.normal), bound = 1e-15 * w.cwiseAbs().dot(t.normal_abs);
    return det > bound ? 1 : det < -bound ? -1 : 0;
}

// Proven: these corners of `b` lie strictly on one side of a's plane.
bool beside_plane(const IndexedTriangle& a, std::initializer_list<const Vec3*> corners) {
    int side = 0;
    for (const Vec3* c : corners) {
        const int s = plane_side(a, *c);
        if (s == 0 || (side != 0 && s != side)) return false;
        side = s;
    }
    return true;
}

}  // namespace

IndexedTriangle IndexedTriangle::of(const std::vector<Vec3>& positions, const Face& f) {
    IndexedTriangle t{f, {positions[f[0]], positions[f[1]], positions[f[2]]}, {}, {}};
    const Vec3 u = t.p[1] - t.p[0], v = t.p[2] - t.p[0];
    t.normal = u.cross(v);
    t.normal_abs = cross_abs(u, v);
    return t;
}

bool triangle_degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
    // A component of the cross product clearly nonzero proves a, b, c are
    // not collinear (each is a 2x2 determinant: bound 1e-15 of its products).
    const Vec3 u = b - a, v = c - a;
    const Vec3 cross = u.cross(v), bound = cross_abs(u, v);
    for (int k = 0; k < 3; ++k)
        if (std::abs(cross[k]) > 1e-15 * bound[k]) return false;
    return exact::collinear(a, b, c);
}

bool faces_intersect(const IndexedTriangle& a, const IndexedTriangle& b) {
    // Which corners are shared: ia[k] = index in b of a's corner k, or -1.
    int ia[3], shared = 0;
    for (int i = 0; i < 3; ++i) {
        ia[i] = -1;
        for (int j = 0; j < 3; ++j)
            if (a.v[i] == b.v[j]) ia[i] = j;
        shared += ia[i] >= 0;
    }
    // Before an exact test: a degenerate face has no sides
    // to compare (CGAL's predicates require none; does_self_intersect reports
    // it on its own), so the pair counts as intersecting.
    const auto degenerate = [&] {
        return triangle_degenerate(a.p[0], a.p[1], a.p[2]) || triangle_degenerate(b.p[0], b.p[1], b.p[2]);
    };
    if (shared == 0) {
        if (beside_plane(a, {&b.p[0], &b.p[1], &b.p[2]}) || beside_plane(b, {&a.p[0], &a.p[1], &a.p[2]}))
            return false;
        const Vec3& o = a.p[0];
        const Corners ra{Vec3::Zero(), a.p[1] - o, a.p[2] - o}, rb{b.p[0] - o, b.p[1] - o, b.p[2] - o};
        return !disjoint_proven(ra, rb) && (degenerate() || exact::triangles_intersect(a.p, b.p));
    }
    if (shared == 1) {
        const int i = ia[0] >= 0 ? 0 : ia[1] >= 0 ? 1 : 2, j = ia[i];
        const Vec3& v = a.p[i];
        const Vec3 &a1 = a.p[(i + 1) % 3], &a2 = a.p[(i + 2) % 3], &b1 = b.p[(j + 1) % 3], &b2 = b.p[(j + 2) % 3];
        if (beside_plane(a, {&b1, &b2}) || beside_plane(b, {&a1, &a2})) return false;
        if (touch_only_proven(a1 - v, a2 - v, b1 - v, b2 - v)) return false;
        return degenerate() || exact::shared_vertex_pair_intersects(v, a1, a2, b1, b2);
    }
    if (shared == 2) {
        const int r = ia[0] < 0 ? 0 : ia[1] < 0 ? 1 : 2;  // a's unshared corner
        int s = 0;
        while (b.v[s] == a.v[(r + 1) % 3] || b.v[s] == a.v[(r + 2) % 3]) ++s;
        const Vec3 &p = a.p[(r + 1) % 3], &q = a.p[(r + 2) % 3];
        if (plane_side(a, b.p[s]) != 0 || no_fold_proven(q - p, a.p[r] - p, b.p[s] - p)) return false;
        return degenerate() || exact::shared_edge_pair_folds(p, q, a.p[r], b.p[s]);
    }
    return false;  // the same face
}

}  // namespace morphogen
