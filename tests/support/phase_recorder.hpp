#pragma once
// A GrowthObserver for tests: the hooks it was called with, in order.
#include "core/growth/growth_observer.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace morphogen::testing {

struct PhaseRecorder final : GrowthObserver {
    enum class Hook { begin, end };
    std::vector<std::pair<Hook, GrowthPhase>> calls;

    void begin(GrowthPhase phase, const GrowthState&, const GrowthWorkspace&) override {
        calls.emplace_back(Hook::begin, phase);
    }
    void end(GrowthPhase phase, const GrowthState&, const GrowthWorkspace&) override {
        calls.emplace_back(Hook::end, phase);
    }
    long count(Hook hook, GrowthPhase phase) const {
        return std::ranges::count(calls, std::pair{hook, phase});
    }
};

}  // namespace morphogen::testing
