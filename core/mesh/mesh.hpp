#pragma once
// TriMesh: a closed, consistently oriented triangle mesh stored as index
// arrays (structure of arrays), with the two topology operations growth needs
// (split a face at a point, flip an edge) kept O(1) by a half-edge "opposite"
// table. Half-edge h = 3*f + k runs from faces[f][k] to faces[f][(k+1)%3].
// Which edges flip, and when, is the growth model's (core/growth/contact/flip_pass.hpp).
//
// Invariants (checked from scratch by check()/validate()):
//   every face has three distinct vertex indices in range; every directed edge
//   occurs once and its reverse once (closed, oriented, edge-manifold); each
//   vertex's faces form one fan (vertex-manifold); connected with
//   V - E + F = 2 (genus 0); no two faces on the same vertex set; every
//   coordinate finite; the cached tables (opposite, valence, one outgoing
//   half-edge per vertex) agree with the faces.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include <array>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

using Vec3 = Eigen::Vector3d;
using Face = std::array<int, 3>;

// A read-only look at any triangle mesh (also ones that are not closed or not
// connected, e.g. a mesh file given to `morphogen score`).
struct MeshView {
    std::span<const Vec3> positions;
    std::span<const Face> faces;
};

// Plain arrays as read from a file, before any topology is checked.
struct MeshArrays {
    std::vector<Vec3> positions;
    std::vector<Face> faces;
    MeshView view() const { return {positions, faces}; }
};

class TriMesh {
public:
    TriMesh() = default;

    // Builds the topology tables. Throws MeshError naming `source` and the
    // first defects found if the faces are not a closed, oriented, genus-0
    // manifold (see check()).
    static TriMesh from_arrays(MeshArrays arrays, const std::string& source = "mesh");

    MeshView view() const { return {positions_, faces_}; }

    int num_vertices() const { return static_cast<int>(positions_.size()); }
    int num_faces() const { return static_cast<int>(faces_.size()); }
    int num_edges() const { return num_faces() * 3 / 2; }

    const std::vector<Vec3>& positions() const { return positions_; }
    // Geometry may be changed freely; topology only through split/flip.
    std::vector<Vec3>& positions() { return positions_; }
    const Vec3& position(int v) const { return positions_[v]; }
    const std::vector<Face>& faces() const { return faces_; }
    const Face& face(int f) const { return faces_[f]; }

    // Number of faces incident to v.
    int valence(int v) const { return valence_[v]; }
    // The half-edge paired with h (same edge, other face, reverse direction).
    int opposite(int h) const { return opposite_[h]; }
    static int face_of(int h) { return h / 3; }
    // The next and the previous half-edge of h's face.
    static int next(int h) { return h - h % 3 + (h % 3 + 1) % 3; }
    static int prev(int h) { return h - h % 3 + (h % 3 + 2) % 3; }
    int from_vertex(int h) const { return faces_[h / 3][h % 3]; }
    int to_vertex(int h) const { return faces_[h / 3][(h % 3 + 1) % 3]; }

    // cross(b-a, c-a): twice the area times the unit normal.
    Vec3 face_cross(int f) const {
        const Face& t = faces_[f];
        const Vec3& a = positions_[t[0]];
        return (positions_[t[1]] - a).cross(positions_[t[2]] - a);
    }
    double face_area(int f) const { return 0.5 * face_cross(f).norm(); }
    Vec3 face_centroid(int f) const;

    // Calls fn(u) for each neighbour u of v once (rotating around v).
    template <class Fn>
    void for_each_neighbour(int v, Fn&& fn) const {
        const int start = outgoing_[v];
        int h = start;
        do {
            fn(to_vertex(h));
            h = opposite_[prev(h)];
        } while (h != start);
    }
    bool adjacent(int a, int b) const;

    // Splits face f at `point` (docs/algorithm.md §5.3): adds vertex v = num_vertices();
    // f = (a,b,c) becomes (a,b,v) and (b,c,v), (c,a,v) are appended in that order.
    // Returns v.
    int split_face(int f, const Vec3& point);

    // Local edge e of face f, with B = f[e], D = f[e+1], A = f[e+2] and g the
    // face across B-D with third vertex C: whether flipping it to A-C keeps
    // the mesh a valid one (A != C, and A and C not joined yet, else two
    // faces would share their vertices). Topology only; when a flip is worth
    // doing is the growth model's (core/growth/contact/flip_pass.hpp, docs/algorithm.md §5.4).
    bool can_flip(int f, int e) const;

    // Flips local edge e of face f (named as in can_flip, which must hold):
    // f := (A,B,C), g := (C,D,A), in O(1) (docs/algorithm.md §2.2, §5.4).
    void flip(int f, int e);

    // Every invariant above, recomputed from the face list; empty = valid.
    std::vector<std::string> check() const;
    // Throws MeshError("<source>: <defects>") if check() finds anything.
    void validate(const std::string& source = "mesh") const;

private:
    void link(int h1, int h2) {
        opposite_[h1] = h2;
        opposite_[h2] = h1;
    }
    // Rebuilds opposite/valence/outgoing from faces; returns defects found.
    std::vector<std::string> build_topology();

    std::vector<Vec3> positions_;
    std::vector<Face> faces_;
    std::vector<int> opposite_;  // per half-edge
    std::vector<int> valence_;   // per vertex
    std::vector<int> outgoing_;  // per vertex: one half-edge leaving it
};

}  // namespace morphogen
