// The scatter's field (see plant_scatter.hpp).
#include "engine/plant_scatter.hpp"

#include "engine/plant_wind.hpp"
#include "core/io/scatter_glb.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace morphogen {

namespace {

// Around each node, the copies 1 .. kScatterCopies-1 stand this many radii
// (the widest species' reach from its foot) away, so a square of
// kSpacing radii holds a species' cluster (2.2 + 1.15 < 7 / 2) apart from
// its neighbours'.
constexpr double kRingRadii = 2.2;
constexpr double kSpacingRadii = 7.0;
constexpr float kScales[kScatterCopies] = {1.0f, 0.85f, 1.15f, 0.95f};
constexpr double kGoldenAngle = 2.399963229728653;  // radians: turns that never line up

// The farthest any vertex reaches from the vertical axis through the foot.
double reach(MeshView mesh) {
    double r2 = 0;
    for (const Vec3& p : mesh.positions) r2 = std::max(r2, p.x() * p.x() + p.y() * p.y());
    return std::sqrt(r2);
}

// A turn by `angle` about glTF's up axis (Y), as x, y, z, w.
std::array<float, 4> turn_about_up(double angle) {
    return {0.0f, static_cast<float>(std::sin(angle / 2)), 0.0f, static_cast<float>(std::cos(angle / 2))};
}

std::vector<ScatterInstance> cluster(std::size_t species, double radius) {
    std::vector<ScatterInstance> copies(1);  // the first: the node itself
    const double start = static_cast<double>(species) * kGoldenAngle;
    for (int k = 1; k < kScatterCopies; ++k) {
        const double at = start + 2 * std::numbers::pi * k / (kScatterCopies - 1);
        ScatterInstance copy;
        copy.translation = {static_cast<float>(kRingRadii * radius * std::cos(at)), 0.0f,
                            static_cast<float>(kRingRadii * radius * std::sin(at))};
        copy.rotation = turn_about_up(k * kGoldenAngle + start);
        copy.scale = kScales[k];
        copies.push_back(copy);
    }
    return copies;
}

}  // namespace

std::string plant_scatter_bytes(std::span<const EnginePlant> plants, const std::string& run, const std::string& source) {
    if (plants.empty()) throw std::invalid_argument("scatter: a species pack needs at least one plant");
    double radius = 0;
    for (const EnginePlant& plant : plants) radius = std::max(radius, reach(plant.levels.front().view()));
    if (!(radius > 0)) radius = 1;  // plants thinner than a float: a metre apart
    const auto columns = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(plants.size()))));
    const std::size_t rows = (plants.size() + columns - 1) / columns;
    const double spacing = kSpacingRadii * radius;

    std::vector<ScatterSpecies> species;
    for (std::size_t i = 0; i < plants.size(); ++i) {
        const EnginePlant& plant = plants[i];
        const double x = (static_cast<double>(i % columns) - (static_cast<double>(columns) - 1) / 2) * spacing;
        const double z = (static_cast<double>(i / columns) - (static_cast<double>(rows) - 1) / 2) * spacing;
        species.push_back(ScatterSpecies{.name = plant.name,
                                         .extras = plant.extras,
                                         .mesh = plant.levels.front().view(),
                                         .wind = plant.wind.front(),
                                         .attributes = wind_preset_attributes(plant.wind.front(), plant.wind_presets),
                                         .position = {static_cast<float>(x), 0.0f, static_cast<float>(z)},
                                         .instances = cluster(i, radius)});
    }
    nlohmann::json extras = {{"generator", "morphogen"},
                             {"species", plants.size()},
                             {"copies_per_species", kScatterCopies},
                             {"spacing_m", spacing}};
    if (!run.empty()) extras["run"] = run;
    return scatter_glb_bytes(species, "scatter", extras, source);
}

}  // namespace morphogen
