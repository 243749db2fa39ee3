#pragma once
// Measures of a plant's architecture from its level-set skeleton
// (fitness/architecture/skeleton.hpp; docs/fitness-measures.md "Architecture measures"): they tell
// a branching tree from a stalk under one crown.
//
// - A branch is the skeleton path from a fork (a node with 2+ children) to
//   the next fork or an end node. Its length = how much farther from the
//   base (the skeleton's distance d) its last node reaches than its fork:
//   the length along the surface, whichever way the branch leaves. Its
//   thickness = the smallest diameter among its nodes within the first half
//   of its length (at least its first node; the end fork left out when
//   there are others): the girth of its stem, so that neither a crown
//   carried at its end nor a lump on it counts. Its tube length = the area
//   of its nodes / (pi x thickness). The rules below use its reach = the
//   smaller of its length and twice its tube length: a sliver that the
//   distance leaves as a local maximum (a few triangles at the rim of a
//   ring) has almost no area, while a limb's tube length is most of its
//   length (less its tapering end).
// - Pruning: a branch to an end node whose reach is below tip_slenderness x
//   its thickness, or below half a band width (one median edge: finer than
//   the mesh shows), is noise (a bump, a lobe), not a tip: it is removed, and
//   removal repeats until every end branch stands (a fork left with one
//   child is a fork no more).
// - tips: the end nodes other than the root; limbs: the branches with
//   reach >= limb_slenderness x thickness; first_fork_height: the lowest
//   fork's centroid z - zmin, or the plant's height (zmax - zmin) when the
//   skeleton never forks; strahler: a leaf is 1, a node the max of its
//   children's, +1 when two or more share that max; solidity: |volume| /
//   convex-hull volume, NaN for an open mesh (an edge used more often in
//   one direction than in the other, after the welding of skeleton.hpp) or
//   a hull of no volume.
#include "fitness/architecture/skeleton.hpp"
#include "core/mesh/mesh.hpp"

#include <vector>

namespace morphogen {

struct ArchitectureParams {
    SkeletonParams skeleton = {};   // band width and base rules
    double limb_slenderness = 3.0;  // a limb is at least this many thicknesses long
    double tip_slenderness = 1.0;   // an end branch shorter than this many thicknesses is pruned
    bool with_solidity = true;      // false leaves solidity NaN and skips the convex hull
};

struct Limb {
    double length = 0, thickness = 0;
    double tube_length = 0;  // area / (pi thickness)
    Vec3 base = Vec3::Zero(), tip = Vec3::Zero();  // centroids of its first (fork) and last node
};

struct Architecture {
    std::vector<Vec3> tip_points;  // position of each tip (the centroid of its skeleton end node)
    int tips = 0;
    std::vector<Limb> limbs;  // the branches that count as limbs, in skeleton order
    double first_fork_height = 0;
    int strahler = 0;
    double solidity = 0;  // NaN for an open mesh or a flat hull
    int forks = 0;        // nodes with 2+ children after pruning
    int nodes = 0;        // skeleton nodes after pruning
    double band_width = 0;
};

// Thread-safe; throws std::invalid_argument for a malformed mesh
// (check_mesh_view), no vertices, or a non-positive slenderness.
Architecture measure_architecture(MeshView mesh, const ArchitectureParams& params = {});

// |volume| / convex-hull volume (the definition above); NaN when open or flat.
double mesh_solidity(MeshView mesh);

}  // namespace morphogen
