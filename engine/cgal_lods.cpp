// Levels of detail, their checks and their wind data with CGAL (see
// plant_lods.hpp); CGAL stays in this file.
#include "engine/plant_lods.hpp"

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

#include <cmath>
#include <cstdint>
#include <limits>
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

// Points on `mesh` for hausdorff_distance: its vertices, each triangle's
// centroid and edge midpoints, and max(2000, 4 x faces) points spread over
// the triangles by area, each at barycentric coordinates from a fixed
// sequence. Ours rather than CGAL's sample_triangle_mesh: CGAL 5.5 draws
// some samples from its default random generator whatever the seed, so the
// same meshes gave distances up to a third apart between calls.
std::vector<Point> surface_samples(MeshView mesh) {
    std::vector<Point> points;
    const auto point = [](const Vec3& p) { return Point(p.x(), p.y(), p.z()); };
    for (const Vec3& p : mesh.positions) points.push_back(point(p));
    std::vector<double> areas;
    for (const Face& f : mesh.faces) {
        const Vec3 &p = mesh.positions[f[0]], &q = mesh.positions[f[1]], &r = mesh.positions[f[2]];
        points.push_back(point((p + q + r) / 3));
        points.push_back(point((p + q) / 2));
        points.push_back(point((q + r) / 2));
        points.push_back(point((r + p) / 2));
        areas.push_back((q - p).cross(r - p).norm() / 2);
    }
    lods::spread_by_area(areas, static_cast<double>(std::max<std::size_t>(2000, 4 * mesh.faces.size())),
                         [&](std::size_t i, double u, double v) {
                             const Face& f = mesh.faces[i];
                             const Vec3 &p = mesh.positions[f[0]], &q = mesh.positions[f[1]], &r = mesh.positions[f[2]];
                             points.push_back(point(p + u * (q - p) + v * (r - p)));
                         });
    return points;
}

// The distance cost comes sparse (LOD0's vertices, each new triangle's
// centroid) and dense (also LOD0's measured points and four points of each
// new triangle): dense keeps thin branches that sparse merges into a
// neighbour, at several times its time.
enum class Cost { quadric, distance, dense_distance };

// `original` collapsed to about `faces` triangles. A closed triangle mesh has
// 3/2 edges per face and a collapse removes 3 edges (2 faces); CGAL stops
// below the threshold, so 3/2 * faces + 1 stops at the first count <= faces.
MeshArrays collapse_to(const Surface& original, double diag, std::size_t faces, Cost kind) {
    Surface surface = original;
    using Policies = SMS::GarlandHeckbert_triangle_policies<Surface, Kernel>;
    Policies policies(surface);
    const SMS::Bounded_normal_change_placement<Policies::Get_placement> placement(policies.get_placement());
    const SMS::Count_stop_predicate<Surface> stop(faces * 3 / 2 + 1);
    if (kind == Cost::quadric) {
        SMS::edge_collapse(surface, stop, CGAL::parameters::get_cost(policies.get_cost()).get_placement(placement));
    } else {
        const lods::DistanceCost<Surface, Kernel, Policies::Get_cost> cost(original, policies.get_cost(), 1e-3 / diag,
                                                                            kind == Cost::dense_distance);
        SMS::edge_collapse(surface, stop, CGAL::parameters::get_cost(cost).get_placement(placement));
    }
    return to_arrays(surface);
}

// The tries for one level, cheapest first (experiments/2026-11-27-lod-bounds.md:
// the quadric cost keeps the bound on most plants at a thirtieth of the
// distance cost's time).
struct Try {
    Cost cost;
    double ratio;
};
// The dense cost only for LOD0s of at least this many triangles: below it
// the measured points are their floor of 2,000 (4 or more a triangle, see
// surface_samples), and tracking them made small plants' refused tries 3-10
// times slower (a report's plants, a test suite's runs) for levels the
// sparse cost already gives them. The plants it is for, trees of thin
// branches, are near the 1,000-vertex cap (1,996 triangles).
constexpr std::size_t kMinDenseFaces = 500;
constexpr Try kTries[] = {{Cost::quadric, kLodHalf},        {Cost::quadric, kLodMaxRatio},
                          {Cost::distance, kLodHalf},       {Cost::distance, kLodMaxRatio},
                          {Cost::dense_distance, kLodHalf}, {Cost::dense_distance, kLodMaxRatio}};

}  // namespace

PlantLods simplify_lods(MeshView lod0, int count) {
    if (count < 1) throw std::invalid_argument("simplify_lods: at least one level");
    PlantLods lods{.levels = {}, .distances = {0.0}, .requested = count};
    lods.levels.push_back(MeshArrays{{lod0.positions.begin(), lod0.positions.end()}, {lod0.faces.begin(), lod0.faces.end()}});
    if (count == 1) return lods;
    const Surface original = to_surface(lod0);
    const double diag = diagonal(lod0);
    for (int i = 1; i < count; ++i) {
        const std::size_t before = lods.levels.back().faces.size();
        bool kept = false;
        double nearest_refused = std::numeric_limits<double>::infinity();
        for (const Try& attempt : kTries) {
            const auto target = static_cast<std::size_t>(std::floor(attempt.ratio * static_cast<double>(before)));
            if (target < kMinLodFaces) break;
            if (attempt.cost == Cost::dense_distance && lod0.faces.size() < kMinDenseFaces) break;
            MeshArrays level = collapse_to(original, diag, target, attempt.cost);
            if (level.faces.size() > target) continue;  // CGAL found no more collapses it may make
            const double distance = hausdorff_distance(lod0, level.view()) / diag;
            if (distance > lod_distance_bound(i)) {
                nearest_refused = std::min(nearest_refused, distance);
                continue;
            }
            lods.levels.push_back(std::move(level));
            lods.distances.push_back(distance);
            kept = true;
            break;
        }
        if (!kept) {
            lods.refused_distance = std::isfinite(nearest_refused) ? nearest_refused : 0.0;
            break;
        }
    }
    return lods;
}

double hausdorff_distance(MeshView a, MeshView b) {
    const Surface sa = to_surface(a), sb = to_surface(b);
    return std::max(PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(surface_samples(a), sb),
                    PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(surface_samples(b), sa));
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
