#include "core/growth/contact/flip_pass.hpp"

#include <bit>
#include <cstdint>
#include <vector>

namespace morphogen {

namespace {

// docs/algorithm.md §5.4's first flip test, |AC| < |BD|: one definition for every caller, so
// the flip pass's marks and try_flip can never round differently.
inline bool diagonal_shorter(const Vec3& pa, const Vec3& pb, const Vec3& pc, const Vec3& pd) {
    return (pc - pa).squaredNorm() < (pd - pb).squaredNorm();
}

// Whether half-edge h could flip in a pass: h < opposite(h) (the edge's
// lower face visits it) and the other diagonal is shorter (the first
// test of docs/algorithm.md §5.4). Every flip needs this; few edges have it.
bool flip_candidate(const TriMesh& mesh, int h) {
    const int o = mesh.opposite(h);
    if (!(h < o)) return false;  // the edge is visited from its lower face only (f < g)
    const Face& t = mesh.face(h / 3);
    const int e = h % 3;
    const Vec3& pb = mesh.position(t[e]);
    const Vec3& pd = mesh.position(t[(e + 1) % 3]);
    const Vec3& pa = mesh.position(t[(e + 2) % 3]);
    const Vec3& pc = mesh.position(mesh.from_vertex(TriMesh::prev(o)));
    return diagonal_shorter(pa, pb, pc, pd);
}

}  // namespace

bool try_flip(TriMesh& mesh, int f, int e, const FlipCriteria& criteria) {
    const int h = 3 * f + e;
    const int hg = mesh.opposite(h);
    const int g = hg / 3;
    if (!(f < g)) return false;
    const int B = mesh.face(f)[e], D = mesh.face(f)[(e + 1) % 3], A = mesh.face(f)[(e + 2) % 3];
    const int C = mesh.face(g)[(hg % 3 + 2) % 3];

    if (mesh.valence(B) <= criteria.min_valence || mesh.valence(D) <= criteria.min_valence) return false;
    const Vec3 &pa = mesh.position(A), &pb = mesh.position(B), &pc = mesh.position(C), &pd = mesh.position(D);
    if (!diagonal_shorter(pa, pb, pc, pd)) return false;

    const Vec3 cross_abd = (pb - pa).cross(pd - pa);
    const Vec3 cross_bcd = (pc - pb).cross(pd - pb);
    const double len_abd = cross_abd.norm(), len_bcd = cross_bcd.norm();
    if (!(len_abd > 0.0) || !(len_bcd > 0.0)) return false;  // zero area: no normal
    const Vec3 n_abd = cross_abd / len_abd, n_bcd = cross_bcd / len_bcd;
    if (!(n_abd.dot(n_bcd) >= criteria.min_normal_dot)) return false;
    const Vec3 n_sum = n_abd + n_bcd;
    if (!((pb - pa).cross(pc - pa).dot(n_sum) > 0.0)) return false;
    if (!((pd - pc).cross(pa - pc).dot(n_sum) > 0.0)) return false;
    if (!mesh.can_flip(f, e)) return false;  // A == C, or A and C already joined
    if (criteria.guard != nullptr && !criteria.guard->allows(mesh, f, g, {A, B, C}, {C, D, A})) return false;
    mesh.flip(f, e);
    return true;
}

int flip_pass(TriMesh& mesh, const FlipCriteria& criteria) {
    // Only a candidate (visited from its lower face, diagonal AC shorter than
    // BD) can flip, and few are: mark them all in one sweep, then
    // run try_flip on the marked half-edges in the order of docs/algorithm.md §5.4 (h = 3f + e).
    // Positions do not move during the pass, so a mark stays right until a flip
    // rewrites the quad around an edge: the half-edges of the two flipped faces
    // and their four outer partners. Their marks are recomputed, for those not
    // yet visited (index > h), so the pass equals the plain loop exactly.
    const int H = 3 * mesh.num_faces();
    std::vector<std::uint64_t> marks((static_cast<std::size_t>(H) + 63) / 64, 0);
    // flip_candidate(h) for every h, face by face so each face's positions are
    // loaded once (calling it per half-edge measured 1.6x slower).
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const Face& t = mesh.face(f);
        const Vec3* p[3] = {&mesh.position(t[0]), &mesh.position(t[1]), &mesh.position(t[2])};
        for (int e = 0; e < 3; ++e) {
            const int h = 3 * f + e, o = mesh.opposite(h);
            if (!(h < o)) continue;  // (a branch, not a mask: measured 40 % faster)
            const Vec3& pc = mesh.position(mesh.from_vertex(TriMesh::prev(o)));
            const bool mark = diagonal_shorter(*p[(e + 2) % 3], *p[e], pc, *p[(e + 1) % 3]);
            marks[h >> 6] |= static_cast<std::uint64_t>(mark) << (h & 63);
        }
    }
    int flips = 0;
    for (std::size_t word = 0; word < marks.size(); ++word) {
        while (marks[word] != 0) {
            const int h = static_cast<int>(word * 64) + std::countr_zero(marks[word]);
            marks[word] &= marks[word] - 1;
            const int f = h / 3, g = mesh.opposite(h) / 3;
            if (!try_flip(mesh, f, h % 3, criteria)) continue;
            ++flips;
            int touched[10];
            for (int k = 0; k < 3; ++k) {
                touched[k] = 3 * f + k;
                touched[3 + k] = 3 * g + k;
            }
            touched[6] = mesh.opposite(3 * f + 0);  // A->B's partner
            touched[7] = mesh.opposite(3 * f + 1);  // B->C's partner
            touched[8] = mesh.opposite(3 * g + 0);  // C->D's partner
            touched[9] = mesh.opposite(3 * g + 1);  // D->A's partner
            for (const int u : touched) {
                if (u <= h) continue;  // already visited in this pass
                const std::uint64_t bit = std::uint64_t{1} << (u & 63);
                if (flip_candidate(mesh, u))
                    marks[u >> 6] |= bit;
                else
                    marks[u >> 6] &= ~bit;
            }
        }
    }
    return flips;
}

}  // namespace morphogen
