// CGAL's convex_hull_3 behind fitness/convex_hull.hpp (CGAL compiles slowly:
// only cgal_*.cpp include it).
#include "fitness/convex_hull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <vector>

namespace morphogen {

double convex_hull_volume(std::span<const Vec3> points) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Point = Kernel::Point_3;
    if (points.size() < 4) return 0.0;
    std::vector<Point> cgal_points;
    cgal_points.reserve(points.size());
    for (const Vec3& p : points) cgal_points.emplace_back(p.x(), p.y(), p.z());
    CGAL::Surface_mesh<Point> hull;
    CGAL::convex_hull_3(cgal_points.begin(), cgal_points.end(), hull);
    // Sum of tetrahedra from one hull vertex over the outward faces (a flat set's
    // hull is a polygon: every tetrahedron flat).
    const Point origin = hull.point(*hull.vertices().begin());
    double volume = 0.0;
    for (const auto face : hull.faces()) {
        std::vector<Point> corners;
        for (const auto v : CGAL::vertices_around_face(hull.halfedge(face), hull)) corners.push_back(hull.point(v));
        for (std::size_t i = 1; i + 1 < corners.size(); ++i)
            volume += CGAL::volume(origin, corners[0], corners[i], corners[i + 1]);
    }
    return std::max(volume, 0.0);
}

}  // namespace morphogen
