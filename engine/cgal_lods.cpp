// Levels of detail, their checks and their wind data with CGAL (see
// plant_lods.hpp); CGAL stays in this file.
#include "engine/plant_lods.hpp"

#include "base/errors.hpp"
#include "engine/cgal_lod_distance_cost.hpp"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_triangle_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <stdexcept>
#include <string>

namespace morphogen {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SMS = CGAL::Surface_mesh_simplification;

Surface to_surface(MeshView mesh) {
    Surface surface;
    std::vector<Surface::Vertex_index> vertices;
    vertices.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) vertices.push_back(surface.add_vertex(Point(p.x(), p.y(), p.z())));
    for (const Face& f : mesh.faces)
        if (surface.add_face(vertices[f[0]], vertices[f[1]], vertices[f[2]]) == Surface::null_face())
            throw std::invalid_argument("simplify_lods: the mesh is not an oriented manifold");
    return surface;
}

MeshArrays to_arrays(Surface& surface) {
    surface.collect_garbage();  // indices 0 .. n-1 again, in their old order
    MeshArrays mesh;
    mesh.positions.reserve(surface.number_of_vertices());
    for (Surface::Vertex_index v : surface.vertices()) {
        const Point& p = surface.point(v);
        mesh.positions.emplace_back(p.x(), p.y(), p.z());
    }
    for (Surface::Face_index f : surface.faces()) {
        Face face{};
        int k = 0;
        for (Surface::Vertex_index v : CGAL::vertices_around_face(surface.halfedge(f), surface))
            face[k++] = static_cast<int>(v.idx());
        mesh.faces.push_back(face);
    }
    return mesh;
}

double diagonal(MeshView mesh) {
    Vec3 lo = mesh.positions[0], hi = mesh.positions[0];
    for (const Vec3& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    return std::max((hi - lo).norm(), 1e-12);
}

// `mesh` collapsed to about `faces` triangles. A closed triangle mesh has
// 3/2 edges per face and a collapse removes 3 edges (2 faces); CGAL stops
// below the threshold, so 3/2 * faces + 1 stops at the first count <= faces.
MeshArrays collapse_to(MeshView mesh, std::size_t faces) {
    const Surface original = to_surface(mesh);
    Surface surface = original;
    using Policies = SMS::GarlandHeckbert_triangle_policies<Surface, Kernel>;
    Policies policies(surface);
    const SMS::Bounded_normal_change_placement<Policies::Get_placement> placement(policies.get_placement());
    const lods::DistanceCost<Surface, Kernel, Policies::Get_cost> cost(original, policies.get_cost(), 1e-3 / diagonal(mesh));
    const SMS::Count_stop_predicate<Surface> stop(faces * 3 / 2 + 1);
    SMS::edge_collapse(surface, stop, CGAL::parameters::get_cost(cost).get_placement(placement));
    return to_arrays(surface);
}

}  // namespace

std::vector<MeshArrays> simplify_lods(MeshView lod0, int count) {
    if (count < 1) throw std::invalid_argument("simplify_lods: at least one level");
    if ((lod0.faces.size() >> (count - 1)) < kMinLodFaces)
        throw MeshError("--lods " + std::to_string(count) + ": " + std::to_string(count) + " levels of detail need at least " +
                                    std::to_string(kMinLodFaces << (count - 1)) + " triangles; the plant has " +
                                    std::to_string(lod0.faces.size()));
    std::vector<MeshArrays> levels;
    levels.push_back(MeshArrays{{lod0.positions.begin(), lod0.positions.end()}, {lod0.faces.begin(), lod0.faces.end()}});
    for (int i = 1; i < count; ++i) levels.push_back(collapse_to(lod0, lod0.faces.size() >> i));
    return levels;
}

double hausdorff_distance(MeshView a, MeshView b) {
    const Surface sa = to_surface(a), sb = to_surface(b);
    const auto samples = [](const Surface& s) {
        return CGAL::parameters::number_of_points_on_faces(std::max<std::size_t>(2000, 4 * s.number_of_faces()))
            .random_seed(1);
    };
    return PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(sa, sb, samples(sa), samples(sb));
}

bool is_closed_manifold(MeshView mesh) {
    Surface surface;
    try {
        surface = to_surface(mesh);
    } catch (const std::invalid_argument&) {
        return false;
    }
    for (Surface::Vertex_index v : surface.vertices())
        if (PMP::is_non_manifold_vertex(v, surface)) return false;
    return CGAL::is_closed(surface) && CGAL::is_valid_polygon_mesh(surface) && CGAL::is_triangle_mesh(surface);
}

std::vector<float> transfer_wind(MeshView lod0, std::span<const float> lod0_wind, MeshView level) {
    using Base = CGAL::Search_traits_3<Kernel>;
    using PointMap = CGAL::Pointer_property_map<Point>::type;
    using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, Base>;
    using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
    std::vector<Point> points;
    points.reserve(lod0.positions.size());
    for (const Vec3& p : lod0.positions) points.emplace_back(p.x(), p.y(), p.z());
    const PointMap map = CGAL::make_property_map(points);
    Search::Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(points.size()),
                      Search::Tree::Splitter(), Traits(map));
    const Search::Distance distance(map);
    std::vector<float> wind;
    wind.reserve(4 * level.positions.size());
    for (const Vec3& p : level.positions) {
        const Search search(tree, Point(p.x(), p.y(), p.z()), 1, 0, true, distance);
        const std::size_t nearest = search.begin()->first;
        wind.insert(wind.end(), lod0_wind.begin() + 4 * nearest, lod0_wind.begin() + 4 * nearest + 4);
    }
    return wind;
}

}  // namespace morphogen
