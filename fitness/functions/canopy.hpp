#pragma once
// The canopy heuristic of docs/algorithm.md §10.1 ("over10area"):
//   canopy = area { (x,y) : H(x,y) > height },  H = max z of the surface above (x,y),
// sampled on square cells of side `cell`: cell (i,j) covers
// [i*cell, (i+1)*cell) x [j*cell, (j+1)*cell) and counts when H at its centre
// ((i+0.5)*cell, (j+0.5)*cell) exceeds `height`. A centre on a triangle's edge
// or vertex is inside it (exact predicates decide); triangles whose
// xy-projection has zero area are skipped. Score = counted cells x cell^2.
#include "core/mesh/mesh.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace morphogen {

struct CanopyParams {
    double height = 10.0;  // fitness.height
    double cell = 0.1;     // fitness.cell, > 0
};

// The x (or y) coordinate of the centre of cell index i; both
// implementations below use exactly this expression.
inline double cell_centre(std::int64_t i, double cell) { return (static_cast<double>(i) + 0.5) * cell; }

using CellIndex = std::pair<std::int64_t, std::int64_t>;  // (i, j)

// The most grid cells one evaluation rasterises (one byte each). A config
// whose plants could need more is refused before a run
// (run/limits/resource_estimate.hpp), unless limits are lifted.
inline constexpr std::int64_t canopy_max_cells = std::int64_t{1} << 28;

// The score, by z-buffer rasterisation: only triangles whose highest vertex is
// above `height`, and only the cell centres in each one's bounding box, are
// tested. Since H > height iff some covering triangle is above height there,
// one bit per cell suffices. Throws std::invalid_argument for a bad mesh view,
// std::length_error if the grid would exceed 2^28 cells. Thread-safe.
double canopy_area(MeshView mesh, const CanopyParams& params);
// The counted cells of the same rasterisation, sorted.
std::vector<CellIndex> canopy_cells(MeshView mesh, const CanopyParams& params);

// The counted cells of canopy_cells, each with H at its centre (the highest
// interpolated z of the triangles covering it; > params.height), sorted by cell.
struct CanopyTop {
    CellIndex cell;
    double top;
};
std::vector<CanopyTop> canopy_tops(MeshView mesh, const CanopyParams& params);

// The reference: a vertical ray from above at every cell centre of the mesh's
// bounding box, first hit on a CGAL AABB tree of the non-vertical triangles.
// Slow; for tests. Sorted.
std::vector<CellIndex> canopy_cells_by_rays(MeshView mesh, const CanopyParams& params);

}  // namespace morphogen
