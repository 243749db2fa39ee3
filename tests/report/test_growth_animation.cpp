// The growth animation: frame choice, the animated glTF read back with
// tinygltf (nodes, meshes, accessors, STEP scale keys, one frame visible at a
// time) and `grow --animate/--frames-obj` end to end, hostile options included.
#include "core/base/errors.hpp"
#include "core/io/mesh_io.hpp"
#include "report/growth_animation.hpp"
#include "run/config/experiment_config.hpp"
#include "run/genome_source.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

using namespace morphogen;
using namespace morphogen::test;

namespace {

ExperimentConfig small_config(int steps) {
    ExperimentConfig config = load_experiment_config("");
    config.growth.steps = steps;
    return config;
}

Genome genome_for(const ExperimentConfig& config, std::uint64_t seed) {
    return random_genome(config.network.layers(), config.growth.mode, config.evolution.init_range, seed);
}

tinygltf::Model parse_checked_glb(const std::string& bytes) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const bool ok = loader.LoadBinaryFromMemory(&model, &err, &warn,
                                                reinterpret_cast<const unsigned char*>(bytes.data()),
                                                static_cast<unsigned int>(bytes.size()));
    INFO(err << warn);
    REQUIRE(ok);
    CHECK(err.empty());
    CHECK(warn.empty());
    return model;
}

std::vector<float> floats(const tinygltf::Model& model, int accessor) {
    const tinygltf::Accessor& acc = model.accessors.at(static_cast<std::size_t>(accessor));
    REQUIRE(acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(acc.bufferView));
    const std::size_t n = acc.count * static_cast<std::size_t>(tinygltf::GetNumComponentsInType(acc.type));
    REQUIRE(view.byteLength == n * 4);
    std::vector<float> out(n);
    std::memcpy(out.data(), model.buffers.at(0).data.data() + view.byteOffset + acc.byteOffset, n * 4);
    return out;
}

// Node `node`'s scale at `time` under STEP interpolation: the value of the
// last key at or before `time` (the first key's before it).
float scale_at(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler, double time) {
    const std::vector<float> times = floats(model, sampler.input);
    const std::vector<float> values = floats(model, sampler.output);
    std::size_t k = 0;
    while (k + 1 < times.size() && times[k + 1] <= time) ++k;
    CHECK(values[3 * k] == values[3 * k + 1]);
    CHECK(values[3 * k] == values[3 * k + 2]);
    return values[3 * k];
}

// Every structural promise of encode_growth_animation_glb, checked on `frames`.
void check_animation(const GrowthFrames& frames, double spf) {
    const auto n = frames.meshes.size();
    const tinygltf::Model model = parse_checked_glb(encode_growth_animation_glb(frames, spf));
    REQUIRE(model.scenes.size() == 1);
    REQUIRE(model.scenes[0].nodes == std::vector<int>{0});
    REQUIRE(model.nodes.size() == n + 1);
    REQUIRE(model.meshes.size() == n);
    CHECK(model.accessors.size() == 5 * n);  // position, normal, index; key times, key scales
    std::vector<int> children(n);
    for (std::size_t i = 0; i < n; ++i) children[i] = static_cast<int>(i) + 1;
    CHECK(model.nodes[0].children == children);
    CHECK(model.nodes[0].mesh == -1);

    for (std::size_t i = 0; i < n; ++i) {
        INFO("frame " << i);
        const tinygltf::Node& node = model.nodes[i + 1];
        CHECK(node.name == "step_" + std::to_string(frames.steps[i]));
        REQUIRE(node.mesh == static_cast<int>(i));
        // At rest only the final mesh shows.
        if (i + 1 < n)
            CHECK(node.scale == std::vector<double>{0, 0, 0});
        else
            CHECK((node.scale.empty() || node.scale == std::vector<double>{1, 1, 1}));
        const tinygltf::Primitive& prim = model.meshes[i].primitives.at(0);
        const tinygltf::Accessor& pos = model.accessors.at(static_cast<std::size_t>(prim.attributes.at("POSITION")));
        CHECK(pos.count == frames.meshes[i].positions.size());
        CHECK(pos.minValues.size() == 3);
        CHECK(pos.maxValues.size() == 3);
        CHECK(model.accessors.at(static_cast<std::size_t>(prim.attributes.at("NORMAL"))).count == pos.count);
        CHECK(model.accessors.at(static_cast<std::size_t>(prim.indices)).count == 3 * frames.meshes[i].faces.size());
    }

    REQUIRE(model.animations.size() == 1);
    const tinygltf::Animation& anim = model.animations[0];
    REQUIRE(anim.channels.size() == n);
    REQUIRE(anim.samplers.size() == n);
    std::set<double> key_times;
    std::size_t keys = 0;
    for (std::size_t i = 0; i < n; ++i) {
        INFO("frame " << i);
        const tinygltf::AnimationChannel& channel = anim.channels[i];
        CHECK(channel.target_node == static_cast<int>(i) + 1);
        CHECK(channel.target_path == "scale");
        const tinygltf::AnimationSampler& sampler = anim.samplers.at(static_cast<std::size_t>(channel.sampler));
        CHECK(sampler.interpolation == "STEP");
        const tinygltf::Accessor& input = model.accessors.at(static_cast<std::size_t>(sampler.input));
        CHECK(input.minValues.size() == 1);  // the validator requires bounds on animation inputs
        const std::vector<float> times = floats(model, sampler.input);
        REQUIRE(floats(model, sampler.output).size() == 3 * times.size());
        CHECK(std::is_sorted(times.begin(), times.end()));
        CHECK(std::adjacent_find(times.begin(), times.end()) == times.end());
        CHECK(times.front() == 0.0f);
        CHECK(times.size() == (n == 1 || i == 0 ? 2u : 3u));
        keys += times.size();
        key_times.insert(times.begin(), times.end());
    }
    CHECK(keys == (n == 1 ? 2 : 3 * n - 1));
    // Every frame has one key time of its own, and the end holds the final one.
    const double end = (static_cast<double>(n) - 1) * spf + std::max(spf, kMinFinalFrameSeconds);
    CHECK(key_times.size() == n + 1);
    CHECK(*key_times.rbegin() == Approx(end));

    // At every key time, and between them, exactly one frame shows: the one due.
    for (double t : key_times) {
        for (const double at : {t, t + spf / 2}) {
            INFO("time " << at);
            int shown = 0, which = -1;
            for (std::size_t i = 0; i < n; ++i) {
                const float s = scale_at(model, anim.samplers[i], at);
                CHECK((s == 0.0f || s == 1.0f));
                if (s == 1.0f) ++shown, which = static_cast<int>(i);
            }
            CHECK(shown == 1);
            const auto due = std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::floor(at / spf + 1e-6)));
            CHECK(which == static_cast<int>(due));
        }
    }
}

}  // namespace

TEST_CASE("animation frames: the seed, evenly spaced steps, the final mesh", "[animation]") {
    CHECK(animation_frame_steps(60, 2) == std::vector<int>{0, 60});
    CHECK(animation_frame_steps(10, 11) == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
    CHECK(animation_frame_steps(10, 4) == std::vector<int>{0, 3, 7, 10});
    CHECK(animation_frame_steps(0, 1) == std::vector<int>{0});
    for (const int steps : {1, 7, 200, 999'999})
        for (const int frames : {2, 3, 50, 1000}) {
            if (frames > steps + 1) continue;
            const std::vector<int> s = animation_frame_steps(steps, frames);
            REQUIRE(s.size() == static_cast<std::size_t>(frames));
            CHECK(s.front() == 0);
            CHECK(s.back() == steps);
            CHECK(std::adjacent_find(s.begin(), s.end(), std::greater_equal<>()) == s.end());
        }

    CHECK(default_animation_frames(200) == 50);
    CHECK(default_animation_frames(10) == 11);
    CHECK(default_animation_frames(0) == 1);
    CHECK(animation_frames_problem(2, 1).empty());
    CHECK(animation_frames_problem(1, 0).empty());
    CHECK(animation_frames_problem(1000, 5000).empty());
    for (const auto& [frames, steps] : std::vector<std::pair<int, int>>{
             {0, 10}, {-1, 10}, {1, 10}, {12, 10}, {2, 0}, {1001, 5000}, {std::numeric_limits<int>::min(), 5},
             {std::numeric_limits<int>::max(), std::numeric_limits<int>::max() - 1}}) {
        INFO(frames << " frames, " << steps << " steps");
        CHECK_FALSE(animation_frames_problem(frames, steps).empty());
    }
    CHECK(animation_frames_problem(12, 10).find("between 2 and 11") != std::string::npos);
}

TEST_CASE("recorded frames are the growth's meshes at their steps, without changing it", "[animation]") {
    const ExperimentConfig config = small_config(40);
    const Genome genome = genome_for(config, 7);
    const GrowthFrames frames = record_growth_frames(config, genome, 9);
    REQUIRE(frames.meshes.size() == 9);
    REQUIRE(frames.steps == animation_frame_steps(40, 9));

    // The same growth, watched step by step.
    const Network network(genome);
    const GenomeGrower grower(config.network, config.growth);
    std::vector<MeshArrays> every{{grower.seed().mesh.positions(), grower.seed().mesh.faces()}};
    GrowthWorkspace workspace;
    const GrowthState plain = grower.grow(network, workspace, [&](const GrowthState& state, int) {
        every.push_back({state.mesh.positions(), state.mesh.faces()});
    });
    REQUIRE(every.size() == 41);
    for (std::size_t i = 0; i < frames.steps.size(); ++i) {
        INFO("frame " << i << ", step " << frames.steps[i]);
        const MeshArrays& expected = every[static_cast<std::size_t>(frames.steps[i])];
        CHECK(frames.meshes[i].positions.size() == expected.positions.size());
        CHECK(frames.meshes[i].positions == expected.positions);
        CHECK(frames.meshes[i].faces == expected.faces);
    }
    CHECK(frames.meshes.front().positions.size() == 12);  // the icosahedron seed
    CHECK(frames.meshes.back().positions == plain.mesh.positions());
    CHECK(frames.meshes.front().positions.size() < frames.meshes.back().positions.size());

    // grow_with_frames returns what grow() does.
    GrowthFrames again;
    GrowthWorkspace workspace2;
    const GrowthState state = grow_with_frames(grower, network, 9, workspace2, again);
    CHECK(state.mesh.positions() == plain.mesh.positions());
    CHECK(state.mesh.faces() == plain.mesh.faces());
    CHECK(state.outputs == plain.outputs);
    CHECK(state.steps_done == 40);

    CHECK_THROWS_AS(record_growth_frames(config, genome, 42), ConfigError);
    CHECK_THROWS_AS(record_growth_frames(config, genome, 1), ConfigError);
    CHECK_THROWS_AS(record_growth_frames(config, genome, 0), ConfigError);
}

TEST_CASE("the animated glTF: one node per frame, STEP scale keys, one frame shown at a time", "[animation]") {
    const ExperimentConfig config = small_config(30);
    const Genome genome = genome_for(config, 3);
    SECTION("many frames") { check_animation(record_growth_frames(config, genome, 31), 0.1); }
    SECTION("two frames, slow") { check_animation(record_growth_frames(config, genome, 2), 2.5); }
    SECTION("one frame of no growth") { check_animation(record_growth_frames(small_config(0), genome, 1), 0.04); }
    SECTION("the same frames give the same bytes") {
        const GrowthFrames frames = record_growth_frames(config, genome, 7);
        CHECK(encode_growth_animation_glb(frames, 0.1) == encode_growth_animation_glb(frames, 0.1));
        CHECK(encode_growth_animation_glb(frames, 0.1) != encode_growth_animation_glb(frames, 0.2));
    }
}

TEST_CASE("a coloured animation: each frame's colours from growth history as its COLOR_0, the same meshes",
          "[animation][colour]") {
    const ExperimentConfig config = small_config(30);
    const Genome genome = genome_for(config, 3);
    const GrowthFrames plain = record_growth_frames(config, genome, 7);
    const GrowthFrames coloured = record_growth_frames(config, genome, 7, true);
    CHECK(plain.colours.empty());
    REQUIRE(coloured.colours.size() == 7);
    for (std::size_t i = 0; i < 7; ++i) {
        CHECK(coloured.meshes[i].positions == plain.meshes[i].positions);
        CHECK(coloured.meshes[i].faces == plain.meshes[i].faces);
        REQUIRE(coloured.colours[i].size() == 4 * coloured.meshes[i].positions.size());
        CHECK(std::all_of(coloured.colours[i].begin(), coloured.colours[i].end(),
                          [](float c) { return c >= 0.0f && c <= 1.0f; }));
    }
    // The final frame has several colours (a seed of one age may have one).
    std::set<std::vector<float>> last;
    for (std::size_t v = 0; v < coloured.meshes.back().positions.size(); ++v)
        last.insert({coloured.colours.back().begin() + 4 * v, coloured.colours.back().begin() + 4 * v + 3});
    CHECK(last.size() > 10);
    const tinygltf::Model with = parse_glb(encode_growth_animation_glb(coloured, 0.1));
    const tinygltf::Model without = parse_glb(encode_growth_animation_glb(plain, 0.1));
    for (const tinygltf::Mesh& mesh : with.meshes) CHECK(mesh.primitives.at(0).attributes.count("COLOR_0") == 1);
    for (const tinygltf::Mesh& mesh : without.meshes) CHECK(mesh.primitives.at(0).attributes.count("COLOR_0") == 0);
    CHECK(with.materials.at(0).pbrMetallicRoughness.baseColorFactor == std::vector<double>{1, 1, 1, 1});
    CHECK(floats(with, with.meshes.back().primitives.at(0).attributes.at("COLOR_0")) == coloured.colours.back());
}

TEST_CASE("the animation refuses what it cannot show, naming the file", "[animation]") {
    const ExperimentConfig config = small_config(10);
    const GrowthFrames frames = record_growth_frames(config, genome_for(config, 1), 3);
    CHECK_THROWS_AS(encode_growth_animation_glb(GrowthFrames{}, 0.1), ConfigError);
    GrowthFrames mismatched = frames;
    mismatched.steps.pop_back();
    CHECK_THROWS_AS(encode_growth_animation_glb(mismatched, 0.1), ConfigError);
    for (const double spf : {0.0, -1.0, 1e-9, 61.0, std::nan(""), std::numeric_limits<double>::infinity()})
        CHECK_THROWS_AS(encode_growth_animation_glb(frames, spf), ConfigError);

    TempDir dir("anim-io");
    const fs::path missing = dir.path / "no" / "such" / "a.glb";
    try {
        write_growth_animation(missing, frames, 0.1);
        FAIL("no error");
    } catch (const IoError& e) {
        CHECK(std::string(e.what()).find(missing.string()) != std::string::npos);
    }
    CHECK_FALSE(fs::exists(missing));
    write_text(dir.path / "file", "x");
    CHECK_THROWS_AS(write_growth_frames_obj(dir.path / "file", frames), IoError);
    CHECK_THROWS_AS(write_growth_frames_obj(dir.path / "file" / "sub", frames), IoError);
}

TEST_CASE("grow --animate and --frames-obj write the growth without changing the mesh", "[animation][cli]") {
    TempDir dir("anim-cli");
    const fs::path plain = dir.path / "plain.obj", mesh = dir.path / "mesh.obj", glb = dir.path / "g.glb",
                   objs = dir.path / "frames";
    REQUIRE(run_morphogen("grow --random 4 --steps 24 -o " + q(plain)).code == 0);
    const CliResult r = run_morphogen("grow --random 4 --steps 24 -o " + q(mesh) + " --animate " + q(glb) +
                                      " --frames 6 --frame-seconds 0.25 --frames-obj " + q(objs));
    INFO(r.output);
    REQUIRE(r.code == 0);
    CHECK(r.output.find("6 frames") != std::string::npos);
    CHECK(read_text(plain) == read_text(mesh));  // same growth, same bytes

    // K OBJ files, each parsing, frame 0 the seed, the last the final mesh.
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(objs)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    CHECK(names == std::vector<std::string>{"frame_0000.obj", "frame_0001.obj", "frame_0002.obj", "frame_0003.obj",
                                            "frame_0004.obj", "frame_0005.obj"});
    std::vector<std::size_t> vertices;
    for (const std::string& name : names) {
        const MeshArrays frame = read_mesh((objs / name).string());
        CHECK_NOTHROW(TriMesh::from_arrays(frame, name));
        vertices.push_back(frame.positions.size());
    }
    CHECK(vertices.front() == 12);
    CHECK(read_text(objs / names.back()) == read_text(mesh));

    // The .glb holds the same frames, and the same frames as the library records.
    const ExperimentConfig config = small_config(24);
    const GrowthFrames frames = record_growth_frames(config, genome_for(config, 4), 6);
    CHECK(read_text(glb) == encode_growth_animation_glb(frames, 0.25));
    const tinygltf::Model model = parse_checked_glb(read_text(glb));
    REQUIRE(model.meshes.size() == 6);
    for (std::size_t i = 0; i < 6; ++i)
        CHECK(model.accessors.at(static_cast<std::size_t>(model.meshes[i].primitives.at(0).attributes.at("POSITION")))
                  .count == vertices[i]);

    // The default: 50 frames, or one per step and the seed for short growth.
    REQUIRE(run_morphogen("grow --random 4 --steps 24 -o " + q(mesh) + " --animate " + q(glb)).code == 0);
    CHECK(parse_checked_glb(read_text(glb)).nodes.size() == 26);
    REQUIRE(run_morphogen("grow --random 4 --steps 80 -o " + q(mesh) + " --animate " + q(glb)).code == 0);
    CHECK(parse_checked_glb(read_text(glb)).nodes.size() == 51);
}

TEST_CASE("grow refuses hostile animation options with one line and exit 2, before writing", "[animation][cli]") {
    TempDir dir("anim-bad");
    const fs::path mesh = dir.path / "m.obj", glb = dir.path / "a.glb";
    const std::string base = "grow --random 2 --steps 20 -o " + q(mesh) + " ";
    for (const std::string& bad : std::vector<std::string>{
             "--animate " + q(glb) + " --frames 0", "--animate " + q(glb) + " --frames -5",
          "--animate " + q(glb) + " --frames 1", "--animate " + q(glb) + " --frames 22",
          "--animate " + q(glb) + " --frames 1001", "--animate " + q(glb) + " --frames 99999999999",
          "--animate " + q(glb) + " --frames 2.5", "--animate " + q(glb) + " --frames x",
          "--frames-obj " + q(dir.path / "f") + " --frames 0", "--frames 5",
          "--animate " + q(glb) + " --frame-seconds 0", "--animate " + q(glb) + " --frame-seconds nan",
          "--animate " + q(glb) + " --frame-seconds -1", "--animate " + q(glb) + " --frame-seconds 1e9",
          "--frame-seconds 0.5", "--animate " + q(dir.path / "a.gltf"), "--animate " + q(dir.path / "a.obj")}) {
        INFO(bad);
        const CliResult r = run_morphogen(base + bad);
        INFO(r.output);
        CHECK(r.code == 2);
        const std::string first = r.output.substr(0, r.output.find('\n'));
        CHECK((first.find("--frame") != std::string::npos || first.find("--animate") != std::string::npos));
        CHECK_FALSE(fs::exists(glb));
        CHECK_FALSE(fs::exists(mesh));  // refused before growing
        CHECK_FALSE(fs::exists(dir.path / "f"));
    }
    // --steps 0: one frame (the seed) is all there is.
    const std::string no_growth = "grow --random 2 --steps 0 -o " + q(mesh) + " --animate " + q(glb);
    CHECK(run_morphogen(no_growth + " --frames 2").code == 2);
    CHECK(run_morphogen(no_growth).code == 0);
    CHECK(parse_checked_glb(read_text(glb)).nodes.size() == 2);
    // Unwritable places: exit 3 naming them.
    write_text(dir.path / "file", "x");
    CliResult r = run_morphogen(base + "--frames-obj " + q(dir.path / "file"));
    CHECK(r.code == 3);
    CHECK(r.output.find((dir.path / "file").string()) != std::string::npos);
    r = run_morphogen(base + "--animate " + q(dir.path / "none" / "a.glb"));
    CHECK(r.code == 3);
    CHECK(r.output.find((dir.path / "none" / "a.glb").string()) != std::string::npos);
}
