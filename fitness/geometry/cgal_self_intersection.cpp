// CGAL Polygon_mesh_processing behind mesh_self_intersects().
#include "fitness/geometry/cgal_geometry.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <vector>

namespace morphogen {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Adds the faces as they are; false if one would break the half-edge structure.
bool build_direct(MeshView mesh, SurfaceMesh& out) {
    std::vector<SurfaceMesh::Vertex_index> vertices;
    vertices.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) vertices.push_back(out.add_vertex(Point3(p.x(), p.y(), p.z())));
    for (const Face& f : mesh.faces) {
        if (out.add_face(vertices[f[0]], vertices[f[1]], vertices[f[2]]) == SurfaceMesh::null_face())
            return false;
    }
    return true;
}

// Repairs orientation and duplicates non-manifold vertices so any soup fits.
void build_from_soup(MeshView mesh, SurfaceMesh& out) {
    std::vector<Point3> points;
    points.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x(), p.y(), p.z());
    std::vector<std::array<std::size_t, 3>> polygons;
    polygons.reserve(mesh.faces.size());
    for (const Face& f : mesh.faces)
        polygons.push_back({static_cast<std::size_t>(f[0]), static_cast<std::size_t>(f[1]),
                            static_cast<std::size_t>(f[2])});
    PMP::orient_polygon_soup(points, polygons);
    PMP::polygon_soup_to_polygon_mesh(points, polygons, out);
}
}  // namespace

bool mesh_self_intersects(MeshView mesh) {
    SurfaceMesh surface;
    if (!build_direct(mesh, surface)) {
        surface.clear();
        build_from_soup(mesh, surface);
    }
    return PMP::does_self_intersect(surface);
}

}  // namespace morphogen
