#pragma once
// Simple shape numbers reported by grow and gallery.
#include "core/mesh/mesh.hpp"

namespace morphogen {

struct MeshStats {
    double height = 0;  // max z (the ground is z = 0)
    double width = 0;   // the larger of the x and y extents
};

MeshStats mesh_stats(MeshView mesh);

}  // namespace morphogen
