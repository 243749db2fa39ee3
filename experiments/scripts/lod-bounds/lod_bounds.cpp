// The LOD study's driver (experiments/2026-11-27-lod-bounds.md): simplifies
// plants to the levels of `--lods 3` with one method and prints, per plant and
// in all, the triangle ratios, whether each level is closed and manifold, and
// the two-sided Hausdorff distance from LOD0 over LOD0's bounding-box diagonal.
//   lod_bounds METHOD random          100 random genomes, as test_engine's LOD test
//   lod_bounds METHOD MESH...         meshes (PLY/OBJ), e.g. configs' bests
//   lod_bounds sweep PLANT...         every method of kSweep at fractions of LOD0's
//                                     triangles (PLANT: a mesh, or tree:S / default:S);
//                                     WHERE=1 says where the farthest samples lie,
//                                     SCAN=1 the least fraction within 1 % and 2 %,
//                                     METHODS=a,b only those methods
// METHOD: library (engine/simplify_lods) or one of CGAL's own policies with
// the count stop of the library: gh_triangle (the old library), gh_plane,
// gh_prob_triangle, lindstrom_turk. DENSE=1 measures with 10x the samples.
#include "core/base/config_reader.hpp"
#include "engine/plant_frame.hpp"
#include "engine/plant_lods.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/growth/growth_params.hpp"
#include "core/io/mesh_io.hpp"
#include "tests/support/test_genomes.hpp"
#include "engine/cgal_lod_distance_cost.hpp"

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_distance_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Polyhedral_envelope_filter.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_probabilistic_triangle_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_triangle_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <Eigen/Eigenvalues>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <queue>
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

static std::vector<MeshArrays> method_lods(const std::string& method, MeshView lod0) {
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
    const std::vector<MeshArrays> levels = method_lods(method, lod0);
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

// ---- sweep: every collapse method the study tried, at several ratios, and
// where the farthest sample lies (lod_bounds sweep PLANT...; PLANT a mesh
// file, or tree:S / default:S for genome S of the random run's settings).
enum class SweepCost { quadric, distance, lindstrom_turk, probabilistic };
enum class SweepPlace { quadric, lindstrom_turk, probabilistic };
struct SweepMethod {
    const char* name;
    SweepCost cost;
    SweepPlace place;
    bool bounded_distance;  // Bounded_distance_placement at the level's bound
    bool envelope;          // Polyhedral_envelope_filter at the level's bound
    bool keep_tips = false; // edges at the tips (local maxima of the graph distance from the foot) never collapse
};
constexpr SweepMethod kSweep[] = {
    {"gh", SweepCost::quadric, SweepPlace::quadric, false, false},
    {"dist", SweepCost::distance, SweepPlace::quadric, false, false},
    {"lt", SweepCost::lindstrom_turk, SweepPlace::lindstrom_turk, false, false},
    {"dist+lt_place", SweepCost::distance, SweepPlace::lindstrom_turk, false, false},
    {"gh+bounded_dist", SweepCost::quadric, SweepPlace::quadric, true, false},
    {"lt+bounded_dist", SweepCost::lindstrom_turk, SweepPlace::lindstrom_turk, true, false},
    {"dist+bounded_dist", SweepCost::distance, SweepPlace::quadric, true, false},
    {"gh+envelope", SweepCost::quadric, SweepPlace::quadric, false, true},
    {"dist+envelope", SweepCost::distance, SweepPlace::quadric, false, true},
    {"gh_prob", SweepCost::probabilistic, SweepPlace::probabilistic, false, false},
    {"gh+tips", SweepCost::quadric, SweepPlace::quadric, false, false, true},
    {"lt+tips", SweepCost::lindstrom_turk, SweepPlace::lindstrom_turk, false, false, true},
    {"dist+tips", SweepCost::distance, SweepPlace::quadric, false, false, true},
};

// The tips of `s`: vertices whose graph distance (edge lengths) from the
// lowest vertex is at least that of every neighbour.
static std::vector<bool> tip_vertices(const Surface& s) {
    std::vector<double> g(s.number_of_vertices(), std::numeric_limits<double>::infinity());
    Surface::Vertex_index foot = *s.vertices().begin();
    for (auto v : s.vertices()) if (s.point(v).y() < s.point(foot).y()) foot = v;
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    g[foot.idx()] = 0;
    queue.emplace(0, foot.idx());
    while (!queue.empty()) {
        const auto [d, i] = queue.top();
        queue.pop();
        if (d > g[i]) continue;
        const Surface::Vertex_index v(i);
        for (auto u : CGAL::vertices_around_target(s.halfedge(v), s)) {
            const double e = d + std::sqrt(CGAL::squared_distance(s.point(v), s.point(u)));
            if (e < g[u.idx()]) g[u.idx()] = e, queue.emplace(e, u.idx());
        }
    }
    std::vector<bool> tip(g.size(), false);
    for (auto v : s.vertices()) {
        bool top = true;
        for (auto u : CGAL::vertices_around_target(s.halfedge(v), s)) top = top && g[v.idx()] >= g[u.idx()];
        tip[v.idx()] = top;
    }
    return tip;
}

template <class Cost, class Placement>
static void sweep_run(Surface& s, std::size_t faces, const Cost& cost, const Placement& placement, double envelope, bool keep_tips) {
    const SMS::Count_stop_predicate<Surface> stop(faces * 3 / 2 + 1);
    if (keep_tips) {
        const std::vector<bool> tip = tip_vertices(s);
        auto constrained = s.add_property_map<Surface::Edge_index, bool>("e:tip", false).first;
        for (auto e : s.edges()) constrained[e] = tip[s.vertex(e, 0).idx()] || tip[s.vertex(e, 1).idx()];
        SMS::edge_collapse(s, stop, CGAL::parameters::get_cost(cost).get_placement(placement).edge_is_constrained_map(constrained));
        s.remove_property_map(constrained);
    } else if (envelope > 0) {
        const SMS::Polyhedral_envelope_filter<Kernel> filter(envelope);
        SMS::edge_collapse(s, stop, CGAL::parameters::get_cost(cost).get_placement(placement).filter(filter));
    } else {
        SMS::edge_collapse(s, stop, CGAL::parameters::get_cost(cost).get_placement(placement));
    }
}

template <class Cost, class Base>
static void sweep_place(Surface& s, std::size_t faces, const Cost& cost, const Base& base, const SweepMethod& m, double bound) {
    const SMS::Bounded_normal_change_placement<Base> normal(base);
    if (m.bounded_distance) {
        const SMS::Bounded_distance_placement<SMS::Bounded_normal_change_placement<Base>, Kernel> bounded(bound, normal);
        sweep_run(s, faces, cost, bounded, m.envelope ? bound : 0, m.keep_tips);
    } else {
        sweep_run(s, faces, cost, normal, m.envelope ? bound : 0, m.keep_tips);
    }
}

// `lod0` collapsed to `faces` by method `m`; `bound` the level's distance bound (model units).
static MeshArrays sweep_collapse(MeshView lod0, std::size_t faces, const SweepMethod& m, double bound, double diag) {
    const Surface original = to_surface(lod0);
    Surface s = original;
    using Policies = SMS::GarlandHeckbert_triangle_policies<Surface, Kernel>;
    Policies policies(s);
    const morphogen::lods::DistanceCost<Surface, Kernel, Policies::Get_cost> distance_cost(original, policies.get_cost(), 1e-3 / diag,
                                                                                                      /*dense=*/true);
    const SMS::LindstromTurk_placement<Surface> lt_place;
    const SMS::LindstromTurk_cost<Surface> lt_cost;
    SMS::GarlandHeckbert_probabilistic_triangle_policies<Surface, Kernel> probabilistic(s);
    const auto with_cost = [&](const auto& placement) {
        if (m.cost == SweepCost::quadric) sweep_place(s, faces, policies.get_cost(), placement, m, bound);
        else if (m.cost == SweepCost::distance) sweep_place(s, faces, distance_cost, placement, m, bound);
        else if (m.cost == SweepCost::lindstrom_turk) sweep_place(s, faces, lt_cost, placement, m, bound);
        else sweep_place(s, faces, probabilistic.get_cost(), placement, m, bound);
    };
    if (m.place == SweepPlace::quadric) with_cost(policies.get_placement());
    else if (m.place == SweepPlace::lindstrom_turk) with_cost(lt_place);
    else with_cost(probabilistic.get_placement());
    return to_arrays(s);
}

// Where the farthest sample of one side lies: its distance, its height over
// LOD0's height, and, around it on LOD0 (vertices within 4x the distance),
// the branch's local axis (PCA), how far along that axis the point is among
// its neighbours (1 = the end: a tip), the tube's radius, and the angle of
// the displacement to the nearest point of the other mesh against the axis
// (about 0: along the branch, a tip cut short; about 90: across, a tube
// flattened or moved).
static void farthest(const char* side, MeshView from, MeshView to, MeshView lod0, double diag, double bound) {
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Surface>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
    const Surface target = to_surface(to), source = to_surface(from);
    Tree tree(faces(target).first, faces(target).second, target);
    tree.accelerate_distance_queries();
    std::vector<Point> samples;
    PMP::sample_triangle_mesh(source, std::back_inserter(samples),
                              CGAL::parameters::number_of_points_on_faces(40 * from.faces.size()).random_seed(7));
    for (const Vec3& p : from.positions) samples.emplace_back(p.x(), p.y(), p.z());
    double best = 0;
    Point worst, nearest;
    int over = 0;
    for (const Point& p : samples) {
        const Point q = tree.closest_point(p);
        const double d = std::sqrt(CGAL::squared_distance(p, q));
        over += d > bound;
        if (d > best) best = d, worst = p, nearest = q;
    }
    double bottom = 1e300, top = -1e300;
    for (const Vec3& p : lod0.positions) bottom = std::min(bottom, p.y()), top = std::max(top, p.y());
    const Vec3 w(worst.x(), worst.y(), worst.z()), n(nearest.x(), nearest.y(), nearest.z());
    // How thick LOD0 is at the worst point (a ray inwards along the worst
    // point's face normal to LOD0's far side; from LOD0's side only), and how
    // far the nearest point of the other mesh lies from LOD0 (0: on another
    // part of LOD0, a branch merged or a tube flattened onto its far side).
    double thickness = -1;
    const Surface grown = to_surface(lod0);
    Tree grown_tree(faces(grown).first, faces(grown).second, grown);
    grown_tree.accelerate_distance_queries();
    const auto [on, face] = grown_tree.closest_point_and_primitive(worst);
    const Vec3 normal = [&] {
        const auto h = grown.halfedge(face);
        const Point &a = grown.point(grown.source(h)), &b = grown.point(grown.target(h)), &c = grown.point(grown.target(grown.next(h)));
        return Vec3(CGAL::cross_product(b - a, c - a).x(), CGAL::cross_product(b - a, c - a).y(), CGAL::cross_product(b - a, c - a).z()).normalized();
    }();
    for (const auto& hit : [&] {
             std::vector<std::pair<decltype(grown_tree.any_intersection(Kernel::Ray_3()))::value_type::first_type, Surface::Face_index>> hits;
             const Vec3 start = w - 1e-6 * diag * normal;
             grown_tree.all_intersections(Kernel::Ray_3(Point(start.x(), start.y(), start.z()), Kernel::Vector_3(-normal.x(), -normal.y(), -normal.z())),
                                          std::back_inserter(hits));
             return hits;
         }()) {
        if (const Point* p = boost::get<Point>(&hit.first)) {
            const double d = std::sqrt(CGAL::squared_distance(*p, worst));
            if (d > 1e-5 * diag && (thickness < 0 || d < thickness)) thickness = d;
        }
    }
    const double other_off = std::sqrt(grown_tree.squared_distance(nearest));
    std::printf("    %s: LOD0 %.2f%% thick there (ray inwards), the nearest point of the other mesh %.2f%% from LOD0\n", side,
                100 * thickness / diag, 100 * other_off / diag);
    std::vector<Vec3> near;
    for (const Vec3& p : lod0.positions)
        if ((p - w).norm() < std::max(4 * best, 0.02 * diag)) near.push_back(p);
    Vec3 mean = Vec3::Zero();
    for (const Vec3& p : near) mean += p;
    mean /= std::max<std::size_t>(1, near.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Vec3& p : near) cov += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Vec3 axis = eig.eigenvectors().col(2);
    double lo = 1e300, hi = -1e300, radius = 0;
    for (const Vec3& p : near) {
        const double t = (p - mean).dot(axis);
        lo = std::min(lo, t), hi = std::max(hi, t);
        radius += ((p - mean) - t * axis).squaredNorm();
    }
    radius = std::sqrt(radius / std::max<std::size_t>(1, near.size()));
    const double t = (w - mean).dot(axis);
    const double along = hi > lo ? (t - lo) / (hi - lo) : 0.5;
    const Vec3 move = n - w;
    const double angle = move.norm() > 0 ? std::acos(std::min(1.0, std::abs(move.normalized().dot(axis)))) * 180 / M_PI : 0;
    std::printf("    %s: %.2f%% at height %.2f; samples over bound %d of %zu; %zu LOD0 vertices near, along axis %.2f "
                "(0/1 = an end), tube radius %.2f%%, displacement %.0f deg to axis\n",
                side, 100 * best / diag, (w.y() - bottom) / (top - bottom), over, samples.size(), near.size(), std::max(along, 1 - along),
                100 * radius / diag, angle);
}

static void sweep(const std::string& name, MeshView grown) {
    const PlacedPlant placed = place_plant(grown, std::nullopt);
    const MeshView lod0 = placed.mesh.view();
    Vec3 lo = lod0.positions[0], hi = lo;
    for (const Vec3& p : lod0.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double diag = (hi - lo).norm();
    const std::size_t n = lod0.faces.size();
    std::vector<std::pair<Surface::Face_index, Surface::Face_index>> crossing;
    const Surface placed_surface = to_surface(lod0);
    PMP::self_intersections(placed_surface, std::back_inserter(crossing));
    std::printf("%s: %zu triangles, diagonal %.3f, %zu pairs of triangles intersecting\n", name.c_str(), n, diag, crossing.size());
    const double fractions[] = {0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.25, 0.3025};
    const char* only = std::getenv("METHODS");
    for (const SweepMethod& m : kSweep) {
        if (only && !std::strstr(only, m.name)) continue;
        std::printf("  %-18s", m.name);
        double seconds = 0;
        for (const double f : fractions) {
            const int level = f > 0.4 ? 1 : 2;
            const double bound = 0.01 * level * diag;
            const auto target = static_cast<std::size_t>(std::floor(f * static_cast<double>(n)));
            const auto start = std::chrono::steady_clock::now();
            const MeshArrays out = sweep_collapse(lod0, target, m, bound, diag);
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const double d = hausdorff_distance(lod0, out.view()) / diag;
            std::printf(" | %.4g->%zu%s %.2f%%", f, out.faces.size(), is_closed_manifold(out.view()) ? "" : " NM", 100 * d);
        }
        std::printf(" | %.1f s\n", seconds);
        if (std::getenv("SCAN")) {  // the least fraction of LOD0's triangles within 1 % (LOD1) and 2 % (LOD2), by 0.02
            for (const int level : {1, 2}) {
                double f = level == 1 ? 0.5 : 0.25, d = 1;
                for (; f < 0.951; f += 0.02) {
                    const MeshArrays out = sweep_collapse(lod0, static_cast<std::size_t>(std::floor(f * double(n))), m, 0.01 * level * diag, diag);
                    if ((d = hausdorff_distance(lod0, out.view()) / diag) <= 0.01 * level) break;
                }
                if (f > 0.951) std::printf("    within %d%%: at no fraction up to 0.95 (%.2f%% there)\n", level, 100 * d);
                else std::printf("    within %d%% from fraction %.2f (%.2f%%)\n", level, f, 100 * d);
            }
        }
        if (std::getenv("WHERE")) {
            for (const double f : {0.5, 0.25}) {
                const double bound = (f > 0.4 ? 0.01 : 0.02) * diag;
                const MeshArrays out = sweep_collapse(lod0, static_cast<std::size_t>(std::floor(f * double(n))), m, bound, diag);
                std::printf("   at %.2f:\n", f);
                farthest("LOD0 far from level", lod0, out.view(), lod0, diag, bound);
                farthest("level far from LOD0", out.view(), lod0, lod0, diag, bound);
            }
        }
    }
}

int main(int argc, char** argv) {
    if (argc < 3) { std::fprintf(stderr, "usage: lod_bounds METHOD random|MESH...\n"); return 2; }
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    const std::string method = argv[1];
    if (method == "sweep") {
        const GenomeGrower defaults(NetworkParams{}, GrowthParams{});
        const GenomeGrower trees = grower_from(R"({"network": {"outputs": 15, "hidden": [30]},
            "growth": {"steps": 150, "max_vertices": 1000, "mode": "branching", "collisions": "allow"}})");
        for (int i = 2; i < argc; ++i) {
            const std::string arg = argv[i];
            if (arg.rfind("tree:", 0) == 0 || arg.rfind("default:", 0) == 0) {
                const GenomeGrower& g = arg[0] == 't' ? trees : defaults;
                const GrowthState state = g.grow(testing::random_test_genome(g.layers(), std::stoull(arg.substr(arg.find(':') + 1))).params);
                sweep(arg, state.mesh.view());
            } else {
                sweep(arg, read_mesh(arg).view());
            }
        }
        return 0;
    }
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
