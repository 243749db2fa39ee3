#pragma once
// The one place the report asks for the growth animation of a genome (an
// animated glTF: one node per frame, STEP scale keys; growth_animation.hpp).
#include "experiment_config.hpp"
#include "network.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace morphogen {

// Writes the animated GLB of `genome`'s growth in `frames` frames to `path`
// and returns true, or returns false with `why` set when this build cannot.
// Throws what growth and writing throw.
bool write_report_animation(const ExperimentConfig& config, const Genome& genome, int frames,
                            const std::filesystem::path& path, std::string& why);

}  // namespace morphogen
