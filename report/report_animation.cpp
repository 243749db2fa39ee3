#include "report/report_animation.hpp"

#include "report/growth_animation.hpp"

#include <algorithm>

namespace morphogen {

std::optional<std::string> report_animation_glb(const ExperimentConfig& config, const Genome& genome, int& frames,
                                                std::string& why, bool colour) {
    frames = std::min(frames, config.growth.steps + 1);
    if (const std::string problem = animation_frames_problem(frames, config.growth.steps); !problem.empty()) {
        why = "growth animation: " + problem;
        return std::nullopt;
    }
    return encode_growth_animation_glb(record_growth_frames(config, genome, frames, colour), kDefaultSecondsPerFrame,
                                       "the growth animation");
}

}  // namespace morphogen
