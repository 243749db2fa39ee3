#pragma once
// Whether points lie inside a plant's body, for placing foliage cards
// (leaf_cards.hpp) outside it. The winding number of the surface about a
// point, counted along the vertical ray above it: each face the ray crosses
// counts +1 where its normal points up (the ray leaves the body there) and -1
// where it points down. For a closed, outward-facing surface this is the
// winding number: 1 inside, 0 outside, 2 where folds of the surface overlap.
// Faces are bucketed by the columns their x-y bounds touch, so a query reads
// only the faces above and below its point.
#include "core/mesh/mesh.hpp"

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace morphogen {

class BodyInside {
public:
    // `mesh` must outlive this. `column` is the edge of the x-y buckets (> 0).
    BodyInside(MeshView mesh, double column);

    // The signed count of faces the upward ray from p crosses, as above.
    int winding(const Vec3& p) const;
    bool inside(const Vec3& p) const { return winding(p) > 0; }

private:
    using Column = std::pair<long long, long long>;
    struct ColumnHash {
        std::size_t operator()(const Column& c) const noexcept;
    };
    long long cell(double x) const;
    MeshView mesh_;
    double column_;
    // Exact keys: a face listed twice under one key would be counted twice.
    std::unordered_map<Column, std::vector<int>, ColumnHash> columns_;
};

}  // namespace morphogen
