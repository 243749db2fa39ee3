#include "core/growth/contact/contact_geometry.hpp"

#include <algorithm>

namespace morphogen {

TriangleDistance distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    // Voronoi regions of the corners, then of the edges, else the face.
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return {ap.squaredNorm(), 0b001};
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return {bp.squaredNorm(), 0b010};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double t = d1 / (d1 - d3);
        return {(ap - t * ab).squaredNorm(), 0b011};
    }
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return {cp.squaredNorm(), 0b100};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double t = d2 / (d2 - d6);
        return {(ap - t * ac).squaredNorm(), 0b101};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {(bp - t * (c - b)).squaredNorm(), 0b110};
    }
    // Inside the face's region: the distance to the plane. (Collinear corners
    // should not get here; if rounding sends them, the nearest corner.)
    const double denominator = va + vb + vc;
    if (!(denominator > 0.0)) return {std::min({ap.squaredNorm(), bp.squaredNorm(), cp.squaredNorm()}), 0b111};
    const double v = vb / denominator, w = vc / denominator;
    return {(ap - v * ab - w * ac).squaredNorm(), 0b111};
}

}  // namespace morphogen
