#pragma once
// A mesh as its surface connects: vertices with equal coordinates merged
// (files such as STL repeat a vertex in every triangle), triangles left with
// a repeated vertex dropped, and only the vertices of the remaining
// triangles kept. Thread-safe; O(V log V + F).
#include "core/mesh/mesh.hpp"

namespace morphogen {

// Assumes a checked view (check_mesh_view). Vertex order: by (x, y, z).
MeshArrays welded_mesh(MeshView mesh);

}  // namespace morphogen
