#pragma once
// A proof that no two faces around one vertex intersect (docs/algorithm.md
// §5.7), for the collision guard: pairs of faces sharing a vertex or an
// edge are most of the pairs it meets, and one certificate per vertex
// replaces all the pair tests of its fan.
//
// The certificate: with N the sum of the fan's face cross products, every
// face (v, u_k, u_k+1) is positively oriented seen along N, and the 1-ring,
// projected onto the plane normal to N, winds once around v. Then the
// projection maps the fan one to one onto a star around v, so two faces of
// the fan meet only in v or in their common edge: no pair sharing v
// intersects by the rule of core/mesh/face_pair.hpp (no opposite edge meets the
// other face; a common edge has the third corners on opposite sides), and
// no face of the fan is degenerate. Every sign the proof uses is certified
// with rounding bounds; where it cannot tell, it answers false.
#include "core/mesh/mesh.hpp"

#include <vector>

namespace morphogen {

// Whether the fan of v, at the mesh's positions, is certified as above.
// `scratch` holds the spokes (u_k - v, in the order of the ring) and the
// faces' cross products.
bool fan_certified(const TriMesh& mesh, int v, std::vector<Vec3>& scratch);

}  // namespace morphogen
