// CGAL's convex_hull_3 behind fitness/geometry/convex_hull.hpp (CGAL compiles slowly:
// only cgal_*.cpp include it).
#include "fitness/geometry/convex_hull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
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
    // The sum of tetrahedra from one hull vertex over the faces, in exact
    // rationals: CGAL orders (and may triangulate) the faces by memory
    // address, so a double sum would vary in its last bits from call to call.
    // A flat set's hull is a polygon: every tetrahedron is flat.
    using Exact = CGAL::Exact_rational;
    const Point origin = hull.point(*hull.vertices().begin());
    auto exact_from_origin = [&](const Point& p) {
        return std::array<Exact, 3>{Exact(p.x()) - Exact(origin.x()), Exact(p.y()) - Exact(origin.y()),
                                    Exact(p.z()) - Exact(origin.z())};
    };
    Exact sum = 0;
    for (const auto face : hull.faces()) {
        std::vector<std::array<Exact, 3>> corners;
        for (const auto v : CGAL::vertices_around_face(hull.halfedge(face), hull))
            corners.push_back(exact_from_origin(hull.point(v)));
        for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
            const auto &a = corners[0], &b = corners[i], &c = corners[i + 1];
            sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
    }
    const double volume = CGAL::to_double(sum / 6);
    return std::max(volume, 0.0);
}

}  // namespace morphogen
