#include "fitness/light.hpp"

#include "fitness/cgal_geometry.hpp"
#include "fitness/measures.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {
constexpr double kMaxRays = light_max_rays_per_sun;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// One sun's rays, given the tree of the mesh's triangles.
double light_with(MeshView mesh, const RayCaster& caster, const Vec3& to_sun, double spacing, double min_height) {
    if (mesh.positions.empty()) return 0.0;
    const Vec3 d = -to_sun.normalized();
    // Basis (u, v) of the plane perpendicular to d; axis-aligned for a vertical sun.
    const Vec3 helper = std::abs(d.z()) > 0.9 ? Vec3::UnitX() : Vec3::UnitZ();
    const Vec3 u = (helper - helper.dot(d) * d).normalized();
    const Vec3 v = d.cross(u);
    double umin = INFINITY, umax = -INFINITY, vmin = INFINITY, vmax = -INFINITY, tmin = INFINITY;
    for (const Vec3& p : mesh.positions) {
        umin = std::min(umin, p.dot(u)), umax = std::max(umax, p.dot(u));
        vmin = std::min(vmin, p.dot(v)), vmax = std::max(vmax, p.dot(v));
        tmin = std::min(tmin, p.dot(d));
    }
    const double k0 = std::floor(umin / spacing), k1 = std::ceil(umax / spacing);
    const double l0 = std::floor(vmin / spacing), l1 = std::ceil(vmax / spacing);
    const double rays = (k1 - k0 + 1) * (l1 - l0 + 1);
    if (!(rays <= kMaxRays))
        throw std::length_error("light: " + std::to_string(rays) + " rays per sun; increase the spacing");
    const double start = tmin - 1.0;  // every ray starts before the mesh
    long long captured = 0;
    for (double k = k0; k <= k1; ++k) {
        for (double l = l0; l <= l1; ++l) {
            const Vec3 origin = (k + 0.5) * spacing * u + (l + 0.5) * spacing * v + start * d;
            const auto hit = caster.first_hit(origin, d);
            if (hit && hit->z() >= min_height) ++captured;
        }
    }
    return static_cast<double>(captured) * spacing * spacing;
}

void check(const LightParams& params) {
    if (!(params.spacing > 0) || !std::isfinite(params.spacing) || !std::isfinite(params.min_height))
        throw std::invalid_argument("light needs a positive spacing and a finite min_height");
}
}  // namespace

std::vector<Vec3> sun_directions(const LightParams& params) {
    std::vector<Vec3> suns;
    for (double elevation : params.elevations_deg) {
        if (!(elevation > 0.0 && elevation <= 90.0))
            throw std::invalid_argument("sun elevation " + std::to_string(elevation) + " is not in (0, 90]");
        const double e = radians(elevation);
        if (elevation == 90.0) {
            suns.emplace_back(0.0, 0.0, 1.0);
            continue;
        }
        for (double azimuth : params.azimuths_deg) {
            const double a = radians(azimuth);
            suns.emplace_back(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
        }
    }
    return suns;
}

double light_from(MeshView mesh, const Vec3& to_sun, double spacing, double min_height) {
    check_mesh_view(mesh);
    check({{}, {}, spacing, min_height});
    const RayCaster caster(mesh, RayCaster::Faces::non_degenerate);
    return light_with(mesh, caster, to_sun, spacing, min_height);
}

double light_captured(MeshView mesh, const LightParams& params) {
    check_mesh_view(mesh);
    check(params);
    const std::vector<Vec3> suns = sun_directions(params);
    if (suns.empty()) throw std::invalid_argument("light needs at least one sun");
    const RayCaster caster(mesh, RayCaster::Faces::non_degenerate);  // one tree for every sun
    double sum = 0.0;
    for (const Vec3& sun : suns) sum += light_with(mesh, caster, sun, params.spacing, params.min_height);
    return sum / static_cast<double>(suns.size());
}

}  // namespace morphogen
