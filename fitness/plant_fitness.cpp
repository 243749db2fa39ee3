#include "fitness/plant_fitness.hpp"

#include "fitness/measures.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace morphogen {

namespace {

double face_area(MeshView mesh, const Face& f) {
    const Vec3& a = mesh.positions[f[0]];
    return 0.5 * (mesh.positions[f[1]] - a).cross(mesh.positions[f[2]] - a).norm();
}

// The foot's axis: the mean (x, y) of the vertices within root_height of
// the lowest one.
Eigen::Vector2d foot_axis(MeshView mesh, double zmin, double root_height) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int count = 0;
    for (const Vec3& p : mesh.positions)
        if (p.z() <= zmin + std::max(root_height, 0.0)) sum += p.head<2>(), ++count;
    return sum / static_cast<double>(count);
}

double bending_moment(MeshView mesh, const Eigen::Vector2d& axis) {
    double moment = 0.0;
    for (const Face& f : mesh.faces) {
        const Vec3 centroid = (mesh.positions[f[0]] + mesh.positions[f[1]] + mesh.positions[f[2]]) / 3.0;
        moment += face_area(mesh, f) * (centroid.head<2>() - axis).norm();
    }
    return moment;
}

}  // namespace

namespace {

// What face i yields of the light it catches (the rectangular hyperbola).
double face_yield(MeshView mesh, std::size_t i, double light, double K) {
    const double area = face_area(mesh, mesh.faces[i]);
    if (!(area > 0.0) || light <= 0.0) return 0.0;
    const double irradiance = light / area;
    return area * (1.0 + K) * irradiance / (irradiance + K);
}

}  // namespace

double saturating_light(MeshView mesh, const std::vector<double>& light_per_face, double half_saturation) {
    double light = 0.0;
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) light += face_yield(mesh, i, light_per_face[i], half_saturation);
    return light;
}

std::vector<double> shoot_light(MeshView mesh, const std::vector<double>& light_per_face, double half_saturation,
                                const std::vector<Vec3>& tips, double shoot_radius) {
    std::vector<double> shoots(tips.size(), 0.0);
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
        if (light_per_face[i] <= 0.0) continue;
        const Face& f = mesh.faces[i];
        const Vec3 centroid = (mesh.positions[f[0]] + mesh.positions[f[1]] + mesh.positions[f[2]]) / 3.0;
        std::size_t nearest = tips.size();
        double nearest_distance = shoot_radius;
        for (std::size_t t = 0; t < tips.size(); ++t) {
            const double distance = (tips[t] - centroid).norm();
            if (distance <= nearest_distance && (nearest == tips.size() || distance < nearest_distance))
                nearest = t, nearest_distance = distance;
        }
        if (nearest < tips.size()) shoots[nearest] += face_yield(mesh, i, light_per_face[i], half_saturation);
    }
    return shoots;
}

PlantScore plant_score(MeshView mesh, const PlantFitnessParams& params) {
    check_mesh_view(mesh);
    PlantScore s;
    if (mesh.positions.empty()) return s;
    double zmin = mesh.positions.front().z();
    for (const Vec3& p : mesh.positions) zmin = std::min(zmin, p.z());
    s.rooted = zmin <= params.root_height;
    if (!s.rooted) return s;
    // Only the tips count here: skip the convex hull (solidity) on every birth.
    ArchitectureParams skeleton_only = params.architecture;
    skeleton_only.with_solidity = false;
    const Architecture architecture = measure_architecture(mesh, skeleton_only);
    s.tips = architecture.tips;
    s.moment = bending_moment(mesh, foot_axis(mesh, zmin, params.root_height));
    s.volume = std::max(0.0, mesh_volume(mesh));
    s.cost = 1.0 + params.moment_cost * s.moment + params.volume_cost * s.volume;
    // Light is the costly part: skip it when no tip stands above the foot.
    const auto above_foot = [zmin](const Vec3& tip) { return tip.z() > zmin; };
    if (std::none_of(architecture.tip_points.begin(), architecture.tip_points.end(), above_foot)) return s;
    const std::vector<double> per_face = light_per_face(mesh, params.light);
    s.light = saturating_light(mesh, per_face, params.half_saturation);
    const std::vector<double> shoots =
        shoot_light(mesh, per_face, params.half_saturation, architecture.tip_points, params.shoot_radius);
    for (std::size_t t = 0; t < shoots.size(); ++t) {
        const double H = params.shoot_half_light;
        const double bearing = H > 0.0 ? shoots[t] / (shoots[t] + H) : 1.0;
        s.bearing_tips += bearing;
        s.reproduction += std::max(0.0, architecture.tip_points[t].z() - zmin) * bearing;
    }
    s.score = std::sqrt(s.light * s.reproduction) / s.cost;
    return s;
}

}  // namespace morphogen
