// `morphogen archive RUN_DIR`: the elites of a MAP-Elites run, from its
// checkpoint: each as .glb + .obj + .genome.json with species.csv, and
// optionally the map of elites as a PNG (each occupied cell's plant at its
// place on the descriptor grid, beside a fitness heatmap). With --pack DIR,
// a species pack of a MAP-Elites or GA run instead (run/exports/run_pack.hpp).
#include "app/commands.hpp"
#include "app/plant_export_options.hpp"
#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "engine/plant_colour.hpp"
#include "report/render.hpp"
#include "run/persistence/checkpoint.hpp"
#include "run/searches/elites_search.hpp"
#include "run/config/experiment_config.hpp"
#include "run/growth_problem.hpp"
#include "run/exports/plant_exports.hpp"
#include "run/persistence/run_directory.hpp"
#include "run/exports/run_pack.hpp"
#include "run/exit_codes.hpp"
#include "run/loop/run_records.hpp"
#include "run/loop/stop_signals.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

namespace {

namespace fs = std::filesystem;

struct ArchiveOptions {
    std::string dir, out, png, pack;
    std::uint64_t top = 0;  // 0 = every elite
    int size = 96;          // pixels per map cell
    bool no_colour = false; // the map's plants in plain green
    PlantExportOptions plant;
};

using Elite = std::pair<std::uint64_t, const Individual*>;  // cell, elite

// The N fittest (ties: the lower cell), or all; in cell order.
std::vector<Elite> chosen_elites(const Archive& archive, std::uint64_t top) {
    std::vector<Elite> elites;
    for (const auto& [cell, elite] : archive.elites()) elites.emplace_back(cell, &elite);
    if (top > 0 && top < elites.size()) {
        std::stable_sort(elites.begin(), elites.end(),
                         [](const Elite& a, const Elite& b) { return a.second->fitness > b.second->fitness; });
        elites.resize(top);
        std::sort(elites.begin(), elites.end(), [](const Elite& a, const Elite& b) { return a.first < b.first; });
    }
    return elites;
}

std::string short_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// Blue (low) to yellow (high), through green.
void heat_colour(double t, std::uint8_t* p) {
    t = std::clamp(t, 0.0, 1.0);
    p[0] = static_cast<std::uint8_t>(40 + 215 * t * t);
    p[1] = static_cast<std::uint8_t>(50 + 180 * t);
    p[2] = static_cast<std::uint8_t>(150 * (1 - t) + 30);
}

// The map of elites of a grid archive: the first descriptor up the y axis,
// the second (if any) along x; with a third, each (x, y) shows the fittest
// elite over it. Plants are framed one by one (each fills its cell).
void write_map(const Archive& archive, const std::vector<Elite>& elites, const GenomeGrower& grower, int size,
               bool colour, const std::string& path) {
    const auto& ranges = archive.ranges();
    const int rows = ranges[0].bins;
    const int cols = ranges.size() >= 2 ? ranges[1].bins : 1;
    std::map<std::pair<int, int>, const Individual*> shown;
    for (const auto& [cell, elite] : elites) {
        const std::vector<std::uint64_t> bins = archive.bins_of(elite->descriptors);
        const std::pair<int, int> at{static_cast<int>(bins[0]), ranges.size() >= 2 ? static_cast<int>(bins[1]) : 0};
        auto it = shown.find(at);
        if (it == shown.end() || elite->fitness > it->second->fitness) shown[at] = elite;
    }
    double lo = 0, hi = 1;
    if (!shown.empty()) {
        lo = hi = shown.begin()->second->fitness;
        for (const auto& [at, e] : shown) lo = std::min(lo, e->fitness), hi = std::max(hi, e->fitness);
    }
    const int left = 110, top = 30, bottom = 60, gap = 80;
    const int panel_w = cols * size, panel_h = rows * size;
    Image image(left + 2 * panel_w + gap + 20, top + panel_h + bottom);
    RenderOptions options;
    options.size = size;
    for (const auto& [at, elite] : shown) {
        const int x0 = left + at.second * size, y0 = top + (rows - 1 - at.first) * size;
        const DatedGrowth grown = grow_dated(grower, elite->params);
        const std::vector<float> colours =
            colour ? growth_colours(grown.state, grown.birth_steps, grower.params()) : std::vector<float>{};
        const Image picture = render_mesh(grown.state.mesh.view(), options, colours);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) std::copy_n(picture.pixel(x, y), 3, image.pixel(x0 + x, y0 + y));
        const double t = hi > lo ? (elite->fitness - lo) / (hi - lo) : 1.0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) heat_colour(t, image.pixel(x0 + panel_w + gap + x, y0 + y));
    }
    // grid lines, empty heatmap cells grey
    for (int panel = 0; panel < 2; ++panel) {
        const int px = left + panel * (panel_w + gap);
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < cols; ++c)
                if (panel == 1 && !shown.count({rows - 1 - r, c}))
                    for (int y = 0; y < size; ++y)
                        for (int x = 0; x < size; ++x) {
                            std::uint8_t* p = image.pixel(px + c * size + x, top + r * size + y);
                            p[0] = p[1] = p[2] = 225;
                        }
        for (int r = 0; r <= rows; ++r)
            for (int x = 0; x < panel_w; ++x) {
                std::uint8_t* p = image.pixel(px + x, std::min(top + r * size, top + panel_h - 1));
                p[0] = p[1] = p[2] = 190;
            }
        for (int c = 0; c <= cols; ++c)
            for (int y = 0; y < panel_h; ++y) {
                std::uint8_t* p = image.pixel(std::min(px + c * size, px + panel_w - 1), top + y);
                p[0] = p[1] = p[2] = 190;
            }
        // axes: the first descriptor's range up the left, the second's along the bottom
        draw_label(image, px - label_width(short_number(ranges[0].max), 2) - 4, top, short_number(ranges[0].max), 2, 40);
        draw_label(image, px - label_width(short_number(ranges[0].min), 2) - 4, top + panel_h - 14,
                   short_number(ranges[0].min), 2, 40);
        if (panel == 0) draw_label(image, 4, top + panel_h / 2, ranges[0].name, 2, 0);
        if (ranges.size() >= 2) {
            draw_label(image, px, top + panel_h + 4, short_number(ranges[1].min), 2, 40);
            draw_label(image, px + panel_w - label_width(short_number(ranges[1].max), 2), top + panel_h + 4,
                       short_number(ranges[1].max), 2, 40);
            draw_label(image, px + panel_w / 2 - label_width(ranges[1].name, 2) / 2, top + panel_h + 30, ranges[1].name,
                       2, 0);
        }
    }
    draw_label(image, left, 8, "elites (" + std::to_string(shown.size()) + " cells)", 2, 0);
    draw_label(image, left + panel_w + gap, 8, "fitness " + short_number(lo) + " (blue) .. " + short_number(hi) + " (yellow)",
               2, 0);
    write_png(image, path);
}

int run_archive(const ArchiveOptions& o) {
    StopSignals signals;  // first: Ctrl-C/SIGTERM stop it between plants, exit 130
    const RunPaths paths = run_paths(o.dir);
    if (!fs::is_directory(paths.dir)) throw IoError("run directory " + o.dir + " does not exist");
    const RunState state = load_checkpoint(paths.checkpoint);
    const ExperimentConfig config = read_experiment_config(state.config, paths.checkpoint.string());
    if (!o.pack.empty()) {
        const GrowthProblem problem(config);
        const std::optional<std::size_t> species =
            write_run_pack(config, *state.search, problem.grower(), o.plant, o.top, o.pack);
        if (!species) {
            std::cerr << "morphogen: stopped by signal " << StopSignals::signal_number() << "; the pack's files were "
                      << "removed, nothing else changed. Write it with the same command again\n";
            return exit_code::interrupted;
        }
        std::cout << "wrote a pack of " << *species << " species to " << o.pack << " (manifest.json, scatter.glb)\n";
        return 0;
    }
    const MapElitesState* run_elites = elites_state(*state.search);
    if (run_elites == nullptr)
        throw ConfigError(o.dir + ": not a MAP-Elites run (evolution.algorithm is \"steady_state\"; its best meshes "
                                  "are in best/, and --pack DIR packs its population)");
    const Archive& archive = run_elites->archive;
    if (!o.png.empty() && archive.kind() != ArchiveKind::grid)
        throw ConfigError("--png: the map of elites is drawn for grid archives; this run's archive is a CVT");
    const GrowthProblem problem(config);
    const std::vector<Elite> elites = chosen_elites(archive, o.top);

    const fs::path out = o.out.empty() ? paths.dir / "elites" : fs::path(o.out);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw IoError(out.string() + ": cannot create: " + ec.message());
    const std::size_t digits = std::to_string(archive.cells() > 0 ? archive.cells() - 1 : 0).size();
    std::string species = "cell,";
    std::vector<std::string> measure_names;
    for (const DescriptorRange& range : archive.ranges()) species += range.name + ',', measure_names.push_back(range.name);
    species += "fitness,file\n";
    for (const auto& [cell, elite] : elites) {
        if (StopSignals::requested()) {
            std::cerr << "morphogen: stopped by signal " << StopSignals::signal_number() << "; " << out.string()
                      << " holds some elites and no species.csv. Write them with the same command again\n";
            return exit_code::interrupted;
        }
        std::string stem = std::to_string(cell);
        stem = "cell_" + std::string(digits - stem.size(), '0') + stem;
        if (o.plant.engine_ready() || o.plant.colour)  // elites are GLBs: --colour alone makes them coloured
            export_engine_plant(problem.grower(), elite->params, birth_record(config, *elite, measure_names, cell),
                                o.plant, out / stem);
        else
            problem.export_genome(elite->params, out / stem);
        species += std::to_string(cell) + ',';
        for (double d : elite->descriptors) species += format_number(d) + ',';
        species += format_number(elite->fitness) + ',' + stem + ".glb\n";
    }
    write_file_atomically(out / "species.csv", species);
    std::cout << "wrote " << elites.size() << " of " << archive.occupied() << " elites to " << out.string()
              << " (species.csv)\n";
    if (!o.png.empty()) {
        write_map(archive, elites, problem.grower(), o.size, !o.no_colour, o.png);
        std::cout << "wrote the map of elites to " << o.png << "\n";
    }
    return 0;
}

}  // namespace

void add_archive_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<ArchiveOptions>();
    CLI::App* cmd =
        root.add_subcommand("archive", "Export the elites of a MAP-Elites run (and draw its map), or a run's species pack");
    cmd->add_option("dir", options->dir, "run directory")->required();
    cmd->add_option("--out", options->out, "where to write the elites (default RUN_DIR/elites)");
    cmd->add_option("--top", options->top, "only the N fittest elites (0 = all)");
    cmd->add_option("--png", options->png, "draw the map of elites (grid archives) to this PNG file");
    cmd->add_option("--size", options->size, "pixels per map cell")->check(CLI::Range(32, 512));
    cmd->add_flag("--no-colour", options->no_colour,
                  "draw the map's plants in plain green, not in colours from growth history");
    cmd->add_option("--pack", options->pack,
                    "Write a species pack to this new directory instead: plant_<id>.glb per species (with "
                    "--height/--lods/--wind), manifest.json and scatter.glb; MAP-Elites runs' elites or GA runs' "
                    "population")
        ->excludes("--out")
        ->excludes("--png");
    add_plant_export_options(cmd, options->plant);
    select_on_pick(cmd, selected, options, run_archive, [options] { check_plant_export_options(options->plant, ""); });
}

}  // namespace morphogen
