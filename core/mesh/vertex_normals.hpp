#pragma once
// The smooth per-vertex normals every mesh writer stores.
#include "core/mesh/mesh.hpp"

#include <vector>

namespace morphogen {

// Unit area-weighted vertex normals (Z-up), the smooth normals every writer
// stores; exactly zero where a vertex has none (no faces, zero area or
// overflow), where writers store "up". Faces must index existing vertices.
std::vector<Vec3> vertex_normals(MeshView mesh);
// The same into `normals` (resized), reusing its storage: for growth steps.
void vertex_normals(MeshView mesh, std::vector<Vec3>& normals);

}  // namespace morphogen
