#include "fitness/mesh_stats.hpp"

#include <algorithm>

namespace morphogen {

MeshStats mesh_stats(MeshView mesh) {
    if (mesh.positions.empty()) return {};
    Vec3 lo = mesh.positions.front(), hi = lo;
    for (const Vec3& p : mesh.positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {hi.z(), std::max(hi.x() - lo.x(), hi.y() - lo.y())};
}

}  // namespace morphogen
