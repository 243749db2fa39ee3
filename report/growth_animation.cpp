// The growth as frames, an animated glTF and an OBJ sequence (see growth_animation.hpp).
#include "report/growth_animation.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "core/io/gltf_mesh.hpp"
#include "core/io/mesh_io.hpp"
#include "engine/birth_steps.hpp"
#include "engine/plant_colour.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>

namespace morphogen {

namespace {

MeshArrays snapshot(const TriMesh& mesh) { return {mesh.positions(), mesh.faces()}; }

void check_frames(int frames, int steps) {
    const std::string problem = animation_frames_problem(frames, steps);
    if (!problem.empty()) throw ConfigError("animation frames " + std::to_string(frames) + ": " + problem);
}

// One node's scale keys: (time, visible) pairs, read with STEP interpolation.
struct Keys {
    std::vector<float> times, scales;  // scales: 3 per key
    void add(double time, bool visible) {
        times.push_back(static_cast<float>(time));
        scales.insert(scales.end(), 3, visible ? 1.0f : 0.0f);
    }
};

// Frame i of n: hidden until i * spf, shown until (i + 1) * spf, then hidden;
// the last shown until `end`. Only the keys that change something (and one at
// 0, so every frame's state is defined from the start).
Keys frame_keys(int i, int n, double spf, double end) {
    Keys keys;
    if (i > 0) keys.add(0.0, false);
    keys.add(i * spf, true);
    keys.add(i + 1 < n ? (i + 1) * spf : end, i + 1 == n);
    return keys;
}

}  // namespace

int default_animation_frames(int steps) { return std::min(kDefaultAnimationFrames, steps + 1); }

std::string animation_frames_problem(int frames, int steps) {
    if (steps < 0) return "growth steps " + std::to_string(steps) + " is negative";
    const int most = std::min(kMaxAnimationFrames, steps + 1);
    const int least = std::min(2, most);
    if (frames >= least && frames <= most) return "";
    std::string why = "must be between " + std::to_string(least) + " and " + std::to_string(most);
    if (most == steps + 1)
        why += " (the seed and the final mesh, at most one frame per step of " + std::to_string(steps) + ")";
    else
        why += " (the most frames an animation may have)";
    return why;
}

std::vector<int> animation_frame_steps(int steps, int frames) {
    if (frames == 1) return {steps};
    std::vector<int> out;
    out.reserve(static_cast<std::size_t>(frames));
    const long long last = frames - 1;
    for (long long i = 0; i < frames; ++i)
        out.push_back(static_cast<int>((i * steps + last / 2) / last));  // round(i * steps / last)
    return out;
}

GrowthState grow_with_frames(const GenomeGrower& grower, const Network& network, int count,
                             GrowthWorkspace& workspace, GrowthFrames& frames, const StepObserver& also, bool colour) {
    const int steps = grower.params().steps;
    check_frames(count, steps);
    frames.steps = animation_frame_steps(steps, count);
    frames.meshes.clear();
    frames.colours.clear();
    frames.meshes.reserve(frames.steps.size());
    if (frames.steps.front() == 0) frames.meshes.push_back(snapshot(grower.seed().mesh));  // start() keeps the seed's mesh
    if (colour && !frames.meshes.empty()) frames.colours.emplace_back();  // the seed's: after growth, with its tint
    std::size_t next = frames.meshes.size();
    BirthSteps births(grower.seed().mesh.num_vertices());
    const StepObserver take_frames = [&](const GrowthState& state, int t) {
        if (also) also(state, t);
        if (colour) births.after_step(state, t);
        if (next < frames.steps.size() && frames.steps[next] == t + 1) {
            frames.meshes.push_back(snapshot(state.mesh));
            if (colour) frames.colours.push_back(growth_colours(state, births.steps(), grower.params()));
            ++next;
        }
    };
    GrowthState state = grower.grow(network, workspace, take_frames);
    if (colour && frames.steps.front() == 0) {
        const std::vector<int> born(frames.meshes.front().positions.size(), 0);
        frames.colours.front() = colour_rgba(plant_colours({.positions = frames.meshes.front().positions,
                                                            .birth_steps = born,
                                                            .steps = steps,
                                                            .active = {},
                                                            .exposure = {},
                                                            .tint = genome_tint(state)}));
    }
    if (frames.meshes.size() != frames.steps.size())  // grow() always does its params' steps
        throw std::logic_error("grow_with_frames: " + std::to_string(steps) + " steps asked, " +
                               std::to_string(state.steps_done) + " done");
    return state;
}

GrowthFrames record_growth_frames(const ExperimentConfig& config, const Genome& genome, int frames, bool colour) {
    check_frames(frames, config.growth.steps);
    const Network network(genome);
    const GenomeGrower grower(config.network, config.growth);
    GrowthWorkspace workspace;
    GrowthFrames out;
    grow_with_frames(grower, network, frames, workspace, out, {}, colour);
    return out;
}

std::string encode_growth_animation_glb(const GrowthFrames& frames, double seconds_per_frame,
                                        const std::string& source) {
    if (frames.meshes.empty() || frames.meshes.size() != frames.steps.size())
        throw ConfigError(source + ": an animation needs frames, each with its step (" +
                          std::to_string(frames.meshes.size()) + " meshes, " + std::to_string(frames.steps.size()) +
                          " steps)");
    if (!(seconds_per_frame >= kMinSecondsPerFrame && seconds_per_frame <= kMaxSecondsPerFrame))
        throw ConfigError(source + ": seconds per frame " + std::to_string(seconds_per_frame) +
                          " is outside [" + std::to_string(kMinSecondsPerFrame) + ", " +
                          std::to_string(kMaxSecondsPerFrame) + "]");
    const int n = static_cast<int>(frames.meshes.size());
    // Refuse before building what could not be written (or read back).
    long double bytes = 0;
    for (const MeshArrays& mesh : frames.meshes) bytes += gltf::mesh_data_bytes(mesh.view());
    for (const std::vector<float>& colours : frames.colours) bytes += 4.0L * colours.size();  // COLOR_0
    bytes += (48.0L + 2048.0L) * n;  // per frame: 3 keys of 16 bytes, and its JSON (about 1.1 KB)
    if (bytes > kMaxMeshFileBytes)
        throw IoError(source + ": an animation of " + std::to_string(n) + " frames would hold " +
                      std::to_string(static_cast<long long>(bytes)) + " bytes, more than the limit of " +
                      std::to_string(kMaxMeshFileBytes) + " for mesh files; use fewer frames");

    tinygltf::Model model = gltf::new_model();
    const bool coloured = !frames.colours.empty();
    if (coloured && frames.colours.size() != frames.meshes.size())
        throw ConfigError(source + ": " + std::to_string(frames.colours.size()) + " frames of colours for " +
                          std::to_string(frames.meshes.size()) + " frames");
    const int material = gltf::add_plant_material(model, coloured);
    tinygltf::Node root;
    root.name = "growth";
    model.nodes.push_back(root);

    const double end = (n - 1) * seconds_per_frame + std::max(seconds_per_frame, kMinFinalFrameSeconds);
    tinygltf::Animation animation;
    animation.name = "growth";
    for (int i = 0; i < n; ++i) {
        const std::string name = "step_" + std::to_string(frames.steps[static_cast<std::size_t>(i)]);
        tinygltf::Node node;
        node.name = name;
        node.mesh = gltf::add_mesh(model, frames.meshes[static_cast<std::size_t>(i)].view(), material, name);
        if (coloured && node.mesh >= 0)
            gltf::add_vertex_attribute(model, node.mesh, "COLOR_0", 4, frames.colours[static_cast<std::size_t>(i)]);
        if (i + 1 < n) node.scale = {0.0, 0.0, 0.0};  // at rest only the final mesh shows
        const int index = static_cast<int>(model.nodes.size());
        model.nodes.push_back(node);
        model.nodes[0].children.push_back(index);

        const Keys keys = frame_keys(i, n, seconds_per_frame, end);
        tinygltf::AnimationSampler sampler;
        sampler.input = gltf::add_floats(model, keys.times, TINYGLTF_TYPE_SCALAR);
        sampler.output = gltf::add_floats(model, keys.scales, TINYGLTF_TYPE_VEC3);
        sampler.interpolation = "STEP";
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel channel;
        channel.sampler = i;
        channel.target_node = index;
        channel.target_path = "scale";
        animation.channels.push_back(channel);
    }
    model.animations.push_back(animation);
    gltf::set_root_scene(model, 0);
    return gltf::glb_bytes(model, source);
}

void write_growth_animation(const std::filesystem::path& out, const GrowthFrames& frames, double seconds_per_frame) {
    write_file_atomically(out, encode_growth_animation_glb(frames, seconds_per_frame, out.string()));
}

void write_growth_frames_obj(const std::filesystem::path& dir, const GrowthFrames& frames) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw IoError(dir.string() + ": cannot create the frames directory" + (ec ? ": " + ec.message() : ""));
    for (std::size_t i = 0; i < frames.meshes.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04zu.obj", i);
        write_mesh(frames.meshes[i].view(), (dir / name).string(), mesh_format(".obj"));
    }
}

}  // namespace morphogen
