#pragma once
// Whether any two faces of a mesh intersect, by the exact rule of
// docs/algorithm.md §5.7 ("When two faces intersect": CGAL's
// does_self_intersect, decided by core/mesh/face_pair.hpp), over the whole mesh
// at once. growth.collisions "touch" runs it once after growth, as its
// fail-safe (§5.7.1): the fitness's own check (CGAL's) lives in fitness/,
// above growth/.
//
// One grid of face boxes (core/mesh/spatial_hash.hpp); pairs sharing a vertex
// whose fan is certified (core/mesh/fan_certificate.hpp) are skipped, as the
// collision guard skips them: the certificate proves them apart. Neither
// changes the answer, only how fast it comes. Deterministic.
#include "core/mesh/mesh.hpp"
#include "core/mesh/spatial_hash.hpp"

#include <cstdint>
#include <vector>

namespace morphogen {

class SelfIntersectionCheck {
public:
    // True if some face is degenerate or some two faces intersect.
    bool intersects(const TriMesh& mesh);

private:
    std::vector<Box3> boxes_;          // per face
    std::vector<char> certified_;      // per vertex: its fan certified
    std::vector<std::uint32_t> seen_;  // per face: the last query that met it
    std::vector<Vec3> scratch_;
    SpatialHash grid_;
};

}  // namespace morphogen
