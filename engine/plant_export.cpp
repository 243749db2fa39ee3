#include "engine/plant_export.hpp"

#include "base/atomic_file.hpp"
#include "base/errors.hpp"
#include "engine/plant_frame.hpp"
#include "engine/plant_lods.hpp"
#include "engine/plant_wind.hpp"
#include "io/plant_glb.hpp"

#include <cmath>
#include <sstream>

namespace morphogen {

namespace {
std::string shortest(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}
}  // namespace

std::string plant_export_problem(const PlantExportOptions& options) {
    if (options.height_m && !(*options.height_m > 0 && *options.height_m <= kMaxPlantHeightMetres))
        return "--height " + shortest(*options.height_m) + ": must be a number of metres in (0, 10000]";
    if (options.lods < 0 || options.lods > kMaxPlantLods)
        return "--lods " + std::to_string(options.lods) + ": must be between 1 and " + std::to_string(kMaxPlantLods);
    return {};
}

std::string plant_glb_bytes(const GrownPlant& plant, const PlantRecord& record, const PlantExportOptions& options,
                            const std::string& source) {
    if (const std::string problem = plant_export_problem(options); !problem.empty()) throw ConfigError(problem);
    const PlacedPlant placed = place_plant(plant.mesh, options.height_m);

    nlohmann::json extras = record_json(record);
    extras["generator"] = "morphogen";
    extras["height_m"] = placed.height_m;
    extras["metres_per_unit"] = placed.metres_per_unit;
    if (options.wind) extras["wind"] = "_WIND";
    std::vector<float> wind;
    if (options.wind) wind = plant_wind(placed.mesh.view(), plant.birth_steps, plant.steps);
    PlantGlb glb{.name = "plant_" + record.id, .extras = std::move(extras), .levels = {}, .lod_nodes = options.lods > 0};
    if (options.lods == 0) {
        glb.levels.push_back(PlantLevel{.mesh = placed.mesh.view(), .wind = std::move(wind), .extras = {}});
        return plant_glb_bytes(glb, source);
    }
    // The levels must outlive glb, which only views them.
    const std::vector<MeshArrays> levels = simplify_lods(placed.mesh.view(), options.lods);
    for (const MeshArrays& level : levels) {
        std::vector<float> level_wind;
        if (options.wind)
            level_wind = glb.levels.empty() ? wind : transfer_wind(placed.mesh.view(), wind, level.view());
        glb.levels.push_back(PlantLevel{.mesh = level.view(),
                                        .wind = std::move(level_wind),
                                        .extras = {{"triangles", level.faces.size()}}});
    }
    return plant_glb_bytes(glb, source);
}

void write_plant_glb(const std::filesystem::path& out, const GrownPlant& plant, const PlantRecord& record,
                     const PlantExportOptions& options) {
    write_file_atomically(out, plant_glb_bytes(plant, record, options, out.string()));
}

}  // namespace morphogen
