#include "growth/contact_guard.hpp"

#include "growth/contact_geometry.hpp"
#include "mesh/face_pair.hpp"
#include "mesh/fan_certificate.hpp"

#include <algorithm>

namespace morphogen {

namespace {

Box3 face_box(const std::vector<Vec3>& x, const Face& f) { return Box3::of(x[f[0]], x[f[1]], x[f[2]]); }

}  // namespace

void ContactGuard::list_faces(const std::vector<Vec3>& now, const std::vector<Vec3>& before,
                              const std::vector<Face>& faces, double r) {
    const std::size_t F = faces.size();
    boxes_.resize(F);
    swept_.resize(F);
    double extent = 0.0;
    for (std::size_t f = 0; f < F; ++f) {
        swept_[f] = face_box(now, faces[f]).merged(face_box(before, faces[f]));
        boxes_[f] = swept_[f].inflated(r);
        extent += (boxes_[f].hi - boxes_[f].lo).maxCoeff();
    }
    // Cells about as large as a listed box: each box in a few cells, a point
    // query in one. Moving faces in one grid, still ones in the other: a
    // still vertex looks only among the moving faces, and where none moves
    // near it (a dormant trunk, a stopped surface) one bounds test decides.
    const double cell = F > 0 && extent > 0.0 ? extent / static_cast<double>(F) : 1.0;
    for (const bool moving : {true, false}) {
        grid_boxes_.clear();
        grid_ids_.clear();
        for (std::size_t f = 0; f < F; ++f)
            if ((face_moving_[f] != 0) == moving) {
                grid_boxes_.push_back(boxes_[f]);
                grid_ids_.push_back(static_cast<int>(f));
            }
        (moving ? moving_grid_ : still_grid_).build(grid_boxes_, grid_ids_, cell);
    }
    listed_ = true;
}

void ContactGuard::test_pair(int v, int f, const std::vector<Vec3>& x, const std::vector<Vec3>& before,
                             const std::vector<Face>& faces, double r) {
    const Face& t = faces[f];
    if (t[0] == v || t[1] == v || t[2] == v) return;
    if (!(displaced_[v] | displaced_[t[0]] | displaced_[t[1]] | displaced_[t[2]])) return;
    const unsigned corners = touches(v, f, x, before, faces, r);
    if (corners == 0) return;
    // v, and the corners of f its nearest point lies between.
    if (displaced_[v]) refuse_[v] = 1;
    for (int k = 0; k < 3; ++k)
        if ((corners >> k & 1U) != 0 && displaced_[t[k]]) refuse_[t[k]] = 1;
}

unsigned ContactGuard::touches(int v, int f, const std::vector<Vec3>& now, const std::vector<Vec3>& before,
                               const std::vector<Face>& faces, double r) {
    const auto [a, b, c] = faces[f];
    const TriangleDistance d = distance_to_triangle(now[v], now[a], now[b], now[c]);
    if (d.squared < r * r) return d.corners;
    // Crossed: v changed sides of f's plane over the move. Where the side
    // changes sign (everything moving linearly), v must be near f.
    const double s0 = (before[b] - before[a]).cross(before[c] - before[a]).dot(before[v] - before[a]);
    const double s1 = (now[b] - now[a]).cross(now[c] - now[a]).dot(now[v] - now[a]);
    if (!((s0 < 0.0 && s1 > 0.0) || (s0 > 0.0 && s1 < 0.0))) return 0;
    const double t = s0 / (s0 - s1);
    const auto at = [&](int u) { return Vec3(before[u] + t * (now[u] - before[u])); };
    const TriangleDistance crossing = distance_to_triangle(at(v), at(a), at(b), at(c));
    return crossing.squared < r * r ? crossing.corners : 0;
}

bool ContactGuard::edges_cross(int a, int b, int c, int d, const std::vector<Vec3>& now,
                               const std::vector<Vec3>& before, double r) {
    // Crossed: the four ends changed from one side of coplanar to the other
    // over the move; where (everything moving linearly), the segments must be
    // near.
    const auto side = [&](const std::vector<Vec3>& q) { return (q[b] - q[a]).cross(q[d] - q[c]).dot(q[c] - q[a]); };
    const double s0 = side(before), s1 = side(now);
    if (!((s0 < 0.0 && s1 > 0.0) || (s0 > 0.0 && s1 < 0.0))) return false;
    // Clearly on each side (|s| above 1e-6 of its scale): two edges of a flat
    // patch are coplanar to rounding, and their signs are noise.
    const auto clear = [&](const std::vector<Vec3>& q, double side_value) {
        return side_value * side_value >
               1e-12 * (q[b] - q[a]).squaredNorm() * (q[d] - q[c]).squaredNorm() * (q[c] - q[a]).squaredNorm();
    };
    if (!clear(before, s0) || !clear(now, s1)) return false;
    const double t = s0 / (s0 - s1);
    const auto at = [&](int u) { return Vec3(before[u] + t * (now[u] - before[u])); };
    return segment_distance_squared(at(a), at(b), at(c), at(d)) < r * r;
}

void ContactGuard::test_face_edges(int f, int g, const std::vector<Vec3>& x, const std::vector<Vec3>& before,
                                   const std::vector<Face>& faces, double r) {
    const Face &s = faces[f], &t = faces[g];
    for (const int u : s)
        if (u == t[0] || u == t[1] || u == t[2]) return;  // a fan's pair (2.)
    if (!(displaced_[s[0]] | displaced_[s[1]] | displaced_[s[2]] | displaced_[t[0]] | displaced_[t[1]] | displaced_[t[2]]))
        return;
    if (!swept_[f].overlaps(swept_[g])) return;  // no edge of one meets an edge of the other's box
    const auto edge_box = [&](int u, int w) { return Box3::of(before[u], x[u], x[u]).merged(Box3::of(before[w], x[w], x[w])); };
    Box3 edges_f[3], edges_g[3];
    for (int k = 0; k < 3; ++k) {
        edges_f[k] = edge_box(s[k], s[(k + 1) % 3]);
        edges_g[k] = edge_box(t[k], t[(k + 1) % 3]);
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int a = s[i], b = s[(i + 1) % 3], c = t[j], d = t[(j + 1) % 3];
            if (!(displaced_[a] | displaced_[b] | displaced_[c] | displaced_[d])) continue;
            if (!edges_f[i].overlaps(edges_g[j])) continue;  // they never meet
            if (!edges_cross(a, b, c, d, x, before, r)) continue;
            for (const int u : {a, b, c, d})
                if (displaced_[u]) refuse_[u] = 1;
        }
}

void ContactGuard::test_edges_near(int f, const std::vector<Vec3>& x, const std::vector<Vec3>& before,
                                   const std::vector<Face>& faces, double r) {
    face_seen_.resize(faces.size(), 0);
    if (++face_query_ == 0) {  // wrapped: every mark is stale
        std::fill(face_seen_.begin(), face_seen_.end(), 0u);
        face_query_ = 1;
    }
    const auto test = [&](int g) {
        if (g == f || face_seen_[g] == face_query_) return;
        face_seen_[g] = face_query_;
        test_face_edges(f, g, x, before, faces, r);
    };
    moving_grid_.for_each_meeting(boxes_[f], test);
    still_grid_.for_each_meeting(boxes_[f], test);
}

void ContactGuard::refuse_tangled_fans(const TriMesh& mesh, const std::vector<char>& check, std::span<const int> neighbour_offsets,
                                       std::span<const int> neighbours) {
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (!check[v] || fan_certified(mesh, v, spokes_)) continue;
        if (displaced_[v]) refuse_[v] = 1;
        for (int k = neighbour_offsets[v]; k < neighbour_offsets[v + 1]; ++k)
            if (displaced_[neighbours[k]]) refuse_[neighbours[k]] = 1;
    }
}

void ContactGuard::settle_move(TriMesh& mesh, const std::vector<Vec3>& before, std::span<const int> neighbour_offsets,
                               std::span<const int> neighbours, double contact_distance, std::vector<int>& touching) {
    std::vector<Vec3>& x = mesh.positions();
    const std::vector<Face>& faces = mesh.faces();
    const int V = mesh.num_vertices(), F = mesh.num_faces();
    const double r = contact_distance;
    touching.clear();
    listed_ = false;
    displaced_.assign(V, 0);
    bool any = false;
    for (int v = 0; v < V; ++v) any |= (displaced_[v] = x[v] != before[v]) != 0;
    if (!any) return;
    face_moving_.resize(F);
    for (int f = 0; f < F; ++f)
        face_moving_[f] = displaced_[faces[f][0]] | displaced_[faces[f][1]] | displaced_[faces[f][2]];
    list_faces(x, before, faces, r);
    refuse_.assign(V, 0);
    // Round 0. 1. Every vertex against the faces listed near its path; a pair
    // counts when one of its four vertices moves. Decided from the proposed
    // state alone.
    for (int v = 0; v < V; ++v) {
        const Box3 path = Box3::of(before[v], x[v], x[v]);
        const auto test = [&](int f) { test_pair(v, f, x, before, faces, r); };
        moving_grid_.for_each_meeting(path, test);
        if (displaced_[v]) still_grid_.for_each_meeting(path, test);
    }
    // 2. Every fan the move changes must stay certified (no two of its faces
    // can meet): the faces around a vertex are too close for the distance.
    check_.assign(V, 0);
    for (int v = 0; v < V; ++v) {
        bool changed = displaced_[v] != 0;
        for (int k = neighbour_offsets[v]; k < neighbour_offsets[v + 1] && !changed; ++k)
            changed = displaced_[neighbours[k]] != 0;
        check_[v] = changed;
    }
    refuse_tangled_fans(mesh, check_, neighbour_offsets, neighbours);
    // 3. Rounds until none refuses more: the vertices refused in the last
    // round go back; every pair and fan they are part of is tested again at
    // the positions now (a face with a corner gone back is a new triangle).
    // Each round refuses at least one more vertex or is the last.
    for (;;) {
        reverted_.clear();
        for (int v = 0; v < V; ++v)
            if (refuse_[v] && displaced_[v]) reverted_.push_back(v);
        if (reverted_.empty()) break;
        check_.assign(V, 0);
        for (const int v : reverted_) {
            x[v] = before[v];
            displaced_[v] = 0;
            check_[v] = 2;  // gone back this round
            for (int k = neighbour_offsets[v]; k < neighbour_offsets[v + 1]; ++k) check_[neighbours[k]] |= 1;
        }
        // Pairs with a reverted vertex as the point: its path's box (it lies
        // in both grids' listed boxes wherever it is now).
        for (const int v : reverted_) {
            const Box3 path = Box3::of(before[v], x[v], x[v]);
            const auto test = [&](int f) { test_pair(v, f, x, before, faces, r); };
            moving_grid_.for_each_meeting(path, test);
            still_grid_.for_each_meeting(path, test);
        }
        // Pairs with a reverted vertex on the face: every vertex listed near
        // the face (a corner of a face whose listed box meets its box).
        for (int f = 0; f < F; ++f) {
            const Face& t = faces[f];
            if (!((check_[t[0]] | check_[t[1]] | check_[t[2]]) & 2)) continue;
            vertex_seen_.resize(V, 0);
            if (++vertex_query_ == 0) {  // wrapped: every mark is stale
                std::fill(vertex_seen_.begin(), vertex_seen_.end(), 0u);
                vertex_query_ = 1;
            }
            const auto test = [&](int g) {
                for (const int w : faces[g]) {
                    if (vertex_seen_[w] == vertex_query_) continue;
                    vertex_seen_[w] = vertex_query_;
                    test_pair(w, f, x, before, faces, r);
                }
            };
            moving_grid_.for_each_meeting(boxes_[f], test);
            still_grid_.for_each_meeting(boxes_[f], test);
            // Edges: a face with a corner gone back is a new triangle, whose
            // edges its moving corners may sweep through another surface's.
            test_edges_near(f, x, before, faces, r);
        }
        refuse_tangled_fans(mesh, check_, neighbour_offsets, neighbours);
    }
    for (int v = 0; v < V; ++v)
        if (refuse_[v]) touching.push_back(v);
    refused += touching.size();
    // The listed boxes hold the faces over the whole move, so wherever each
    // vertex ended: the flip guard uses them as they are.
}

void ContactGuard::face_changed(const TriMesh& mesh, int f) {
    if (!listed_) return;  // nothing moved: the flip guard lists from scratch
    const Box3 box = face_box(mesh.positions(), mesh.face(f));
    if (f < static_cast<int>(boxes_.size()) && boxes_[f].contains(box)) return;
    if (f >= static_cast<int>(boxes_.size())) boxes_.resize(static_cast<std::size_t>(f) + 1, box);
    boxes_[f] = box;
    still_grid_.insert(f, box);
}

bool ContactGuard::allows(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) {
    const std::vector<Vec3>& x = mesh.positions();
    if (!listed_) {
        face_moving_.assign(mesh.faces().size(), 0);
        list_faces(x, x, mesh.faces(), 0.0);
    }
    const IndexedTriangle tf = IndexedTriangle::of(x, new_f), tg = IndexedTriangle::of(x, new_g);
    for (const IndexedTriangle* t : {&tf, &tg})
        if (triangle_degenerate(t->p[0], t->p[1], t->p[2])) return false;
    if (faces_intersect(tf, tg)) return false;
    seen_.resize(boxes_.size(), 0);
    for (const IndexedTriangle* t : {&tf, &tg}) {
        const Box3 box = Box3::of(t->p[0], t->p[1], t->p[2]);
        if (++query_ == 0) {  // wrapped: every mark is stale
            std::fill(seen_.begin(), seen_.end(), 0u);
            query_ = 1;
        }
        bool hit = false;
        const auto test = [&](int j) {
            if (hit || j == f || j == g || seen_[j] == query_) return;
            seen_[j] = query_;
            const Face& fj = mesh.face(j);
            if (box.overlaps(face_box(x, fj)) && faces_intersect(*t, IndexedTriangle::of(x, fj))) hit = true;
        };
        moving_grid_.for_each_meeting(box, test);
        still_grid_.for_each_meeting(box, test);
        if (hit) return false;
    }
    // The new faces lie in the old pair's boxes; listed again, so later flips
    // of the pass see them as they are.
    const Box3 pair = boxes_[f].merged(boxes_[g]);
    for (const int h : {f, g}) {
        boxes_[h] = pair;
        still_grid_.insert(h, pair);
    }
    return true;
}

}  // namespace morphogen
