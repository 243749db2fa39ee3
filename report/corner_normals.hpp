#pragma once
// Normals for smooth shading with crisp creases: each corner of a face gets
// the area-weighted mean of the normals of the faces around its vertex that
// bend less than the crease angle from this face (as modellers' "auto
// smooth" does). A smooth surface shades like its per-vertex normals (the
// ones the mesh writers store); a real crease, such as a cube's edge, stays
// sharp on both sides.
#include "core/mesh/mesh.hpp"

#include <array>
#include <vector>

namespace morphogen {

// One unit normal per corner of every face, in face order; zero for a face
// with no area or a non-finite vertex. Faces bending more than
// `crease_angle_deg` from a neighbour keep their edge (0: every corner takes
// its face's normal, flat shading). Faces must index existing vertices.
std::vector<std::array<Vec3, 3>> corner_normals(MeshView mesh, double crease_angle_deg);

}  // namespace morphogen
