#pragma once
// The engine-ready GLB of one plant (docs/file-formats.md, "Engine-ready
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

// One level of detail: its mesh (Z-up, converted to glTF's Y-up here) and,
// when the plant has wind data, four floats per vertex in [0, 1].
struct PlantLevel {
    MeshView mesh;
    std::vector<float> wind;   // empty, or 4 * mesh.positions.size() values
    std::vector<VertexAttribute> attributes{};  // written after _WIND, in this order
    nlohmann::json extras;     // this level's own extras (null: none)
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
};

// The .glb bytes. Throws std::invalid_argument for no levels, several levels
// without lod_nodes, wind data or an attribute of the wrong length, or an
// attribute whose name is taken or that has not 2, 3 or 4 components; IoError naming
// `source` if tinygltf cannot encode the model.
std::string plant_glb_bytes(const PlantGlb& plant, const std::string& source);

}  // namespace morphogen
