// glTF pieces of foliage cards (see gltf_leaves.hpp).
#include "core/io/gltf_leaves.hpp"

#include <stdexcept>
#include <vector>

namespace morphogen::gltf {

int add_leaf_material(tinygltf::Model& model, const std::string& png, int tex_coord) {
    if (png.empty()) throw std::invalid_argument("leaf material: no texture");
    if (model.buffers.empty()) model.buffers.emplace_back();
    std::vector<unsigned char>& data = model.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = png.size();
    data.insert(data.end(), png.begin(), png.end());
    data.resize((data.size() + 3) / 4 * 4, 0);  // the next view starts 4-byte aligned
    model.bufferViews.push_back(view);

    tinygltf::Image image;
    image.name = "leaf";
    image.mimeType = "image/png";
    image.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
    model.images.push_back(image);
    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    model.samplers.push_back(sampler);
    tinygltf::Texture texture;
    texture.name = "leaf";
    texture.sampler = static_cast<int>(model.samplers.size()) - 1;
    texture.source = static_cast<int>(model.images.size()) - 1;
    model.textures.push_back(texture);

    tinygltf::Material material;
    material.name = "leaf";
    material.doubleSided = true;  // a card is seen from both sides
    material.alphaMode = "MASK";  // cut out along the leaf's outline, no sorting
    material.alphaCutoff = 0.5;
    material.pbrMetallicRoughness.baseColorTexture.index = static_cast<int>(model.textures.size()) - 1;
    material.pbrMetallicRoughness.baseColorTexture.texCoord = tex_coord;
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.7;
    model.materials.push_back(material);
    return static_cast<int>(model.materials.size()) - 1;
}

void append_primitive(tinygltf::Model& model, int from, int to) {
    if (from != static_cast<int>(model.meshes.size()) - 1 || to < 0 || to >= from ||
        model.meshes[static_cast<std::size_t>(from)].primitives.size() != 1)
        throw std::invalid_argument("append_primitive: mesh " + std::to_string(from) + " cannot join mesh " +
                                    std::to_string(to));
    tinygltf::Primitive primitive = model.meshes.back().primitives[0];
    model.meshes.pop_back();
    model.meshes[static_cast<std::size_t>(to)].primitives.push_back(std::move(primitive));
}

}  // namespace morphogen::gltf
