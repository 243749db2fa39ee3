#include "core/collision.hpp"

#include <algorithm>
#include <chrono>

namespace morphogen {

namespace {

Box3 face_box(const std::vector<Vec3>& x, const Face& f) { return Box3::of(x[f[0]], x[f[1]], x[f[2]]); }

}  // namespace

void CollisionGuard::settle_move(TriMesh& mesh, const std::vector<Vec3>& before) {
    std::vector<Vec3>& x = mesh.positions();
    const std::vector<Face>& faces = mesh.faces();
    const int V = mesh.num_vertices(), F = mesh.num_faces();
    proposed_.assign(x.begin(), x.end());
    scale_.assign(V, 0.0);
    changed_.assign(V, 0);
    bool any = false;
    for (int v = 0; v < V; ++v)
        if (x[v] != before[v]) {
            scale_[v] = 1.0;
            changed_[v] = 1;
            any = true;
        }
    // The grid lists each face's box over its whole move: wherever a vertex
    // ends between `before` and `proposed`, the face stays inside it (a
    // rounded before + s * (proposed - before) is monotone in s), so one grid
    // serves every round, and the split and flip phases after.
    swept_.resize(F);
    boxes_.resize(F);
    double extent_sum = 0.0, extent_max = 0.0;
    triangles_.resize(F);
    for (int f = 0; f < F; ++f) {
        triangles_[f] = IndexedTriangle::of(x, faces[f]);
        boxes_[f] = face_box(x, faces[f]);
        swept_[f] = boxes_[f].merged(face_box(before, faces[f]));
        const double extent = (swept_[f].hi - swept_[f].lo).maxCoeff();
        extent_sum += extent;
        extent_max = std::max(extent_max, extent);
    }
    // Cells about as large as a face: a face lies in a few cells and a cell
    // holds a few faces. No box spans more than 17 cells a side.
    double cell = std::max(extent_sum / std::max(F, 1), extent_max / 16.0);
    if (!(cell > 0.0)) cell = 1.0;
    grid_.build(cell, swept_);
    stamp_.assign(F, 0);
    query_ = 0;
    if (!any) return;

    for (int round = 0; find_collisions(mesh); ++round) {
        // Every vertex of an intersecting face that still moves halves its
        // step, or after kHalvings rounds goes back to where it was. A set, not
        // a sequence: the order pairs were found in does not matter.
        std::fill(changed_.begin(), changed_.end(), 0);
        for (int v = 0; v < V; ++v) {
            if (!hit_[v] || scale_[v] == 0.0) continue;
            if (scale_[v] == 1.0) ++shortened;
            scale_[v] = round < kHalvings ? 0.5 * scale_[v] : 0.0;
            if (scale_[v] == 0.0) ++refused;
            x[v] = scale_[v] == 0.0 ? before[v] : Vec3(before[v] + scale_[v] * (proposed_[v] - before[v]));
            changed_[v] = 1;
        }
    }
}

bool CollisionGuard::find_collisions(const TriMesh& mesh) {
    const std::vector<Vec3>& x = mesh.positions();
    const std::vector<Face>& faces = mesh.faces();
    const int F = mesh.num_faces();
    face_active_.assign(F, 0);
    active_.clear();
    for (int f = 0; f < F; ++f) {
        const Face& t = faces[f];
        if (changed_[t[0]] || changed_[t[1]] || changed_[t[2]]) {
            face_active_[f] = 1;
            active_.push_back(f);
            boxes_[f] = face_box(x, t);
            triangles_[f] = IndexedTriangle::of(x, t);
        }
    }
    if (active_.empty()) return false;
    hit_.assign(x.size(), 0);
    bool found = false;
    const auto mark = [&](const Face& t) {
        for (int v : t) hit_[v] = 1;
        found = true;
    };
    for (const int i : active_) {
        const IndexedTriangle& ti = triangles_[i];
        if (triangle_degenerate(ti.p[0], ti.p[1], ti.p[2])) mark(faces[i]);
        ++query_;
        const Box3& box = boxes_[i];
        grid_.for_each_candidate(swept_[i], [&](int j, const Box3& listed) {
            // Each pair once: two active faces from the lower one. The listed
            // (swept) box holds j's box now: most candidates end at the first test.
            if (!listed.overlaps(box) || j == i || (face_active_[j] && j < i) || !first_visit(j)) return;
            if (box.overlaps(boxes_[j]) && faces_intersect(ti, triangles_[j])) {
                mark(faces[i]);
                mark(faces[j]);
            }
        });
    }
    return found;
}

void CollisionGuard::face_changed(const TriMesh& mesh, int f) {
    if (static_cast<std::size_t>(f) >= stamp_.size()) stamp_.resize(static_cast<std::size_t>(f) + 1, 0);
    grid_.insert(f, face_box(mesh.positions(), mesh.face(f)));
}

bool CollisionGuard::allows(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) {
    if (!timed) return allows_untimed(mesh, f, g, new_f, new_g);
    const auto start = std::chrono::steady_clock::now();
    const bool allowed = allows_untimed(mesh, f, g, new_f, new_g);
    flip_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return allowed;
}

bool CollisionGuard::allows_untimed(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) {
    const std::vector<Vec3>& x = mesh.positions();
    const IndexedTriangle tf = IndexedTriangle::of(x, new_f), tg = IndexedTriangle::of(x, new_g);
    for (const IndexedTriangle* t : {&tf, &tg})
        if (triangle_degenerate(t->p[0], t->p[1], t->p[2])) return false;
    if (faces_intersect(tf, tg)) return false;
    for (const IndexedTriangle* t : {&tf, &tg}) {
        const Box3 box = Box3::of(t->p[0], t->p[1], t->p[2]);
        ++query_;
        bool hit = false;
        grid_.for_each_candidate(box, [&](int j, const Box3& listed) {
            // A stale listing (j changed since) may fail here; j's newer one follows.
            if (hit || !listed.overlaps(box) || j == f || j == g || !first_visit(j)) return;
            const IndexedTriangle tj = IndexedTriangle::of(x, mesh.face(j));
            if (box.overlaps(Box3::of(tj.p[0], tj.p[1], tj.p[2])) && faces_intersect(*t, tj)) hit = true;
        });
        if (hit) return false;
    }
    face_changed(mesh, f);
    face_changed(mesh, g);
    return true;
}

}  // namespace morphogen
