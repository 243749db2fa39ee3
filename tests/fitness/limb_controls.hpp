#pragma once
// Labelled control shapes for the architecture measures (docs/fitness.md
// "Architecture measures"): plant forms whose tips, limbs and first fork a
// person reads at a glance, built as closed triangle meshes at a given
// vertex count. Each is an implicit solid (unions of capsules, spheres and
// cylinders) polygonised finely by marching tetrahedra, then simplified by
// CGAL's edge collapse (Garland-Heckbert quadrics, normals kept from
// flipping) to the count: the adaptive, uneven triangles of a decimated
// mesh, where a measure tied to the edge length is most easily fooled.
#include "core/mesh/mesh.hpp"
#include "tests/support/implicit_mesh.hpp"

#include <string>
#include <vector>

namespace morphogen::testing {

struct LimbControl {
    std::string name;
    std::string description;  // what a person sees
    int tips = 0;             // ends of protrusions at least as long as they are thick
    int limbs = 0;            // branches (fork to fork or tip) at least 3x as long as thick
    // The first fork's height over the plant's height, within +- fork_tolerance;
    // 1 when the form never forks.
    double fork_fraction = 1.0;
    double fork_tolerance = 0.0;
};

// The controls, in a fixed order: y, prongs3, candelabra3, candelabra5,
// broccoli, mushroom, column, coral, cactus, tree6 (crowns that touch).
const std::vector<LimbControl>& limb_controls();

// A control's solid: field < 0 inside, positive on the box [lo, hi].
struct LimbControlSolid {
    Field field;
    Vec3 lo, hi;
};
// Throws std::invalid_argument for an unknown name.
LimbControlSolid limb_control_solid(const std::string& name);

// The finely polygonised solid of the named control (about 20,000 vertices
// or more); throws std::invalid_argument for an unknown name.
MeshArrays limb_control_fine_mesh(const std::string& name);

// `mesh` simplified to about `vertices` vertices (fewer faces than 2 x
// vertices are left alone). Deterministic for the same input; throws
// std::invalid_argument for a mesh that is not an oriented manifold.
MeshArrays decimated(const MeshArrays& mesh, int vertices);

// The vertex counts the controls are made at.
inline const std::vector<int>& limb_control_resolutions() {
    static const std::vector<int> counts{500, 1000, 2000, 5000};
    return counts;
}

// The named control at each of limb_control_resolutions(), in that order:
// the fine mesh decimated to the largest count, each smaller one from the
// next larger (a fifth of the work of decimating each from the fine mesh).
std::vector<MeshArrays> limb_control_meshes(const std::string& name);

}  // namespace morphogen::testing
