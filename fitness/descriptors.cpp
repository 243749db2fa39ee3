#include "fitness/descriptors.hpp"

#include "core/base/config_reader.hpp"
#include "fitness/architecture/architecture.hpp"
#include "fitness/measures.hpp"
#include "fitness/architecture/tree_sections.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace morphogen {

namespace {
// z halfway between the lowest and the highest vertex.
double mid_height(MeshView mesh) {
    double low = mesh.positions[0].z(), high = low;
    for (const Vec3& p : mesh.positions) low = std::min(low, p.z()), high = std::max(high, p.z());
    return 0.5 * (low + high);
}

// Vertices at or above (top) / at or below (bottom) the mid height.
std::vector<Vec3> half(MeshView mesh, bool top) {
    const double mid = mid_height(mesh);
    std::vector<Vec3> out;
    for (const Vec3& p : mesh.positions)
        if (top ? p.z() >= mid : p.z() <= mid) out.push_back(p);
    return out;
}

void require_vertices(MeshView mesh) {
    if (mesh.positions.empty()) throw std::invalid_argument("a mesh without vertices has no shape measures");
}

// The skeleton's measures without the convex hull (solidity has its own row).
Architecture skeleton_measures(MeshView mesh) { return measure_architecture(mesh, {.with_solidity = false}); }

const DescriptorMeasure kMeasures[] = {
    {"height", [](MeshView m, const CanopyParams&) { return mesh_height(m); }, "maximum z of the vertices"},
    {"footprint", [](MeshView m, const CanopyParams&) { return mesh_footprint(m); },
     "area of the convex hull of the vertices' xy-projections"},
    {"width", [](MeshView m, const CanopyParams&) { return mesh_width(m); },
     "largest distance between two vertices' xy-projections"},
    {"area", [](MeshView m, const CanopyParams&) { return mesh_area(m); }, "surface area"},
    {"volume", [](MeshView m, const CanopyParams&) { return mesh_volume(m); }, "signed enclosed volume"},
    {"vertices", [](MeshView m, const CanopyParams&) { return static_cast<double>(m.positions.size()); },
     "number of vertices"},
    {"faces", [](MeshView m, const CanopyParams&) { return static_cast<double>(m.faces.size()); }, "number of faces"},
    {"canopy", [](MeshView m, const CanopyParams& c) { return canopy_area(m, c); },
     "canopy area above the fitness's height"},
    {"slenderness", [](MeshView m, const CanopyParams&) { return mesh_slenderness(m); },
     "height / sqrt(footprint)"},
    {"crown_height", [](MeshView m, const CanopyParams& c) { return mesh_crown_height(m, c); },
     "mean top height over the canopy's cells"},
    {"spread", [](MeshView m, const CanopyParams&) { return mesh_spread(m); },
     "width of the top half over width of the bottom half"},
    {"lean", [](MeshView m, const CanopyParams&) { return mesh_lean(m); },
     "xy distance between the mean vertex of the top half and of the bottom half"},
    {"sphericity", [](MeshView m, const CanopyParams&) { return mesh_sphericity(m); },
     "pi^(1/3) (6 |volume|)^(2/3) / area: 1 for a sphere, small for thin branches"},
    {"trunk_ratio", [](MeshView m, const CanopyParams&) { return tree_sections(m).trunk_ratio; },
     "widest section of the lowest quarter / widest of the upper half (a tree: <= 0.25)"},
    {"upper_loops", [](MeshView m, const CanopyParams&) { return static_cast<double>(tree_sections(m).upper_loops); },
     "most loops of a horizontal section in the upper half (branches: >= 3)"},
    {"tips", [](MeshView m, const CanopyParams&) { return static_cast<double>(skeleton_measures(m).tips); },
     "end nodes of the level-set skeleton, noise pruned"},
    {"limbs", [](MeshView m, const CanopyParams&) { return static_cast<double>(skeleton_measures(m).limbs.size()); },
     "skeleton branches above a fork at least 3 times as long as thick"},
    {"first_fork_height", [](MeshView m, const CanopyParams&) { return skeleton_measures(m).first_fork_height; },
     "height of the skeleton's lowest fork above the lowest vertex (the plant's height if none)"},
    {"strahler", [](MeshView m, const CanopyParams&) { return static_cast<double>(skeleton_measures(m).strahler); },
     "Strahler order of the skeleton (1: no branching)"},
    {"solidity", [](MeshView m, const CanopyParams&) { return mesh_solidity(m); },
     "volume / convex-hull volume (NaN for an open mesh)"},
};
}  // namespace

double mesh_slenderness(MeshView mesh) { return mesh_height(mesh) / std::sqrt(mesh_footprint(mesh)); }

double mesh_crown_height(MeshView mesh, const CanopyParams& canopy) {
    const std::vector<CanopyTop> tops = canopy_tops(mesh, canopy);
    if (tops.empty()) return canopy.height;
    double sum = 0.0;
    for (const CanopyTop& t : tops) sum += t.top;
    return sum / static_cast<double>(tops.size());
}

double mesh_spread(MeshView mesh) {
    require_vertices(mesh);
    return xy_width(half(mesh, true)) / xy_width(half(mesh, false));
}

double mesh_lean(MeshView mesh) {
    require_vertices(mesh);
    auto mean_xy = [](const std::vector<Vec3>& points) {
        double x = 0.0, y = 0.0;
        for (const Vec3& p : points) x += p.x(), y += p.y();
        const auto n = static_cast<double>(points.size());
        return std::pair{x / n, y / n};
    };
    const auto [tx, ty] = mean_xy(half(mesh, true));
    const auto [bx, by] = mean_xy(half(mesh, false));
    return std::hypot(tx - bx, ty - by);
}

double mesh_sphericity(MeshView mesh) {
    const double v = std::abs(mesh_volume(mesh));
    return std::cbrt(std::numbers::pi) * std::pow(6.0 * v, 2.0 / 3.0) / mesh_area(mesh);
}

std::span<const DescriptorMeasure> descriptor_measures() { return kMeasures; }

std::vector<std::string> descriptor_measure_names() {
    std::vector<std::string> names;
    for (const DescriptorMeasure& m : kMeasures) names.emplace_back(m.name);
    return names;
}

const DescriptorMeasure& find_descriptor_measure(const std::string& name) {
    for (const DescriptorMeasure& m : kMeasures)
        if (name == m.name) return m;
    const std::vector<std::string> names = descriptor_measure_names();
    std::string message = "unknown measure \"" + name + "\"";
    if (auto near = nearest(name, names)) {
        message += " (did you mean \"" + *near + "\"?)";
    } else {
        message += "; known:";
        for (const std::string& n : names) message += " " + n;
    }
    throw std::invalid_argument(message);
}

DescriptorSet::DescriptorSet(const std::vector<std::string>& names, CanopyParams canopy)
    : names_(names), canopy_(canopy) {
    for (const std::string& name : names_) measures_.push_back(&find_descriptor_measure(name));
}

std::vector<double> DescriptorSet::operator()(MeshView mesh) const {
    check_mesh_view(mesh);
    require_vertices(mesh);
    std::vector<double> values;
    values.reserve(measures_.size());
    for (const DescriptorMeasure* m : measures_) {
        const double value = m->measure(mesh, canopy_);
        if (!std::isfinite(value))
            throw std::invalid_argument("non-finite descriptor " + std::to_string(values.size()) + " (" + m->name +
                                        " = " + std::to_string(value) + ")");
        values.push_back(value);
    }
    return values;
}

}  // namespace morphogen
