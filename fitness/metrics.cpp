// The metrics report of a mesh (score command, run records).
#include "fitness/fitness.hpp"

#include "fitness/functions/canopy.hpp"
#include "fitness/geometry/cgal_geometry.hpp"
#include "fitness/measures.hpp"

namespace morphogen {

using nlohmann::json;

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
