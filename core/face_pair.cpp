// The floating-point half of core/face_pair.hpp. Every "no" it gives is
// proven: a separating direction L is found such that the two triangles'
// projections onto L are apart by more than their rounding errors. Any L
// proves separation, so L itself may be rounded; only the projections need
// error bounds. Whatever it cannot prove goes to the exact predicates.
#include "core/face_pair.hpp"

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

// One shared vertex at the origin; (a1, a2) and (b1, b2) the other corners.
bool touch_only_proven(const Vec3& a1, const Vec3& a2, const Vec3& b1, const Vec3& b2) {
    const Vec3 na = a1.cross(a2), nb = b1.cross(b2);
    for (const Vec3& axis : {na, nb, na.cross(a1), na.cross(a2), nb.cross(b1), nb.cross(b2), a1.cross(b1),
                             a1.cross(b2), a2.cross(b1), a2.cross(b2)})
        if (apart_at_origin(axis, a1, a2, b1, b2)) return true;
    return false;
}

// Edge p-q shared: proven not coplanar (the orient3d filter, Shewchuk's
// bound (7 + 56 eps) eps of the permanent, rounded up to 1e-15).
bool not_coplanar_proven(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
    const Vec3 u = q - p, v = r - p, w = s - p;
    const double det = w.dot(u.cross(v));
    const Vec3 ua = u.cwiseAbs(), va = v.cwiseAbs();
    const Vec3 permanent_cross(ua.y() * va.z() + ua.z() * va.y(), ua.z() * va.x() + ua.x() * va.z(),
                               ua.x() * va.y() + ua.y() * va.x());
    return std::abs(det) > 1e-15 * w.cwiseAbs().dot(permanent_cross);
}

}  // namespace

bool triangle_degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
    // A component of the cross product clearly nonzero proves a, b, c are not collinear.
    const Vec3 u = b - a, v = c - a;
    const Vec3 cross = u.cross(v);
    const Vec3 ua = u.cwiseAbs(), va = v.cwiseAbs();
    const Vec3 bound(ua.y() * va.z() + ua.z() * va.y(), ua.z() * va.x() + ua.x() * va.z(),
                     ua.x() * va.y() + ua.y() * va.x());
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
        const Vec3& o = a.p[0];
        const Corners ra{Vec3::Zero(), a.p[1] - o, a.p[2] - o}, rb{b.p[0] - o, b.p[1] - o, b.p[2] - o};
        return !disjoint_proven(ra, rb) && (degenerate() || exact::triangles_intersect(a.p, b.p));
    }
    if (shared == 1) {
        const int i = ia[0] >= 0 ? 0 : ia[1] >= 0 ? 1 : 2, j = ia[i];
        const Vec3& v = a.p[i];
        const Vec3 &a1 = a.p[(i + 1) % 3], &a2 = a.p[(i + 2) % 3], &b1 = b.p[(j + 1) % 3], &b2 = b.p[(j + 2) % 3];
        if (touch_only_proven(a1 - v, a2 - v, b1 - v, b2 - v)) return false;
        return degenerate() || exact::shared_vertex_pair_intersects(v, a1, a2, b1, b2);
    }
    if (shared == 2) {
        const int r = ia[0] < 0 ? 0 : ia[1] < 0 ? 1 : 2;  // a's unshared corner
        int s = 0;
        while (b.v[s] == a.v[(r + 1) % 3] || b.v[s] == a.v[(r + 2) % 3]) ++s;
        const Vec3 &p = a.p[(r + 1) % 3], &q = a.p[(r + 2) % 3];
        if (not_coplanar_proven(p, q, a.p[r], b.p[s])) return false;
        return degenerate() || exact::shared_edge_pair_folds(p, q, a.p[r], b.p[s]);
    }
    return false;  // the same face
}

}  // namespace morphogen
