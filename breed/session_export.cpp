// Export of a BreedSession's plant (breed/session.hpp): its genome, an
// engine-ready GLB and an OBJ in exports/.
#include "breed/session.hpp"

#include "breed/breed_errors.hpp"
#include "engine/plant_record.hpp"
#include "run/exports/plant_exports.hpp"

#include <charconv>

namespace morphogen {

namespace {

std::uint64_t plant_number(const std::string& id) {
    std::uint64_t n = 0;
    std::from_chars(id.data() + 1, id.data() + id.size(), n);
    return n;
}

}  // namespace

std::pair<std::string, std::string> BreedSession::export_plant(const std::string& id,
                                                              const PlantExportOptions& options) {
    std::lock_guard lock(mutex_);
    const BreedPlant& p = plant(id);
    if (const std::string problem = plant_export_problem(options); !problem.empty()) throw bad_request(problem);
    PlantRecord record;
    record.id = id;
    record.genome_hash = genome_hash(p.params);
    record.fitness = p.fitness;
    for (const auto& [name, value] : p.measures) record.measures.emplace_back(name, value);
    record.run = name();
    record.birth = plant_number(id);
    for (const std::string& parent : p.parents) record.parents.push_back(plant_number(parent));
    export_engine_plant(growth_.grower(), p.params, record, options, dir_ / "exports" / id);
    return {"exports/" + id + ".genome.json", "exports/" + id + ".glb"};
}

}  // namespace morphogen
