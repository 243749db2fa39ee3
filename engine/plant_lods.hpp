#pragma once
// Levels of detail of a plant (`--lods N`; docs/file-formats.md, "Levels of
// detail"): CGAL's edge collapse, each collapse costed by how far it takes
// the surface from LOD0 in both directions (cgal_lod_distance_cost.hpp; the
// Garland-Heckbert quadric cost alone let the tips of thin branches slide
// away), placed by Garland-Heckbert's triangle quadrics with the normal
// change bounded so no triangle folds over. Each level keeps the mesh closed
// and manifold (an edge collapse on CGAL's Surface_mesh keeps the link
// condition).
#include "mesh/mesh.hpp"

#include <span>
#include <vector>

namespace morphogen {

// Level i (i >= 1) is `lod0` collapsed to about faces / 2^i triangles;
// levels[0] is lod0 itself. Each level is made from lod0, not from the one
// before, so errors do not add up. Throws std::invalid_argument when
// `count` < 1, MeshError (naming --lods) when level count - 1 would have
// fewer than kMinLodFaces faces.
std::vector<MeshArrays> simplify_lods(MeshView lod0, int count);
inline constexpr std::size_t kMinLodFaces = 8;

// The two-sided (symmetric) Hausdorff distance between two closed meshes,
// approximated by CGAL from points sampled on each (deterministic).
double hausdorff_distance(MeshView a, MeshView b);

// Whether `mesh` is a closed 2-manifold by CGAL's checks: every edge has
// two faces, no vertex is non-manifold, and it is a valid polygon mesh.
bool is_closed_manifold(MeshView mesh);

// Each vertex of `level` takes the 4 wind values of the nearest vertex of
// `lod0` (plant_wind.hpp), so every level sways as LOD0 does.
std::vector<float> transfer_wind(MeshView lod0, std::span<const float> lod0_wind, MeshView level);

}  // namespace morphogen
