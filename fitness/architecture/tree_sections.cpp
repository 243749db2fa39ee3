#include "fitness/architecture/tree_sections.hpp"

#include "fitness/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace morphogen {

namespace {
// The mesh with equal positions merged and degenerate triangles dropped.
struct Welded {
    std::vector<Vec3> positions;
    std::vector<Face> faces;
};

Welded weld(MeshView mesh) {
    Welded out;
    std::map<std::tuple<double, double, double>, int> index;
    std::vector<int> remap(mesh.positions.size(), -1);
    for (const Face& f : mesh.faces) {
        Face g;
        for (int k = 0; k < 3; ++k) {
            const int v = f[k];
            if (remap[v] < 0) {
                const Vec3& p = mesh.positions[v];
                const auto [it, fresh] = index.emplace(std::make_tuple(p.x(), p.y(), p.z()),
                                                       static_cast<int>(out.positions.size()));
                if (fresh) out.positions.push_back(p);
                remap[v] = it->second;
            }
            g[k] = remap[v];
        }
        if (g[0] != g[1] && g[1] != g[2] && g[0] != g[2]) out.faces.push_back(g);
    }
    return out;
}

int find(std::vector<int>& parent, int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
}

struct Section {
    double width = 0.0;
    int loops = 0;
};

Section section_at(const Welded& mesh, double h) {
    // Crossed edges, numbered as met; a triangle that crosses joins its two.
    std::map<std::pair<int, int>, int> edge_id;
    std::vector<Vec3> points;
    std::vector<int> parent;
    auto crossed = [&](int a, int b) -> int {
        const auto key = std::minmax(a, b);
        const auto [it, fresh] = edge_id.emplace(key, static_cast<int>(points.size()));
        if (fresh) {
            const Vec3& below = mesh.positions[mesh.positions[a].z() < h ? a : b];
            const Vec3& above = mesh.positions[mesh.positions[a].z() < h ? b : a];
            const double t = (h - below.z()) / (above.z() - below.z());
            points.push_back(below + t * (above - below));
            parent.push_back(static_cast<int>(parent.size()));
        }
        return it->second;
    };
    for (const Face& f : mesh.faces) {
        int ends[2], found = 0;
        for (int k = 0; k < 3; ++k) {
            const int a = f[k], b = f[(k + 1) % 3];
            if ((mesh.positions[a].z() >= h) != (mesh.positions[b].z() >= h)) ends[found++] = crossed(a, b);
        }
        if (found == 2) parent[find(parent, ends[0])] = find(parent, ends[1]);
    }
    Section s;
    for (int i = 0; i < static_cast<int>(parent.size()); ++i) s.loops += find(parent, i) == i ? 1 : 0;
    s.width = points.empty() ? 0.0 : xy_width(points);
    return s;
}
}  // namespace

TreeSections tree_sections(MeshView mesh, int sections) {
    check_mesh_view(mesh);
    if (sections < 1) throw std::invalid_argument("tree sections: at least one section");
    const Welded welded = weld(mesh);
    if (welded.faces.empty()) throw std::invalid_argument("tree sections: the mesh has no faces");
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (const Face& f : welded.faces)
        for (int k = 0; k < 3; ++k) {
            zmin = std::min(zmin, welded.positions[f[k]].z());
            zmax = std::max(zmax, welded.positions[f[k]].z());
        }
    const double height = zmax - zmin;
    double low_width = 0.0, high_width = 0.0;
    bool any_low = false;
    TreeSections out;
    for (int i = 0; i < sections && height > 0.0; ++i) {
        const int odd = 2 * i + 1;  // h = zmin + odd H / (2 N)
        const bool low = 2 * odd <= sections, high = odd >= sections;
        if (!low && !high) continue;
        const Section s = section_at(welded, zmin + odd * height / (2.0 * sections));
        if (low) {
            any_low = true;
            low_width = std::max(low_width, s.width);
        }
        if (high) {
            high_width = std::max(high_width, s.width);
            out.upper_loops = std::max(out.upper_loops, s.loops);
        }
    }
    out.zmin = zmin;
    out.trunk_ratio = any_low && high_width > 0.0 ? low_width / high_width : std::nan("");
    return out;
}

}  // namespace morphogen
