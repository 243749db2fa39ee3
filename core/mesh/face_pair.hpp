#pragma once
// Whether two faces of one mesh intersect, by the rule of CGAL's
// Polygon_mesh_processing::does_self_intersect (docs/algorithm.md §5.7), so
// that growth with growth.collisions "prevent" and the fitness check
// (mesh_self_intersects) agree on every pair:
//   - no shared vertex: the closed triangles intersect;
//   - one shared vertex v: the edge of either triangle opposite v meets the
//     other triangle (touching at v alone is allowed);
//   - a shared edge: the four points are coplanar and the two third vertices
//     lie on the same side of the edge (the faces fold onto each other);
//   - a degenerate face (three collinear corners) intersects by itself.
// Exact: a floating-point filter with certified error bounds decides almost
// every pair; what it cannot decide goes to CGAL's exact predicates
// (core/mesh/cgal_face_pair.cpp, the only file of mesh/ that includes CGAL).
#include "core/mesh/mesh.hpp"

#include <array>

namespace morphogen {

// A triangle by vertex indices (to find shared vertices), corner positions,
// and its plane for the filter: normal = (p1 - p0) x (p2 - p0) as rounded,
// normal_abs the same products taken in absolute value (its error scale).
struct IndexedTriangle {
    Face v;
    std::array<Vec3, 3> p;
    Vec3 normal, normal_abs;
    static IndexedTriangle of(const std::vector<Vec3>& positions, const Face& f);
};

// The rule above for two different triangles (they may share 0, 1 or 2
// vertex indices; sharing 2 means sharing that edge, as in a manifold mesh).
bool faces_intersect(const IndexedTriangle& a, const IndexedTriangle& b);
// Whether the three corners are collinear (exactly).
bool triangle_degenerate(const Vec3& a, const Vec3& b, const Vec3& c);

namespace exact {
// CGAL (Exact_predicates_inexact_constructions_kernel), exact for any input.
bool triangles_intersect(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);
// Triangle (v, a, b) and segment c-d, or triangle (v, c, d) and segment a-b.
bool shared_vertex_pair_intersects(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// Edge p-q shared, r and s the third corners: coplanar and on the same side.
bool shared_edge_pair_folds(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s);
bool collinear(const Vec3& a, const Vec3& b, const Vec3& c);
}  // namespace exact

}  // namespace morphogen
