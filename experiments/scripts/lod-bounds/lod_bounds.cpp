// The LOD study's driver (experiments/2026-11-27-lod-bounds.md): simplifies
// plants to the levels of `--lods 3` with one method and prints, per plant and
// in all, the triangle ratios, whether each level is closed and manifold, and
// the two-sided Hausdorff distance from LOD0 over LOD0's bounding-box diagonal.
//   lod_bounds METHOD random          100 random genomes, as test_engine's LOD test
//   lod_bounds METHOD MESH...         meshes (PLY/OBJ), e.g. configs' bests
// METHOD: library (engine/simplify_lods) or one of CGAL's own policies with
// the count stop of the library: gh_triangle (the old library), gh_plane,
// gh_prob_triangle, lindstrom_turk. DENSE=1 measures with 10x the samples.
#include "base/config_reader.hpp"
#include "engine/plant_frame.hpp"
#include "engine/plant_lods.hpp"
#include "growth/genome_grower.hpp"
#include "growth/growth_params.hpp"
#include "io/mesh_io.hpp"
#include "tests/support/test_genomes.hpp"

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_probabilistic_triangle_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_triangle_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

using namespace morphogen;
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
namespace SMS = CGAL::Surface_mesh_simplification;
namespace PMP = CGAL::Polygon_mesh_processing;

static Surface to_surface(MeshView mesh) {
    Surface s;
    std::vector<Surface::Vertex_index> v;
    for (const Vec3& p : mesh.positions) v.push_back(s.add_vertex(Point(p.x(), p.y(), p.z())));
    for (const Face& f : mesh.faces) s.add_face(v[f[0]], v[f[1]], v[f[2]]);
    return s;
}

static MeshArrays to_arrays(Surface& s) {
    s.collect_garbage();
    MeshArrays m;
    for (auto v : s.vertices()) m.positions.emplace_back(s.point(v).x(), s.point(v).y(), s.point(v).z());
    for (auto f : s.faces()) {
        Face face{};
        int k = 0;
        for (auto v : CGAL::vertices_around_face(s.halfedge(f), s)) face[k++] = static_cast<int>(v.idx());
        m.faces.push_back(face);
    }
    return m;
}

template <class Policies>
static MeshArrays collapse_with(MeshView mesh, std::size_t faces) {
    Surface s = to_surface(mesh);
    Policies policies(s);
    const SMS::Bounded_normal_change_placement<typename Policies::Get_placement> placement(policies.get_placement());
    SMS::edge_collapse(s, SMS::Count_stop_predicate<Surface>(faces * 3 / 2 + 1),
                       CGAL::parameters::get_cost(policies.get_cost()).get_placement(placement));
    return to_arrays(s);
}

static MeshArrays collapse_lt(MeshView mesh, std::size_t faces) {
    Surface s = to_surface(mesh);
    const SMS::Bounded_normal_change_placement<SMS::LindstromTurk_placement<Surface>> placement;
    SMS::edge_collapse(s, SMS::Count_stop_predicate<Surface>(faces * 3 / 2 + 1),
                       CGAL::parameters::get_cost(SMS::LindstromTurk_cost<Surface>()).get_placement(placement));
    return to_arrays(s);
}

static std::vector<MeshArrays> lods(const std::string& method, MeshView lod0) {
    if (method == "library") return simplify_lods(lod0, 3).levels;  // may stop short (plant_lods.hpp)
    std::vector<MeshArrays> out{MeshArrays{{lod0.positions.begin(), lod0.positions.end()}, {lod0.faces.begin(), lod0.faces.end()}}};
    for (int i = 1; i < 3; ++i) {
        const std::size_t target = lod0.faces.size() >> i;
        if (method == "gh_triangle") out.push_back(collapse_with<SMS::GarlandHeckbert_triangle_policies<Surface, Kernel>>(lod0, target));
        else if (method == "gh_plane") out.push_back(collapse_with<SMS::GarlandHeckbert_plane_policies<Surface, Kernel>>(lod0, target));
        else if (method == "gh_prob_triangle") out.push_back(collapse_with<SMS::GarlandHeckbert_probabilistic_triangle_policies<Surface, Kernel>>(lod0, target));
        else if (method == "lindstrom_turk") out.push_back(collapse_lt(lod0, target));
        else { std::fprintf(stderr, "unknown method %s\n", method.c_str()); std::exit(2); }
    }
    return out;
}

static double distance(MeshView a, MeshView b) {
    if (!std::getenv("DENSE")) return hausdorff_distance(a, b);
    const Surface sa = to_surface(a), sb = to_surface(b);
    const auto n = [](const Surface& s) {
        return CGAL::parameters::number_of_points_on_faces(std::max<std::size_t>(20000, 40 * s.number_of_faces())).random_seed(7);
    };
    return PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(sa, sb, n(sa), n(sb));
}

struct Totals {
    int plants = 0, measured = 0, short_chains = 0, not_manifold = 0, ratio_off = 0, over[3] = {}, large = 0, large_over[3] = {};
    double worst[3] = {}, large_worst[3] = {}, worst_ratio = 0, seconds = 0;
};

static void measure(const std::string& method, const std::string& name, MeshView grown, Totals& t) {
    const PlacedPlant placed = place_plant(grown, std::nullopt);
    const MeshView lod0 = placed.mesh.view();
    ++t.plants;
    if (lod0.faces.size() < kMinLodFaces << 2) return;
    ++t.measured;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<MeshArrays> levels = lods(method, lod0);
    t.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Vec3 lo = lod0.positions[0], hi = lo;
    for (const Vec3& p : lod0.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double diag = (hi - lo).norm();
    const bool large = lod0.faces.size() >= 1000;
    t.large += large;
    std::printf("%s %zu", name.c_str(), lod0.faces.size());
    if (levels.size() < 3) ++t.short_chains;
    for (int i = 1; i < static_cast<int>(levels.size()); ++i) {
        const MeshView level = levels[static_cast<std::size_t>(i)].view();
        const double ratio = double(level.faces.size()) / double(levels[static_cast<std::size_t>(i - 1)].faces.size());
        const double off = std::abs(ratio - 0.5) / 0.5;
        t.worst_ratio = std::max(t.worst_ratio, off);
        t.ratio_off += off > 0.1;
        const bool manifold = is_closed_manifold(level);
        t.not_manifold += !manifold;
        const double d = distance(lod0, level) / diag;
        t.worst[i] = std::max(t.worst[i], d);
        t.over[i] += d > 0.01 * i;
        if (large) t.large_worst[i] = std::max(t.large_worst[i], d), t.large_over[i] += d > 0.01 * i;
        std::printf(" | LOD%d %zu ratio %.3f %s %.2f%%", i, level.faces.size(), ratio, manifold ? "manifold" : "NOT-MANIFOLD", 100 * d);
    }
    std::printf(levels.size() < 3 ? " | stopped at LOD%zu\n" : "\n", levels.size() - 1);
}

static GenomeGrower grower_from(const char* text) {
    nlohmann::json config = nlohmann::json::parse(text);
    ConfigIssues issues;
    ObjectReader network(&config["network"], "network", issues);
    ObjectReader growth(&config["growth"], "growth", issues);
    return GenomeGrower(read_network_params(network), read_growth_params(growth));
}

int main(int argc, char** argv) {
    if (argc < 3) { std::fprintf(stderr, "usage: lod_bounds METHOD random|MESH...\n"); return 2; }
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    const std::string method = argv[1];
    Totals t;
    if (std::string(argv[2]) == "random") {
        // The growth defaults, and branching trees as test_engine's LOD test grows them.
        const GenomeGrower defaults(NetworkParams{}, GrowthParams{});
        const GenomeGrower trees = grower_from(R"({"network": {"outputs": 15, "hidden": [30]},
            "growth": {"steps": 150, "max_vertices": 1000, "mode": "branching", "collisions": "allow"}})");
        for (const GenomeGrower* g : {&defaults, &trees})
            for (std::uint64_t seed = 1; seed <= 50; ++seed) {
                const GrowthState state = g->grow(testing::random_test_genome(g->layers(), seed).params);
                measure(method, (g == &defaults ? "default-" : "tree-") + std::to_string(seed), state.mesh.view(), t);
            }
    } else {
        for (int i = 2; i < argc; ++i) {
            const MeshArrays mesh = read_mesh(argv[i]);
            measure(method, argv[i], mesh.view(), t);
        }
    }
    std::printf("SUMMARY %s: %d plants, %d measured (%d large); short chains %d; not manifold %d; ratio off > 10%% %d (worst %.1f%%); "
                "LOD1 worst %.2f%% over-1%% %d (large %.2f%%, %d); LOD2 worst %.2f%% over-2%% %d (large %.2f%%, %d); %.2f s simplifying\n",
                method.c_str(), t.plants, t.measured, t.large, t.short_chains, t.not_manifold, t.ratio_off, 100 * t.worst_ratio,
                100 * t.worst[1], t.over[1], 100 * t.large_worst[1], t.large_over[1], 100 * t.worst[2], t.over[2],
                100 * t.large_worst[2], t.large_over[2], t.seconds);
}
