// `morphogen grow`: grow one genome and write its mesh.
#include "app/commands.hpp"
#include "fitness/mesh_stats.hpp"
#include "app/plant_export_options.hpp"
#include "app/resource_options.hpp"
#include "core/base/errors.hpp"
#include "engine/birth_steps.hpp"
#include "engine/leaf_cards.hpp"
#include "engine/plant_colour.hpp"
#include "engine/plant_export.hpp"
#include "fitness/descriptors.hpp"
#include "core/growth/genome_io.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/io/mesh_io.hpp"
#include "report/growth_animation.hpp"
#include "run/config/experiment_config.hpp"
#include "run/genome_source.hpp"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

namespace morphogen {

namespace {

struct GrowOptions {
    std::string config;
    std::optional<std::uint64_t> random_seed;
    std::string genome;
    std::optional<int> steps;
    std::string output;
    std::string save_genome;
    std::string animate;     // --animate OUT.glb
    std::string frames_obj;  // --frames-obj DIR
    std::optional<int> frames;
    double frame_seconds = kDefaultSecondsPerFrame;
    MeshWriteOptions mesh_options;
    PlantExportOptions plant;
    ResourceOptions resources;
};

// What the engine-ready GLB's extras say about a grown genome: named by its
// hash (it has no birth in a run), scored and measured by the config.
PlantRecord grown_record(const ExperimentConfig& config, const Genome& genome, MeshView mesh) {
    PlantRecord record;
    record.genome_hash = genome_hash(genome.params);
    record.id = record.genome_hash.substr(0, 8);
    const FitnessOutcome outcome = config.fitness->evaluate(mesh);
    if (outcome.valid) record.fitness = outcome.score;
    const std::vector<std::string> names = config.qd.measure_names();
    if (names.empty()) return record;
    try {
        const std::vector<double> values =
            DescriptorSet(names, config.fitness->canopy_params())(mesh);
        for (std::size_t i = 0; i < names.size(); ++i) record.measures.emplace_back(names[i], values[i]);
    } catch (const std::invalid_argument&) {
        // A mesh a measure cannot take keeps no measures, as in a GA run's lineage.
    }
    return record;
}

int run_grow(const GrowOptions& options) {
    ExperimentConfig config = load_experiment_config(options.config);
    if (options.steps) config.growth.steps = *options.steps;
    check_resource_limits(config, Workload{.scores = false, .writers = 1}, options.resources.limits(),
                          config_source(options.config));
    // Refuse an unknown extension, or colours it cannot hold, before growing.
    if (options.plant.colour && !mesh_format_from_path(options.output).colours)
        throw ConfigError("--colour: " + options.output + " cannot hold vertex colours; write " + colour_extensions());
    const bool animating = !options.animate.empty() || !options.frames_obj.empty();
    const int frames = options.frames.value_or(default_animation_frames(config.growth.steps));
    if (animating) {
        const std::string problem = animation_frames_problem(frames, config.growth.steps);
        if (!problem.empty()) throw ConfigError("--frames " + std::to_string(frames) + ": " + problem);
    }
    const GenomeGrower grower(config.network, config.growth);
    const Genome genome = options.random_seed
                              ? random_genome(grower.layers(), config.growth.mode, config.evolution.init_range, *options.random_seed)
                              : load_genome_for(grower.layers(), options.genome);
    const Network network(genome);

    const auto start = std::chrono::steady_clock::now();
    GrowthWorkspace workspace;
    GrowthFrames recorded;
    // Birth steps for --wind, --colour and --leaves: dated by the one growth
    // (grow_dated), or by the animation's step observer.
    const bool dated = options.plant.wind || options.plant.colour || options.plant.leaves;
    BirthSteps births(grower.seed().mesh.num_vertices());
    std::vector<int> birth_steps;
    const GrowthState state =
        animating ? grow_with_frames(grower, network, frames, workspace, recorded,
                                     dated ? births.observer() : StepObserver{}, options.plant.colour)
        : dated   ? grower.grow_dated(network, workspace, birth_steps)
                  : grower.grow(network, workspace);
    if (animating) birth_steps = births.steps();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::vector<double> light = options.plant.leaves ? leaf_light(state, config.growth) : std::vector<double>{};
    const std::vector<float> colours =  // the leaves' light is the final exposure: computed once
        options.plant.colour ? growth_colours(state, birth_steps, config.growth, light) : std::vector<float>{};
    // A coloured GLB is a plant's GLB (its colours are a material's, not a mesh file's).
    const bool glb = mesh_format_from_path(options.output).extension == ".glb";
    if (options.plant.engine_ready() || (options.plant.colour && glb)) {
        write_plant_glb(options.output,
                        GrownPlant{.mesh = state.mesh.view(), .birth_steps = birth_steps, .steps = state.steps_done,
                                   .colours = colours, .light = light},
                        grown_record(config, genome, state.mesh.view()), options.plant);
    }
    else {
        MeshWriteOptions mesh_options = options.mesh_options;
        mesh_options.colours = colours;
        write_mesh(state.mesh.view(), options.output, mesh_options);
    }
    if (!options.save_genome.empty()) save_genome(genome, options.save_genome);
    const MeshStats stats = mesh_stats(state.mesh.view());
    std::printf("%s: %d vertices, %d faces, height %.3f, width %.3f, %d steps in %.3f s\n", options.output.c_str(),
                state.mesh.num_vertices(), state.mesh.num_faces(), stats.height, stats.width, state.steps_done,
                seconds);
    if (!options.animate.empty()) {
        write_growth_animation(options.animate, recorded, options.frame_seconds);
        std::printf("%s: %d frames, %g s per frame\n", options.animate.c_str(), frames, options.frame_seconds);
    }
    if (!options.frames_obj.empty()) {
        write_growth_frames_obj(options.frames_obj, recorded);
        std::printf("%s: %d frames, frame_0000.obj to frame_%04d.obj\n", options.frames_obj.c_str(), frames,
                    frames - 1);
    }
    return 0;
}

}  // namespace

void add_grow_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<GrowOptions>();
    CLI::App* cmd = root.add_subcommand("grow", "Grow one genome from a seed mesh and write the mesh");
    add_config_option(cmd, options->config);
    auto* random = cmd->add_option("--random", options->random_seed, "Grow a random genome from this seed");
    auto* genome = cmd->add_option("--genome", options->genome, "Grow this genome file")->check(CLI::ExistingFile);
    random->excludes(genome);
    cmd->add_option("--steps", options->steps, "Override growth.steps")->check(CLI::Range(0, 1'000'000));
    cmd->add_option("-o,--output", options->output, "Output mesh (" + mesh_extensions() + ")")->required();
    auto* animate = cmd->add_option("--animate", options->animate,
                                    "Also write the growth as an animated glTF (.glb), one node per frame")
                        ->check([](const std::string& path) {
                            std::string ext = std::filesystem::path(path).extension().string();
                            for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
                            return ext == ".glb" ? std::string() : "must name a .glb file (binary glTF)";
                        });
    auto* frames_obj = cmd->add_option("--frames-obj", options->frames_obj,
                                       "Also write the growth's frames as DIR/frame_NNNN.obj");
    auto* frames = cmd->add_option("--frames", options->frames,
                                   "Frames of --animate/--frames-obj: the seed, evenly spaced steps, the final mesh "
                                   "(default: 50, at most steps + 1)")
                       ->check(CLI::Range(1, kMaxAnimationFrames));
    auto* frame_seconds = cmd->add_option("--frame-seconds", options->frame_seconds,
                                          "Seconds each --animate frame shows (default 0.1)");
    cmd->add_option("--save-genome", options->save_genome, "Also write the genome as JSON");
    cmd->add_flag("--ply-double", options->mesh_options.ply_double,
                  "PLY output: 64-bit coordinates and normals (exact) instead of float32 (what WebGL viewers draw)");
    add_plant_export_options(cmd, options->plant);
    add_resource_options(cmd, options->resources);
    select_on_pick(cmd, selected, options, run_grow, [options, random, genome, animate, frames_obj, frames, frame_seconds] {
        check_plant_export_options(options->plant, options->output);
        if (random->count() + genome->count() != 1)
            throw CLI::RequiredError("grow needs one of --random SEED or --genome FILE");
        if (frames->count() > 0 && animate->count() + frames_obj->count() == 0)
            throw CLI::ValidationError("--frames", "needs --animate or --frames-obj");
        if (frame_seconds->count() > 0 && animate->count() == 0)
            throw CLI::ValidationError("--frame-seconds", "needs --animate");
        // Here, not CLI::Range: a range check lets NaN through.
        if (!(options->frame_seconds >= kMinSecondsPerFrame && options->frame_seconds <= kMaxSecondsPerFrame))
            throw CLI::ValidationError("--frame-seconds", "must be between 0.001 and 60");
    });
}

}  // namespace morphogen
