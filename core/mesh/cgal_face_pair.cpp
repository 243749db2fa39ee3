// The exact half of core/mesh/face_pair.hpp: the predicates CGAL's
// does_self_intersect uses (CGAL/Polygon_mesh_processing/self_intersections.h,
// do_faces_intersect), on the same kernel, so both sides decide alike.
#include "core/mesh/face_pair.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

namespace morphogen::exact {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using Segment3 = Kernel::Segment_3;

Point3 point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
}  // namespace

bool triangles_intersect(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
    return CGAL::do_intersect(Triangle3(point(a[0]), point(a[1]), point(a[2])),
                              Triangle3(point(b[0]), point(b[1]), point(b[2])));
}

bool shared_vertex_pair_intersects(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const Point3 pv = point(v), pa = point(a), pb = point(b), pc = point(c), pd = point(d);
    return CGAL::do_intersect(Triangle3(pv, pa, pb), Segment3(pc, pd)) ||
           CGAL::do_intersect(Triangle3(pv, pc, pd), Segment3(pa, pb));
}

bool shared_edge_pair_folds(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
    const Point3 pp = point(p), pq = point(q), pr = point(r), ps = point(s);
    return CGAL::coplanar(pp, pq, pr, ps) && CGAL::coplanar_orientation(pp, pq, pr, ps) == CGAL::POSITIVE;
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) { return CGAL::collinear(point(a), point(b), point(c)); }

}  // namespace morphogen::exact
