#include "core/growth/seeds/seeds.hpp"

#include "core/base/errors.hpp"
#include "core/io/mesh_io.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace morphogen {

namespace {

MeshArrays icosahedron() {
    const double p = std::numbers::phi;
    MeshArrays m;
    m.positions = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                   {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
    m.faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
               {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    return m;
}

MeshArrays octahedron() {
    MeshArrays m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

MeshArrays tetrahedron() {
    MeshArrays m;
    m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    m.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    return m;
}

double signed_volume(const TriMesh& mesh) {
    double six_volume = 0.0;
    for (const Face& f : mesh.faces())
        six_volume += mesh.position(f[0]).dot(mesh.position(f[1]).cross(mesh.position(f[2])));
    return six_volume / 6.0;
}

}  // namespace

const std::vector<std::string>& builtin_seed_names() {
    static const std::vector<std::string> names{"icosahedron", "octahedron", "tetrahedron"};
    return names;
}

bool is_builtin_seed(const std::string& name) {
    const auto& names = builtin_seed_names();
    return std::find(names.begin(), names.end(), name) != names.end();
}

TriMesh builtin_seed_mesh(const std::string& name, double radius) {
    MeshArrays arrays = name == "icosahedron" ? icosahedron()
                        : name == "octahedron" ? octahedron()
                        : name == "tetrahedron" ? tetrahedron()
                                                : throw MeshError("unknown built-in seed \"" + name + "\"");
    double lowest = 0.0;
    for (Vec3& p : arrays.positions) p *= radius / p.norm();
    for (const Vec3& p : arrays.positions) lowest = std::min(lowest, p.z());
    for (Vec3& p : arrays.positions) p.z() -= lowest;
    return TriMesh::from_arrays(std::move(arrays), name);
}

std::vector<Vec3> area_weighted_normals(const TriMesh& mesh, const std::string& source) {
    std::vector<Vec3> normals(mesh.num_vertices(), Vec3::Zero());
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const Vec3 cross = mesh.face_cross(f);
        for (int v : mesh.face(f)) normals[v] += cross;
    }
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        const double length = normals[v].norm();
        if (!(length > 1e-12))
            throw MeshError(source + ": the area-weighted normal of vertex " + std::to_string(v) +
                            " vanishes, so it has no growth direction");
        normals[v] /= length;
    }
    return normals;
}

Seed make_seed(const std::string& seed_mesh, double radius) {
    Seed seed;
    if (is_builtin_seed(seed_mesh)) {
        seed.mesh = builtin_seed_mesh(seed_mesh, radius);
    } else {
        MeshArrays arrays;
        try {
            arrays = read_mesh(seed_mesh);
        } catch (const IoError& e) {
            // Name the config key as well as the file: the same words in validate, evolve and grow.
            throw IoError(std::string("growth.seed_mesh: ") + e.what());
        }
        seed.mesh = TriMesh::from_arrays(std::move(arrays), "seed mesh " + seed_mesh);
        const double volume = signed_volume(seed.mesh);
        if (!(volume > 0.0))
            throw MeshError("seed mesh " + seed_mesh + ": faces are oriented inward (signed volume " +
                            std::to_string(volume) + " is not positive); reverse the face order");
    }
    seed.directions = area_weighted_normals(seed.mesh, "seed mesh " + seed_mesh);
    return seed;
}

Seed make_seed(const GrowthParams& growth) { return make_seed(growth.seed_mesh, growth.seed_radius); }

}  // namespace morphogen
