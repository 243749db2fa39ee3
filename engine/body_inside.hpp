#pragma once
// Whether points lie inside a plant's body, for placing foliage cards
// (leaf_cards.hpp) outside it. The winding number of the surface about a
// point, counted along the vertical ray above it: each face the ray crosses
// counts +1 where its normal points up (the ray leaves the body there) and -1
// where it points down. For a closed, outward-facing surface this is the
// winding number: 1 inside, 0 outside, 2 where folds of the surface overlap.
// Faces are bucketed by the columns their x-y bounds touch, so a query reads
// only the faces above and below its point: a sorted list of (column, face)
// with each face's corners beside it, searched by bisection (no hash map of
// lists to allocate, and a query reads one contiguous run).
#include "core/mesh/mesh.hpp"

#include <utility>
#include <vector>

namespace morphogen {

class BodyInside {
public:
    // `column` is the edge of the x-y buckets (> 0). The faces are copied.
    BodyInside(MeshView mesh, double column);

    // The signed count of faces the upward ray from p crosses, as above.
    int winding(const Vec3& p) const;
    bool inside(const Vec3& p) const { return winding(p) > 0; }

private:
    using Column = std::pair<long long, long long>;
    long long cell(double x) const;
    double column_;
    struct Triangle {
        Vec3 a, b, c;
        double area;  // twice the signed area of its x-y projection, not 0
    };
    // Sorted by column, then face; one entry per column a face touches, so
    // no face is counted twice for one point.
    std::vector<Column> columns_;
    std::vector<Triangle> triangles_;  // the face of each entry
};

}  // namespace morphogen
