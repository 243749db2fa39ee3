#pragma once
// A uniform grid of axis-aligned boxes, hashed (docs/algorithm.md §5.7): the
// broad phase of the collision check. Each box is listed in every cell it
// overlaps; a query visits the cells a box overlaps and reports what is
// listed there. Entries can be added at any time (a face that changes is
// simply listed again); nothing is removed until reset(), so a caller must
// check every candidate against its current box and expect repeats.
// Deterministic: entries are visited in a fixed order for a fixed history.
#include "core/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace morphogen {

struct Box3 {
    Vec3 lo, hi;
    static Box3 of(const Vec3& a, const Vec3& b, const Vec3& c) {
        return {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
    }
    Box3 merged(const Box3& o) const { return {lo.cwiseMin(o.lo), hi.cwiseMax(o.hi)}; }
    // Closed boxes: touching counts as overlapping (as for CGAL's boxes).
    bool overlaps(const Box3& o) const {
        return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y() &&
               lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
    }
};

struct Cell {
    std::int64_t x, y, z;
    bool operator==(const Cell&) const = default;
};

class SpatialHash {
public:
    // Empties the grid and sets the cell edge (> 0, finite) and the table
    // size (a power of two >= 2 * expected_entries; kept if already larger).
    void reset(double cell_size, std::size_t expected_entries);
    // Lists `id` in every cell `box` overlaps.
    void insert(int id, const Box3& box);

    Cell cell_of(const Vec3& p) const { return {coordinate(p.x()), coordinate(p.y()), coordinate(p.z())}; }

    // Calls fn(cell, id) for every entry listed in the buckets of the cells
    // `box` overlaps. A bucket may also hold entries of other cells (hash
    // collisions) and the same id more than once.
    template <class Fn>
    void for_each_candidate(const Box3& box, Fn&& fn) const {
        const Cell lo = cell_of(box.lo), hi = cell_of(box.hi);
        for (std::int64_t x = lo.x; x <= hi.x; ++x)
            for (std::int64_t y = lo.y; y <= hi.y; ++y)
                for (std::int64_t z = lo.z; z <= hi.z; ++z) {
                    const Cell cell{x, y, z};
                    for (int e = head_[bucket(cell)]; e >= 0; e = entries_[e].next) fn(cell, entries_[e].id);
                }
    }

private:
    struct Entry {
        int id, next;
    };
    std::int64_t coordinate(double v) const { return static_cast<std::int64_t>(std::floor(v * inverse_cell_)); }
    std::size_t bucket(const Cell& c) const {
        const auto h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull ^
                       static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full ^
                       static_cast<std::uint64_t>(c.z) * 0x165667B19E3779F9ull;
        return static_cast<std::size_t>(h >> 32) & mask_;
    }

    double inverse_cell_ = 1.0;
    std::size_t mask_ = 0;
    std::vector<int> head_;  // per bucket: the last entry added, -1 = none
    std::vector<Entry> entries_;
};

}  // namespace morphogen
