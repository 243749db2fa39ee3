// CGAL AABB tree behind RayCaster, and the exact 2-D orientation fallback.
#include "fitness/geometry/cgal_geometry.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

namespace morphogen {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using Triangles = std::vector<Triangle3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point3 point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
Vec3 vec(const Point3& p) { return {p.x(), p.y(), p.z()}; }
}  // namespace

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
    using P2 = Kernel::Point_2;
    return static_cast<int>(CGAL::orientation(P2(ax, ay), P2(bx, by), P2(cx, cy)));
}

struct RayCaster::Impl {
    Triangles triangles;  // must outlive the tree (primitives hold iterators)
    std::vector<int> face_of;  // per triangle: its face in the mesh
    Tree tree;
};

RayCaster::RayCaster(MeshView mesh, Faces which) : impl_(std::make_unique<Impl>()) {
    impl_->triangles.reserve(mesh.faces.size());
    for (const Face& f : mesh.faces) {
        const Point3 a = point(mesh.positions[f[0]]);
        const Point3 b = point(mesh.positions[f[1]]);
        const Point3 c = point(mesh.positions[f[2]]);
        // CGAL's ray/triangle intersection requires non-degenerate triangles.
        if (CGAL::collinear(a, b, c)) continue;
        if (which == Faces::non_vertical &&
            orient2d_exact(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()) == 0)
            continue;
        impl_->triangles.emplace_back(a, b, c);
        impl_->face_of.push_back(static_cast<int>(&f - mesh.faces.data()));
    }
    impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
    // Built now: the lazy build inside a const query would race between threads.
    impl_->tree.build();
}

RayCaster::~RayCaster() = default;
RayCaster::RayCaster(RayCaster&&) noexcept = default;
RayCaster& RayCaster::operator=(RayCaster&&) noexcept = default;

int RayCaster::num_triangles() const { return static_cast<int>(impl_->triangles.size()); }

std::optional<Vec3> RayCaster::first_hit(const Vec3& origin, const Vec3& direction) const {
    const std::optional<Hit> hit = first_hit_face(origin, direction);
    if (!hit) return std::nullopt;
    return hit->point;
}

std::optional<RayCaster::Hit> RayCaster::first_hit_face(const Vec3& origin, const Vec3& direction) const {
    if (impl_->triangles.empty()) return std::nullopt;
    const Kernel::Ray_3 ray(point(origin), Kernel::Vector_3(direction.x(), direction.y(), direction.z()));
    const auto hit = impl_->tree.first_intersection(ray);
    if (!hit) return std::nullopt;
    const int face = impl_->face_of[static_cast<std::size_t>(hit->second - impl_->triangles.cbegin())];
    if (const Point3* p = boost::get<Point3>(&hit->first)) return Hit{vec(*p), face};
    if (const Kernel::Segment_3* s = boost::get<Kernel::Segment_3>(&hit->first)) {
        const Vec3 a = vec(s->source()), b = vec(s->target());
        return Hit{(a - origin).dot(direction) <= (b - origin).dot(direction) ? a : b, face};
    }
    return std::nullopt;
}

std::optional<Vec3> RayCaster::first_hit_exact(const Vec3& origin, const Vec3& direction) const {
    using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
    const Kernel::Ray_3 ray(point(origin), Kernel::Vector_3(direction.x(), direction.y(), direction.z()));
    // Which triangles are hit is decided by exact predicates already.
    std::vector<Tree::Primitive_id> hits;
    impl_->tree.all_intersected_primitives(ray, std::back_inserter(hits));
    const CGAL::Cartesian_converter<Kernel, Exact> to_exact;
    const Exact::Ray_3 exact_ray = to_exact(ray);
    std::optional<Exact::Point_3> best;
    auto consider = [&](const Exact::Point_3& p) {
        if (!best || CGAL::has_smaller_distance_to_point(exact_ray.source(), p, *best)) best = p;
    };
    for (const auto& id : hits) {
        const auto meet = CGAL::intersection(exact_ray, to_exact(*id));
        if (!meet) continue;
        if (const auto* p = boost::get<Exact::Point_3>(&*meet)) consider(*p);
        if (const auto* s = boost::get<Exact::Segment_3>(&*meet)) {
            consider(s->source());
            consider(s->target());
        }
    }
    if (!best) return std::nullopt;
    return Vec3(CGAL::to_double(best->x()), CGAL::to_double(best->y()), CGAL::to_double(best->z()));
}

}  // namespace morphogen
