// The engine-ready GLB (see plant_glb.hpp).
#include "io/plant_glb.hpp"

#include "io/gltf_mesh.hpp"

#include <stdexcept>

namespace morphogen {

namespace {

// glTF extras are JSON; tinygltf keeps them as its own Value tree.
tinygltf::Value to_value(const nlohmann::json& json) {
    switch (json.type()) {
    case nlohmann::json::value_t::boolean: return tinygltf::Value(json.get<bool>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
        // Value holds int: larger whole numbers go as doubles (exact below 2^53).
        if (json.get<double>() >= -2147483648.0 && json.get<double>() <= 2147483647.0)
            return tinygltf::Value(json.get<int>());
        return tinygltf::Value(json.get<double>());
    case nlohmann::json::value_t::number_float: return tinygltf::Value(json.get<double>());
    case nlohmann::json::value_t::string: return tinygltf::Value(json.get<std::string>());
    case nlohmann::json::value_t::array: {
        tinygltf::Value::Array items;
        for (const nlohmann::json& item : json) items.push_back(to_value(item));
        return tinygltf::Value(std::move(items));
    }
    case nlohmann::json::value_t::object: {
        tinygltf::Value::Object members;
        for (const auto& [key, item] : json.items()) members[key] = to_value(item);
        return tinygltf::Value(std::move(members));
    }
    default: return {};
    }
}

// The mesh of one level, with its _WIND attribute when it has wind data.
int add_level_mesh(tinygltf::Model& model, const PlantLevel& level, int material, const std::string& name) {
    const int mesh = gltf::add_mesh(model, level.mesh, material, name);
    if (mesh < 0) throw std::invalid_argument(name + ": a plant level needs vertices and faces");
    if (level.wind.empty()) return mesh;
    if (level.wind.size() != 4 * level.mesh.positions.size())
        throw std::invalid_argument(name + ": wind data needs 4 values per vertex");
    model.meshes[mesh].primitives[0].attributes["_WIND"] =
        gltf::add_floats(model, level.wind, TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
    return mesh;
}

}  // namespace

std::string plant_glb_bytes(const PlantGlb& plant, const std::string& source) {
    if (plant.levels.empty()) throw std::invalid_argument("plant_glb_bytes: a plant needs at least one level");
    if (plant.levels.size() > 1 && !plant.lod_nodes)
        throw std::invalid_argument("plant_glb_bytes: several levels need LOD nodes");
    tinygltf::Model model = gltf::new_model();
    const int material = gltf::add_plant_material(model);

    tinygltf::Node root;
    root.name = plant.name;
    root.extras = to_value(plant.extras);
    model.nodes.push_back(root);
    if (!plant.lod_nodes) {
        model.nodes[0].mesh = add_level_mesh(model, plant.levels[0], material, plant.name);
    } else {
        for (std::size_t i = 0; i < plant.levels.size(); ++i) {
            tinygltf::Node node;
            node.name = plant.name + "_LOD" + std::to_string(i);
            node.mesh = add_level_mesh(model, plant.levels[i], material, node.name);
            node.extras = to_value(plant.levels[i].extras);
            model.nodes.push_back(node);
            model.nodes[0].children.push_back(static_cast<int>(model.nodes.size()) - 1);
        }
    }
    gltf::set_root_scene(model, 0);
    return gltf::glb_bytes(model, source);
}

}  // namespace morphogen
