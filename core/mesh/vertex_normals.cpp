#include "core/mesh/vertex_normals.hpp"

#include <cmath>

namespace morphogen {

std::vector<Vec3> vertex_normals(MeshView mesh) {
    std::vector<Vec3> normals;
    vertex_normals(mesh, normals);
    return normals;
}

void vertex_normals(MeshView mesh, std::vector<Vec3>& normals) {
    normals.assign(mesh.positions.size(), Vec3::Zero());
    for (const Face& f : mesh.faces) {
        const Vec3 n = (mesh.positions[f[1]] - mesh.positions[f[0]])
                           .cross(mesh.positions[f[2]] - mesh.positions[f[0]]);
        for (int v : f) normals[v] += n;  // area-weighted: |n| is twice the area
    }
    for (Vec3& n : normals) {
        const double len = n.norm();
        n = len > 0 && std::isfinite(len) ? Vec3(n / len) : Vec3::Zero();
    }
}

}  // namespace morphogen
