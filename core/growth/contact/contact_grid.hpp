#pragma once
// The broad phase of the contact rule (docs/algorithm.md §5.7.1), rebuilt
// every step: a dense uniform grid over the boxes' common bounds, each box
// listed by id in every cell it overlaps, the box itself kept once per id in
// single precision (rounded outward). Cells hold bare ids (4 bytes, so the
// per-step build writes little) and the boxes, a few kB, stay in cache for
// the queries; direct cell indices make the point queries cheap; a grown mesh
// is compact, so the grid stays small. Boxes added after the build (a split's
// or a flip's faces) go into per-cell chains, and replace the id's box.
// Coordinates beyond the grid fall into its border cells, so nothing is
// missed.
#include "core/mesh/spatial_hash.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace morphogen {

class ContactGrid {
public:

    // Lists boxes[i] as id i, and nothing else, in cells of edge about
    // `cell_size` (> 0; made larger where the bounds would need too many).
    // `marks` (empty, or one per box): which boxes a marked_only query sees.
    void build(const std::vector<Box3>& boxes, double cell_size, const std::vector<char>& marks = {});
    // Lists `box` as `id` too (id may be new, one past the last, or listed).
    void insert(int id, const Box3& box);

    // Calls fn(id) for every id whose box (the latest listed for it) meets
    // `box` (closed), once per cell they share: an id may come more than once.
    // With `marked_only`, only the ids build() was told to mark. A cell's ids
    // are screened without a branch per id (most fail, and unpredictably), a
    // block at a time, then fn runs on the ones that meet.
    template <class Fn>
    void for_each_meeting(const Box3& box, Fn&& fn, bool marked_only = false) const {
        const FloatBox query = outward(box);
        const std::uint32_t need_mark = marked_only ? 1U : 0U;
        const std::array<int, 3> lo = cell_of(box.lo), hi = cell_of(box.hi);
        constexpr std::uint32_t kBlock = 64;
        int met[kBlock];
        const auto listed = [&](int id) { return boxes_[id].meets(query) & (boxes_[id].mark >= need_mark); };
        for (int i = lo[0]; i <= hi[0]; ++i)
            for (int j = lo[1]; j <= hi[1]; ++j) {
                const int row = (i * cells_[1] + j) * cells_[2];
                const std::uint32_t end = start_[row + hi[2] + 1];
                for (std::uint32_t block = start_[row + lo[2]]; block < end; block += kBlock) {
                    const std::uint32_t stop = std::min(end, block + kBlock);
                    int n = 0;
                    for (std::uint32_t e = block; e < stop; ++e) {
                        met[n] = ids_[e];
                        n += static_cast<int>(listed(ids_[e]));
                    }
                    for (int k = 0; k < n; ++k) fn(met[k]);
                }
                for (int k = lo[2]; k <= hi[2]; ++k)
                    for (int e = late_head_[row + k]; e >= 0; e = late_[e].next)
                        if (listed(late_[e].id)) fn(late_[e].id);
            }
    }

private:
    // A box in single precision, rounded outward: it holds the double box.
    struct FloatBox {
        float lo[3], hi[3];
        bool meets(const FloatBox& o) const {
            return (lo[0] <= o.hi[0]) & (o.lo[0] <= hi[0]) & (lo[1] <= o.hi[1]) & (o.lo[1] <= hi[1]) &
                   (lo[2] <= o.hi[2]) & (o.lo[2] <= hi[2]);
        }
    };
    struct ListedBox : FloatBox {
        std::uint32_t mark;  // 1: seen by marked_only queries
    };
    struct LateEntry {
        int id;
        int next;
        int cell;  // whose chain it heads or continues
    };
    // The cells a box overlaps: the lowest and the highest, per axis.
    struct CellRange {
        std::array<int, 3> lo, hi;
    };
    // The cell holding p, clamped into the grid. (A truncating cast, not
    // std::floor, which is a library call in a portable build: the value is
    // clamped at 0 first, where the two agree.)
    std::array<int, 3> cell_of(const Vec3& p) const {
        std::array<int, 3> c;
        for (int k = 0; k < 3; ++k) {
            const double t = (p[k] - origin_[k]) * inverse_cell_;
            c[k] = t <= 0.0 ? 0 : t >= static_cast<double>(cells_[k] - 1) ? cells_[k] - 1 : static_cast<int>(t);
        }
        return c;
    }
    static FloatBox outward(const Box3& box);
    template <class Fn>
    void for_each_cell(const CellRange& range, Fn&& fn) const;

    Vec3 origin_ = Vec3::Zero();
    double inverse_cell_ = 1.0;
    std::array<int, 3> cells_{1, 1, 1};
    std::vector<std::uint32_t> start_;  // per cell + 1: where its ids begin
    std::vector<int> ids_;              // by cell
    std::vector<ListedBox> boxes_;      // per id
    std::vector<int> late_head_;        // per cell: the last inserted chain entry, -1 = none
    std::vector<LateEntry> late_;
    std::vector<CellRange> range_scratch_;  // build()'s scratch: each box's cells
};

}  // namespace morphogen
