#pragma once
// The level-set skeleton of a plant mesh (a Reeb graph of geodesic distance
// from the base, cut into bands; cf. Verroust & Lazarus 2000, Xu et al. 2007;
// docs/fitness-measures.md "Architecture measures"):
//
// - vertices with equal coordinates are merged, triangles left with a
//   repeated vertex dropped (files that split vertices still connect);
// - the base = the vertices with z <= zmin + base_height; d(v) = the distance
//   from the base by Dijkstra's algorithm over the edges whose updates also
//   cross each triangle in a straight line (from a point of a settled edge,
//   d linear along it, to the opposite corner), so a front does not zigzag
//   along the edges of coarse or stretched triangles; d is linear over each
//   triangle; vertices the base does not reach are left out;
// - band k = {d in [k w, (k+1) w)}; each triangle is clipped to every band it
//   crosses; two clipped pieces of one band are one node when their
//   triangles share an edge or a vertex whose d lies in the band (closed),
//   so a node is exactly a connected piece of the surface within the band;
//   all of band 0 is one node, the root;
// - pieces of bands k and k+1 touch when a triangle crosses from one to the
//   other or a vertex on the boundary lies on both. Band by band, a clipped
//   piece of band k > 0 that touches nodes of band k-1 takes the one it
//   touches most as its lineage, and the other pieces of its band the
//   lineage nearest to them (in steps through the band); a node is a
//   connected piece of one lineage (the pieces of one lineage that meet
//   another lineage count as one: the two sides of a cut loop), and its
//   parent is its lineage. So where two branches touch (a loop: crowns that
//   overlap), the band is split between them rather than made the crown of
//   one, and the skeleton is a tree rooted at the base. On a surface without
//   loops every connected piece of a band has one lineage: the pieces are
//   the nodes.
//
// A node's diameter is its perimeter / pi, the perimeter being the mean
// length of the level curves through the piece (by the coarea formula,
// sum(area |grad d|) / the span of d it covers): exact for a round tube at
// any tilt, and blind to how the mesh samples the band.
//
// Thread-safe; O((V + F) log V) plus the clipped pieces (about 1-3 per
// triangle at the default band width).
#include "core/mesh/mesh.hpp"

#include <vector>

namespace morphogen {

struct SkeletonParams {
    // Band width; 0 = band_edges x the median edge length (the mesh cannot show
    // features finer than its edges; two edges per band keep every band piece
    // several triangles wide and a round branch a few bands long).
    double band_width = 0.0;
    double band_edges = 2.0;
    // Base height above the lowest vertex; negative = half the band width, so
    // a flat or nearly flat bottom is one base rather than a ring spreading
    // from whichever vertex happens to be lowest.
    double base_height = -1.0;
    // The band width is at least (largest distance) / max_bands, bounding the work.
    int max_bands = 1000;
};

struct SkeletonNode {
    int band = 0;
    Vec3 centroid = Vec3::Zero();  // area-weighted centroid of the piece
    double area = 0.0;
    double diameter = 0.0;  // perimeter / pi (see above); 0 for a piece of no area
    double distance = 0.0;  // the largest d on the piece
    int parent = -1;        // -1 for the root
    std::vector<int> children;
};

struct Skeleton {
    std::vector<SkeletonNode> nodes;  // the root first, then by band
    double band_width = 0.0;
    double base_height = 0.0;
    double zmin = 0.0, zmax = 0.0;  // over the vertices of proper triangles (all vertices if none)
};

// Throws std::invalid_argument for a malformed mesh (check_mesh_view) or no
// vertices, and for a non-positive band_edges or max_bands. A mesh without a
// triangle of three distinct vertices, or of no extent, is one root node at
// its lowest vertex.
Skeleton level_set_skeleton(MeshView mesh, const SkeletonParams& params = {});

}  // namespace morphogen
