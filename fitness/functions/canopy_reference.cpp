// The canopy by vertical ray shooting (docs/algorithm.md §10.1's second
// implementation): independent of the rasteriser except for the grid
// definition, so tests can compare the two cell for cell. Hit points are
// constructed exactly: double-precision ray/triangle constructions go wrong on
// triangles seen almost edge-on from above.
#include "fitness/functions/canopy.hpp"

#include "fitness/geometry/cgal_geometry.hpp"
#include "fitness/measures.hpp"

#include <algorithm>
#include <cmath>

namespace morphogen {

std::vector<CellIndex> canopy_cells_by_rays(MeshView mesh, const CanopyParams& params) {
    check_mesh_view(mesh);
    std::vector<CellIndex> cells;
    if (mesh.positions.empty()) return cells;
    const RayCaster caster(mesh, RayCaster::Faces::non_vertical);
    Vec3 low = mesh.positions[0], high = low;
    for (const Vec3& p : mesh.positions) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    const double cell = params.cell;
    const auto i0 = static_cast<std::int64_t>(std::floor(low.x() / cell)) - 1;
    const auto i1 = static_cast<std::int64_t>(std::ceil(high.x() / cell)) + 1;
    const auto j0 = static_cast<std::int64_t>(std::floor(low.y() / cell)) - 1;
    const auto j1 = static_cast<std::int64_t>(std::ceil(high.y() / cell)) + 1;
    const double top = high.z() + 1.0;
    const Vec3 down(0.0, 0.0, -1.0);
    for (std::int64_t i = i0; i <= i1; ++i) {
        for (std::int64_t j = j0; j <= j1; ++j) {
            const auto hit = caster.first_hit_exact(Vec3(cell_centre(i, cell), cell_centre(j, cell), top), down);
            if (hit && hit->z() > params.height) cells.emplace_back(i, j);
        }
    }
    std::sort(cells.begin(), cells.end());
    return cells;
}

}  // namespace morphogen
