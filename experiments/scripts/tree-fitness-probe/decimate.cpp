// Decimates an OBJ to at most N vertices (CGAL edge collapse, Garland-Heckbert
// triangle quadrics, normals kept from flipping), to ask what a hand-built
// tree is worth under the plant fitness at the growth's vertex budget
// (experiments/2026-11-28-architecture-maps.md).
//   g++ -std=c++20 -O2 -isystem /usr/include/eigen3 experiments/scripts/tree-fitness-probe/decimate.cpp -o /tmp/decimate -lgmp -lmpfr
//   /tmp/decimate IN.obj N OUT.obj
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_triangle_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <cstdio>
#include <string>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMS = CGAL::Surface_mesh_simplification;

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fputs("usage: decimate IN.obj MAX_VERTICES OUT.obj\n", stderr);
        return 2;
    }
    Mesh mesh;
    if (!CGAL::IO::read_OBJ(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh)) {
        std::fprintf(stderr, "decimate: cannot read a triangle mesh from %s\n", argv[1]);
        return 1;
    }
    const std::size_t target = std::stoul(argv[2]);
    // A closed mesh has E = 3V - 6: collapsing edges down to 3·target - 6 leaves target vertices.
    SMS::Count_stop_predicate<Mesh> stop(3 * target - 6);
    using Policies = SMS::GarlandHeckbert_triangle_policies<Mesh, Kernel>;
    Policies policies(mesh);
    SMS::Bounded_normal_change_placement<Policies::Get_placement> placement(policies.get_placement());
    SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(policies.get_cost()).get_placement(placement));
    mesh.collect_garbage();
    if (!CGAL::IO::write_OBJ(argv[3], mesh, CGAL::parameters::stream_precision(17))) return 1;
    std::printf("%zu vertices, %zu faces\n", mesh.number_of_vertices(), mesh.number_of_faces());
}
