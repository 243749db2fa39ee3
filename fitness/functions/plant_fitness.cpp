#include "fitness/functions/plant_fitness.hpp"

#include "fitness/measures.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_map>

namespace morphogen {

namespace {

double face_area(MeshView mesh, const Face& f) {
    const Vec3& a = mesh.positions[f[0]];
    return 0.5 * (mesh.positions[f[1]] - a).cross(mesh.positions[f[2]] - a).norm();
}

Vec3 centroid_of(MeshView mesh, const Face& f) {
    return (mesh.positions[f[0]] + mesh.positions[f[1]] + mesh.positions[f[2]]) / 3.0;
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
    for (const Face& f : mesh.faces) moment += face_area(mesh, f) * (centroid_of(mesh, f).head<2>() - axis).norm();
    return moment;
}

// The rectangular hyperbola: what `area` yields at mean relative irradiance
// `irradiance` (a leaf's light response).
double saturating_yield(double area, double irradiance, double K) {
    return area * (1.0 + K) * irradiance / (irradiance + K);
}

// Leaves: the 3-D cells of side leaf_size that hold the faces' centroids.
struct LeafKey {
    long long x, y, z;
    bool operator==(const LeafKey&) const = default;
};
struct LeafKeyHash {
    std::size_t operator()(const LeafKey& k) const {
        // Unsigned: wraps instead of overflowing for cells far out.
        const auto u = [](long long v) { return static_cast<unsigned long long>(v); };
        return std::hash<unsigned long long>()(u(k.x) * 73856093ULL ^ u(k.y) * 19349663ULL ^ u(k.z) * 83492791ULL);
    }
};

// Each tip's S_t from per-face yields: a face feeds the nearest tip within reach.
std::vector<double> shoots_from_yields(MeshView mesh, const std::vector<double>& yields, const std::vector<Vec3>& tips,
                                       double shoot_radius) {
    std::vector<double> shoots(tips.size(), 0.0);
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
        if (yields[i] <= 0.0) continue;
        const Vec3 centroid = centroid_of(mesh, mesh.faces[i]);
        std::size_t nearest = tips.size();
        double nearest_distance = shoot_radius;
        for (std::size_t t = 0; t < tips.size(); ++t) {
            const double distance = (tips[t] - centroid).norm();
            if (distance <= nearest_distance && (nearest == tips.size() || distance < nearest_distance))
                nearest = t, nearest_distance = distance;
        }
        if (nearest < tips.size()) shoots[nearest] += yields[i];
    }
    return shoots;
}

}  // namespace

std::vector<double> face_yields(MeshView mesh, const std::vector<double>& light_per_face, double half_saturation,
                                double leaf_size) {
    // Each face's area, and its leaf's area and light: the face's own when
    // leaf_size is 0, else summed over the faces whose centroids share its cube.
    std::vector<double> areas(mesh.faces.size());
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) areas[i] = face_area(mesh, mesh.faces[i]);
    std::vector<double> leaf_area = areas, leaf_light = light_per_face;
    if (leaf_size > 0.0) {
        struct Leaf {
            double area = 0.0, light = 0.0;
        };
        std::unordered_map<LeafKey, Leaf, LeafKeyHash> leaves;
        std::vector<const Leaf*> leaf_of(mesh.faces.size(), nullptr);
        for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
            if (!(areas[i] > 0.0)) continue;
            const Vec3 c = centroid_of(mesh, mesh.faces[i]) / leaf_size;
            // Clamped so that the cast is defined for any finite mesh (cells that far out merge).
            const auto cell = [](double v) { return static_cast<long long>(std::floor(std::clamp(v, -1e15, 1e15))); };
            Leaf& leaf = leaves[LeafKey{cell(c.x()), cell(c.y()), cell(c.z())}];  // stays valid as the map grows
            leaf.area += areas[i], leaf.light += light_per_face[i];
            leaf_of[i] = &leaf;
        }
        for (std::size_t i = 0; i < mesh.faces.size(); ++i)
            if (leaf_of[i] != nullptr) leaf_area[i] = leaf_of[i]->area, leaf_light[i] = leaf_of[i]->light;
    }
    std::vector<double> yields(mesh.faces.size(), 0.0);
    for (std::size_t i = 0; i < mesh.faces.size(); ++i)
        if (areas[i] > 0.0 && leaf_light[i] > 0.0)
            yields[i] = saturating_yield(areas[i], leaf_light[i] / leaf_area[i], half_saturation);
    return yields;
}

double saturating_light(MeshView mesh, const std::vector<double>& light_per_face, double half_saturation,
                        double leaf_size) {
    double light = 0.0;
    for (double y : face_yields(mesh, light_per_face, half_saturation, leaf_size)) light += y;
    return light;
}

std::vector<double> shoot_light(MeshView mesh, const std::vector<double>& light_per_face, double half_saturation,
                                const std::vector<Vec3>& tips, double shoot_radius, double leaf_size) {
    return shoots_from_yields(mesh, face_yields(mesh, light_per_face, half_saturation, leaf_size), tips, shoot_radius);
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
    const std::vector<double> yields =
        face_yields(mesh, light_per_face(mesh, params.light), params.half_saturation, params.leaf_size);
    for (double y : yields) s.light += y;
    const std::vector<double> shoots = shoots_from_yields(mesh, yields, architecture.tip_points, params.shoot_radius);
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
