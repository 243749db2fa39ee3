// GLB (glTF 2.0 binary) writer, Y-up, with smooth vertex normals.
#include "mesh_io_detail.hpp"

#include "errors.hpp"

#include <Eigen/Geometry>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

namespace morphogen::mesh_io_detail {

namespace {

// glTF is Y-up, right-handed; our meshes are Z-up: (x, y, z) -> (x, z, -y)
// is a proper rotation, so orientation (and outward normals) are kept.
Vec3 to_y_up(const Vec3& p) { return {p.x(), p.z(), -p.y()}; }

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

tinygltf::Model gltf_model(MeshView mesh) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "morphogen";

    tinygltf::Material material;
    material.name = "plant";
    material.doubleSided = true;  // grown meshes are viewed from inside too (open canopies)
    material.pbrMetallicRoughness.baseColorFactor = {0.33, 0.62, 0.24, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.8;
    model.materials.push_back(material);

    tinygltf::Node node;
    node.name = "morphogen";
    // glTF requires count >= 1 in accessors and byteLength >= 1 in buffers:
    // an empty mesh becomes a scene with one empty node.
    if (!mesh.positions.empty() && !mesh.faces.empty()) {
        const std::size_t nv = mesh.positions.size();
        std::vector<unsigned char> data;
        data.reserve(nv * 24 + mesh.faces.size() * 12);
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

        const int pos_view = add_view(model, 0, nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
        const int nrm_view = add_view(model, nv * 12, nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
        const int idx_view = add_view(model, nv * 24, mesh.faces.size() * 12,
                                      TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        const int pos = add_accessor(model, pos_view, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                     TINYGLTF_TYPE_VEC3, nv);
        model.accessors[pos].minValues = {lo.x(), lo.y(), lo.z()};
        model.accessors[pos].maxValues = {hi.x(), hi.y(), hi.z()};
        const int nrm = add_accessor(model, nrm_view, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                     TINYGLTF_TYPE_VEC3, nv);
        const int idx = add_accessor(model, idx_view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                     TINYGLTF_TYPE_SCALAR, mesh.faces.size() * 3);
        tinygltf::Buffer buffer;
        buffer.data = std::move(data);
        model.buffers.push_back(std::move(buffer));

        tinygltf::Primitive prim;
        prim.attributes["POSITION"] = pos;
        prim.attributes["NORMAL"] = nrm;
        prim.indices = idx;
        prim.material = 0;
        prim.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh gmesh;
        gmesh.name = "morphogen";
        gmesh.primitives.push_back(prim);
        model.meshes.push_back(gmesh);
        node.mesh = 0;
    }
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    return model;
}

}  // namespace

std::string glb_bytes(MeshView mesh, const std::string& path) {
    const tinygltf::Model model = gltf_model(mesh);
    std::ostringstream stream;
    tinygltf::TinyGLTF gltf;
    if (!gltf.WriteGltfSceneToStream(&model, stream, false, true))
        fail(path, "cannot encode glTF binary");
    return std::move(stream).str();
}

}  // namespace morphogen::mesh_io_detail
