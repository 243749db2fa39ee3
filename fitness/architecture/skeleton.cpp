#include "fitness/architecture/skeleton.hpp"

#include "fitness/measures.hpp"
#include "fitness/architecture/welded_mesh.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

namespace morphogen {

namespace {

constexpr double kUnreached = std::numeric_limits<double>::infinity();

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int a) {
        while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
        return a;
    }
    // The smaller index becomes the root, so the result does not depend on the order of joins.
    void join(int a, int b) {
        a = find(a), b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<int> parent_;
};

// Each undirected edge once, with the triangles on it.
struct EdgeFaces {
    int a, b;           // a < b
    int first, count;   // into Edges::faces
};
struct Edges {
    std::vector<EdgeFaces> edges;
    std::vector<int> faces;
};

Edges edges_of(const MeshArrays& mesh) {
    std::vector<std::array<int, 3>> sides;  // (a, b, face), a < b
    sides.reserve(mesh.faces.size() * 3);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int u = mesh.faces[f][k], v = mesh.faces[f][(k + 1) % 3];
            sides.push_back({std::min(u, v), std::max(u, v), static_cast<int>(f)});
        }
    std::sort(sides.begin(), sides.end());
    Edges out;
    out.faces.reserve(sides.size());
    for (std::size_t i = 0; i < sides.size(); ++i) {
        if (i == 0 || sides[i][0] != sides[i - 1][0] || sides[i][1] != sides[i - 1][1])
            out.edges.push_back({sides[i][0], sides[i][1], static_cast<int>(out.faces.size()), 0});
        out.faces.push_back(sides[i][2]);
        ++out.edges.back().count;
    }
    return out;
}

double median_edge_length(const MeshArrays& mesh, const Edges& edges) {
    std::vector<double> lengths;
    lengths.reserve(edges.edges.size());
    for (const EdgeFaces& e : edges.edges) lengths.push_back((mesh.positions[e.a] - mesh.positions[e.b]).norm());
    if (lengths.empty()) return 0.0;
    auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    return *middle;
}

// The arrival at c of a front that reaches a at da and b at db, travelling
// straight from a point of the segment ab (d linear along it); infinite when
// the straight path would leave through a or b (the edges cover those).
double through_triangle(const Vec3& a, const Vec3& b, const Vec3& c, double da, double db) {
    const Vec3 e = b - a, w = c - a;
    const double e2 = e.squaredNorm(), delta = db - da;
    if (!(e2 > 0) || delta * delta >= e2) return kUnreached;
    const double foot = w.dot(e) / e2;                            // c's foot on the line ab, as a parameter
    const double h2 = std::max(0.0, w.squaredNorm() - foot * foot * e2);  // c's squared distance from the line
    const double g = std::sqrt(h2 / (1.0 - delta * delta / e2));  // from the crossing point to c
    const double t = foot - delta * g / e2;
    if (!(t > 0.0 && t < 1.0)) return kUnreached;
    return da + t * delta + g;
}

// Distances from every vertex with z <= base_z: Dijkstra whose updates also
// cross triangles (from a settled edge to the opposite corner), so a front
// travels straight over a triangle instead of zigzagging along its edges.
std::vector<double> base_distances(const MeshArrays& mesh, const Edges& edges, double base_z) {
    const std::size_t n = mesh.positions.size();
    std::vector<int> start(n + 1, 0), next(edges.edges.size() * 2);
    for (const EdgeFaces& e : edges.edges) ++start[e.a + 1], ++start[e.b + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const EdgeFaces& e : edges.edges) next[fill[e.a]++] = e.b, next[fill[e.b]++] = e.a;
    std::vector<int> face_start(n + 1, 0), corner_face(mesh.faces.size() * 3);
    for (const Face& f : mesh.faces)
        for (int v : f) ++face_start[v + 1];
    std::partial_sum(face_start.begin(), face_start.end(), face_start.begin());
    std::vector<int> face_fill(face_start.begin(), face_start.end() - 1);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int v : mesh.faces[f]) corner_face[face_fill[v]++] = static_cast<int>(f);

    std::vector<double> d(n, kUnreached);
    std::vector<bool> settled(n, false);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t v = 0; v < n; ++v)
        if (mesh.positions[v].z() <= base_z) d[v] = 0.0, queue.emplace(0.0, static_cast<int>(v));
    auto offer = [&](int u, double du) {
        if (du < d[u]) d[u] = du, queue.emplace(du, u);
    };
    while (!queue.empty()) {
        const auto [dv, v] = queue.top();
        queue.pop();
        if (dv > d[v] || settled[v]) continue;
        settled[v] = true;
        for (int i = start[v]; i < start[v + 1]; ++i) {
            const int u = next[i];
            if (!settled[u]) offer(u, dv + (mesh.positions[u] - mesh.positions[v]).norm());
        }
        for (int i = face_start[v]; i < face_start[v + 1]; ++i) {
            const Face& f = mesh.faces[corner_face[i]];
            for (int k = 0; k < 3; ++k) {
                const int x = f[k], u = f[(k + 1) % 3];
                if (x == v || u == v || !settled[x] || settled[u]) continue;
                offer(u, through_triangle(mesh.positions[v], mesh.positions[x], mesh.positions[u], dv, d[x]));
            }
        }
    }
    return d;
}

// The bands [k, k+1) of t = d / w a triangle covers with positive length:
// floor(t_min) .. ceil(t_max) - 1 (at least the first).
std::pair<int, int> band_range(double t0, double t1, double t2) {
    const double lo = std::min({t0, t1, t2}), hi = std::max({t0, t1, t2});
    const int first = static_cast<int>(std::floor(lo));
    return {first, std::max(first, static_cast<int>(std::ceil(hi)) - 1)};
}

struct Corner {
    Vec3 p = Vec3::Zero();
    double t = 0.0;
};

// A convex polygon of at most 5 corners: a triangle cut by two planes.
struct Polygon {
    std::array<Corner, 5> corners;
    int size = 0;
    void push(const Corner& c) { corners[size++] = c; }
};

// The part of a triangle with t in [lo, hi] (Sutherland-Hodgman on t).
Polygon clip(const Polygon& triangle, double lo, double hi) {
    Polygon polygon = triangle;
    for (const double sign : {1.0, -1.0}) {
        const double bound = sign > 0 ? lo : hi;  // keep sign * (t - bound) >= 0
        Polygon kept;
        for (int i = 0; i < polygon.size; ++i) {
            const Corner& a = polygon.corners[i];
            const Corner& b = polygon.corners[(i + 1) % polygon.size];
            const double sa = sign * (a.t - bound), sb = sign * (b.t - bound);
            if (sa >= 0) kept.push(a);
            if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
                const double s = sa / (sa - sb);
                kept.push({a.p + s * (b.p - a.p), bound});
            }
        }
        polygon = kept;
    }
    return polygon;
}

// What a clipped triangle adds to its node.
struct Piece {
    double area = 0.0;
    Vec3 moment = Vec3::Zero();  // sum of area x centroid
    double level_length = 0.0;   // sum of area x |grad d|: the integral of the level curves' length over d
    double t_lo = kUnreached, t_hi = -kUnreached;
    void add(const Piece& o) {
        area += o.area, moment += o.moment, level_length += o.level_length;
        t_lo = std::min(t_lo, o.t_lo), t_hi = std::max(t_hi, o.t_hi);
    }
};

// |grad d| of d linear over the triangle (a, b, c); 0 for a degenerate one.
double gradient_norm(const Vec3& a, const Vec3& b, const Vec3& c, double da, double db, double dc) {
    const Vec3 e1 = b - a, e2 = c - a, n = e1.cross(e2);
    const double n2 = n.squaredNorm();
    if (n2 <= 0.0) return 0.0;
    return ((db - da) * e2.cross(n) + (dc - da) * n.cross(e1)).norm() / n2;
}

Piece piece_of(const Polygon& polygon, double grad) {
    Piece piece;
    const auto& c = polygon.corners;
    for (int i = 1; i + 1 < polygon.size; ++i) {
        const double a = 0.5 * (c[i].p - c[0].p).cross(c[i + 1].p - c[0].p).norm();
        piece.area += a;
        piece.moment += a * (c[0].p + c[i].p + c[i + 1].p) / 3.0;
    }
    piece.level_length = piece.area * grad;
    for (int i = 0; i < polygon.size; ++i)
        piece.t_lo = std::min(piece.t_lo, c[i].t), piece.t_hi = std::max(piece.t_hi, c[i].t);
    return piece;
}

// Every (triangle, band) pair the triangle covers, with its clipped piece.
struct Fragments {
    std::vector<int> first, band_lo, band_hi;  // per triangle; first = -1 when unreached
    std::vector<int> band;                     // per fragment
    std::vector<Piece> pieces;                 // per fragment
    // The fragment of triangle f in band k, or -1.
    int of(int f, int k) const {
        if (first[f] < 0 || k < band_lo[f] || k > band_hi[f]) return -1;
        return first[f] + k - band_lo[f];
    }
};

Fragments clip_into_bands(const MeshArrays& mesh, const std::vector<double>& d, double w) {
    Fragments out;
    const std::size_t faces = mesh.faces.size();
    out.first.assign(faces, -1), out.band_lo.assign(faces, 0), out.band_hi.assign(faces, -1);
    for (std::size_t f = 0; f < faces; ++f) {
        const Face& g = mesh.faces[f];
        if (d[g[0]] == kUnreached) continue;  // the whole triangle is (its edges join its corners)
        const Vec3 &a = mesh.positions[g[0]], &b = mesh.positions[g[1]], &c = mesh.positions[g[2]];
        const Polygon triangle{{{{a, d[g[0]] / w}, {b, d[g[1]] / w}, {c, d[g[2]] / w}}}, 3};
        const auto [lo, hi] = band_range(triangle.corners[0].t, triangle.corners[1].t, triangle.corners[2].t);
        const double grad = gradient_norm(a, b, c, d[g[0]], d[g[1]], d[g[2]]);
        out.first[f] = static_cast<int>(out.band.size()), out.band_lo[f] = lo, out.band_hi[f] = hi;
        for (int k = lo; k <= hi; ++k) {
            out.band.push_back(k);
            out.pieces.push_back(piece_of(clip(triangle, k, k + 1.0), grad));
        }
    }
    return out;
}

// The bands whose closed interval [k, k+1] holds t: two when t is an integer.
int lowest_band_holding(double t) { return static_cast<int>(std::ceil(t)) - 1; }
int highest_band_holding(double t) { return static_cast<int>(std::floor(t)); }

// The fragments that touch: pairs of one band (`same`) and pairs of
// consecutive bands (`across`, as (lower, upper)).
struct Touching {
    std::vector<std::pair<int, int>> same, across;
};

Touching touching_fragments(const Fragments& fragments, const MeshArrays& mesh, const Edges& edges,
                            const std::vector<double>& t) {
    Touching out;
    // Triangles across an edge, in every band the edge reaches.
    for (const EdgeFaces& e : edges.edges) {
        if (e.count < 2 || t[e.a] == kUnreached) continue;
        const int k_hi = highest_band_holding(std::max(t[e.a], t[e.b]));
        for (int k = lowest_band_holding(std::min(t[e.a], t[e.b])); k <= k_hi; ++k) {
            int anchor = -1;
            for (int i = e.first; i < e.first + e.count; ++i) {
                const int fragment = fragments.of(edges.faces[i], k);
                if (fragment < 0) continue;
                if (anchor < 0) anchor = fragment;
                else out.same.emplace_back(anchor, fragment);
            }
        }
    }
    // Triangles around a vertex, in the one or two bands holding it; a vertex
    // on a band boundary makes the pieces on either side touch.
    std::vector<std::array<int, 2>> anchor(mesh.positions.size(), {-1, -1});  // lower band, upper band
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if (fragments.first[f] < 0) continue;
        for (int v : mesh.faces[f]) {
            const int k_hi = highest_band_holding(t[v]);
            for (int k = lowest_band_holding(t[v]); k <= k_hi; ++k) {
                const int fragment = fragments.of(static_cast<int>(f), k);
                if (fragment < 0) continue;
                int& a = anchor[v][k == k_hi ? 1 : 0];
                if (a < 0) a = fragment;
                else out.same.emplace_back(a, fragment);
            }
        }
    }
    for (const auto& [lower, upper] : anchor)
        if (lower >= 0 && upper >= 0) out.across.emplace_back(lower, upper);
    // A triangle crossing a boundary touches both sides.
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = fragments.band_lo[f]; k < fragments.band_hi[f]; ++k)
            out.across.emplace_back(fragments.of(static_cast<int>(f), k), fragments.of(static_cast<int>(f), k + 1));
    return out;
}

// Compressed lists: the entries of row r are at [start[r], start[r + 1]).
struct Rows {
    std::vector<int> start, entries;
    Rows(std::size_t rows, const std::vector<std::pair<int, int>>& pairs, bool both_ways) : start(rows + 1, 0) {
        for (const auto& [a, b] : pairs) {
            ++start[a + 1];
            if (both_ways) ++start[b + 1];
        }
        std::partial_sum(start.begin(), start.end(), start.begin());
        entries.resize(static_cast<std::size_t>(start.back()));
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (const auto& [a, b] : pairs) {
            entries[fill[a]++] = b;
            if (both_ways) entries[fill[b]++] = a;
        }
    }
};

// Each fragment of one band > 0 (`begin`..`end`) takes as its lineage the
// node of the band below it touches most (the smallest on a tie); a fragment
// touching none, the lineage nearest to it in steps through the band (-1 if
// none is).
void assign_lineages(std::vector<int>::const_iterator begin, std::vector<int>::const_iterator end, const Rows& below,
                     const Rows& same, const std::vector<int>& node_of, std::vector<int>& lineage) {
    std::deque<int> queue;
    std::vector<int> touched;
    for (auto it = begin; it != end; ++it) {
        const int f = *it;
        touched.clear();
        for (int j = below.start[f]; j < below.start[f + 1]; ++j) touched.push_back(node_of[below.entries[j]]);
        std::sort(touched.begin(), touched.end());
        int best_count = 0;
        for (std::size_t j = 0; j < touched.size();) {
            std::size_t run = j;
            while (run < touched.size() && touched[run] == touched[j]) ++run;
            if (static_cast<int>(run - j) > best_count) best_count = static_cast<int>(run - j), lineage[f] = touched[j];
            j = run;
        }
        if (lineage[f] >= 0) queue.push_back(f);
    }
    while (!queue.empty()) {
        const int f = queue.front();
        queue.pop_front();
        for (int j = same.start[f]; j < same.start[f + 1]; ++j)
            if (const int g = same.entries[j]; lineage[g] < 0) lineage[g] = lineage[f], queue.push_back(g);
    }
}

// The nodes, band by band (the root, all of band 0, first; then by band and
// first fragment). A fragment touching nodes of the band below takes the one
// it touches most as its lineage; the others take the lineage nearest to
// them through their band; a node is a connected piece of one lineage, and
// its parent is that lineage. So a piece where two branches touch (a loop) is
// split between them, not made the crown of one.
Skeleton nodes_of(const Fragments& fragments, const Touching& touching, double w) {
    const int count = static_cast<int>(fragments.band.size());
    const Rows same(fragments.band.size(), touching.same, true);
    std::vector<std::pair<int, int>> downward;  // (upper, lower)
    for (const auto& [lower, upper] : touching.across)
        if (fragments.band[upper] == fragments.band[lower] + 1) downward.emplace_back(upper, lower);
    const Rows below(fragments.band.size(), downward, false);

    std::vector<int> by_band(count);
    std::iota(by_band.begin(), by_band.end(), 0);
    std::stable_sort(by_band.begin(), by_band.end(), [&](int a, int b) { return fragments.band[a] < fragments.band[b]; });

    std::vector<int> node_of(count, -1), lineage(count, -1);
    std::vector<int> parents;
    UnionFind pieces(fragments.band.size());
    for (std::size_t first = 0; first < by_band.size();) {
        const int band = fragments.band[by_band[first]];
        std::size_t last = first;
        while (last < by_band.size() && fragments.band[by_band[last]] == band) ++last;
        if (band > 0) assign_lineages(by_band.begin() + first, by_band.begin() + last, below, same, node_of, lineage);
        // A node: a connected piece of one lineage, where the pieces of a
        // lineage that meet another one (the two sides of a loop's cut) are one.
        std::map<int, int> border;  // lineage -> a fragment of it next to another lineage
        for (std::size_t i = first; i < last; ++i) {
            const int f = by_band[i];
            for (int j = same.start[f]; j < same.start[f + 1]; ++j) {
                const int g = same.entries[j];
                if (band == 0 || lineage[g] == lineage[f]) pieces.join(f, g);
                else if (const auto [it, fresh] = border.emplace(lineage[f], f); !fresh) pieces.join(it->second, f);
            }
        }
        if (band == 0)
            for (std::size_t i = first + 1; i < last; ++i) pieces.join(by_band[first], by_band[i]);
        std::map<int, int> node_of_piece;
        for (std::size_t i = first; i < last; ++i) {  // by_band holds a band's fragments in increasing order
            const int f = by_band[i];
            const auto [it, fresh] = node_of_piece.emplace(pieces.find(f), static_cast<int>(parents.size()));
            if (fresh) parents.push_back(lineage[f]);
            node_of[f] = it->second;
        }
        first = last;
    }

    std::vector<Piece> sums(parents.size());
    for (int i = 0; i < count; ++i) sums[node_of[i]].add(fragments.pieces[i]);
    Skeleton skeleton;
    skeleton.band_width = w;
    skeleton.nodes.resize(parents.size());
    for (std::size_t n = 0; n < parents.size(); ++n) {
        SkeletonNode& node = skeleton.nodes[n];
        const Piece& s = sums[n];
        node.area = s.area;
        node.centroid = s.area > 0 ? Vec3(s.moment / s.area) : Vec3::Zero();
        const double span = (s.t_hi - s.t_lo) * w;
        node.diameter = span > 0 ? s.level_length / (std::numbers::pi * span) : 0.0;
        node.distance = std::max(0.0, s.t_hi * w);
    }
    for (int i = 0; i < count; ++i) skeleton.nodes[node_of[i]].band = fragments.band[i];
    // A node above band 0 that touches nothing below (a rounding tie) joins the root.
    for (std::size_t n = 1; n < skeleton.nodes.size(); ++n) {
        SkeletonNode& node = skeleton.nodes[n];
        node.parent = parents[n] >= 0 ? parents[n] : 0;
        skeleton.nodes[node.parent].children.push_back(static_cast<int>(n));
    }
    return skeleton;
}

// A mesh with nothing to cut into bands: its root at the lowest vertex.
Skeleton lone_root(MeshView mesh) {
    const auto lowest = std::min_element(mesh.positions.begin(), mesh.positions.end(),
                                         [](const Vec3& a, const Vec3& b) { return a.z() < b.z(); });
    Skeleton skeleton;
    skeleton.nodes.emplace_back().centroid = *lowest;
    double zmax = lowest->z();
    for (const Vec3& p : mesh.positions) zmax = std::max(zmax, p.z());
    skeleton.zmin = lowest->z(), skeleton.zmax = zmax;
    return skeleton;
}

}  // namespace

Skeleton level_set_skeleton(MeshView mesh, const SkeletonParams& params) {
    check_mesh_view(mesh);
    if (mesh.positions.empty()) throw std::invalid_argument("a mesh without vertices has no skeleton");
    if (!(params.band_edges > 0) || !std::isfinite(params.band_edges))
        throw std::invalid_argument("skeleton band_edges must be positive and finite");
    if (params.max_bands < 1) throw std::invalid_argument("skeleton max_bands must be at least 1");
    if (!std::isfinite(params.band_width) || !std::isfinite(params.base_height))
        throw std::invalid_argument("skeleton band_width and base_height must be finite");

    const MeshArrays welded = welded_mesh(mesh);
    if (welded.faces.empty()) return lone_root(mesh);
    const Edges edges = edges_of(welded);
    double zmin = welded.positions[0].z(), zmax = zmin;
    for (const Vec3& p : welded.positions) zmin = std::min(zmin, p.z()), zmax = std::max(zmax, p.z());

    double w = params.band_width > 0 ? params.band_width : params.band_edges * median_edge_length(welded, edges);
    const double base_height = params.base_height >= 0 ? params.base_height : 0.5 * w;
    std::vector<double> d = base_distances(welded, edges, zmin + base_height);
    double reach = 0.0;
    for (double x : d)
        if (x != kUnreached) reach = std::max(reach, x);
    w = std::max(w, reach / params.max_bands);
    if (!(w > 0)) return lone_root(mesh);

    std::vector<double> t(d.size());
    for (std::size_t v = 0; v < d.size(); ++v) t[v] = d[v] == kUnreached ? kUnreached : d[v] / w;
    const Fragments fragments = clip_into_bands(welded, d, w);
    Skeleton skeleton = nodes_of(fragments, touching_fragments(fragments, welded, edges, t), w);
    skeleton.base_height = base_height, skeleton.zmin = zmin, skeleton.zmax = zmax;
    return skeleton;
}

}  // namespace morphogen
