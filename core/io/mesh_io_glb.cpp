// GLB (glTF 2.0 binary): the writer, Y-up, with smooth vertex normals, and
// the reader of a file's first mesh (a plant's body, LOD0 of an engine export).
#include "core/io/mesh_io_detail.hpp"

#include "core/io/gltf_mesh.hpp"

#include <cstdint>
#include <cstring>
#include <string>

namespace morphogen::mesh_io_detail {

std::string glb_bytes(MeshView mesh, const std::string& path, std::span<const float> colours) {
    check_colours(mesh, colours);
    tinygltf::Model model = gltf::new_model();
    const int material = gltf::add_plant_material(model, !colours.empty());

    tinygltf::Node node;
    node.name = "morphogen";
    // An empty mesh becomes a scene with one empty node (add_mesh returns -1).
    node.mesh = gltf::add_mesh(model, mesh, material, "morphogen");
    if (node.mesh >= 0 && !colours.empty()) gltf::add_vertex_attribute(model, node.mesh, "COLOR_0", 4, colours);
    model.nodes.push_back(node);
    gltf::set_root_scene(model, 0);
    return gltf::glb_bytes(model, path);
}

}  // namespace morphogen::mesh_io_detail

namespace morphogen::mesh_io_detail {

namespace {

// Where accessor `index`'s elements lie in its buffer, each `size` bytes:
// checked against the buffer view and the buffer before anything is read.
struct Elements {
    const unsigned char* first = nullptr;
    std::size_t stride = 0, count = 0;
};

const tinygltf::Accessor& accessor_at(const tinygltf::Model& model, int index, const std::string& path,
                                      const std::string& what) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) fail(path, what + ": no such accessor");
    return model.accessors[static_cast<std::size_t>(index)];
}

Elements elements(const tinygltf::Model& model, int index, std::size_t size, const std::string& path,
                  const std::string& what) {
    const tinygltf::Accessor& accessor = accessor_at(model, index, path, what);
    if (accessor.sparse.isSparse) fail(path, what + ": sparse accessors are not read");
    if (accessor.bufferView < 0 || static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
        fail(path, what + ": no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) fail(path, what + ": no buffer");
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : size;
    const long double end = static_cast<long double>(view.byteOffset) + accessor.byteOffset +
                            (accessor.count == 0 ? 0.0L : static_cast<long double>(stride) * (accessor.count - 1) + size);
    if (stride < size || end > static_cast<long double>(view.byteOffset) + view.byteLength ||
        static_cast<long double>(view.byteOffset) + view.byteLength > buffer.size())
        fail(path, what + ": " + std::to_string(accessor.count) + " elements do not fit in their buffer");
    return {buffer.data() + view.byteOffset + accessor.byteOffset, stride, accessor.count};
}

template <class T>
T element(const Elements& e, std::size_t i, std::size_t component = 0) {
    T value;
    std::memcpy(&value, e.first + i * e.stride + component * sizeof(T), sizeof(T));
    return value;
}

}  // namespace

// The linear colour that stands for a textured material (leaf cards) in pictures.
constexpr float kTexturedGreen[4] = {0.10f, 0.32f, 0.05f, 1.0f};

// Appends the primitive's float COLOR_0 (VEC3 or VEC4) to `colours`, one RGBA
// per of its `count` vertices; without COLOR_0, its material's base colour
// (kTexturedGreen where the material is textured). False for COLOR_0 of
// another kind.
bool append_colours(const tinygltf::Model& model, const tinygltf::Primitive& primitive, std::size_t count,
                    const std::string& path, const std::string& what, std::vector<float>& colours) {
    const auto colour = primitive.attributes.find("COLOR_0");
    if (colour == primitive.attributes.end()) {
        const bool has_material = primitive.material >= 0 && static_cast<std::size_t>(primitive.material) < model.materials.size();
        const tinygltf::PbrMetallicRoughness* pbr =
            has_material ? &model.materials[static_cast<std::size_t>(primitive.material)].pbrMetallicRoughness : nullptr;
        float rgba[4] = {kTexturedGreen[0], kTexturedGreen[1], kTexturedGreen[2], kTexturedGreen[3]};
        if (pbr && pbr->baseColorTexture.index < 0 && pbr->baseColorFactor.size() == 4)
            for (int c = 0; c < 4; ++c) rgba[c] = static_cast<float>(pbr->baseColorFactor[static_cast<std::size_t>(c)]);
        for (std::size_t i = 0; i < count; ++i) colours.insert(colours.end(), rgba, rgba + 4);
        return true;
    }
    const tinygltf::Accessor& a = accessor_at(model, colour->second, path, what + " COLOR_0");
    const int width = a.type == TINYGLTF_TYPE_VEC3 ? 3 : a.type == TINYGLTF_TYPE_VEC4 ? 4 : 0;
    if (width == 0 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.count != count) return false;
    const Elements e = elements(model, colour->second, 4 * static_cast<std::size_t>(width), path, what + " COLOR_0");
    for (std::size_t i = 0; i < e.count; ++i)
        for (int c = 0; c < 4; ++c) colours.push_back(c < width ? element<float>(e, i, c) : 1.0f);
    return true;
}

MeshArrays read_glb(const std::string& path, std::string_view bytes, std::vector<float>* colours) {
    bool all_coloured = colours != nullptr, any_colour = false;
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    if (!loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                     static_cast<unsigned int>(bytes.size())))
        fail(path, "not a valid GLB: " + excerpt(error.substr(0, error.find('\n'))));
    // The plant's body: the first mesh (LOD0 of an engine export; a breed
    // session's or grow's one mesh), in its own coordinates (node transforms
    // are not applied), turned from glTF's y up back to morphogen's z up.
    if (model.meshes.empty()) fail(path, "holds no mesh");
    MeshArrays out;
    for (const tinygltf::Primitive& primitive : model.meshes[0].primitives) {
        const std::string what = "mesh 0 (" + excerpt(model.meshes[0].name) + ")";
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1)
            fail(path, what + ": a primitive that is not triangles (mode " + std::to_string(primitive.mode) + ")");
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) fail(path, what + ": a primitive without POSITION");
        const tinygltf::Accessor& p = accessor_at(model, position->second, path, what + " POSITION");
        if (p.type != TINYGLTF_TYPE_VEC3 || p.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
            fail(path, what + ": POSITION is not float VEC3");
        const Elements positions = elements(model, position->second, 12, path, what + " POSITION");
        const std::size_t base = out.positions.size();
        check_vertex_count(static_cast<long long>(base + positions.count), path);
        for (std::size_t i = 0; i < positions.count; ++i) {
            const Vec3 v = gltf::from_y_up(Vec3(element<float>(positions, i, 0), element<float>(positions, i, 1),
                                                element<float>(positions, i, 2)));
            check_position(v, path, "vertex", static_cast<long long>(base + i));
            out.positions.push_back(v);
        }
        if (all_coloured) all_coloured = append_colours(model, primitive, positions.count, path, what, *colours);
        any_colour = any_colour || primitive.attributes.count("COLOR_0") > 0;
        std::vector<std::size_t> corners;
        if (primitive.indices < 0) {
            for (std::size_t i = 0; i < positions.count; ++i) corners.push_back(i);
        } else {
            const tinygltf::Accessor& a = accessor_at(model, primitive.indices, path, what + " indices");
            const int type = a.componentType;
            const std::size_t size = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                                     : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                     : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                      : 0;
            if (a.type != TINYGLTF_TYPE_SCALAR || size == 0) fail(path, what + ": indices are not unsigned integers");
            const Elements indices = elements(model, primitive.indices, size, path, what + " indices");
            check_triangle_count(out.faces.size() + indices.count / 3, 2, path, 0);
            for (std::size_t i = 0; i < indices.count; ++i)
                corners.push_back(size == 1   ? element<std::uint8_t>(indices, i)
                                  : size == 2 ? element<std::uint16_t>(indices, i)
                                              : element<std::uint32_t>(indices, i));
        }
        if (corners.size() % 3 != 0) fail(path, what + ": " + std::to_string(corners.size()) + " corners, not triangles");
        for (std::size_t i = 0; i < corners.size(); i += 3) {
            Face face;
            for (int k = 0; k < 3; ++k) {
                if (corners[i + k] >= positions.count)
                    fail(path, what + ": triangle " + std::to_string(i / 3) + " has vertex index " +
                                   std::to_string(corners[i + k]) + " of " + std::to_string(positions.count));
                face[k] = static_cast<int>(base + corners[i + k]);
            }
            out.faces.push_back(face);
        }
    }
    if (colours && !(all_coloured && any_colour)) colours->clear();
    return out;
}

}  // namespace morphogen::mesh_io_detail
