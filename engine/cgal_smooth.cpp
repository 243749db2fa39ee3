// Loop subdivision with CGAL (see plant_smooth.hpp). Subdivision's topology
// depends only on the connectivity, so the attributes ride along as the
// "points" of meshes with the same faces: three floats at a time.
#include "engine/plant_smooth.hpp"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>

#include <stdexcept>

namespace morphogen {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

// A Surface_mesh with the faces of `mesh` and vertex i at points[i].
SurfaceMesh surface(std::span<const Face> faces, const std::vector<Point>& points) {
    SurfaceMesh out;
    out.reserve(static_cast<SurfaceMesh::size_type>(points.size()), 0,
                static_cast<SurfaceMesh::size_type>(faces.size()));
    for (const Point& p : points) out.add_vertex(p);
    for (const Face& f : faces) {
        const auto v = [](int i) { return SurfaceMesh::Vertex_index(static_cast<SurfaceMesh::size_type>(i)); };
        if (out.add_face(v(f[0]), v(f[1]), v(f[2])) == SurfaceMesh::null_face())
            throw std::invalid_argument("--smooth: the mesh is not a closed, oriented manifold");
    }
    return out;
}

SurfaceMesh subdivided(std::span<const Face> faces, const std::vector<Point>& points, int rounds) {
    SurfaceMesh m = surface(faces, points);
    CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(rounds));
    return m;
}

}  // namespace

std::string smooth_rounds_problem(int rounds) {
    if (rounds >= 0 && rounds <= kMaxSmoothRounds) return {};
    return "--smooth " + std::to_string(rounds) + ": must be 0 to " + std::to_string(kMaxSmoothRounds) +
           " rounds (each multiplies the triangles by 4)";
}

SmoothedMesh smooth_mesh(MeshView mesh, int rounds, std::span<const std::span<const float>> attributes) {
    if (const std::string problem = smooth_rounds_problem(rounds); !problem.empty()) throw std::invalid_argument(problem);
    const std::size_t n = mesh.positions.size();
    for (const std::span<const float> a : attributes)
        if (n == 0 ? !a.empty() : a.size() % n != 0)
            throw std::invalid_argument("--smooth: an attribute of " + std::to_string(a.size()) + " floats for " +
                                        std::to_string(n) + " vertices");
    SmoothedMesh out;
    std::vector<Point> points;
    points.reserve(n);
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x(), p.y(), p.z());
    const SurfaceMesh m = subdivided(mesh.faces, points, rounds);
    // Vertices in the mesh's order (the old ones first), numbered densely.
    std::vector<int> dense(m.number_of_vertices() + m.number_of_removed_vertices(), -1);
    for (const auto v : m.vertices()) {
        const Point& p = m.point(v);
        dense[v.idx()] = static_cast<int>(out.mesh.positions.size());
        out.mesh.positions.emplace_back(p.x(), p.y(), p.z());
    }
    for (const auto f : m.faces()) {
        Face face;
        int k = 0;
        for (const auto v : CGAL::vertices_around_face(m.halfedge(f), m)) face[k++] = dense[v.idx()];
        out.mesh.faces.push_back(face);
    }
    const std::size_t smoothed = out.mesh.positions.size();
    for (const std::span<const float> a : attributes) {
        std::vector<float>& values = out.attributes.emplace_back();
        if (a.empty()) continue;
        const std::size_t width = a.size() / n;
        values.assign(smoothed * width, 0.0f);
        for (std::size_t first = 0; first < width; first += 3) {  // three channels a pass
            std::vector<Point> channels;
            channels.reserve(n);
            const auto at = [&](std::size_t v, std::size_t c) { return first + c < width ? a[v * width + first + c] : 0.0f; };
            for (std::size_t v = 0; v < n; ++v) channels.emplace_back(at(v, 0), at(v, 1), at(v, 2));
            const SurfaceMesh s = subdivided(mesh.faces, channels, rounds);
            std::size_t v = 0;
            for (const auto vertex : s.vertices()) {
                const Point& p = s.point(vertex);
                for (std::size_t c = 0; c < 3 && first + c < width; ++c)
                    values[v * width + first + c] = static_cast<float>(p[static_cast<int>(c)]);
                ++v;
            }
        }
    }
    return out;
}

}  // namespace morphogen
