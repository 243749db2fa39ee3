#include "fitness/functions/light.hpp"

#include "fitness/geometry/cgal_geometry.hpp"
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

// Casts one sun's lattice of rays (light.hpp) over `mesh`'s projected box at
// the caster's triangles (the mesh, or its stand: `scene`), and calls
// on_hit(hit) for each ray whose first hit is at z >= min_height.
template <class OnHit>
void cast_lattice(MeshView mesh, MeshView scene, const RayCaster& caster, const Vec3& to_sun, double spacing,
                  double min_height, OnHit&& on_hit) {
    if (mesh.positions.empty()) return;
    const Vec3 d = -to_sun.normalized();
    // Basis (u, v) of the plane perpendicular to d; axis-aligned for a vertical sun.
    const Vec3 helper = std::abs(d.z()) > 0.9 ? Vec3::UnitX() : Vec3::UnitZ();
    const Vec3 u = (helper - helper.dot(d) * d).normalized();
    const Vec3 v = d.cross(u);
    double umin = INFINITY, umax = -INFINITY, vmin = INFINITY, vmax = -INFINITY, tmin = INFINITY;
    for (const Vec3& p : mesh.positions) {
        umin = std::min(umin, p.dot(u)), umax = std::max(umax, p.dot(u));
        vmin = std::min(vmin, p.dot(v)), vmax = std::max(vmax, p.dot(v));
    }
    for (const Vec3& p : scene.positions) tmin = std::min(tmin, p.dot(d));
    const double k0 = std::floor(umin / spacing), k1 = std::ceil(umax / spacing);
    const double l0 = std::floor(vmin / spacing), l1 = std::ceil(vmax / spacing);
    const double rays = (k1 - k0 + 1) * (l1 - l0 + 1);
    if (!(rays <= kMaxRays))
        throw std::length_error("light: " + std::to_string(rays) + " rays per sun; increase the spacing");
    const double start = tmin - 1.0;  // every ray starts before the mesh
    for (double k = k0; k <= k1; ++k) {
        for (double l = l0; l <= l1; ++l) {
            const Vec3 origin = (k + 0.5) * spacing * u + (l + 0.5) * spacing * v + start * d;
            const auto hit = caster.first_hit_face(origin, d);
            if (hit && hit->point.z() >= min_height) on_hit(*hit);
        }
    }
}

// One sun's light, given the tree of the mesh's triangles.
double light_with(MeshView mesh, const RayCaster& caster, const Vec3& to_sun, double spacing, double min_height) {
    long long captured = 0;
    cast_lattice(mesh, mesh, caster, to_sun, spacing, min_height, [&](const RayCaster::Hit&) { ++captured; });
    return static_cast<double>(captured) * spacing * spacing;
}

void check(const LightParams& params) {
    if (!(params.spacing > 0) || !std::isfinite(params.spacing) || !std::isfinite(params.min_height))
        throw std::invalid_argument("light needs a positive spacing and a finite min_height");
    if (!(params.stand_spacing >= 0) || !std::isfinite(params.stand_spacing))
        throw std::invalid_argument("light needs a stand_spacing >= 0");
}

// Rays per face of `mesh` (the plant's faces only) over every sun.
std::vector<long long> rays_per_face(MeshView mesh, const LightParams& params, const std::vector<Vec3>& suns) {
    MeshArrays stand;  // empty when the plant stands alone
    if (params.stand_spacing > 0.0) stand = stand_of(mesh, params.stand_spacing);
    const MeshView scene = params.stand_spacing > 0.0 ? stand.view() : mesh;
    const RayCaster caster(scene, RayCaster::Faces::non_degenerate);  // one tree for every sun
    std::vector<long long> rays(mesh.faces.size(), 0);
    for (const Vec3& sun : suns)
        cast_lattice(mesh, scene, caster, sun, params.spacing, params.min_height, [&](const RayCaster::Hit& hit) {
            if (static_cast<std::size_t>(hit.face) < rays.size()) ++rays[static_cast<std::size_t>(hit.face)];
        });
    return rays;
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

MeshArrays stand_of(MeshView mesh, double stand_spacing) {
    MeshArrays stand{{mesh.positions.begin(), mesh.positions.end()}, {mesh.faces.begin(), mesh.faces.end()}};
    if (!(stand_spacing > 0.0)) return stand;
    const int n = static_cast<int>(mesh.positions.size());
    int copy = 0;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j) {
            if (i == 0 && j == 0) continue;
            const Vec3 shift(i * stand_spacing, j * stand_spacing, 0.0);
            for (const Vec3& p : mesh.positions) stand.positions.push_back(p + shift);
            const int offset = n * ++copy;
            for (const Face& f : mesh.faces) stand.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
        }
    return stand;
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
    if (params.stand_spacing > 0.0) {
        long long captured = 0;
        for (long long r : rays_per_face(mesh, params, suns)) captured += r;
        return static_cast<double>(captured) * params.spacing * params.spacing / static_cast<double>(suns.size());
    }
    const RayCaster caster(mesh, RayCaster::Faces::non_degenerate);  // one tree for every sun
    double sum = 0.0;
    for (const Vec3& sun : suns) sum += light_with(mesh, caster, sun, params.spacing, params.min_height);
    return sum / static_cast<double>(suns.size());
}

std::vector<double> light_per_face(MeshView mesh, const LightParams& params) {
    check_mesh_view(mesh);
    check(params);
    const std::vector<Vec3> suns = sun_directions(params);
    if (suns.empty()) throw std::invalid_argument("light needs at least one sun");
    const std::vector<long long> rays = rays_per_face(mesh, params, suns);
    std::vector<double> light(rays.size());
    const double per_ray = params.spacing * params.spacing / static_cast<double>(suns.size());
    for (std::size_t f = 0; f < rays.size(); ++f) light[f] = static_cast<double>(rays[f]) * per_ray;
    return light;
}

}  // namespace morphogen
