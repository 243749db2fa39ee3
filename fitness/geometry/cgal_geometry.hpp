#pragma once
// The plain interface to the CGAL geometry this library needs (CGAL
// compiles slowly, so it is included only by cgal_ray_caster.cpp and
// cgal_self_intersection.cpp). Exact predicates, inexact constructions
// (CGAL::Exact_predicates_inexact_constructions_kernel).
#include "core/mesh/mesh.hpp"

#include <memory>
#include <optional>

namespace morphogen {

// Sign of the exact orientation of the 2-D points a, b, c: +1 counter-
// clockwise, -1 clockwise, 0 collinear. The slow exact fallback of the filtered
// predicate in canopy.cpp.
int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy);

// First intersection of rays with a set of mesh triangles (an AABB tree).
// Thread-safe for queries once constructed (the tree is built eagerly).
class RayCaster {
public:
    enum class Faces {
        non_degenerate,  // every face that is a proper triangle in 3-D
        non_vertical,    // faces whose xy-projection has non-zero area (docs/algorithm.md §10.1)
    };
    RayCaster(MeshView mesh, Faces which);
    ~RayCaster();
    RayCaster(RayCaster&&) noexcept;
    RayCaster& operator=(RayCaster&&) noexcept;

    // The intersection nearest to `origin` along origin + t*direction, t >= 0
    // (boundaries count: a ray through an edge or vertex hits). Where the ray
    // lies in a triangle's plane, the nearest point of that overlap.
    // The point is constructed in double precision, so where the ray meets a
    // triangle seen almost edge-on it can be far off (and so can the choice of
    // the nearest triangle); fine for counting hits (light), not for a reference.
    std::optional<Vec3> first_hit(const Vec3& origin, const Vec3& direction) const;
    // The same, but every candidate intersection is constructed exactly
    // (CGAL Epeck) and the nearest is rounded once: slow, for reference tests.
    std::optional<Vec3> first_hit_exact(const Vec3& origin, const Vec3& direction) const;
    // first_hit's point and the index (in the mesh given to the constructor)
    // of the face it lies on.
    struct Hit {
        Vec3 point;
        int face;
    };
    std::optional<Hit> first_hit_face(const Vec3& origin, const Vec3& direction) const;
    int num_triangles() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Whether any two faces intersect other than in their shared vertices/edges
// (CGAL::Polygon_mesh_processing::does_self_intersect). Degenerate faces
// count as self-intersections. A face set that is not an oriented edge-manifold
// is made one by duplicating its non-manifold vertices (CGAL
// orient_polygon_soup), so surfaces touching there count as intersecting.
bool mesh_self_intersects(MeshView mesh);

}  // namespace morphogen
