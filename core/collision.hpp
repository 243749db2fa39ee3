#pragma once
// growth.collisions "prevent" (docs/algorithm.md §5.7): the surface never
// passes through itself. A move is shortened or refused vertex by vertex
// until no two faces intersect (by the rule of core/face_pair.hpp, CGAL's);
// a flip that would make two faces intersect is refused. Single-threaded
// and deterministic: what it decides depends only on the mesh, never on the
// order it visits pairs in.
#include "core/face_pair.hpp"
#include "core/mesh.hpp"
#include "core/spatial_hash.hpp"

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
    // intersect, then lists every face in the grid for split and flip.
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
    // When `timed`, allows() adds its seconds here (the flip phase's share
    // of the collision work, for PhaseTimes::collide).
    bool timed = false;
    double flip_seconds = 0.0;

private:
    // Faces with a changed vertex against every face whose grid box meets
    // theirs; marks the vertices of intersecting pairs in hit_.
    bool find_collisions(const TriMesh& mesh);
    bool allows_untimed(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g);

    SpatialHash grid_;
    std::vector<Box3> swept_;        // per face: its box before and after the move
    std::vector<Box3> boxes_;        // per face: its box now
    std::vector<IndexedTriangle> triangles_;  // per face: as it is now
    std::vector<double> scale_;      // per vertex: the fraction of its step it takes
    std::vector<Vec3> proposed_;     // per vertex: where the move wanted it
    std::vector<char> changed_;      // per vertex: moved since the last check
    std::vector<char> hit_;          // per vertex: on a face that intersects
    std::vector<char> face_active_;  // per face: has a changed vertex
    std::vector<int> active_;
    std::vector<std::uint32_t> stamp_;  // per face: the last query that tested it
    std::uint32_t query_ = 0;
    // Each query's own stamp: candidates repeat (a face lies in several cells).
    bool first_visit(int face) {
        if (stamp_[face] == query_) return false;
        stamp_[face] = query_;
        return true;
    }
};

}  // namespace morphogen
