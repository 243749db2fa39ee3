#include "core/mesh/face_listing.hpp"

#include <algorithm>

namespace morphogen {

void FaceListing::clear() {
    boxes_.clear();
    for (std::vector<int>& list : partners_) list.clear();  // keeps their capacity
    pending_.clear();
    is_pending_.clear();
    grid_built_ = false;
}

void FaceListing::relist(int f, const Box3& box) {
    const auto index = static_cast<std::size_t>(f);
    if (index == boxes_.size()) {
        boxes_.push_back(box);
        if (partners_.size() <= index) partners_.resize(index + 1);
        is_pending_.push_back(0);
        stamp_.resize(boxes_.size(), 0);
    }
    boxes_[index] = box;
    if (!is_pending_[index]) {
        is_pending_[index] = 1;
        pending_.push_back(f);
    }
    if (grid_built_) grid_.insert(f, box);
}

void FaceListing::rebuild_grid() {
    // Cells about as large as a listing box, as in the grid of one step.
    grid_.build(SpatialHash::cell_size_for(boxes_), boxes_);
    grid_built_ = true;
}

void FaceListing::unlink(int f, int g) {
    std::vector<int>& list = partners_[g];
    const auto at = std::find(list.begin(), list.end(), f);
    *at = list.back();
    list.pop_back();
}

void FaceListing::refresh(const std::function<bool(int, int)>& keep) {
    if (pending_.empty()) return;
    // A grid whose stale entries reach a quarter of its built ones (or none
    // yet) is built again from the listing boxes; otherwise the relisted ones
    // are already in it. Queries walk the late entries one by one, so a
    // fresher grid pays (docs/performance.md: 6 % of the guard's time).
    if (!grid_built_ || grid_.late_entries() > grid_.built_entries() / 4 + 64) rebuild_grid();
    for (const int f : pending_) {
        for (const int g : partners_[f])
            if (!is_pending_[g]) unlink(f, g);
        partners_[f].clear();
    }
    // Each pair once: a pending face found by a lower pending one was added then.
    for (const int f : pending_)
        for_each_meeting(boxes_[f], [&](int g) {
            if (g == f || (is_pending_[g] && g < f) || !keep(f, g)) return;
            partners_[f].push_back(g);
            partners_[g].push_back(f);
        });
    for (const int f : pending_) is_pending_[f] = 0;
    pending_.clear();
}

}  // namespace morphogen
