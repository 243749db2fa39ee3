#pragma once
// glTF building blocks shared by the GLB mesh writer (mesh_io_glb.cpp) and the
// growth animation (report/growth_animation.cpp), the plant GLB and the
// scatter (plant_glb.cpp, scatter_glb.cpp): the plant material, meshes and
// float arrays appended to one buffer, and the binary (.glb) encoding.
// Meshes are stored Y-up (glTF's convention) as float32 positions with
// min/max (the validator requires them), smooth normals and uint32 indices.
#include "core/mesh/mesh.hpp"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <span>
#include <string>

namespace morphogen::gltf {

// Our meshes are Z-up; glTF is Y-up, right-handed: (x, y, z) -> (x, z, -y) is
// a proper rotation, so orientation (and outward normals) are kept.
inline Vec3 to_y_up(const Vec3& p) { return {p.x(), p.z(), -p.y()}; }
// Its inverse: a glTF position back in morphogen's frame (z up).
inline Vec3 from_y_up(const Vec3& p) { return {p.x(), -p.z(), p.y()}; }

// An empty glTF 2.0 model whose asset names morphogen as its generator.
tinygltf::Model new_model();

// Makes node `root` the one scene of `model`, and that scene the default.
void set_root_scene(tinygltf::Model& model, int root);

// Adds the double-sided green material every morphogen glTF uses; returns its
// index. `white`: base colour white, for meshes whose COLOR_0 is the colour.
int add_plant_material(tinygltf::Model& model, bool white = false);

// The bytes add_mesh appends to the buffer for `mesh`.
std::size_t mesh_data_bytes(MeshView mesh);

// Appends the mesh's positions, normals and indices to buffer 0 (created when
// absent) and a glTF mesh `name` of one triangle primitive drawn with
// `material`; returns the mesh's index. A mesh with no vertices or no faces
// adds nothing and returns -1 (glTF accessors need count >= 1).
int add_mesh(tinygltf::Model& model, MeshView mesh, int material, const std::string& name);

// Appends `values` (count * components of `type`, e.g. TINYGLTF_TYPE_VEC3) to
// buffer 0 as float32 and returns their accessor, with min/max (required for
// animation inputs). `target` is the buffer view's: 0 (none) for animation
// data, TINYGLTF_TARGET_ARRAY_BUFFER for a vertex attribute.
int add_floats(tinygltf::Model& model, std::span<const float> values, int type, int target = 0);

// `json` as tinygltf's Value, for glTF `extras` (null: none). Whole numbers
// beyond int go as doubles (exact below 2^53).
tinygltf::Value json_value(const nlohmann::json& json);

// add_mesh, and with wind data (4 floats per vertex, empty: none) the
// mesh's `_WIND` vertex attribute. Throws std::invalid_argument for a mesh
// without vertices or faces, or wind data of the wrong length.
int add_wind_mesh(tinygltf::Model& model, MeshView mesh, std::span<const float> wind, int material,
                  const std::string& name);

// Adds `values` (float32, `components` 2, 3 or 4 per vertex: VEC2 .. VEC4)
// as the vertex attribute `name` of mesh `mesh`'s primitive. Throws
// std::invalid_argument for a name the primitive has already, other
// components, or values for another number of vertices.
void add_vertex_attribute(tinygltf::Model& model, int mesh, const std::string& name, int components,
                          std::span<const float> values);

// The .glb bytes of `model`; IoError naming `path` if tinygltf cannot encode it.
std::string glb_bytes(const tinygltf::Model& model, const std::string& path);

}  // namespace morphogen::gltf
