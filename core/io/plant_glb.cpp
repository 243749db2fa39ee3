// The engine-ready GLB (see plant_glb.hpp).
#include "core/io/plant_glb.hpp"

#include "core/io/gltf_mesh.hpp"

#include <stdexcept>

namespace morphogen {

namespace {
// The level's mesh with _WIND and its further attributes; returns its index.
int add_level_mesh(tinygltf::Model& model, const PlantLevel& level, int material, const std::string& name) {
    const int mesh = gltf::add_wind_mesh(model, level.mesh, level.wind, material, name);
    for (const VertexAttribute& attribute : level.attributes)
        gltf::add_vertex_attribute(model, mesh, attribute.name, attribute.components, attribute.values);
    return mesh;
}
}  // namespace

std::string plant_glb_bytes(const PlantGlb& plant, const std::string& source) {
    if (plant.levels.empty()) throw std::invalid_argument("plant_glb_bytes: a plant needs at least one level");
    if (plant.levels.size() > 1 && !plant.lod_nodes)
        throw std::invalid_argument("plant_glb_bytes: several levels need LOD nodes");
    tinygltf::Model model = gltf::new_model();
    const int material = gltf::add_plant_material(model, plant.vertex_colours);

    tinygltf::Node root;
    root.name = plant.name;
    root.extras = gltf::json_value(plant.extras);
    model.nodes.push_back(root);
    if (!plant.lod_nodes) {
        model.nodes[0].mesh = add_level_mesh(model, plant.levels[0], material, plant.name);
    } else {
        for (std::size_t i = 0; i < plant.levels.size(); ++i) {
            tinygltf::Node node;
            node.name = plant.name + "_LOD" + std::to_string(i);
            node.mesh = add_level_mesh(model, plant.levels[i], material, node.name);
            node.extras = gltf::json_value(plant.levels[i].extras);
            model.nodes.push_back(node);
            model.nodes[0].children.push_back(static_cast<int>(model.nodes.size()) - 1);
        }
    }
    gltf::set_root_scene(model, 0);
    return gltf::glb_bytes(model, source);
}

}  // namespace morphogen
