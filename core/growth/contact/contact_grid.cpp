#include "core/growth/contact/contact_grid.hpp"

#include <cmath>
#include <limits>

namespace morphogen {

namespace {
// At most this many cells per listed box (on average): a sparse mesh gets
// larger cells rather than a huge, empty grid.
constexpr double kMaxCellsPerBox = 8.0;
}  // namespace

ContactGrid::FloatBox ContactGrid::outward(const Box3& box) {
    // A float is within half an ulp, at most |x| * 2^-24, of the double it
    // rounds: moving it out by twice that (and a little for underflow) is safe.
    const auto down = [](double v) {
        const auto f = static_cast<float>(v);
        return f - (std::abs(f) * 0x1p-23f + 0x1p-126f);
    };
    const auto up = [](double v) {
        const auto f = static_cast<float>(v);
        return f + (std::abs(f) * 0x1p-23f + 0x1p-126f);
    };
    return {{down(box.lo.x()), down(box.lo.y()), down(box.lo.z())}, {up(box.hi.x()), up(box.hi.y()), up(box.hi.z())}};
}

template <class Fn>
void ContactGrid::for_each_cell(const CellRange& range, Fn&& fn) const {
    const auto& [lo, hi] = range;
    for (int i = lo[0]; i <= hi[0]; ++i)
        for (int j = lo[1]; j <= hi[1]; ++j)
            for (int k = lo[2]; k <= hi[2]; ++k) fn((i * cells_[1] + j) * cells_[2] + k);
}

void ContactGrid::build(const std::vector<Box3>& boxes, double cell_size, const std::vector<char>& marks) {
    Box3 bounds{Vec3::Zero(), Vec3::Zero()};
    if (!boxes.empty()) bounds = boxes.front();
    for (const Box3& box : boxes) bounds = bounds.merged(box);
    origin_ = bounds.lo;
    const Vec3 size = bounds.hi - bounds.lo;
    const double budget = kMaxCellsPerBox * static_cast<double>(std::max<std::size_t>(boxes.size(), 1));
    const auto cells_for = [&](double cell) { return (size / cell).array().ceil().max(1.0).prod(); };
    double cell = cell_size;
    while (cells_for(cell) > budget) cell *= 2.0;
    inverse_cell_ = 1.0 / cell;
    for (int k = 0; k < 3; ++k) cells_[k] = std::max(1, static_cast<int>(std::ceil(size[k] * inverse_cell_)));
    const std::size_t count = static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2];
    // Counting sort by cell: count, prefix sums (each cell's end), fill
    // backwards (each cell's end moves down to its start, and its ids stay
    // ascending). Each box's cell range is found once and kept for the fill.
    start_.assign(count + 1, 0);
    std::vector<CellRange>& ranges = range_scratch_;
    ranges.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        ranges[i] = {cell_of(boxes[i].lo), cell_of(boxes[i].hi)};
        for_each_cell(ranges[i], [&](int c) { ++start_[c]; });
    }
    for (std::size_t c = 0; c < count; ++c) start_[c + 1] += start_[c];
    ids_.resize(start_[count]);
    boxes_.resize(boxes.size());
    for (std::size_t i = boxes.size(); i-- > 0;) {
        boxes_[i] = {outward(boxes[i]), marks.empty() || marks[i] != 0 ? 1U : 0U};
        for_each_cell(ranges[i], [&](int c) { ids_[--start_[c]] = static_cast<int>(i); });
    }
    // Only the cells a late entry went into need their chain emptied (most
    // builds have none): a full reset would write every cell again.
    if (late_head_.size() != count) {
        late_head_.assign(count, -1);
    } else {
        for (const LateEntry& e : late_) late_head_[e.cell] = -1;
    }
    late_.clear();
}

void ContactGrid::insert(int id, const Box3& box) {
    if (id >= static_cast<int>(boxes_.size())) boxes_.resize(static_cast<std::size_t>(id) + 1);
    boxes_[id] = {outward(box), 1U};
    for_each_cell(CellRange{cell_of(box.lo), cell_of(box.hi)}, [&](int c) {
        late_.push_back({id, late_head_[c], c});
        late_head_[c] = static_cast<int>(late_.size()) - 1;
    });
}

}  // namespace morphogen
