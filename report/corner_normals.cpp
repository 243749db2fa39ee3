#include "report/corner_normals.hpp"

#include <cmath>
#include <numbers>

namespace morphogen {

std::vector<std::array<Vec3, 3>> corner_normals(MeshView mesh, double crease_angle_deg) {
    const std::size_t nf = mesh.faces.size(), nv = mesh.positions.size();
    std::vector<Vec3> area(nf, Vec3::Zero()), unit(nf, Vec3::Zero());  // |area| is twice the face's area
    for (std::size_t f = 0; f < nf; ++f) {
        const Face& t = mesh.faces[f];
        const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
        const double len = n.norm();
        if (len > 0 && std::isfinite(len)) area[f] = n, unit[f] = n / len;
    }
    // The faces around each vertex, as one list cut at first[v].
    std::vector<std::size_t> first(nv + 1, 0), around(3 * nf);
    for (const Face& t : mesh.faces)
        for (int v : t) ++first[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t f = 0; f < nf; ++f)
        for (int v : mesh.faces[f]) around[fill[static_cast<std::size_t>(v)]++] = f;

    const double min_cos = std::cos(crease_angle_deg * std::numbers::pi / 180);
    std::vector<std::array<Vec3, 3>> out(nf);
    for (std::size_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) {
            const auto v = static_cast<std::size_t>(mesh.faces[f][k]);
            Vec3 sum = Vec3::Zero();
            for (std::size_t i = first[v]; i < first[v + 1]; ++i)
                if (around[i] == f || unit[f].dot(unit[around[i]]) >= min_cos) sum += area[around[i]];
            const double len = sum.norm();
            out[f][k] = len > 0 ? Vec3(sum / len) : unit[f];
        }
    return out;
}

}  // namespace morphogen
