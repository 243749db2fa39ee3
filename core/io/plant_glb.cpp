// The engine-ready GLB (see plant_glb.hpp).
#include "core/io/plant_glb.hpp"

#include "core/io/gltf_mesh.hpp"
#include "core/io/gltf_leaves.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>

namespace morphogen {

namespace {
// The leaf material and the TEXCOORD_n of its texture, when some level has cards.
struct LeafMaterial {
    int material = -1;
    int tex_coord = 0;
};

// A mesh of one primitive with _WIND and further attributes; returns its index.
int add_attributed_mesh(tinygltf::Model& model, MeshView mesh, std::span<const float> wind,
                        std::span<const VertexAttribute> attributes, int material, const std::string& name) {
    const int index = gltf::add_wind_mesh(model, mesh, wind, material, name);
    for (const VertexAttribute& attribute : attributes)
        gltf::add_vertex_attribute(model, index, attribute.name, attribute.components, attribute.values);
    return index;
}

// The level's mesh, with its cards as a second primitive; returns its index.
int add_level_mesh(tinygltf::Model& model, const PlantLevel& level, int material, const std::string& name,
                   const LeafMaterial& leaf) {
    const int mesh = add_attributed_mesh(model, level.mesh, level.wind, level.attributes, material, name);
    if (level.leaves.mesh.positions.empty()) return mesh;
    const int cards =
        add_attributed_mesh(model, level.leaves.mesh, level.leaves.wind, level.leaves.attributes, leaf.material, name + " leaves");
    gltf::add_vertex_attribute(model, cards, "TEXCOORD_" + std::to_string(leaf.tex_coord), 2, level.leaves.uv);
    gltf::append_primitive(model, cards, mesh);
    return mesh;
}

// The first TEXCOORD_n the cards' attributes leave free (2 beside the uv wind preset's).
int leaf_tex_coord(const LeafPrimitive& leaves) {
    int n = 0;
    while (std::ranges::any_of(leaves.attributes,
                               [&](const VertexAttribute& a) { return a.name == "TEXCOORD_" + std::to_string(n); }))
        ++n;
    return n;
}
}  // namespace

std::string plant_glb_bytes(const PlantGlb& plant, const std::string& source) {
    if (plant.levels.empty()) throw std::invalid_argument("plant_glb_bytes: a plant needs at least one level");
    if (plant.levels.size() > 1 && !plant.lod_nodes)
        throw std::invalid_argument("plant_glb_bytes: several levels need LOD nodes");
    tinygltf::Model model = gltf::new_model();
    const int material = gltf::add_plant_material(model, plant.vertex_colours);
    LeafMaterial leaf;
    for (const PlantLevel& level : plant.levels)
        if (!level.leaves.mesh.positions.empty() && leaf.material < 0) {
            leaf.tex_coord = leaf_tex_coord(level.leaves);
            leaf.material = gltf::add_leaf_material(model, plant.leaf_png, leaf.tex_coord);
        }

    tinygltf::Node root;
    root.name = plant.name;
    root.extras = gltf::json_value(plant.extras);
    model.nodes.push_back(root);
    if (!plant.lod_nodes) {
        model.nodes[0].mesh = add_level_mesh(model, plant.levels[0], material, plant.name, leaf);
    } else {
        for (std::size_t i = 0; i < plant.levels.size(); ++i) {
            tinygltf::Node node;
            node.name = plant.name + "_LOD" + std::to_string(i);
            node.mesh = add_level_mesh(model, plant.levels[i], material, node.name, leaf);
            node.extras = gltf::json_value(plant.levels[i].extras);
            model.nodes.push_back(node);
            model.nodes[0].children.push_back(static_cast<int>(model.nodes.size()) - 1);
        }
    }
    gltf::set_root_scene(model, 0);
    return gltf::glb_bytes(model, source);
}

}  // namespace morphogen
