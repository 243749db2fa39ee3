#pragma once
// Wind data for game engines: the `_WIND` vertex attribute of an engine-ready
// GLB (docs/file-formats.md, "Wind data", with the sway formula), four
// floats per vertex in [0, 1]:
//   x  bend: 0 at the foot rising to 1 at the farthest tip, as the square of
//      the distance from the foot along the surface over its largest value
//   y  flutter: when the vertex was born, birth step / steps (the seed's 0,
//      the youngest tips 1)
//   z  phase: the azimuth of the vertex around the vertical axis through the
//      foot, over 2 pi, so limbs leaning different ways sway out of step
//      (sin(2 pi z) is continuous where z wraps from 1 to 0)
//   w  stiffness: how much of the plant the vertex carries, log(1 + carried)
//      / log(1 + vertices) along the shortest paths to the foot, smoothed
//      over each vertex's neighbours: near 1 low on the trunk, near 0 at tips
#include "mesh/mesh.hpp"

#include <span>
#include <vector>

namespace morphogen {

// `placed` is the plant placed at its foot (plant_frame.hpp: Z-up, lowest
// point z = 0); birth_steps[v] is the step after which vertex v first
// existed (0 for the seed's), `steps` the steps growth did. Returns 4 floats
// per vertex. Throws std::invalid_argument when birth_steps does not have one
// entry per vertex. The same mesh and births give the same values.
std::vector<float> plant_wind(MeshView placed, std::span<const int> birth_steps, int steps);

}  // namespace morphogen
