#pragma once
// The collision guard's broad phase kept from step to step (docs/algorithm.md
// §5.7). Every face f has a listing box L_f that holds f's box now (the
// caller keeps it so: a face whose box leaves L_f is listed again); two faces
// whose listing boxes meet are partners, unless the owner's rule `keep`
// (given to refresh) leaves the pair out. So two faces whose boxes meet are
// partners or left out by the rule, and a step only walks partner lists: no
// grid is built, and a face is looked up in the grid only when it is listed
// again (its box left L_f by the margin the caller gave it, or the face
// changed).
//
// Partner lists are symmetric and hold no repeats. Deterministic: a fixed
// history of calls gives fixed lists (their order does not matter to the
// guard, which decides on sets).
#include "core/mesh/spatial_hash.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace morphogen {

class FaceListing {
public:
    // Forgets every face.
    void clear();
    int size() const { return static_cast<int>(boxes_.size()); }

    // Gives face f (an existing one, or f == size(): a new one) the listing
    // box `box`. Its partners are stale until refresh().
    void relist(int f, const Box3& box);
    // Recomputes the partners of every face relisted since the last refresh,
    // each pair kept only where keep(f, g) holds (a rule that may change for
    // a pair only when one of its faces is relisted).
    void refresh(const std::function<bool(int, int)>& keep);

    const Box3& box(int f) const { return boxes_[f]; }
    // Valid after refresh(): every face whose listing box meets f's (and
    // that the rule keeps).
    std::span<const int> partners(int f) const { return partners_[f]; }

    // Calls fn(g) once for every face g whose listing box meets `query`
    // (any order; relisted faces included before refresh()).
    template <class Fn>
    void for_each_meeting(const Box3& query, Fn&& fn) {
        if (!grid_built_) rebuild_grid();
        next_query();
        grid_.for_each_candidate(query, [&](int g, const Box3& listed) {
            // A stale entry (g relisted since) may still meet the query; g's
            // listing box now decides, once.
            if (!listed.overlaps(query) || !boxes_[g].overlaps(query) || stamp_[g] == query_) return;
            stamp_[g] = query_;
            fn(g);
        });
    }

private:
    void rebuild_grid();
    // A fresh stamp; on wrap-around every stamp is cleared (lists live long).
    void next_query() {
        if (++query_ == 0) {
            std::fill(stamp_.begin(), stamp_.end(), 0u);
            query_ = 1;
        }
    }
    void unlink(int f, int g);  // removes f from g's partners

    std::vector<Box3> boxes_;
    std::vector<std::vector<int>> partners_;
    std::vector<int> pending_;     // relisted since the last refresh
    std::vector<char> is_pending_;
    SpatialHash grid_;             // every listing box, and stale ones
    bool grid_built_ = false;
    std::vector<std::uint32_t> stamp_;  // per face: the last query that reported it
    std::uint32_t query_ = 0;
};

}  // namespace morphogen
