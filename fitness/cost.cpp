// The measured costs of the fitness building blocks (fitness/cost.hpp).
#include "fitness/cost.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace morphogen {

namespace {

// Bytes per face of the final mesh, measured on this build (peak RSS of runs
// that stress one part; see docs/limits.md) and rounded up.
constexpr double light_tree_bytes_per_face = 200;  // CGAL AABB tree of the triangles
constexpr double canopy_bytes_per_face = 72;       // triangles above the height
constexpr double self_intersection_bytes_per_face = 250;
constexpr double measure_bytes_per_face = 48;

// Seconds of one core (development VM), rounded up from timed `score` runs
// on meshes of 2 000 to 400 000 vertices.
constexpr double light_tree_second_per_face = 1.5e-6;
constexpr double light_ray_second = 0.5e-6, light_ray_second_per_level = 0.1e-6;  // + log2(faces) levels
constexpr double canopy_second_per_cell = 100e-9, canopy_second_per_face = 200e-9;
constexpr double self_intersection_second_per_face = 3e-6;
constexpr double measure_second_per_face = 50e-9;

std::vector<std::string> with(std::vector<std::string> first, const std::vector<std::string>& more) {
    first.insert(first.end(), more.begin(), more.end());
    return first;
}

}  // namespace

CostScope CostScope::term(std::size_t i) const {
    CostScope scope = *this;
    scope.path = path + ".terms[" + std::to_string(i) + "]";
    return scope;
}

void FitnessCost::need_bytes(double b) { bytes = std::max(bytes, b); }

void add_measure_cost(FitnessCost& cost, const CostScope& scope, const std::string& what, double passes) {
    cost.need_bytes(scope.faces * measure_bytes_per_face);
    cost.work.push_back({what, {scope.path + ".type"}, passes * scope.faces * measure_second_per_face});
}

void add_self_intersection_cost(FitnessCost& cost, double faces, const std::string& why_key) {
    cost.need_bytes(faces * self_intersection_bytes_per_face);
    cost.work.push_back({"self-intersection test of " + group_digits(faces) + " faces", {why_key, "growth.max_vertices"},
                         faces * self_intersection_second_per_face});
}

void add_canopy_cost(FitnessCost& cost, const CanopyParams& params, const CostScope& scope) {
    const double cell = params.cell;
    const Vec3& lo = scope.lo;
    const Vec3& hi = scope.hi;
    const double cells = ((hi.x() - lo.x()) / cell + 3) * ((hi.y() - lo.y()) / cell + 3);
    const std::vector<std::string> keys = with({scope.path + ".cell"}, scope.extent_keys);
    cost.need_bytes(cells + scope.faces * canopy_bytes_per_face);
    cost.work.push_back({"canopy grid of up to " + group_digits(cells) + " cells (" + scope.path + ")", keys,
                         cells * canopy_second_per_cell + scope.faces * canopy_second_per_face});
    cost.caps.push_back({"canopy grid cells (" + scope.path + ".cell over a plant up to " +
                             group_digits(std::ceil(std::max(hi.x() - lo.x(), hi.y() - lo.y()))) + " wide)",
                         keys, cells, static_cast<double>(canopy_max_cells)});
}

void add_light_cost(FitnessCost& cost, const LightParams& params, const CostScope& scope) {
    const std::string& path = scope.path;
    // In a stand the rays meet a tree of the plant and its eight copies.
    const double scene_faces = params.stand_spacing > 0.0 ? 9 * scope.faces : scope.faces;
    double suns = 0;
    for (double e : params.elevations_deg) suns += e == 90.0 ? 1.0 : static_cast<double>(params.azimuths_deg.size());
    // Rays per sun: the lattice covers the projected box of the mesh, whose
    // sides are at most the box's diagonal; light.cpp adds at most 3 per side.
    const double side = scope.width() / params.spacing + 3;
    const double rays = side * side;
    const std::vector<std::string> keys = with({path + ".spacing"}, scope.extent_keys);
    cost.need_bytes(scene_faces * light_tree_bytes_per_face);
    const double per_ray = light_ray_second + light_ray_second_per_level * std::log2(scene_faces + 2);
    cost.work.push_back({"light: " + group_digits(suns) + " suns x up to " + group_digits(rays) + " rays (" + path + ")",
                         with(keys, {path + ".elevations_deg", path + ".azimuths_deg"}),
                         suns * rays * per_ray + scene_faces * light_tree_second_per_face});
    cost.caps.push_back({"light rays per sun (" + path + ".spacing " + group_digits(params.spacing) +
                             " over a plant up to " + group_digits(std::ceil(scope.width())) + " wide)",
                         keys, rays, light_max_rays_per_sun});
}

std::string group_digits(double n) {
    char text[64];
    if (n != std::floor(n) || !(n < 1e15)) {
        std::snprintf(text, sizeof text, "%.3g", n);
        return text;
    }
    std::snprintf(text, sizeof text, "%.0f", n);
    std::string digits = text, out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

}  // namespace morphogen
