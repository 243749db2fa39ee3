#pragma once
// When each vertex of a growing mesh was born, for the wind data's flutter
// (plant_wind.hpp). Growth appends vertices in birth order and never removes
// one, so the vertex count after each step, seen through the grower's
// per-step observer, dates every vertex without changing growth.
#include "core/growth/growth.hpp"

#include <vector>

namespace morphogen {

class BirthSteps {
public:
    // The seed's vertices are born at step 0.
    explicit BirthSteps(int seed_vertices) : steps_(static_cast<std::size_t>(seed_vertices), 0) {}

    // Called after step t (Grower's StepObserver): the vertices added by it
    // are born at step t + 1.
    void after_step(const GrowthState& state, int step) {
        steps_.resize(static_cast<std::size_t>(state.mesh.num_vertices()), step + 1);
    }
    StepObserver observer() {
        return [this](const GrowthState& state, int step) { after_step(state, step); };
    }

    // One entry per vertex of the mesh as last observed.
    const std::vector<int>& steps() const { return steps_; }

private:
    std::vector<int> steps_;
};

}  // namespace morphogen
