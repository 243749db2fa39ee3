#pragma once
// Where a game engine expects a plant: its origin at the centre of its foot,
// the lowest point at height 0, and one unit a metre (docs/file-formats.md,
// "Engine-ready GLB"). Axes stay ours (Z-up); the GLB writer turns them Y-up.
#include "core/mesh/mesh.hpp"

#include <optional>

namespace morphogen {

// The foot: the vertices within this fraction of the plant's height above
// its lowest point. Its centre is the middle of their x-y bounding box.
inline constexpr double kFootBand = 0.02;

struct PlacedPlant {
    MeshArrays mesh;              // same vertices and faces, moved and scaled
    double metres_per_unit = 1.0; // the scale applied: 1 unless a height was asked for
    double height_m = 0.0;        // the placed plant's height (top minus lowest point)
};

// Moves `mesh` so that the centre of its foot is the origin and its lowest
// point has z = 0; with `height_m`, also scales it uniformly to that height.
// Throws MeshError for a mesh without vertices, or when asked to scale a
// plant of height 0.
PlacedPlant place_plant(MeshView mesh, std::optional<double> height_m);

}  // namespace morphogen
