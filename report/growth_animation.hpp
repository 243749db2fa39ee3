#pragma once
// The growth of one genome as an animation (`morphogen grow --animate`,
// `--frames-obj`, and the report's viewer). A growing mesh changes its vertex
// count and flips change its triangles, so glTF morph targets cannot hold it:
// each frame is a mesh and node of its own under one root node, and one
// animation shows them in turn with STEP-interpolated scale keys, (1,1,1) for
// the frame shown and (0,0,0) for the others (docs/file-formats.md).
#include "core/growth/genome_grower.hpp"
#include "core/growth/network/network.hpp"
#include "core/mesh/mesh.hpp"
#include "run/config/experiment_config.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace morphogen {

// meshes[i] is the mesh after steps[i] growth steps: steps rise strictly from
// 0 (the seed) to the steps growth did (the final mesh).
struct GrowthFrames {
    std::vector<MeshArrays> meshes;
    std::vector<int> steps;
    // Empty, or per frame its colours from growth history (4 linear floats
    // per vertex, engine/plant_colour.hpp): the animation's COLOR_0.
    std::vector<std::vector<float>> colours;
};

inline constexpr int kDefaultAnimationFrames = 50;
inline constexpr int kMaxAnimationFrames = 1000;
inline constexpr double kDefaultSecondsPerFrame = 0.1;  // 50 frames: 5 s
// The final frame stays at least this long before a player loops.
inline constexpr double kMinFinalFrameSeconds = 1.0;
inline constexpr double kMinSecondsPerFrame = 0.001, kMaxSecondsPerFrame = 60.0;

// min(kDefaultAnimationFrames, steps + 1): what --frames defaults to.
int default_animation_frames(int steps);
// Why `frames` frames cannot show `steps` steps, or "" when they can: the
// seed and the final mesh are frames, and no step is shown twice, so frames
// must lie in [2, steps + 1] (just 1 when steps is 0) and within
// kMaxAnimationFrames.
std::string animation_frames_problem(int frames, int steps);
// The steps after which frames are taken: 0, evenly spaced steps (rounded),
// `steps`. Requires animation_frames_problem(frames, steps) to be "".
std::vector<int> animation_frame_steps(int steps, int frames);

// Grows `network` exactly as grower.grow(network, workspace) does (the same
// final state, returned) while copying into `frames` the meshes after
// animation_frame_steps(steps, count) of its steps, and calling `also` (when
// set) after every step; with `colour`, also each frame's colours (the
// seed's by the paper mode's rule, §13, with the final tint). Throws
// ConfigError for a bad `count`.
GrowthState grow_with_frames(const GenomeGrower& grower, const Network& network, int count,
                             GrowthWorkspace& workspace, GrowthFrames& frames, const StepObserver& also = {},
                             bool colour = false);

// Grows `genome` with config.network/config.growth and returns `frames` frames
// (ConfigError when animation_frames_problem says no), coloured with `colour`.
GrowthFrames record_growth_frames(const ExperimentConfig& config, const Genome& genome, int frames,
                                  bool colour = false);

// The animated glTF: node 0 is the root ("growth"), node i + 1 shows frame i
// (mesh i, named "step_<steps[i]>"); frame i is shown from i * seconds_per_frame
// for seconds_per_frame, the last one for max(seconds_per_frame,
// kMinFinalFrameSeconds), and it is the one visible at rest (no animation
// playing). Frames with colours carry COLOR_0 and the white material.
// Throws ConfigError for no frames, mismatched steps/meshes or
// seconds_per_frame outside [kMinSecondsPerFrame, kMaxSecondsPerFrame], and
// IoError naming `source` if the file would pass kMaxMeshFileBytes.
std::string encode_growth_animation_glb(const GrowthFrames& frames, double seconds_per_frame,
                                        const std::string& source = "animation");
// Writes those bytes atomically (core/base/atomic_file.hpp); IoError naming `out`.
void write_growth_animation(const std::filesystem::path& out, const GrowthFrames& frames, double seconds_per_frame);

// Writes frame i as dir/frame_NNNN.obj (4 digits, i from 0), creating `dir`;
// IoError naming the directory or file that cannot be written.
void write_growth_frames_obj(const std::filesystem::path& dir, const GrowthFrames& frames);

}  // namespace morphogen
