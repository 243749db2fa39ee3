#include "core/mesh/mesh.hpp"

#include "core/base/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

namespace morphogen {

namespace {

std::uint64_t edge_key(int from, int to) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) | static_cast<std::uint32_t>(to);
}

std::string join_defects(const std::vector<std::string>& defects, std::size_t limit = 5) {
    std::string text;
    for (std::size_t i = 0; i < defects.size() && i < limit; ++i) text += (i ? "; " : "") + defects[i];
    if (defects.size() > limit) text += "; ... (" + std::to_string(defects.size() - limit) + " more)";
    return text;
}

}  // namespace

TriMesh TriMesh::from_arrays(MeshArrays arrays, const std::string& source) {
    TriMesh mesh;
    mesh.positions_ = std::move(arrays.positions);
    mesh.faces_ = std::move(arrays.faces);
    std::vector<std::string> defects = mesh.build_topology();
    if (defects.empty()) defects = mesh.check();
    if (!defects.empty()) throw MeshError(source + ": " + join_defects(defects));
    return mesh;
}

std::vector<std::string> TriMesh::build_topology() {
    std::vector<std::string> defects;
    const int V = num_vertices();
    const int F = num_faces();
    opposite_.assign(3 * static_cast<std::size_t>(F), -1);
    valence_.assign(V, 0);
    outgoing_.assign(V, -1);
    if (F == 0) {
        defects.push_back("the mesh has no faces");
        return defects;
    }
    for (int f = 0; f < F; ++f) {
        const Face& t = faces_[f];
        for (int k = 0; k < 3; ++k) {
            if (t[k] < 0 || t[k] >= V) {
                defects.push_back("face " + std::to_string(f) + " has vertex index " + std::to_string(t[k]) +
                                  " out of range [0, " + std::to_string(V) + ")");
                return defects;
            }
        }
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
            defects.push_back("face " + std::to_string(f) + " is degenerate (repeats a vertex)");
            return defects;
        }
    }
    std::unordered_map<std::uint64_t, int> half_edges;
    half_edges.reserve(3 * static_cast<std::size_t>(F));
    for (int f = 0; f < F; ++f) {
        for (int k = 0; k < 3; ++k) {
            const int h = 3 * f + k;
            const int a = faces_[f][k], b = faces_[f][(k + 1) % 3];
            if (!half_edges.emplace(edge_key(a, b), h).second) {
                defects.push_back("edge " + std::to_string(a) + "-" + std::to_string(b) +
                                  " is used twice in the same direction (non-manifold or inconsistently oriented)");
            }
            ++valence_[a];
            outgoing_[a] = h;
        }
    }
    for (const auto& [key, h] : half_edges) {
        const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
        auto it = half_edges.find(edge_key(b, a));
        if (it == half_edges.end()) {
            defects.push_back("edge " + std::to_string(a) + "-" + std::to_string(b) +
                              " has only one face (the mesh is open)");
        } else {
            opposite_[h] = it->second;
        }
    }
    for (int v = 0; v < V; ++v)
        if (valence_[v] == 0) defects.push_back("vertex " + std::to_string(v) + " is in no face");
    std::sort(defects.begin(), defects.end());
    return defects;
}

Vec3 TriMesh::face_centroid(int f) const {
    const Face& t = faces_[f];
    return (positions_[t[0]] + positions_[t[1]] + positions_[t[2]]) / 3.0;
}

bool TriMesh::adjacent(int a, int b) const {
    const int start = outgoing_[a];
    int h = start;
    do {
        if (to_vertex(h) == b) return true;
        h = opposite_[prev(h)];
    } while (h != start);
    return false;
}

int TriMesh::split_face(int f, const Vec3& point) {
    const int v = num_vertices();
    const Face old = faces_[f];
    const int a = old[0], b = old[1], c = old[2];
    const int f1 = num_faces(), f2 = f1 + 1;
    const int o1 = opposite_[3 * f + 1], o2 = opposite_[3 * f + 2];

    positions_.push_back(point);
    faces_[f] = {a, b, v};
    faces_.push_back({b, c, v});
    faces_.push_back({c, a, v});
    opposite_.resize(opposite_.size() + 6);
    // Outer edges keep their partners: a->b stays at 3f, b->c moves to 3f1, c->a to 3f2.
    link(3 * f1, o1);
    link(3 * f2, o2);
    // Inner spokes.
    link(3 * f + 1, 3 * f1 + 2);   // b->v | v->b
    link(3 * f1 + 1, 3 * f2 + 2);  // c->v | v->c
    link(3 * f2 + 1, 3 * f + 2);   // a->v | v->a

    ++valence_[a];
    ++valence_[b];
    ++valence_[c];
    valence_.push_back(3);
    outgoing_[a] = 3 * f;
    outgoing_[b] = 3 * f + 1;
    outgoing_[c] = 3 * f1 + 1;
    outgoing_.push_back(3 * f + 2);
    return v;
}

bool TriMesh::can_flip(int f, int e) const {
    const int hg = opposite_[3 * f + e];
    const int A = faces_[f][(e + 2) % 3];
    const int C = faces_[hg / 3][(hg % 3 + 2) % 3];
    return !(A == C || adjacent(A, C));
}

void TriMesh::flip(int f, int e) {
    const int hg = opposite_[3 * f + e];
    const int g = hg / 3;
    const int B = faces_[f][e], D = faces_[f][(e + 1) % 3], A = faces_[f][(e + 2) % 3];
    const int C = faces_[g][(hg % 3 + 2) % 3];

    // Partners of the four outer edges before the faces are rewritten.
    const int o_ab = opposite_[3 * f + (e + 2) % 3];    // A->B in f
    const int o_da = opposite_[3 * f + (e + 1) % 3];    // D->A in f
    const int o_bc = opposite_[3 * g + (hg % 3 + 1) % 3];  // B->C in g
    const int o_cd = opposite_[3 * g + (hg % 3 + 2) % 3];  // C->D in g

    faces_[f] = {A, B, C};
    faces_[g] = {C, D, A};
    link(3 * f + 0, o_ab);      // A->B
    link(3 * f + 1, o_bc);      // B->C
    link(3 * g + 0, o_cd);      // C->D
    link(3 * g + 1, o_da);      // D->A
    link(3 * f + 2, 3 * g + 2); // C->A | A->C

    --valence_[B];
    --valence_[D];
    ++valence_[A];
    ++valence_[C];
    outgoing_[A] = 3 * f + 0;
    outgoing_[B] = 3 * f + 1;
    outgoing_[C] = 3 * g + 0;
    outgoing_[D] = 3 * g + 1;
}

std::vector<std::string> TriMesh::check() const {
    TriMesh fresh;
    fresh.positions_ = positions_;
    fresh.faces_ = faces_;
    std::vector<std::string> defects = fresh.build_topology();
    if (!defects.empty()) return defects;
    const int V = num_vertices();
    const int F = num_faces();

    for (int v = 0; v < V; ++v) {
        const Vec3& p = positions_[v];
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
            defects.push_back("vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
    // Vertex-manifold: the fan around each vertex covers all its faces.
    for (int v = 0; v < V; ++v) {
        int count = 0;
        const int start = fresh.outgoing_[v];
        int h = start;
        do {
            ++count;
            h = fresh.opposite_[prev(h)];
        } while (h != start && count <= fresh.valence_[v]);
        if (count != fresh.valence_[v])
            defects.push_back("vertex " + std::to_string(v) + " is non-manifold (its faces form more than one fan)");
    }
    // No two faces on the same vertex set.
    std::unordered_set<std::uint64_t> seen;
    seen.reserve(F);
    for (int f = 0; f < F; ++f) {
        Face s = faces_[f];
        std::sort(s.begin(), s.end());
        const std::uint64_t key = (static_cast<std::uint64_t>(s[0]) * 0x9e3779b97f4a7c15ULL) ^
                                  (static_cast<std::uint64_t>(s[1]) << 21) ^ static_cast<std::uint64_t>(s[2]);
        if (!seen.insert(key).second) {
            for (int g = 0; g < f; ++g) {
                Face t = faces_[g];
                std::sort(t.begin(), t.end());
                if (t == s) {
                    defects.push_back("faces " + std::to_string(g) + " and " + std::to_string(f) +
                                      " use the same three vertices");
                    break;
                }
            }
        }
    }
    // Connected, and genus 0 by Euler's formula.
    std::vector<int> component(V, -1);
    std::vector<int> stack{0};
    component[0] = 0;
    int reached = 1;
    while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        fresh.for_each_neighbour(v, [&](int u) {
            if (component[u] < 0) {
                component[u] = 0;
                ++reached;
                stack.push_back(u);
            }
        });
    }
    if (reached != V)
        defects.push_back("the mesh is not connected (" + std::to_string(V - reached) +
                          " vertices are not reachable from vertex 0)");
    const int euler = V - num_edges() + F;
    if (euler != 2)
        defects.push_back("V - E + F = " + std::to_string(euler) + ", not 2 (not a sphere: genus " +
                          std::to_string((2 - euler) / 2) + ")");
    // The cached tables must agree with the faces.
    if (!opposite_.empty() || !valence_.empty()) {
        if (opposite_ != fresh.opposite_) defects.push_back("cached opposite half-edges disagree with the faces");
        if (valence_ != fresh.valence_) defects.push_back("cached valences disagree with the faces");
        for (int v = 0; v < V && v < static_cast<int>(outgoing_.size()); ++v) {
            if (outgoing_[v] < 0 || outgoing_[v] >= 3 * F || from_vertex(outgoing_[v]) != v) {
                defects.push_back("cached outgoing half-edge of vertex " + std::to_string(v) + " is wrong");
                break;
            }
        }
    }
    return defects;
}

void TriMesh::validate(const std::string& source) const {
    const std::vector<std::string> defects = check();
    if (!defects.empty()) throw MeshError(source + ": " + join_defects(defects));
}

}  // namespace morphogen
