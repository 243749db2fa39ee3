#pragma once
// growth.collisions "prevent" (docs/algorithm.md §5.7): the surface never
// passes through itself. A move is shortened or refused vertex by vertex
// until no two faces intersect (by the rule of core/mesh/face_pair.hpp, CGAL's);
// a flip that would make two faces intersect is refused. Single-threaded
// and deterministic: what it decides depends only on the mesh, never on the
// order it visits pairs in.
//
// Cheap (docs/performance-collisions.md, "Collision-aware growth"): the broad phase
// (core/mesh/face_listing.hpp) lives from step to step and is only updated where
// a face left its listing box or changed, and holds only pairs sharing no
// vertex; pairs of faces around a vertex are proven apart a fan at a time
// (core/mesh/fan_certificate.hpp), and tested around the vertex where its fan is
// not certified. Neither changes a decision: a pair is skipped only when it
// is proven apart.
#include "core/growth/contact/flip_pass.hpp"
#include "core/mesh/face_listing.hpp"
#include "core/mesh/face_pair.hpp"
#include "core/mesh/mesh.hpp"
#include "core/mesh/spatial_hash.hpp"

#include <cstdint>
#include <vector>

namespace morphogen {

class CollisionGuard final : public FlipGuard {
public:
    // Times a colliding vertex's step is halved before it is refused.
    static constexpr int kHalvings = 4;

    // The move of §5.2 has put `mesh` at its proposed positions; `before` holds
    // the positions it had (same vertices, no two faces intersecting then).
    // Moves vertices back towards `before` (§5.7) until no two faces
    // intersect. Any mesh may be given: one that is not the guard's last
    // mesh (as split and flips left it) is listed from scratch.
    void settle_move(TriMesh& mesh, const std::vector<Vec3>& before);

    // Face f changed or was appended (a split, §5.3): lists it again.
    // Call after settle_move, for every face a split writes.
    void face_changed(const TriMesh& mesh, int f);

    // FlipGuard: whether faces f, g may become new_f, new_g without an
    // intersection (also between the two, and no degenerate face). A true
    // answer lists both again: the flip is then done.
    bool allows(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) override;

    // Vertices whose step was shortened, and refused, since construction.
    std::uint64_t shortened = 0, refused = 0;

private:
    // Whether the guard's listing describes this mesh (its faces, and
    // positions `before`), as the last settle, splits and flips left it.
    bool in_step(const TriMesh& mesh, const std::vector<Vec3>& before) const;
    void list_from_scratch(const TriMesh& mesh, const std::vector<Vec3>& before);
    // Every pair of faces, one with a changed vertex, whose boxes meet and
    // that no certified fan proves apart, tested; marks the vertices of
    // intersecting pairs in hit_. Pairs sharing a vertex are found around
    // the vertex, the others in the partner lists (which hold only those).
    bool find_collisions(const TriMesh& mesh);
    // Whether v's fan is certified at the positions of this round.
    bool fan_ok(const TriMesh& mesh, int v);
    // The faces around v, in ring order, into fan_faces_.
    void collect_fan(const TriMesh& mesh, int v, int some_face);
    const IndexedTriangle& triangle(const TriMesh& mesh, int f);

    FaceListing listing_;
    std::vector<Face> faces_;          // the faces the listing describes
    std::vector<Vec3> positions_;      // the positions it describes (after the settle, splits)
    std::vector<Box3> boxes_;          // per face: its box now
    std::vector<IndexedTriangle> triangles_;  // per face: as it is now, where triangle_known_
    std::vector<char> triangle_known_;
    std::vector<double> scale_;        // per vertex: the fraction of its step it takes
    std::vector<Vec3> proposed_;       // per vertex: where the move wanted it
    std::vector<char> changed_;        // per vertex: moved since the last check
    std::vector<char> hit_;            // per vertex: on a face that intersects
    std::vector<char> face_active_;    // per face: has a changed vertex
    std::vector<int> active_;
    // Per vertex, within one settle: whether fan_ok_ holds for the fan as it
    // is now (a vertex that moves forgets its own and its neighbours').
    std::vector<char> fan_known_, fan_ok_;
    std::vector<Vec3> spokes_;         // fan_certified's scratch
    std::vector<int> fan_faces_;       // collect_fan's output
    std::vector<unsigned> fan_stamp_;  // per vertex: the round its fan's pairs were tested
    unsigned round_stamp_ = 0;
};

}  // namespace morphogen
