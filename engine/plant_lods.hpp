#pragma once
// Levels of detail of a plant (`--lods N`; docs/engine-glb.md, "Levels of
// detail"): CGAL's edge collapse, costed by Garland-Heckbert's quadrics where
// they keep the distance bound and otherwise by how far a collapse takes the
// surface from LOD0 in both directions (cgal_lod_distance_cost.hpp; the
// quadric cost alone lets the tips of thin branches slide away), placed by
// Garland-Heckbert's triangle quadrics with the normal change bounded so no
// triangle folds over. Each level keeps the mesh closed
// and manifold (an edge collapse on CGAL's Surface_mesh keeps the link
// condition).
#include "core/mesh/mesh.hpp"

#include <span>
#include <vector>

namespace morphogen {

// The bound on level i's two-sided Hausdorff distance from LOD0, over LOD0's
// bounding-box diagonal: 1 % per level (LOD1 1 %, LOD2 2 %; docs/file-formats.md).
inline double lod_distance_bound(int level) { return 0.01 * level; }
// A level aims at half the triangles of the one before; when that leaves the
// bound it may keep up to this ratio (10 % above half).
inline constexpr double kLodHalf = 0.5;
inline constexpr double kLodMaxRatio = 0.55;
inline constexpr std::size_t kMinLodFaces = 8;

struct PlantLods {
    std::vector<MeshArrays> levels;  // LOD0 (the mesh given) .. the last level that kept its bound
    std::vector<double> distances;   // per level: Hausdorff distance from LOD0 / LOD0's diagonal (0 for LOD0)
    int requested = 0;               // the levels asked for; levels.size() <= requested
    // When the chain stopped: the nearest any try of the first level not
    // written came to LOD0 (over the diagonal; 0 when no try could be measured).
    double refused_distance = 0.0;

    bool short_chain() const { return static_cast<int>(levels.size()) < requested; }
};

// Up to `count` levels; level i (i >= 1) is `lod0` collapsed (CGAL's edge
// collapse, made from lod0, not from the level before) to about half the
// triangles of level i - 1. Each level is tried cheapest first: Garland-
// Heckbert's quadric cost at ratio 1/2, then at kLodMaxRatio, then the
// distance cost (cgal_lod_distance_cost.hpp) at both; the first whose
// measured distance (hausdorff_distance) is within lod_distance_bound(i)
// is kept. When none is, the chain stops there: fewer levels than asked (a
// level that leaves the plant's shape is worse than none); so does a level
// that would have fewer than kMinLodFaces triangles (a small plant gets the
// levels it can have, refused_distance 0). Throws std::invalid_argument when
// `count` < 1.
PlantLods simplify_lods(MeshView lod0, int count);

// The two-sided (symmetric) Hausdorff distance between two closed meshes,
// approximated from points on each (vertices, centroids, edge midpoints and
// max(2000, 4 x faces) points spread by area, from a fixed sequence: the
// same figure every run) and their exact distance to the other mesh (CGAL's
// max_distance_to_triangle_mesh).
double hausdorff_distance(MeshView a, MeshView b);

// Whether `mesh` is a closed 2-manifold by CGAL's checks: every edge has
// two faces, no vertex is non-manifold, and it is a valid polygon mesh.
bool is_closed_manifold(MeshView mesh);

// Each vertex of `level` takes the 4 wind values of the nearest vertex of
// `lod0` (plant_wind.hpp), so every level sways as LOD0 does.
std::vector<float> transfer_wind(MeshView lod0, std::span<const float> lod0_wind, MeshView level);

}  // namespace morphogen
