#pragma once
// The report's growth animation of a genome: the animated glTF of
// growth_animation.hpp (one node per frame, STEP scale keys), as bytes.
#include "core/growth/network/network.hpp"
#include "run/config/experiment_config.hpp"

#include <optional>
#include <string>

namespace morphogen {

// The GLB of `genome`'s growth in min(frames, growth.steps + 1) frames
// (`frames` is set to the count used), or none with `why` set when no
// animation can be made of it. Throws what growth and encoding throw.
// `colour`: the frames in their colours from growth history (COLOR_0).
std::optional<std::string> report_animation_glb(const ExperimentConfig& config, const Genome& genome, int& frames,
                                                std::string& why, bool colour = true);

}  // namespace morphogen
