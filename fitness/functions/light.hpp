#pragma once
// Light captured from the sky. For each sun, parallel rays travel along
// -to_sun through a square lattice of spacing `spacing` on the plane
// perpendicular to them (ray k, l passes through (k+0.5)*spacing,
// (l+0.5)*spacing in that plane's basis), covering the mesh's projected
// bounding box. A ray scores its cross-section spacing^2 if its first hit on
// the mesh (CGAL AABB tree) has z >= min_height: the mesh shades itself. The
// score is the mean over suns, an area comparable with the canopy's: a flat
// horizontal square under a vertical sun captures its own area.
//
// With stand_spacing D > 0 the plant stands in a stand of copies of itself:
// eight more, at (i·D, j·D) for i, j in {-1, 0, 1} but not both 0, the 3×3
// block of a square lattice. The rays still cover the plant's own box and
// start before the whole block; a ray whose first hit is on a copy captures
// nothing (the neighbour shades the plant). Height pays only under such
// competition (Givnish 1982, the height-growth game); alone, a plant lit
// from the sides does as well low and broad.
#include "core/mesh/mesh.hpp"

#include <vector>

namespace morphogen {

struct LightParams {
    // Sun directions: every elevation (degrees above the horizon, (0, 90])
    // with every azimuth (degrees from +x towards +y); elevation 90 counts once.
    std::vector<double> elevations_deg{90.0, 45.0};
    std::vector<double> azimuths_deg{0.0, 90.0, 180.0, 270.0};
    double spacing = 0.1;     // distance between neighbouring rays, > 0
    double min_height = 0.0;  // hits below this z capture nothing
    double stand_spacing = 0.0;  // > 0: among 8 copies at this lattice spacing; 0: alone
};

// The most rays one sun casts in one evaluation. A config whose plants could
// need more is refused before a run (run/limits/resource_estimate.hpp), unless
// limits are lifted.
inline constexpr double light_max_rays_per_sun = double(1 << 26);

// Unit vectors pointing towards each sun, in the order elevation-major.
std::vector<Vec3> sun_directions(const LightParams& params);

// Light from one sun, the plant alone; throws std::length_error beyond
// light_max_rays_per_sun rays.
double light_from(MeshView mesh, const Vec3& to_sun, double spacing, double min_height);

// The plant and, with stand_spacing > 0, its eight neighbours (the plant's
// faces first, so a face index below mesh.faces.size() is the plant's own).
MeshArrays stand_of(MeshView mesh, double stand_spacing);

// Mean of light_from over sun_directions(params). Thread-safe.
double light_captured(MeshView mesh, const LightParams& params);

// The same light, face by face: per face of `mesh`, the cross-section of the
// rays whose first hit lies on it, mean over the suns (so the entries add up
// to light_captured, up to rounding). Thread-safe.
std::vector<double> light_per_face(MeshView mesh, const LightParams& params);

}  // namespace morphogen
