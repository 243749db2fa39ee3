#pragma once
// --smooth N: LOD0 after N rounds of Loop subdivision (CGAL's
// Subdivision_method_3): every round splits each triangle in four and moves
// the vertices by Loop's masks, so the surface turns smooth and the
// triangles grow by 4^N. Vertex attributes (colours, wind data) are carried
// by the same masks, so they blend smoothly and stay within their range.
#include "core/mesh/mesh.hpp"

#include <span>
#include <string>
#include <vector>

namespace morphogen {

inline constexpr int kMaxSmoothRounds = 3;  // 64 x the triangles; a 10,000-triangle plant becomes 640,000

// Why `rounds` cannot be used ("--smooth 4: ..."), or "" for 0 .. kMaxSmoothRounds.
std::string smooth_rounds_problem(int rounds);

struct SmoothedMesh {
    MeshArrays mesh;
    // Per attribute given: its values on the smoothed vertices, as many per
    // vertex as it had.
    std::vector<std::vector<float>> attributes;
};

// `rounds` of Loop subdivision of the closed mesh `mesh`; each attribute
// (empty, or a whole number of floats per vertex) is subdivided with it.
// Throws std::invalid_argument for rounds outside 0 .. kMaxSmoothRounds or an
// attribute of another length.
SmoothedMesh smooth_mesh(MeshView mesh, int rounds, std::span<const std::span<const float>> attributes = {});

}  // namespace morphogen
