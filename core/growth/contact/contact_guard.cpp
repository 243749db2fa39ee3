#include "core/growth/contact/contact_guard.hpp"

#include "core/growth/contact/contact_geometry.hpp"
#include "core/mesh/face_pair.hpp"
#include "core/mesh/fan_certificate.hpp"

#include <algorithm>

namespace morphogen {

namespace {

Box3 face_box(const std::vector<Vec3>& x, const Face& f) { return Box3::of(x[f[0]], x[f[1]], x[f[2]]); }

}  // namespace

void ContactGuard::list_faces(const std::vector<Vec3>& now, const std::vector<Vec3>& before,
                              const std::vector<Face>& faces, double r, const std::vector<char>& marks) {
    const std::size_t F = faces.size();
    boxes_.resize(F);
    double extent = 0.0;
    for (std::size_t f = 0; f < F; ++f) {
        boxes_[f] = face_box(now, faces[f]).merged(face_box(before, faces[f])).inflated(r);
        extent += (boxes_[f].hi - boxes_[f].lo).maxCoeff();
    }
    // Cells about as large as a listed box: each box in a few cells, a point
    // query in one.
    const double cell = F > 0 && extent > 0.0 ? extent / static_cast<double>(F) : 1.0;
    grid_.build(boxes_, cell, marks);
    listed_ = true;
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

void ContactGuard::refuse_tangled_fans(const TriMesh& mesh, const std::vector<char>& check,
                                       std::span<const int> neighbour_offsets, std::span<const int> neighbours) {
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (!check[v]) continue;
        // A fan whose moving vertices are all refused already: its test could
        // refuse nothing new, whatever it says (a refusal only ever adds).
        bool open = moving_[v] && !refuse_[v];
        for (int k = neighbour_offsets[v]; k < neighbour_offsets[v + 1] && !open; ++k)
            open = moving_[neighbours[k]] && !refuse_[neighbours[k]];
        if (!open || fan_certified(mesh, v, spokes_)) continue;
        if (moving_[v]) refuse_[v] = 1;
        for (int k = neighbour_offsets[v]; k < neighbour_offsets[v + 1]; ++k)
            if (moving_[neighbours[k]]) refuse_[neighbours[k]] = 1;
    }
}

void ContactGuard::settle_move(TriMesh& mesh, const std::vector<Vec3>& before, std::span<const int> neighbour_offsets,
                               std::span<const int> neighbours, double contact_distance, std::vector<int>& touching) {
    std::vector<Vec3>& x = mesh.positions();
    const std::vector<Face>& faces = mesh.faces();
    const int V = mesh.num_vertices();
    touching.clear();
    listed_ = false;
    moving_.assign(V, 0);
    bool any = false;
    for (int v = 0; v < V; ++v) any |= (moving_[v] = x[v] != before[v]) != 0;
    if (!any) return;
    refuse_.assign(V, 0);
    face_moving_.resize(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f)
        face_moving_[f] = moving_[faces[f][0]] | moving_[faces[f][1]] | moving_[faces[f][2]];
    list_faces(x, before, faces, contact_distance, face_moving_);
    // 1. Every vertex against the faces listed near its path; a pair counts
    // when one of its two moves. Decided from the proposed state alone.
    for (int v = 0; v < V; ++v) {
        const Box3 path = Box3::of(before[v], x[v], x[v]);
        const bool v_moves = moving_[v] != 0;
        // A vertex that stays meets only the moving faces (marked in the grid).
        grid_.for_each_meeting(path, [&](int f) {
            const Face& t = faces[f];
            if (t[0] == v || t[1] == v || t[2] == v) return;
            const unsigned corners = touches(v, f, x, before, faces, contact_distance);
            if (corners == 0) return;
            // v, and the corners of f its nearest point lies between.
            if (moving_[v]) refuse_[v] = 1;
            for (int k = 0; k < 3; ++k)
                if ((corners >> k & 1U) != 0 && moving_[t[k]]) refuse_[t[k]] = 1;
        }, !v_moves);
    }
    // 2. Every fan the move changes must stay certified (no two of its faces
    // can meet): the faces around a vertex are too close for the distance.
    check_.assign(V, 0);
    for (int v = 0; v < V; ++v) {
        bool changed = moving_[v] != 0;
        for (int k = neighbour_offsets[v]; k < neighbour_offsets[v + 1] && !changed; ++k)
            changed = moving_[neighbours[k]] != 0;
        check_[v] = changed;
    }
    refuse_tangled_fans(mesh, check_, neighbour_offsets, neighbours);
    // 3. The refused go back; the fans around them changed again, and are
    // checked once more (one round: what it refuses goes back unchecked).
    check_.assign(V, 0);
    for (int v = 0; v < V; ++v) {
        if (!refuse_[v]) continue;
        x[v] = before[v];
        check_[v] = 1;
        for (int k = neighbour_offsets[v]; k < neighbour_offsets[v + 1]; ++k) check_[neighbours[k]] = 1;
    }
    refuse_tangled_fans(mesh, check_, neighbour_offsets, neighbours);
    for (int v = 0; v < V; ++v)
        if (refuse_[v]) {
            x[v] = before[v];
            touching.push_back(v);
        }
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
    grid_.insert(f, box);
}

bool ContactGuard::allows(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) {
    const std::vector<Vec3>& x = mesh.positions();
    if (!listed_) list_faces(x, x, mesh.faces(), 0.0);
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
        grid_.for_each_meeting(box, [&](int j) {
            if (hit || j == f || j == g || seen_[j] == query_) return;
            seen_[j] = query_;
            const Face& fj = mesh.face(j);
            if (box.overlaps(face_box(x, fj)) && faces_intersect(*t, IndexedTriangle::of(x, fj))) hit = true;
        });
        if (hit) return false;
    }
    // The new faces lie in the old pair's boxes; listed again, so later flips
    // of the pass see them as they are.
    const Box3 pair = boxes_[f].merged(boxes_[g]);
    for (const int h : {f, g}) {
        boxes_[h] = pair;
        grid_.insert(h, pair);
    }
    return true;
}

}  // namespace morphogen
