#include "core/growth/contact/collision.hpp"

#include "core/mesh/fan_certificate.hpp"

#include <algorithm>

namespace morphogen {

namespace {

Box3 face_box(const std::vector<Vec3>& x, const Face& f) { return Box3::of(x[f[0]], x[f[1]], x[f[2]]); }

// How far a listing box reaches beyond the face's box (any margin is
// correct; it only trades lookups against partners). A face moving by `step`
// (its fastest corner, per coordinate) a step is listed again after some
// kMarginSteps such steps; a still or changed face gets a small share of its size.
constexpr double kMarginSteps = 4.0;
constexpr double kAheadSteps = 16.0;
constexpr double kMarginOfSize = 0.01;
double listing_margin(const Box3& box, double step) {
    return kMarginSteps * step + kMarginOfSize * (box.hi - box.lo).maxCoeff();
}

bool share_a_vertex(const Face& a, const Face& b) {
    for (const int v : a)
        if (v == b[0] || v == b[1] || v == b[2]) return true;
    return false;
}

}  // namespace

bool CollisionGuard::in_step(const TriMesh& mesh, const std::vector<Vec3>& before) const {
    return listing_.size() == mesh.num_faces() && faces_ == mesh.faces() && positions_ == before;
}

void CollisionGuard::list_from_scratch(const TriMesh& mesh, const std::vector<Vec3>& before) {
    listing_.clear();
    faces_ = mesh.faces();
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const Box3 box = face_box(before, faces_[f]);
        listing_.relist(f, box.inflated(listing_margin(box, 0.0)));
    }
}

void CollisionGuard::settle_move(TriMesh& mesh, const std::vector<Vec3>& before) {
    std::vector<Vec3>& x = mesh.positions();
    const std::vector<Face>& faces = mesh.faces();
    const int V = mesh.num_vertices(), F = mesh.num_faces();
    if (!in_step(mesh, before)) list_from_scratch(mesh, before);
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
    // Every position a vertex takes in the rounds below lies between `before`
    // and `proposed` (a rounded before + s * (proposed - before), s a power of
    // two, is monotone in s), so a face stays inside the box of its move; the
    // listing box already holds its box before the move, and is widened only
    // where the box after the move leaves it.
    for (int f = 0; f < F; ++f) {
        const Face& t = faces[f];
        if (!(changed_[t[0]] | changed_[t[1]] | changed_[t[2]])) continue;
        const Box3 after = face_box(x, t);
        if (listing_.box(f).contains(after)) continue;
        // In the paper's model vertices keep their direction (h_i, §5.2): the
        // box reaches as far as kAheadSteps more such moves would take the
        // face. (In the branching mode, §5.8, directions turn: a face then
        // leaves its box sooner and is listed again; the reach only sizes
        // the box, the containment test above decides.)
        Vec3 ahead[3];
        for (int k = 0; k < 3; ++k) ahead[k] = x[t[k]] + kAheadSteps * (x[t[k]] - before[t[k]]);
        const Box3 swept = after.merged(face_box(before, t)).merged(Box3::of(ahead[0], ahead[1], ahead[2]));
        listing_.relist(f, swept.inflated(listing_margin(after, 0.0)));
    }
    // Pairs sharing a vertex are met around the vertex (find_collisions);
    // whether a pair shares one changes only when a face changes, and a
    // changed face is relisted.
    listing_.refresh([this](int f, int g) { return !share_a_vertex(faces_[f], faces_[g]); });
    boxes_.resize(F);
    for (int f = 0; f < F; ++f) boxes_[f] = face_box(x, faces[f]);
    triangles_.resize(F);
    triangle_known_.assign(F, 0);
    fan_known_.assign(V, 0);
    fan_ok_.resize(V, 0);
    fan_stamp_.resize(V, 0);

    for (int round = 0; any && find_collisions(mesh); ++round) {
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
            fan_known_[v] = 0;
            mesh.for_each_neighbour(v, [&](int u) { fan_known_[u] = 0; });
        }
    }
    positions_.assign(x.begin(), x.end());
}

const IndexedTriangle& CollisionGuard::triangle(const TriMesh& mesh, int f) {
    if (!triangle_known_[f]) {
        triangles_[f] = IndexedTriangle::of(mesh.positions(), mesh.face(f));
        triangle_known_[f] = 1;
    }
    return triangles_[f];
}

bool CollisionGuard::fan_ok(const TriMesh& mesh, int v) {
    if (!fan_known_[v]) {
        fan_ok_[v] = fan_certified(mesh, v, spokes_);
        fan_known_[v] = 1;
    }
    return fan_ok_[v];
}

void CollisionGuard::collect_fan(const TriMesh& mesh, int v, int some_face) {
    const Face& t = mesh.face(some_face);
    const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    const int start = 3 * some_face + k;  // a half-edge leaving v
    fan_faces_.clear();
    int h = start;
    do {
        fan_faces_.push_back(TriMesh::face_of(h));
        const int into_v = h - h % 3 + (h % 3 + 2) % 3;  // the half-edge before h, in h's face
        h = mesh.opposite(into_v);
    } while (h != start);
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
            triangle_known_[f] = 0;
        }
    }
    if (active_.empty()) return false;
    hit_.assign(x.size(), 0);
    bool found = false;
    const auto test = [&](int f, int g) {
        if (faces_intersect(triangle(mesh, f), triangle(mesh, g))) {
            for (const int v : faces[f]) hit_[v] = 1;
            for (const int v : faces[g]) hit_[v] = 1;
            found = true;
        }
    };
    if (++round_stamp_ == 0) {  // wrapped: every stamp is stale
        std::fill(fan_stamp_.begin(), fan_stamp_.end(), 0u);
        round_stamp_ = 1;
    }
    // Every pair with an active face whose boxes meet, once, unless a fan
    // around a shared vertex is certified.
    for (const int i : active_) {
        const Face& fi = faces[i];
        // A certified fan has no degenerate face.
        const bool certified = fan_ok(mesh, fi[0]) | fan_ok(mesh, fi[1]) | fan_ok(mesh, fi[2]);
        if (!certified && triangle_degenerate(x[fi[0]], x[fi[1]], x[fi[2]])) {
            for (const int v : fi) hit_[v] = 1;
            found = true;
        }
        // Pairs sharing v (their boxes meet at v), from v's fan, once a round.
        for (const int v : fi) {
            if (fan_ok(mesh, v) || fan_stamp_[v] == round_stamp_) continue;
            fan_stamp_[v] = round_stamp_;
            collect_fan(mesh, v, i);
            const std::size_t n = fan_faces_.size();
            for (std::size_t a = 0; a < n; ++a)
                for (std::size_t b = a + 1; b < n; ++b) {
                    const int f = fan_faces_[a], g = fan_faces_[b];
                    if (!face_active_[f] && !face_active_[g]) continue;
                    // Sharing the edge v-w too: proven by w's fan, or met
                    // again (and tested) around w where w < v.
                    int w = -1;
                    for (const int u : faces[f])
                        if (u != v && (u == faces[g][0] || u == faces[g][1] || u == faces[g][2])) w = u;
                    if (w >= 0 && (w < v || fan_ok(mesh, w))) continue;
                    test(f, g);
                }
        }
        // Pairs sharing no vertex: the partners.
        const Box3& box = boxes_[i];
        for (const int j : listing_.partners(i)) {
            if ((face_active_[j] && j < i) || !box.overlaps(boxes_[j])) continue;
            test(i, j);
        }
    }
    return found;
}

void CollisionGuard::face_changed(const TriMesh& mesh, int f) {
    const std::vector<Vec3>& x = mesh.positions();
    // A split appends its vertex (at the face's centroid) and two faces.
    while (positions_.size() < x.size()) positions_.push_back(x[positions_.size()]);
    for (int h = static_cast<int>(faces_.size()); h <= f; ++h) {
        faces_.push_back(mesh.face(h));
    }
    faces_[f] = mesh.face(f);
    const Box3 box = face_box(x, faces_[f]);
    for (int h = listing_.size(); h < f; ++h) {  // only if a caller skipped one
        const Box3 skipped = face_box(x, faces_[h]);
        listing_.relist(h, skipped.inflated(listing_margin(skipped, 0.0)));
    }
    listing_.relist(f, box.inflated(listing_margin(box, 0.0)));
}

bool CollisionGuard::allows(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) {
    const std::vector<Vec3>& x = mesh.positions();
    const IndexedTriangle tf = IndexedTriangle::of(x, new_f), tg = IndexedTriangle::of(x, new_g);
    for (const IndexedTriangle* t : {&tf, &tg})
        if (triangle_degenerate(t->p[0], t->p[1], t->p[2])) return false;
    if (faces_intersect(tf, tg)) return false;
    for (const IndexedTriangle* t : {&tf, &tg}) {
        const Box3 box = Box3::of(t->p[0], t->p[1], t->p[2]);
        bool hit = false;
        listing_.for_each_meeting(box, [&](int j) {
            if (hit || j == f || j == g) return;
            const Face& fj = mesh.face(j);
            if (!box.overlaps(face_box(x, fj))) return;
            if (faces_intersect(*t, IndexedTriangle::of(x, fj))) hit = true;
        });
        if (hit) return false;
    }
    // The flip is done: the new faces are listed for the rest of the pass,
    // so a later flip is tested against them as they are (§5.7).
    faces_[f] = new_f;
    faces_[g] = new_g;
    for (const int h : {f, g}) {
        const Box3 box = face_box(x, faces_[h]);
        listing_.relist(h, box.inflated(listing_margin(box, 0.0)));
    }
    return true;
}

}  // namespace morphogen
