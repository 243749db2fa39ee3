#pragma once
// The scatter of a species pack laid out in glTF (docs/file-formats.md,
// "scatter.glb"): one node per species, which every glTF client draws once
// at the node's place, and the node's extra copies as an
// EXT_mesh_gpu_instancing extension (in extensionsUsed, never in
// extensionsRequired), which only clients that know it draw. Where the copies
// go is the caller's (engine/plant_scatter.hpp); this file only lays them out.
#include "core/io/plant_glb.hpp"
#include "core/mesh/mesh.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

// One drawing of a species' mesh relative to its node, in glTF's axes (Y-up):
// WorldPosition = Node * Translation * Rotation * Scale * VertexPosition.
struct ScatterInstance {
    std::array<float, 3> translation{0, 0, 0};
    std::array<float, 4> rotation{0, 0, 0, 1};  // unit quaternion x, y, z, w
    float scale = 1.0f;                         // uniform
};

struct ScatterSpecies {
    std::string name;          // the node's and the mesh's name ("plant_<id>")
    nlohmann::json extras;     // the node's extras (null: none)
    MeshView mesh;             // Z-up, as every morphogen mesh; turned Y-up here
    std::span<const float> wind;  // empty, or 4 floats per vertex: the mesh's _WIND attribute
    std::vector<VertexAttribute> attributes{};  // further attributes after _WIND (wind presets)
    std::array<float, 3> position{0, 0, 0};  // the node's translation (Y-up)
    // The drawings with the extension. Empty: a plain node. Otherwise the
    // first must be the identity, so that a client without the extension
    // draws the one copy that a client with it draws there too.
    std::vector<ScatterInstance> instances;
};

// The .glb bytes: a root node `root_name` (extras `root_extras`) whose
// children are the species' nodes, in order. Throws std::invalid_argument
// for no species, a mesh without faces, wind or an attribute of the wrong
// length (plant_glb.hpp) or
// instances whose first is not the identity; IoError naming `source` if
// tinygltf cannot encode the model.
std::string scatter_glb_bytes(std::span<const ScatterSpecies> species, const std::string& root_name,
                              const nlohmann::json& root_extras, const std::string& source);

}  // namespace morphogen
