#pragma once
// The volume of the convex hull of points (CGAL's convex_hull_3 with exact
// predicates, in cgal_convex_hull.cpp). Thread-safe and reproducible: the
// volume is summed exactly, so it does not depend on CGAL's face order.
#include "core/mesh/mesh.hpp"

#include <span>

namespace morphogen {

// 0 for fewer than 4 points or points on one plane.
double convex_hull_volume(std::span<const Vec3> points);

}  // namespace morphogen
