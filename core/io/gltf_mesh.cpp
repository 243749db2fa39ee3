// glTF building blocks (see gltf_mesh.hpp).
#include "core/io/gltf_mesh.hpp"

#include "core/base/errors.hpp"
#include "core/mesh/vertex_normals.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace morphogen::gltf {

namespace {

// The shared smooth normals (vertex_normals), Y-up; "up" where undefined.
std::vector<Vec3> smooth_normals_y_up(MeshView mesh) {
    std::vector<Vec3> normals = vertex_normals(mesh);
    for (Vec3& n : normals) n = n == Vec3::Zero() ? Vec3(0, 1, 0) : to_y_up(n);
    return normals;
}

template <class T>
void append_raw(std::vector<unsigned char>& out, T value) {
    const auto size = out.size();
    out.resize(size + sizeof(T));
    std::memcpy(out.data() + size, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big)
        std::reverse(out.begin() + static_cast<std::ptrdiff_t>(size), out.end());
}

// Buffer 0, created on first use. Every item in it is 4 bytes wide, so every
// view starts 4-byte aligned as glTF requires.
std::vector<unsigned char>& buffer_data(tinygltf::Model& model) {
    if (model.buffers.empty()) model.buffers.emplace_back();
    return model.buffers[0].data;
}

int add_view(tinygltf::Model& model, std::size_t offset, std::size_t length, int target) {
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = length;
    view.target = target;
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component, int type, std::size_t count) {
    tinygltf::Accessor acc;
    acc.bufferView = view;
    acc.byteOffset = 0;
    acc.componentType = component;
    acc.type = type;
    acc.count = count;
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size()) - 1;
}

}  // namespace

tinygltf::Model new_model() {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "morphogen";
    return model;
}

void set_root_scene(tinygltf::Model& model, int root) {
    tinygltf::Scene scene;
    scene.nodes.push_back(root);
    model.scenes.push_back(scene);
    model.defaultScene = static_cast<int>(model.scenes.size()) - 1;
}

int add_plant_material(tinygltf::Model& model, bool white) {
    tinygltf::Material material;
    material.name = "plant";
    material.doubleSided = true;  // grown meshes are viewed from inside too (open canopies)
    material.pbrMetallicRoughness.baseColorFactor = {0.33, 0.62, 0.24, 1.0};
    if (white) material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.8;
    model.materials.push_back(material);
    return static_cast<int>(model.materials.size()) - 1;
}

std::size_t mesh_data_bytes(MeshView mesh) {
    if (mesh.positions.empty() || mesh.faces.empty()) return 0;
    return mesh.positions.size() * 24 + mesh.faces.size() * 12;
}

int add_mesh(tinygltf::Model& model, MeshView mesh, int material, const std::string& name) {
    if (mesh.positions.empty() || mesh.faces.empty()) return -1;
    const std::size_t nv = mesh.positions.size();
    std::vector<unsigned char>& data = buffer_data(model);
    const std::size_t base = data.size();
    data.reserve(base + mesh_data_bytes(mesh));
    Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
    Eigen::Vector3f hi = -lo;
    for (const Vec3& p : mesh.positions) {
        const Eigen::Vector3f q = to_y_up(p).cast<float>();
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
        for (int k = 0; k < 3; ++k) append_raw(data, q[k]);
    }
    for (const Vec3& n : smooth_normals_y_up(mesh))
        for (int k = 0; k < 3; ++k) append_raw(data, static_cast<float>(n[k]));
    for (const Face& f : mesh.faces)
        for (int v : f) append_raw(data, static_cast<std::uint32_t>(v));

    const int pos_view = add_view(model, base, nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int nrm_view = add_view(model, base + nv * 12, nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int idx_view =
        add_view(model, base + nv * 24, mesh.faces.size() * 12, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    const int pos = add_accessor(model, pos_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
    model.accessors[pos].minValues = {lo.x(), lo.y(), lo.z()};
    model.accessors[pos].maxValues = {hi.x(), hi.y(), hi.z()};
    const int nrm = add_accessor(model, nrm_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
    const int idx = add_accessor(model, idx_view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                 mesh.faces.size() * 3);

    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = pos;
    prim.attributes["NORMAL"] = nrm;
    prim.indices = idx;
    prim.material = material;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh gmesh;
    gmesh.name = name;
    gmesh.primitives.push_back(prim);
    model.meshes.push_back(gmesh);
    return static_cast<int>(model.meshes.size()) - 1;
}

int add_floats(tinygltf::Model& model, std::span<const float> values, int type, int target) {
    const auto components = static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type)));
    std::vector<unsigned char>& data = buffer_data(model);
    const std::size_t base = data.size();
    std::vector<double> lo(components, std::numeric_limits<double>::infinity());
    std::vector<double> hi(components, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
        append_raw(data, values[i]);
        lo[i % components] = std::min(lo[i % components], static_cast<double>(values[i]));
        hi[i % components] = std::max(hi[i % components], static_cast<double>(values[i]));
    }
    const int view = add_view(model, base, values.size() * 4, target);
    const int acc = add_accessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, values.size() / components);
    model.accessors[acc].minValues = std::move(lo);
    model.accessors[acc].maxValues = std::move(hi);
    return acc;
}

tinygltf::Value json_value(const nlohmann::json& json) {
    switch (json.type()) {
    case nlohmann::json::value_t::boolean: return tinygltf::Value(json.get<bool>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
        // Value holds int: larger whole numbers go as doubles (exact below 2^53).
        if (json.get<double>() >= -2147483648.0 && json.get<double>() <= 2147483647.0)
            return tinygltf::Value(json.get<int>());
        return tinygltf::Value(json.get<double>());
    case nlohmann::json::value_t::number_float: return tinygltf::Value(json.get<double>());
    case nlohmann::json::value_t::string: return tinygltf::Value(json.get<std::string>());
    case nlohmann::json::value_t::array: {
        tinygltf::Value::Array items;
        for (const nlohmann::json& item : json) items.push_back(json_value(item));
        return tinygltf::Value(std::move(items));
    }
    case nlohmann::json::value_t::object: {
        tinygltf::Value::Object members;
        for (const auto& [key, item] : json.items()) members[key] = json_value(item);
        return tinygltf::Value(std::move(members));
    }
    default: return {};
    }
}

int add_wind_mesh(tinygltf::Model& model, MeshView mesh, std::span<const float> wind, int material,
                  const std::string& name) {
    const int index = add_mesh(model, mesh, material, name);
    if (index < 0) throw std::invalid_argument(name + ": a plant mesh needs vertices and faces");
    if (wind.empty()) return index;
    if (wind.size() != 4 * mesh.positions.size())
        throw std::invalid_argument(name + ": wind data needs 4 values per vertex");
    model.meshes[index].primitives[0].attributes["_WIND"] =
        add_floats(model, wind, TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
    return index;
}

void add_vertex_attribute(tinygltf::Model& model, int mesh, const std::string& name, int components,
                          std::span<const float> values) {
    tinygltf::Primitive& primitive = model.meshes.at(static_cast<std::size_t>(mesh)).primitives.at(0);
    const std::string& mesh_name = model.meshes[static_cast<std::size_t>(mesh)].name;
    if (primitive.attributes.count(name) != 0)
        throw std::invalid_argument(mesh_name + ": attribute " + name + " is there already");
    const int types[] = {TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4};
    if (components < 2 || components > 4)
        throw std::invalid_argument(mesh_name + ": attribute " + name + " needs 2, 3 or 4 components");
    const std::size_t vertices = model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("POSITION"))).count;
    if (values.size() != static_cast<std::size_t>(components) * vertices)
        throw std::invalid_argument(mesh_name + ": attribute " + name + " needs " + std::to_string(components) +
                                    " values per vertex");
    const int type = types[components - 2];
    primitive.attributes[name] = add_floats(model, values, type, TINYGLTF_TARGET_ARRAY_BUFFER);
}

std::string glb_bytes(const tinygltf::Model& model, const std::string& path) {
    std::ostringstream stream;
    tinygltf::TinyGLTF gltf;
    if (!gltf.WriteGltfSceneToStream(&model, stream, false, true))
        throw IoError(path + ": cannot encode glTF binary");
    return std::move(stream).str();
}

}  // namespace morphogen::gltf
