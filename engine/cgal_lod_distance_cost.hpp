#pragma once
// The cost of an edge collapse for the levels of detail (cgal_lods.cpp only;
// CGAL stays in the engine's CGAL files): how far the collapse takes the
// surface from the grown mesh, in both directions, so that CGAL's edge
// collapse removes first what changes the plant's shape least. Garland-
// Heckbert's quadric cost is a sum of squared distances to planes: at the tip
// of a thin branch every plane nearly contains the branch's axis, so sliding
// the tip down the branch costs almost nothing and the tips went first (LOD2
// of a tree 7 % of its diagonal away). Here the cost is the larger of
//   - the farthest grown vertex merged into the collapsed edge's vertices
//     from the triangles around the new vertex, and of those merged into
//     the vertices around the edge from the new triangles and their own
//     (grown mesh -> level; without the second, later collapses eroded thin
//     branches whose tips an earlier one had merged), and
//   - the farthest of the new vertex, its new edges' midpoints and its new
//     triangles' centroids from the grown mesh (level -> grown mesh, by an
//     AABB tree of LOD0),
// with the base policy's cost (the quadrics) added at a tiny weight to order
// collapses that cost no distance (flat parts). The base policy keeps its
// quadrics up to date through this cost (CGAL's Update_tag).
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel/global_functions_3.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace morphogen::lods {

// `wanted` points spread over triangles by area, each at barycentric
// coordinates from a fixed sequence (splitmix64): calls add(i, u, v) for a
// point at u, v of triangle i (areas[i] its area). The same points every run:
// hausdorff_distance measures LOD0 at them and DistanceCost tracks them.
template <class Add>
void spread_by_area(const std::vector<double>& areas, double wanted, Add add) {
    double total = 0;
    for (const double a : areas) total += a;
    std::uint64_t state = 0x9E3779B97F4A7C15ULL;
    const auto uniform = [&state] {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    };
    double done = 0;
    std::size_t placed = 0;
    for (std::size_t i = 0; i < areas.size() && total > 0; ++i) {
        done += areas[i];
        const auto upto = static_cast<std::size_t>(std::llround(wanted * done / total));
        for (; placed < upto; ++placed) {
            double u = uniform(), v = uniform();
            if (u + v > 1) u = 1 - u, v = 1 - v;
            add(i, u, v);
        }
    }
}

template <class Surface, class Kernel, class BaseCost>
class DistanceCost {
public:
    using Update_tag = CGAL::Tag_true;
    using Point = typename Kernel::Point_3;
    using Triangle = typename Kernel::Triangle_3;
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Surface>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

    // `original` is LOD0 and must outlive this cost; `tie_weight` scales
    // the base cost (a squared distance) added to order zero-distance
    // collapses. `dense`: track LOD0's measured points and four points of
    // each new triangle (thin tubes merged into a neighbour), not only LOD0's
    // vertices and each new triangle's centroid.
    DistanceCost(const Surface& original, BaseCost base, double tie_weight, bool dense)
        : base_(std::move(base)), tie_weight_(tie_weight), dense_(dense),
          tree_(std::make_shared<Tree>(faces(original).first, faces(original).second, original)),
          merged_(std::make_shared<std::vector<std::vector<Point>>>()) {
        tree_->accelerate_distance_queries();
    }

    template <class Mesh, class Vpm, class Traits>
    void initialize(const Mesh& mesh, const Vpm vpm, const Traits& traits) const {
        base_.initialize(mesh, vpm, traits);
        merged_->assign(num_vertices(mesh), {});
        for (auto v : vertices(mesh)) (*merged_)[v.idx()].push_back(get(vpm, v));
        if (!dense_) return;
        // LOD0's points that hausdorff_distance measures (edge midpoints,
        // centroids and points spread by area), each kept with the nearest
        // corner of its triangle: a thin tube merged into a neighbour can keep
        // its vertices near the level while its triangles' insides leave it
        // (the tree config's best: 1.96 % at LOD1 with vertices alone, 1.10 %
        // with these; experiments/2026-11-27-lod-bounds.md).
        std::vector<std::array<typename boost::graph_traits<Mesh>::vertex_descriptor, 3>> corners;
        std::vector<double> areas;
        const auto keep = [&](const auto& corner, const Point& p) {
            auto best = corner[0];
            for (const auto c : corner)
                if (CGAL::squared_distance(p, get(vpm, c)) < CGAL::squared_distance(p, get(vpm, best))) best = c;
            (*merged_)[best.idx()].push_back(p);
        };
        for (auto f : faces(mesh)) {
            const auto h = halfedge(f, mesh);
            corners.push_back({source(h, mesh), target(h, mesh), target(next(h, mesh), mesh)});
            const Point &a = get(vpm, corners.back()[0]), &b = get(vpm, corners.back()[1]), &c = get(vpm, corners.back()[2]);
            areas.push_back(std::sqrt(CGAL::cross_product(b - a, c - a).squared_length()) / 2);
            const auto mid = [](const Point& p, const Point& q) {
                return Point((p.x() + q.x()) / 2, (p.y() + q.y()) / 2, (p.z() + q.z()) / 2);
            };
            keep(corners.back(), Point((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3, (a.z() + b.z() + c.z()) / 3));
            keep(corners.back(), mid(a, b));
            keep(corners.back(), mid(b, c));
            keep(corners.back(), mid(c, a));
        }
        spread_by_area(areas, static_cast<double>(std::max<std::size_t>(2000, 4 * corners.size())),
                       [&](std::size_t i, double u, double v) {
                           const Point &p = get(vpm, corners[i][0]), &q = get(vpm, corners[i][1]), &r = get(vpm, corners[i][2]);
                           keep(corners[i], p + u * (q - p) + v * (r - p));
                       });
    }

    template <class Profile, class Vertex>
    void update_after_collapse(const Profile& profile, const Vertex kept) const {
        base_.update_after_collapse(profile, kept);
        std::vector<Point> joined = (*merged_)[profile.v0().idx()];
        const std::vector<Point>& other = (*merged_)[profile.v1().idx()];
        joined.insert(joined.end(), other.begin(), other.end());
        (*merged_)[profile.v0().idx()].clear();
        (*merged_)[profile.v1().idx()].clear();
        (*merged_)[kept.idx()] = std::move(joined);
    }

    template <class Profile>
    boost::optional<typename Profile::FT> operator()(const Profile& profile,
                                                    const boost::optional<Point>& placement) const {
        if (!placement) return {};
        const auto base = base_(profile, placement);
        if (!base) return {};
        const Point& q = *placement;
        const auto& vpm = profile.vertex_point_map();
        // The triangles around the new vertex: the star of the edge less the
        // two triangles the collapse removes; v1 of each is the moved vertex.
        std::vector<Triangle> star;
        const auto& triangles = profile.triangles();
        auto it = triangles.begin();
        if (profile.left_face_exists()) ++it;
        if (profile.right_face_exists()) ++it;
        double level_to_grown = tree_->squared_distance(q);
        for (; it != triangles.end(); ++it) {
            const Point& a = get(vpm, it->v0);
            const Point& c = get(vpm, it->v2);
            star.emplace_back(a, q, c);
            level_to_grown = std::max(level_to_grown, tree_->squared_distance(Point((a.x() + q.x()) / 2, (a.y() + q.y()) / 2, (a.z() + q.z()) / 2)));
            // The centroid and three points between it and the corners (a new
            // triangle can leave LOD0 inside while its corners stay on it).
            constexpr std::array<std::array<double, 3>, 4> kWeights{{{1.0 / 3, 1.0 / 3, 1.0 / 3},
                                                                    {2.0 / 3, 1.0 / 6, 1.0 / 6},
                                                                    {1.0 / 6, 2.0 / 3, 1.0 / 6},
                                                                    {1.0 / 6, 1.0 / 6, 2.0 / 3}}};
            for (const auto& [wa, wq, wc] : std::span(kWeights).first(dense_ ? 4 : 1))
                level_to_grown = std::max(level_to_grown, tree_->squared_distance(Point(wa * a.x() + wq * q.x() + wc * c.x(),
                                                                                        wa * a.y() + wq * q.y() + wc * c.y(),
                                                                                        wa * a.z() + wq * q.z() + wc * c.z())));
        }
        if (star.empty()) return {};
        const auto nearest = [](const Point& p, const std::vector<Triangle>& near, double bound) {
            double best = std::numeric_limits<double>::infinity();
            for (const Triangle& t : near)
                if ((best = std::min(best, CGAL::squared_distance(p, t))) <= bound) break;
            return best;
        };
        double grown_to_level = 0;
        for (const auto v : {profile.v0(), profile.v1()})
            for (const Point& p : (*merged_)[v.idx()]) grown_to_level = std::max(grown_to_level, nearest(p, star, grown_to_level));
        // The grown vertices merged into the vertices around the edge lay
        // near triangles the collapse moves: their distance to the new star
        // and their own unmoved triangles.
        const auto& mesh = profile.surface_mesh();
        std::vector<Triangle> near;
        for (const auto u : profile.link()) {
            near.assign(star.begin(), star.end());
            for (const auto f : CGAL::faces_around_target(halfedge(u, mesh), mesh)) {
                if (f == boost::graph_traits<Surface>::null_face()) continue;
                const auto h = halfedge(f, mesh);
                const auto a = source(h, mesh), b = target(h, mesh), c = target(next(h, mesh), mesh);
                if (a == profile.v0() || a == profile.v1() || b == profile.v0() || b == profile.v1() ||
                    c == profile.v0() || c == profile.v1())
                    continue;
                near.emplace_back(get(vpm, a), get(vpm, b), get(vpm, c));
            }
            for (const Point& p : (*merged_)[u.idx()]) grown_to_level = std::max(grown_to_level, nearest(p, near, grown_to_level));
        }
        return std::sqrt(std::max(level_to_grown, grown_to_level)) + tie_weight_ * *base;
    }

private:
    BaseCost base_;
    double tie_weight_;
    bool dense_;
    std::shared_ptr<Tree> tree_;  // CGAL copies its policies: they share these
    std::shared_ptr<std::vector<std::vector<Point>>> merged_;  // grown vertices merged into each vertex
};

}  // namespace morphogen::lods
