// GLB (glTF 2.0 binary) writer, Y-up, with smooth vertex normals.
#include "core/io/mesh_io_detail.hpp"

#include "core/io/gltf_mesh.hpp"

#include <string>

namespace morphogen::mesh_io_detail {

std::string glb_bytes(MeshView mesh, const std::string& path) {
    tinygltf::Model model = gltf::new_model();
    const int material = gltf::add_plant_material(model);

    tinygltf::Node node;
    node.name = "morphogen";
    // An empty mesh becomes a scene with one empty node (add_mesh returns -1).
    node.mesh = gltf::add_mesh(model, mesh, material, "morphogen");
    model.nodes.push_back(node);
    gltf::set_root_scene(model, 0);
    return gltf::glb_bytes(model, path);
}

}  // namespace morphogen::mesh_io_detail
