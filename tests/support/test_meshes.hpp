#pragma once
// Small meshes and helpers shared by the tests (the mesh room only).
#include "core/mesh/mesh.hpp"

#include <string>
#include <utility>

namespace morphogen::testing {

// A square pyramid (apex 4) whose base Q0 Q1 Q2 Q3 is split by the diagonal
// Q0-Q2 into faces 4 = (Q0,Q2,Q1) and 5 = (Q0,Q3,Q2). Flipping Q0-Q2 to Q1-Q3
// is the canonical flip of the tests.
inline MeshArrays pyramid(Vec3 q0, Vec3 q1, Vec3 q2, Vec3 q3, Vec3 apex = {0, 0, 1}) {
    MeshArrays m;
    m.positions = {q0, q1, q2, q3, apex};
    m.faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 2, 1}, {0, 3, 2}};
    return m;
}

// The (face, local edge) whose half-edge runs from -> to, or {-1, -1}.
inline std::pair<int, int> find_half_edge(const TriMesh& mesh, int from, int to) {
    for (int f = 0; f < mesh.num_faces(); ++f)
        for (int e = 0; e < 3; ++e)
            if (mesh.face(f)[e] == from && mesh.face(f)[(e + 1) % 3] == to) return {f, e};
    return {-1, -1};
}

}  // namespace morphogen::testing
