#include "tests/fitness/limb_controls.hpp"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_triangle_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace morphogen::testing {

namespace {

constexpr double kPi = std::numbers::pi;

// The marching-tetrahedra grid giving the solid about `vertices` vertices:
// the count grows as 1 / h^2, measured once on a coarse grid.
MeshArrays polygonised(const Field& field, const Vec3& lo, const Vec3& hi, int vertices) {
    constexpr double coarse = 0.25;
    const MeshArrays first = implicit_mesh(field, lo, hi, coarse);
    const double h = coarse * std::sqrt(static_cast<double>(first.positions.size()) / vertices);
    return implicit_mesh(field, lo, hi, std::min(h, coarse));
}


// A trunk (r 0.5) to z 4 and two arms (r 0.4) to (+-2.5, 0, 8).
LimbControlSolid y_shape() {
    Field f = [](const Vec3& p) {
        double v = cylinder_field(p, {0, 0, 0}, 0.5, 4.2);
        for (const double side : {-1.0, 1.0}) v = smooth_union(v, capsule_field(p, {0, 0, 4}, {side * 2.5, 0, 8}, 0.4), 0.2);
        return v;
    };
    return {f, {-3.5, -1, -0.5}, {3.5, 1, 9}};
}

// A thick trunk (r 0.9) to z 3 and three thick prongs (r 0.6) to z 9, each
// with two lumps (r 0.75) on it: the lumpy three-pronged Y of a breeding session.
LimbControlSolid three_prongs() {
    Field f = [](const Vec3& p) {
        double v = cylinder_field(p, {0, 0, 0}, 0.9, 3.2);
        for (int k = 0; k < 3; ++k) {
            const double a = kPi / 2 + 2 * kPi * k / 3;
            const Vec3 base(0, 0, 3), end(2.6 * std::cos(a), 2.6 * std::sin(a), 9);
            v = smooth_union(v, capsule_field(p, base, end, 0.6), 0.25);
            for (const double t : {0.45, 0.8}) v = smooth_union(v, sphere_field(p, base + t * (end - base), 0.75), 0.2);
        }
        return v;
    };
    return {f, {-4, -4, -0.5}, {4, 4, 10.2}};
}

// A trunk (r 0.5) to z 4 under a bar along x at z 4 carrying `arms` candles
// (r 0.4) up to z 9, `spacing` apart.
LimbControlSolid candelabra(int arms, double spacing) {
    const double half = spacing * (arms - 1) / 2.0;
    Field f = [=](const Vec3& p) {
        double v = cylinder_field(p, {0, 0, 0}, 0.5, 4.0);
        v = smooth_union(v, capsule_field(p, {-half, 0, 4}, {half, 0, 4}, 0.4), 0.15);
        for (int i = 0; i < arms; ++i) {
            const double x = -half + spacing * i;
            v = smooth_union(v, capsule_field(p, {x, 0, 4}, {x, 0, 9}, 0.4), 0.15);
        }
        return v;
    };
    return {f, {-half - 1, -1, -0.5}, {half + 1, 1, 10}};
}

// A flattened dome with 19 round lobes on its top, on a short thick stalk.
LimbControlSolid broccoli() {
    Field f = [](const Vec3& p) {
        double v = cylinder_field(p, {0, 0, 0}, 0.8, 2.5);
        v = smooth_union(v, ellipsoid_field(p, {0, 0, 3.2}, {2.2, 2.2, 1.4}), 0.4);
        for (int ring = 0; ring < 3; ++ring) {
            const int count = ring == 0 ? 1 : 6 * ring;
            for (int i = 0; i < count; ++i) {
                const double polar = 0.55 * ring, azimuth = 2 * kPi * (i + 0.5 * ring) / count;
                const Vec3 on_dome(2.2 * std::sin(polar) * std::cos(azimuth), 2.2 * std::sin(polar) * std::sin(azimuth),
                                   3.2 + 1.4 * std::cos(polar));
                v = smooth_union(v, sphere_field(p, on_dome, 0.45), 0.15);
            }
        }
        return v;
    };
    return {f, {-3, -3, -0.5}, {3, 3, 5.6}};
}

// A cap (a flattened ellipsoid, 4.4 across) on a thin stem (r 0.35).
LimbControlSolid mushroom() {
    Field f = [](const Vec3& p) {
        return smooth_union(cylinder_field(p, {0, 0, 0}, 0.35, 4.2), ellipsoid_field(p, {0, 0, 4.4}, {2.2, 2.2, 0.7}), 0.3);
    };
    return {f, {-3, -3, -0.5}, {3, 3, 5.6}};
}

// An upright column (r 0.7) with a round top at z 9.
LimbControlSolid column() {
    Field f = [](const Vec3& p) {
        return smooth_union(cylinder_field(p, {0, 0, 0}, 0.7, 8.3), sphere_field(p, {0, 0, 8.3}, 0.7), 0.1);
    };
    return {f, {-1.5, -1.5, -0.5}, {1.5, 1.5, 9.6}};
}

// A staghorn coral: a trunk (r 0.5) to z 2.5 forks into two branches (r 0.4)
// to (+-1.8, 0, 5.5), each forking into two twigs (r 0.3) up to z 9.
LimbControlSolid coral() {
    Field f = [](const Vec3& p) {
        double v = cylinder_field(p, {0, 0, 0}, 0.5, 2.7);
        for (const double s : {-1.0, 1.0}) {
            const Vec3 fork(s * 1.8, 0, 5.5);
            v = smooth_union(v, capsule_field(p, {0, 0, 2.5}, fork, 0.4), 0.15);
            for (const double t : {-1.0, 1.0}) v = smooth_union(v, capsule_field(p, fork, {s * 2.4, t * 1.3, 9}, 0.3), 0.1);
        }
        return v;
    };
    return {f, {-3.5, -2.5, -0.5}, {3.5, 2.5, 10}};
}

// A saguaro: a column (r 0.65) with a round top at z 11, and two arms (r 0.45)
// that leave it sideways at z 3 and 4, bend and rise to z 6.5 and 7.5.
LimbControlSolid cactus() {
    Field f = [](const Vec3& p) {
        double v = smooth_union(cylinder_field(p, {0, 0, 0}, 0.65, 10.35), sphere_field(p, {0, 0, 10.35}, 0.65), 0.1);
        for (const auto& [side, z, top] : {std::tuple{-1.0, 3.0, 6.5}, std::tuple{1.0, 4.0, 7.5}}) {
            v = smooth_union(v, capsule_field(p, {0, 0, z}, {side * 1.7, 0, z}, 0.45), 0.2);
            v = smooth_union(v, capsule_field(p, {side * 1.7, 0, z}, {side * 1.7, 0, top}, 0.45), 0.1);
        }
        return v;
    };
    return {f, {-2.7, -1.2, -0.5}, {2.7, 1.2, 11.6}};
}

// A tree: a trunk (r 0.7) forking at z 5.2 into six limbs (r 0.45) to radius
// 4 at z 12.7, each under a round crown (r 2.7); neighbouring crowns overlap.
LimbControlSolid tree6() {
    Field f = [](const Vec3& p) {
        double v = cylinder_field(p, {0, 0, 0}, 0.7, 5.5);
        for (int i = 0; i < 6; ++i) {
            const double a = 2 * kPi * i / 6;
            const Vec3 end(4 * std::cos(a), 4 * std::sin(a), 12.7);
            v = smooth_union(v, capsule_field(p, {0, 0, 5.2}, end, 0.45), 0.2);
            v = smooth_union(v, sphere_field(p, end, 2.7), 0.3);
        }
        return v;
    };
    return {f, {-8, -8, -0.5}, {8, 8, 16}};
}

}  // namespace

const std::vector<LimbControl>& limb_controls() {
    // Fork heights: where the branches' surfaces part, over the top's height.
    static const std::vector<LimbControl> controls{
        {"y", "a trunk forking into two slender arms", 2, 2, 4.75 / 8.4, 0.08},
        {"prongs3", "a thick trunk forking into three thick, lumpy prongs", 3, 3, 4.8 / 9.6, 0.08},
        {"candelabra3", "three candles on a bar on a trunk", 3, 3, 4.2 / 9.4, 0.08},
        {"candelabra5", "five candles on a bar on a trunk", 5, 5, 4.2 / 9.4, 0.08},
        {"broccoli", "a lobed dome on a short stalk", 1, 0, 1.0, 0.02},
        {"mushroom", "a wide cap on a thin stem", 1, 0, 1.0, 0.02},
        {"column", "an upright column", 1, 0, 1.0, 0.02},
        {"coral", "a trunk forking into two branches, each forking into two twigs", 4, 6, 3.3 / 9.3, 0.08},
        {"cactus", "a saguaro: a column with two arms that leave sideways and rise", 3, 3, 3.5 / 11.0, 0.08},
        {"tree6", "a trunk forking into six limbs under six round crowns that overlap", 6, 6, 7.1 / 15.4, 0.08},
    };
    return controls;
}

LimbControlSolid limb_control_solid(const std::string& name) {
    if (name == "y") return y_shape();
    if (name == "prongs3") return three_prongs();
    if (name == "candelabra3") return candelabra(3, 2.0);
    if (name == "candelabra5") return candelabra(5, 1.5);
    if (name == "broccoli") return broccoli();
    if (name == "mushroom") return mushroom();
    if (name == "column") return column();
    if (name == "coral") return coral();
    if (name == "cactus") return cactus();
    if (name == "tree6") return tree6();
    throw std::invalid_argument("no limb control named " + name);
}

MeshArrays limb_control_fine_mesh(const std::string& name) {
    const LimbControlSolid solid = limb_control_solid(name);
    // The large tree needs more vertices for its six crowns and thin limbs.
    return polygonised(solid.field, solid.lo, solid.hi, name == "tree6" ? 96000 : 24000);
}

MeshArrays decimated(const MeshArrays& mesh, int vertices) {
    using Kernel = CGAL::Simple_cartesian<double>;
    using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
    namespace SMS = CGAL::Surface_mesh_simplification;
    Surface surface;
    std::vector<Surface::Vertex_index> index;
    index.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) index.push_back(surface.add_vertex({p.x(), p.y(), p.z()}));
    for (const Face& f : mesh.faces)
        if (surface.add_face(index[f[0]], index[f[1]], index[f[2]]) == Surface::null_face())
            throw std::invalid_argument("decimated: the mesh is not an oriented manifold");
    // A closed genus-0 mesh has E = 3V - 6 edges.
    SMS::Count_stop_predicate<Surface> stop(static_cast<std::size_t>(3 * vertices - 6));
    using Policies = SMS::GarlandHeckbert_triangle_policies<Surface, Kernel>;
    Policies policies(surface);
    SMS::Bounded_normal_change_placement<Policies::Get_placement> placement(policies.get_placement());
    SMS::edge_collapse(surface, stop, CGAL::parameters::get_cost(policies.get_cost()).get_placement(placement));
    surface.collect_garbage();
    MeshArrays out;
    out.positions.reserve(surface.number_of_vertices());
    for (const auto v : surface.vertices()) {
        const auto& p = surface.point(v);
        out.positions.emplace_back(p.x(), p.y(), p.z());
    }
    for (const auto f : surface.faces()) {
        Face face{};
        int k = 0;
        for (const auto v : CGAL::vertices_around_face(surface.halfedge(f), surface)) face[k++] = static_cast<int>(v.idx());
        out.faces.push_back(face);
    }
    return out;
}

std::vector<MeshArrays> limb_control_meshes(const std::string& name) {
    const std::vector<int>& counts = limb_control_resolutions();
    std::vector<MeshArrays> meshes(counts.size());
    MeshArrays source = limb_control_fine_mesh(name);
    for (std::size_t i = counts.size(); i-- > 0;) source = meshes[i] = decimated(source, counts[i]);
    return meshes;
}

}  // namespace morphogen::testing
