// The metrics report of a mesh (score command, run records).
#include "fitness/fitness.hpp"

#include "fitness/canopy.hpp"
#include "fitness/cgal_geometry.hpp"
#include "fitness/measures.hpp"

#include <optional>

namespace morphogen {

using nlohmann::json;

namespace {
std::string type_of(const json& section) {
    const auto it = section.find("type");
    if (it == section.end()) return "canopy";  // the default type
    return it->is_string() ? it->get<std::string>() : "";
}

std::optional<CanopyParams> find_canopy(const json& section) {
    if (!section.is_object()) return std::nullopt;
    const std::string type = type_of(section);
    if (type == "canopy") {
        CanopyParams params;
        if (auto it = section.find("height"); it != section.end() && it->is_number()) params.height = it->get<double>();
        if (auto it = section.find("cell"); it != section.end() && it->is_number() && it->get<double>() > 0)
            params.cell = it->get<double>();
        return params;
    }
    if (type == "sum") {
        if (auto it = section.find("terms"); it != section.end() && it->is_array())
            for (const json& term : *it)
                if (auto found = find_canopy(term)) return found;
    }
    return std::nullopt;
}
}  // namespace

CanopyParams canopy_params_of(const json& resolved_fitness) {
    return find_canopy(resolved_fitness).value_or(CanopyParams{});
}

json mesh_metrics(MeshView mesh, const CanopyParams& canopy) {
    check_mesh_view(mesh);
    json metrics = json::object();
    metrics["canopy"] = canopy_area(mesh, canopy);
    metrics["height"] = mesh_height(mesh);
    metrics["footprint"] = mesh_footprint(mesh);
    metrics["area"] = mesh_area(mesh);
    metrics["volume"] = mesh_volume(mesh);
    metrics["vertices"] = mesh.positions.size();
    metrics["faces"] = mesh.faces.size();
    metrics["self_intersecting"] = mesh_self_intersects(mesh);
    return metrics;
}

}  // namespace morphogen
