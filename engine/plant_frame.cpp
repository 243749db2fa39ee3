#include "engine/plant_frame.hpp"

#include "core/base/errors.hpp"

#include <algorithm>
#include <limits>
#include <string>

namespace morphogen {

PlacedPlant place_plant(MeshView mesh, std::optional<double> height_m) {
    if (mesh.positions.empty()) throw MeshError("cannot place a plant without vertices");
    double lowest = std::numeric_limits<double>::infinity(), top = -lowest;
    for (const Vec3& p : mesh.positions) lowest = std::min(lowest, p.z()), top = std::max(top, p.z());
    const double height = top - lowest;
    Eigen::Vector2d foot_lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d foot_hi = -foot_lo;
    for (const Vec3& p : mesh.positions) {
        if (p.z() > lowest + kFootBand * height) continue;
        foot_lo = foot_lo.cwiseMin(p.head<2>());
        foot_hi = foot_hi.cwiseMax(p.head<2>());
    }
    const Vec3 origin((foot_lo.x() + foot_hi.x()) / 2, (foot_lo.y() + foot_hi.y()) / 2, lowest);

    PlacedPlant placed;
    if (height_m) {
        if (!(height > 0))
            throw MeshError("cannot scale a plant of height 0 to " + std::to_string(*height_m) + " m");
        placed.metres_per_unit = *height_m / height;
    }
    placed.height_m = height * placed.metres_per_unit;
    placed.mesh.faces.assign(mesh.faces.begin(), mesh.faces.end());
    placed.mesh.positions.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) placed.mesh.positions.push_back((p - origin) * placed.metres_per_unit);
    return placed;
}

}  // namespace morphogen
