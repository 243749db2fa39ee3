#pragma once
// Horizontal sections of a mesh and the two numbers that say "tree"
// (docs/fitness-measures.md "Tree measures"; the same definitions, bit for bit in
// what they decide, as scripts/tree_shape.py, which checks any mesh file):
//
// - sections at N evenly spaced heights h_i = zmin + (i + 1/2) H / N,
//   H = zmax - zmin over the vertices used by a face; a vertex is above the
//   plane when z >= h, an edge is crossed when its ends are on both sides;
//   the section point on edge (a below, b above) is a + t (b - a),
//   t = (h - za) / (zb - za); its width is the xy diameter of its points;
//   its loops are the connected components of the crossed edges joined by
//   the triangles that cross;
// - trunk_ratio = largest width over the sections of the lowest quarter
//   (2 (2i + 1) <= N, decided on the index) / largest width over the upper
//   half (2i + 1 >= N): a tree has <= 0.25;
// - upper_loops = the most loops of any section in the upper half: a tree
//   has >= 3 (branches).
// Vertices with equal coordinates are merged first, and triangles left with
// a repeated vertex dropped, so files that split vertices still connect.
#include "core/mesh/mesh.hpp"

namespace morphogen {

struct TreeSections {
    double trunk_ratio = 0.0;  // NaN when undefined (no height, N < 2, or a zero upper width)
    int upper_loops = 0;
    double zmin = 0.0;  // the lowest z of a vertex used by a face, where the sections start
};

// Throws std::invalid_argument for a malformed mesh, no faces, or sections < 1.
TreeSections tree_sections(MeshView mesh, int sections = 64);

}  // namespace morphogen
