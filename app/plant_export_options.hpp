#pragma once
// The options that ask grow and archive for engine-ready GLBs
// (engine/plant_export.hpp, docs/game-engines.md):
//   --height M  scale the plant to M metres (default: a model unit is a metre)
//   --lods N    levels of detail LOD0 .. LOD(N-1) (engine/plant_lods.hpp)
//   --wind      the _WIND vertex attribute (engine/plant_wind.hpp)
//   --wind-preset NAME[,NAME]  also copies of it where engines read them
//               (color, uv, godot; repeatable; needs --wind)
//   --colour    COLOR_0 from growth history (engine/plant_colour.hpp)
//   --leaves [--leaf-size F] [--leaf-density D]  foliage cards (engine/leaf_cards.hpp)
//   --smooth N  LOD0 after N rounds of Loop subdivision (engine/plant_smooth.hpp)
// Header-only: app/ holds at most 15 source files.
#include "engine/plant_export.hpp"

#include <CLI/CLI.hpp>

#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace morphogen {

inline void add_plant_export_options(CLI::App* command, PlantExportOptions& options) {
    command->add_option("--height", options.height_m,
                        "Engine-ready GLB: origin at the foot, scaled to this many metres, 0.001 to 10000 (default: 1 unit = 1 m)");
    command->add_option("--lods", options.lods,
                        "Engine-ready GLB with N levels of detail (1..8), child nodes plant_<id>_LOD0.., "
                        "each about half the triangles of the one before")
        ->check(CLI::Range(1, kMaxPlantLods));
    command->add_flag("--wind", options.wind,
                      "Engine-ready GLB with wind data: the _WIND vertex attribute (bend, flutter, phase, stiffness)");
    command->add_flag("--colour", options.colour,
                      "Engine-ready GLB with vertex colours from growth history and the genome's hue "
                      "(COLOR_0, docs/algorithm.md section 13); the material turns white");
    command->add_flag("--leaves", options.leaves,
                      "Engine-ready GLB with foliage cards at the exposed young vertices: a second primitive "
                      "with the leaf material (alpha mask, two-sided, an embedded leaf texture)");
    command->add_option("--leaf-size", options.leaf_size,
                        "With --leaves: each card's length as a fraction of the plant's height, above 0 and at most 0.5 "
                        "(default 0.06)");
    command->add_option("--leaf-density", options.leaf_density,
                        "With --leaves: the fraction of eligible vertices that carry a card, above 0 and at most 1 "
                        "(default 0.5; cards keep half a card's length apart)");
    command->add_option("--smooth", options.smooth,
                        "Engine-ready GLB whose LOD0 is smoothed by N rounds of Loop subdivision, 0 to 3 "
                        "(4^N x its triangles; colours and wind data blend with it)");
    command
        ->add_option_function<std::vector<std::string>>(
            "--wind-preset",
            [&options](const std::vector<std::string>& names) {
                for (const std::string& name : names) {
                    const std::optional<WindPreset> preset = wind_preset_named(name);
                    if (!preset)
                        throw CLI::ValidationError("--wind-preset '" + name +
                                                   "': not a preset; the presets are color, uv and godot");
                    options.wind_presets.push_back(*preset);
                }
            },
            "With --wind, also copy the wind data where engines read it: color (COLOR_0, CryEngine's channels; "
            "tints viewers), uv (TEXCOORD_0 and _1: UV channels 0 and 1), godot (_CUSTOM0); repeatable or a "
            "comma list")
        ->delimiter(',')
        ->type_name("NAME");
}

// Throws CLI::ValidationError (exit 2) naming the option for a bad value, or
// when the options ask for an engine-ready GLB and `glb_path` (the output the
// command writes them to; "" when it writes GLBs anyway) is not a .glb file.
inline void check_plant_export_options(const PlantExportOptions& options, const std::string& glb_path) {
    if (const std::string problem = plant_export_problem(options); !problem.empty())
        throw CLI::ValidationError(problem);
    if (!options.engine_ready() || glb_path.empty()) return;
    std::string ext = std::filesystem::path(glb_path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".glb") {
        const char* option = options.lods > 0 ? "--lods" : options.wind ? "--wind" : options.leaves ? "--leaves"
                             : options.smooth != 0 ? "--smooth" : options.colour ? "--colour" : "--height";
        throw CLI::ValidationError(std::string(option) + ": writes an engine-ready GLB, so the output must be .glb, not '" +
                                   glb_path + "'");
    }
}

}  // namespace morphogen
