#pragma once
// growth.collisions "touch" (docs/algorithm.md §5.7.1): a vertex that comes
// within growth.contact_distance of a face (or crosses it) in a move stays
// where it was and goes dormant, and so do the moving vertices of a fan the
// move would tangle; a flip that would make two faces intersect is not done.
// Cheap by design: one grid of face boxes a step, one lookup and a few
// point-triangle tests per vertex, one fan certificate per changed fan,
// every vertex decided from the same proposed state (one more fan round
// after the refusals, no halving). It does not prove the mesh clean: a grown
// mesh is checked once, by the fitness (§10.3).
// Single-threaded and deterministic: what it decides depends only on the
// mesh, never on the order it visits pairs in.
#include "core/growth/contact/contact_grid.hpp"
#include "core/growth/contact/flip_pass.hpp"
#include "core/mesh/mesh.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace morphogen {

class ContactGuard final : public FlipGuard {
public:
    // `mesh` holds the positions the move of §5.2 proposes, `before` those it
    // had; the neighbour lists (CSR) are the mesh's. Every moving vertex of a
    // contact pair or a tangled fan (§5.7.1) goes back to `before`; they are
    // returned in `touching`, ascending. `contact_distance` > 0.
    void settle_move(TriMesh& mesh, const std::vector<Vec3>& before, std::span<const int> neighbour_offsets,
                     std::span<const int> neighbours, double contact_distance, std::vector<int>& touching);

    // Face f was written or appended by a split (§5.3), after settle_move:
    // listed where it now lies, for the flip guard.
    void face_changed(const TriMesh& mesh, int f);

    // FlipGuard: whether faces f, g may become new_f, new_g with no two faces
    // intersecting (by core/mesh/face_pair.hpp, exactly) and neither degenerate.
    // A true answer lists both again: the flip is then done.
    bool allows(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) override;

    // Vertices refused since construction.
    std::uint64_t refused = 0;

private:
    // Lists every face's box over the move (before to now), grown by r;
    // `marks` (empty or per face) as ContactGrid::build's.
    void list_faces(const std::vector<Vec3>& now, const std::vector<Vec3>& before, const std::vector<Face>& faces,
                    double r, const std::vector<char>& marks = {});
    // Whether vertex v and face f form a contact pair (v not in f): the
    // corners of f that carry the nearest point (bit k: corner k), else 0.
    static unsigned touches(int v, int f, const std::vector<Vec3>& now, const std::vector<Vec3>& before,
                            const std::vector<Face>& faces, double r);
    // Refuses the moving vertices of every fan of a vertex in `check` that is
    // not certified (core/mesh/fan_certificate.hpp) at the mesh's positions.
    void refuse_tangled_fans(const TriMesh& mesh, const std::vector<char>& check, std::span<const int> neighbour_offsets,
                             std::span<const int> neighbours);

    ContactGrid grid_;
    std::vector<Box3> boxes_;   // per face: the box it is listed with
    std::vector<char> moving_;       // per vertex: moved by the proposal
    std::vector<char> face_moving_;  // per face: has a corner that moved
    std::vector<char> refuse_;       // per vertex: to go back (in a contact pair or a tangled fan, and moving)
    std::vector<char> check_;        // per vertex: whose fan to certify
    std::vector<unsigned> seen_;  // per face: the query that met it last (allows)
    unsigned query_ = 0;
    std::vector<Vec3> spokes_;
    bool listed_ = false;  // whether the grid describes this step's faces
};

}  // namespace morphogen
