#pragma once
// Seed meshes (docs/algorithm.md §3). Built-in seeds have radius `radius` and are
// moved so their lowest point is at z = 0; their vertex and face order is
// fixed (docs/algorithm.md §3.2 lists it, tests pin it) because it decides the split
// and flip order. A file seed is used as it is.
#include "core/growth/growth_params.hpp"
#include "core/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace morphogen {

struct Seed {
    TriMesh mesh;
    std::vector<Vec3> directions;  // initial growth direction h_i per vertex
};

// Names of the built-in seeds: icosahedron, octahedron, tetrahedron.
const std::vector<std::string>& builtin_seed_names();
bool is_builtin_seed(const std::string& name);
TriMesh builtin_seed_mesh(const std::string& name, double radius);

// Normalised area-weighted vertex normals; throws MeshError naming `source`
// and the vertex if a sum vanishes.
std::vector<Vec3> area_weighted_normals(const TriMesh& mesh, const std::string& source);

// A built-in seed by name, or a mesh file (OBJ/PLY/OFF/STL) by path, checked to be
// a closed, outward-oriented genus-0 triangle manifold (MeshError/IoError
// naming the file and the defect otherwise).
Seed make_seed(const std::string& seed_mesh, double radius);
// The seed growth.seed_mesh names, at growth.seed_radius.
Seed make_seed(const GrowthParams& growth);

}  // namespace morphogen
