#pragma once
// The engine-ready GLB of one plant (docs/engine-glb.md, "Engine-ready
// GLB"): a node an engine keys on by name, its levels of detail as child
// nodes `<name>_LOD<i>`, glTF `extras` carried on the plant's node, and an
// optional `_WIND` vertex attribute and copies of it where engines read them
// (engine/plant_wind.hpp, wind presets). The meshes are placed by the caller
// (engine/plant_frame.hpp); this file only lays them out in glTF.
#include "core/mesh/mesh.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphogen {

// A further float vertex attribute of a level, such as COLOR_0 or TEXCOORD_0:
// its glTF name, its components per vertex (2, 3 or 4: VEC2 .. VEC4) and its
// values, `components` per vertex.
struct VertexAttribute {
    std::string name;
    int components = 0;
    std::vector<float> values;
};

// Foliage cards of a level (engine/leaf_cards.hpp): a second primitive of
// the level's mesh, drawn with the leaf material (alphaMode MASK,
// doubleSided, the leaf texture). No vertices: none.
struct LeafPrimitive {
    MeshView mesh;                               // Z-up, as the level's mesh
    std::vector<float> uv;                       // 2 per vertex: the leaf texture's coordinates
    std::vector<float> wind;                     // _WIND, 4 per vertex, or empty
    std::vector<VertexAttribute> attributes{};   // written after _WIND (wind presets)
};

// One level of detail: its mesh (Z-up, converted to glTF's Y-up here) and,
// when the plant has wind data, four floats per vertex in [0, 1].
struct PlantLevel {
    MeshView mesh;
    std::vector<float> wind;   // empty, or 4 * mesh.positions.size() values
    std::vector<VertexAttribute> attributes{};  // written after _WIND, in this order
    nlohmann::json extras;     // this level's own extras (null: none)
    LeafPrimitive leaves{};    // its foliage cards, if any
};

struct PlantGlb {
    std::string name;          // "plant_<id>": the node's and (one level) the mesh's name
    nlohmann::json extras;     // the plant's extras, on its node (an object)
    std::vector<PlantLevel> levels;
    // true: node `name` holds one child node per level, `name_LOD<i>`, each
    // with its mesh `name_LOD<i>`; false: one level, node and mesh `name`.
    bool lod_nodes = false;
    // true: the levels carry COLOR_0 (engine/plant_colour.hpp), so the
    // material's base colour is white and the vertex colour is the colour.
    bool vertex_colours = false;
    // With foliage cards on any level: the leaf texture, PNG bytes
    // (engine/leaf_texture.hpp). Its coordinates go in the first TEXCOORD_n
    // the cards' attributes leave free.
    std::string leaf_png{};
};

// The .glb bytes. Throws std::invalid_argument for no levels, several levels
// without lod_nodes, wind data or an attribute of the wrong length, or an
// attribute whose name is taken or that has not 2, 3 or 4 components, or
// foliage cards without leaf_png or with data of the wrong length; IoError naming
// `source` if tinygltf cannot encode the model.
std::string plant_glb_bytes(const PlantGlb& plant, const std::string& source);

}  // namespace morphogen
