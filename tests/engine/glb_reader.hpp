#pragma once
// Reads a GLB back with tinygltf for the engine tests, and the float data of
// an accessor (tightly packed float32, as morphogen writes them).
#include <tiny_gltf.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace morphogen::test {

inline tinygltf::Model parse_glb(const std::string& bytes) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    if (!loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                     static_cast<unsigned>(bytes.size())))
        throw std::runtime_error("not a GLB: " + error);
    return model;
}

inline std::vector<float> accessor_floats(const tinygltf::Model& model, int accessor) {
    const tinygltf::Accessor& acc = model.accessors.at(accessor);
    const tinygltf::BufferView& view = model.bufferViews.at(acc.bufferView);
    const auto components = static_cast<std::size_t>(tinygltf::GetNumComponentsInType(acc.type));
    std::vector<float> values(acc.count * components);
    std::memcpy(values.data(), model.buffers.at(view.buffer).data.data() + view.byteOffset + acc.byteOffset,
                values.size() * sizeof(float));
    return values;
}

}  // namespace morphogen::test
