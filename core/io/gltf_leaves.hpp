#pragma once
// glTF pieces of foliage cards (plant_glb.hpp, LeafPrimitive): the leaf
// material with its embedded texture, and the move that makes the cards a
// second primitive of their level's mesh.
#include <tiny_gltf.h>

#include <string>

namespace morphogen::gltf {

// Appends the PNG to buffer 0 and adds its image, a sampler, a texture and
// the material "leaf" (alphaMode MASK, cutoff 0.5, doubleSided, the texture
// as baseColorTexture read from TEXCOORD_`tex_coord`); returns the material.
// Throws std::invalid_argument for no PNG bytes.
int add_leaf_material(tinygltf::Model& model, const std::string& png, int tex_coord);

// Moves the one primitive of mesh `from`, the last mesh, to the end of mesh
// `to`'s primitives and removes mesh `from`. Throws std::invalid_argument
// unless `from` is the last mesh, has one primitive and `to` comes before it.
void append_primitive(tinygltf::Model& model, int from, int to);

}  // namespace morphogen::gltf
