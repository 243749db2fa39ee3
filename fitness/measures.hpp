#pragma once
// Plain geometric measures of a triangle mesh, usable as fitness terms and
// metrics. None needs the mesh to be closed except volume.
#include "core/mesh/mesh.hpp"

#include <span>

namespace morphogen {

// Throws std::invalid_argument if a face index is out of range or a
// coordinate is not finite: every function of this library assumes neither.
void check_mesh_view(MeshView mesh);

// Maximum z over all vertices; throws std::invalid_argument for no vertices.
double mesh_height(MeshView mesh);
// Area of the convex hull of the vertices' xy-projections (monotone chain).
double mesh_footprint(MeshView mesh);
// Largest distance between the xy-projections of two vertices (the diameter
// of the footprint's convex hull, by rotating calipers); 0 for one point.
double mesh_width(MeshView mesh);
// The same over any points.
double xy_width(std::span<const Vec3> positions);
// Sum of triangle areas.
double mesh_area(MeshView mesh);
// Signed volume by the divergence theorem, sum of det(a,b,c)/6: the enclosed
// volume for a closed outward-oriented mesh, meaningless for an open one.
double mesh_volume(MeshView mesh);

}  // namespace morphogen
