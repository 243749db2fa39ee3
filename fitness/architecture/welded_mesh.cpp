#include "fitness/architecture/welded_mesh.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

namespace morphogen {

MeshArrays welded_mesh(MeshView mesh) {
    const auto lexicographic = [&](int a, int b) {
        const Vec3& p = mesh.positions[a];
        const Vec3& q = mesh.positions[b];
        return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
    };
    std::vector<int> order(mesh.positions.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), lexicographic);
    std::vector<int> merged(mesh.positions.size());  // vertex -> its class, numbered in sorted order
    int classes = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (i > 0 && lexicographic(order[i - 1], order[i])) ++classes;
        merged[order[i]] = classes;
    }

    MeshArrays out;
    std::vector<int> kept(order.empty() ? 0 : static_cast<std::size_t>(classes) + 1, -1);
    std::vector<int> first_of(kept.size(), -1);  // a vertex of each class
    for (int v : order) first_of[merged[v]] = first_of[merged[v]] < 0 ? v : first_of[merged[v]];
    for (const Face& f : mesh.faces) {
        const Face g{merged[f[0]], merged[f[1]], merged[f[2]]};
        if (g[0] == g[1] || g[1] == g[2] || g[0] == g[2]) continue;
        out.faces.push_back(g);
        for (int c : g) kept[c] = 0;
    }
    for (std::size_t c = 0; c < kept.size(); ++c) {
        if (kept[c] < 0) continue;
        kept[c] = static_cast<int>(out.positions.size());
        out.positions.push_back(mesh.positions[first_of[c]]);
    }
    for (Face& f : out.faces)
        for (int& v : f) v = kept[v];
    return out;
}

}  // namespace morphogen
