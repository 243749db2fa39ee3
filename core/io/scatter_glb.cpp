// The scatter's glTF layout (see scatter_glb.hpp).
#include "core/io/scatter_glb.hpp"

#include "core/io/gltf_mesh.hpp"

#include <stdexcept>

namespace morphogen {

namespace {

constexpr const char* kInstancing = "EXT_mesh_gpu_instancing";

bool is_identity(const ScatterInstance& instance) {
    const ScatterInstance identity;
    return instance.translation == identity.translation && instance.rotation == identity.rotation &&
           instance.scale == identity.scale;
}

// The node's EXT_mesh_gpu_instancing object: TRANSLATION, ROTATION and SCALE
// accessors of one element per instance. No buffer view target: instance
// attributes are not vertex attributes.
tinygltf::Value instancing(tinygltf::Model& model, const std::vector<ScatterInstance>& instances) {
    std::vector<float> translation, rotation, scale;
    for (const ScatterInstance& instance : instances) {
        translation.insert(translation.end(), instance.translation.begin(), instance.translation.end());
        rotation.insert(rotation.end(), instance.rotation.begin(), instance.rotation.end());
        scale.insert(scale.end(), {instance.scale, instance.scale, instance.scale});
    }
    tinygltf::Value::Object attributes;
    attributes["TRANSLATION"] = tinygltf::Value(gltf::add_floats(model, translation, TINYGLTF_TYPE_VEC3));
    attributes["ROTATION"] = tinygltf::Value(gltf::add_floats(model, rotation, TINYGLTF_TYPE_VEC4));
    attributes["SCALE"] = tinygltf::Value(gltf::add_floats(model, scale, TINYGLTF_TYPE_VEC3));
    tinygltf::Value::Object extension;
    extension["attributes"] = tinygltf::Value(std::move(attributes));
    return tinygltf::Value(std::move(extension));
}

}  // namespace

std::string scatter_glb_bytes(std::span<const ScatterSpecies> species, const std::string& root_name,
                              const nlohmann::json& root_extras, const std::string& source) {
    if (species.empty()) throw std::invalid_argument("scatter_glb_bytes: a scatter needs at least one species");
    tinygltf::Model model = gltf::new_model();
    const int material = gltf::add_plant_material(model);

    tinygltf::Node root;
    root.name = root_name;
    root.extras = gltf::json_value(root_extras);
    model.nodes.push_back(root);
    bool instanced = false;
    for (const ScatterSpecies& one : species) {
        if (!one.instances.empty() && !is_identity(one.instances.front()))
            throw std::invalid_argument(one.name + ": the first instance must be the identity (the plain node's copy)");
        tinygltf::Node node;
        node.name = one.name;
        node.mesh = gltf::add_wind_mesh(model, one.mesh, one.wind, material, one.name);
        for (const VertexAttribute& attribute : one.attributes)
            gltf::add_vertex_attribute(model, node.mesh, attribute.name, attribute.components, attribute.values);
        node.translation = {one.position[0], one.position[1], one.position[2]};
        node.extras = gltf::json_value(one.extras);
        if (!one.instances.empty()) {
            node.extensions[kInstancing] = instancing(model, one.instances);
            instanced = true;
        }
        model.nodes.push_back(std::move(node));
        model.nodes[0].children.push_back(static_cast<int>(model.nodes.size()) - 1);
    }
    if (instanced) model.extensionsUsed.push_back(kInstancing);  // used, never required: the nodes are the fallback
    gltf::set_root_scene(model, 0);
    return gltf::glb_bytes(model, source);
}

}  // namespace morphogen
