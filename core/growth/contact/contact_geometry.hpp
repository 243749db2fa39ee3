#pragma once
// The nearness the contact rule of docs/algorithm.md §5.7.1 measures between
// a point and a triangle, in plain floating point (the rule is a cheap
// margin, not an exact predicate).
#include "core/mesh/mesh.hpp"

namespace morphogen {

// The squared distance from p to the closed triangle (a, b, c), degenerate
// triangles included (Ericson, Real-Time Collision Detection, §5.1.5), and
// the corners the nearest point lies between: bit k for corner k (a single
// corner, the two ends of a side, or all three inside the face).
struct TriangleDistance {
    double squared;
    unsigned corners;
};
TriangleDistance distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace morphogen
