// The registry of fitness functions by name: each entry reads and checks its
// own keys (ObjectReader, so every issue names its key path) and builds the
// function, which states its own cost. A built-in function is one class and
// one row of kTypes; one from elsewhere is registered (register_fitness_type).
#include "fitness/fitness.hpp"

#include "fitness/functions/canopy.hpp"
#include "fitness/geometry/cgal_geometry.hpp"
#include "fitness/functions/light.hpp"
#include "fitness/measures.hpp"
#include "fitness/functions/plant_fitness.hpp"
#include "fitness/functions/tree_fitness.hpp"
#include "fitness/architecture/tree_sections.hpp"

#include <stdexcept>
#include <utility>

namespace morphogen {

using nlohmann::json;

namespace {

constexpr double kBig = 1e12;  // bounds of "any" number, readable in messages

class CanopyFunction final : public FitnessFunction {
public:
    explicit CanopyFunction(CanopyParams params) : params_(params) {}
    std::string type() const override { return "canopy"; }
    double evaluate(MeshView mesh) const override { return canopy_area(mesh, params_); }
    void add_cost(FitnessCost& cost, const CostScope& scope) const override { add_canopy_cost(cost, params_, scope); }
    std::optional<CanopyParams> canopy() const override { return params_; }

private:
    CanopyParams params_;
};

class LightFunction final : public FitnessFunction {
public:
    explicit LightFunction(LightParams params) : params_(std::move(params)) {}
    std::string type() const override { return "light"; }
    double evaluate(MeshView mesh) const override { return light_captured(mesh, params_); }
    void add_cost(FitnessCost& cost, const CostScope& scope) const override { add_light_cost(cost, params_, scope); }

private:
    LightParams params_;
};

class TreeFunction final : public FitnessFunction {
public:
    explicit TreeFunction(TreeFitnessParams params) : params_(std::move(params)) {}
    std::string type() const override { return "tree"; }
    double evaluate(MeshView mesh) const override { return tree_score(mesh, params_).score; }
    // The rays of its light, and the sections and the volume as cheap as a measure.
    void add_cost(FitnessCost& cost, const CostScope& scope) const override {
        add_measure_cost(cost, scope, "tree sections and volume", 2);
        add_light_cost(cost, params_.light, scope);
    }

private:
    TreeFitnessParams params_;
};

class PlantFunction final : public FitnessFunction {
public:
    explicit PlantFunction(PlantFitnessParams params) : params_(std::move(params)) {}
    std::string type() const override { return "plant"; }
    double evaluate(MeshView mesh) const override { return plant_score(mesh, params_).score; }
    // The rays of its light, and the skeleton and the moment as cheap as a measure.
    void add_cost(FitnessCost& cost, const CostScope& scope) const override {
        add_measure_cost(cost, scope, "plant skeleton and moment", 2);
        add_light_cost(cost, params_.light, scope);
    }
    Terms terms(MeshView mesh) const override {
        const PlantScore s = plant_score(mesh, params_);
        return {{"light", s.light},     {"reproduction", s.reproduction}, {"tips", s.tips},
                {"bearing_tips", s.bearing_tips}, {"moment", s.moment},     {"volume", s.volume},
                {"cost", s.cost}};
    }

private:
    PlantFitnessParams params_;
};

// A measure without keys (height, area, ...).
class MeasureFunction final : public FitnessFunction {
public:
    using Measure = double (*)(MeshView);
    MeasureFunction(std::string name, Measure measure) : name_(std::move(name)), measure_(measure) {}
    std::string type() const override { return name_; }
    double evaluate(MeshView mesh) const override { return measure_(mesh); }
    void add_cost(FitnessCost& cost, const CostScope& scope) const override {
        add_measure_cost(cost, scope, name_ + " of the mesh");
    }

private:
    std::string name_;
    Measure measure_;
};

// 1 if the mesh self-intersects: a measure that costs a self-intersection test.
class SelfIntersectingFunction final : public FitnessFunction {
public:
    std::string type() const override { return "self_intersecting"; }
    double evaluate(MeshView mesh) const override { return mesh_self_intersects(mesh) ? 1.0 : 0.0; }
    void add_cost(FitnessCost& cost, const CostScope& scope) const override {
        add_self_intersection_cost(cost, scope.faces, scope.path + ".type");
    }
};

class SumFunction final : public FitnessFunction {
public:
    using Term = std::pair<double, std::unique_ptr<FitnessFunction>>;  // weight, function
    explicit SumFunction(std::vector<Term> terms) : terms_(std::move(terms)) {}
    std::string type() const override { return "sum"; }
    double evaluate(MeshView mesh) const override {
        double sum = 0.0;
        for (const auto& [weight, function] : terms_) sum += weight * function->evaluate(mesh);
        return sum;
    }
    bool thread_safe() const override {
        for (const auto& term : terms_)
            if (!term.second->thread_safe()) return false;
        return true;
    }
    void add_cost(FitnessCost& cost, const CostScope& scope) const override {
        for (std::size_t i = 0; i < terms_.size(); ++i) terms_[i].second->add_cost(cost, scope.term(i));
    }
    std::optional<CanopyParams> canopy() const override {
        for (const auto& term : terms_)
            if (auto found = term.second->canopy()) return found;
        return std::nullopt;
    }

private:
    std::vector<Term> terms_;
};

std::unique_ptr<FitnessFunction> read_canopy(ObjectReader& reader) {
    CanopyParams params;
    params.height = reader.number("height", params.height, -kBig, kBig);
    params.cell = reader.number("cell", params.cell, 0.0, kBig, /*min_exclusive=*/true);
    return std::make_unique<CanopyFunction>(params);
}

// The keys of `light`, shared by `tree`; `params` holds the defaults.
void read_light_params(ObjectReader& reader, LightParams& params) {
    params.elevations_deg = reader.number_list("elevations_deg", params.elevations_deg, 0.0, 90.0);
    params.azimuths_deg = reader.number_list("azimuths_deg", params.azimuths_deg, -360.0, 360.0);
    params.spacing = reader.number("spacing", params.spacing, 0.0, kBig, /*min_exclusive=*/true);
    params.min_height = reader.number("min_height", params.min_height, -kBig, kBig);
    params.stand_spacing = reader.number("stand_spacing", params.stand_spacing, 0.0, kBig);
    const std::string elevations = reader.path_of("elevations_deg");
    if (params.elevations_deg.empty()) reader.issues().add(elevations, "needs at least one sun elevation");
    for (std::size_t i = 0; i < params.elevations_deg.size(); ++i)
        if (params.elevations_deg[i] == 0.0)
            reader.issues().add(elevations + "[" + std::to_string(i) + "]", "0 is out of range (0, 90]");
    bool needs_azimuth = false;
    for (double e : params.elevations_deg) needs_azimuth |= e != 90.0;
    if (needs_azimuth && params.azimuths_deg.empty())
        reader.issues().add(reader.path_of("azimuths_deg"), "needs at least one azimuth for elevations below 90");
}

std::unique_ptr<FitnessFunction> read_light(ObjectReader& reader) {
    LightParams params;
    read_light_params(reader, params);
    return std::make_unique<LightFunction>(std::move(params));
}

std::unique_ptr<FitnessFunction> read_tree(ObjectReader& reader) {
    TreeFitnessParams params;
    read_light_params(reader, params.light);
    params.trunk_target = reader.number("trunk_target", params.trunk_target, 0.0, kBig, /*min_exclusive=*/true);
    params.trunk_power = reader.number("trunk_power", params.trunk_power, 1.0, 10.0);
    params.loops_target = static_cast<int>(reader.integer("loops_target", params.loops_target, 1, 1000));
    params.material_cost = reader.number("material_cost", params.material_cost, 0.0, kBig);
    params.root_height = reader.number("root_height", params.root_height, -kBig, kBig);
    return std::make_unique<TreeFunction>(std::move(params));
}

std::unique_ptr<FitnessFunction> read_plant(ObjectReader& reader) {
    PlantFitnessParams params;
    read_light_params(reader, params.light);
    params.half_saturation = reader.number("half_saturation", params.half_saturation, 0.0, kBig, /*min_exclusive=*/true);
    params.leaf_size = reader.number("leaf_size", params.leaf_size, 0.0, kBig);
    params.moment_cost = reader.number("moment_cost", params.moment_cost, 0.0, kBig);
    params.volume_cost = reader.number("volume_cost", params.volume_cost, 0.0, kBig);
    params.root_height = reader.number("root_height", params.root_height, -kBig, kBig);
    params.shoot_radius = reader.number("shoot_radius", params.shoot_radius, 0.0, kBig, /*min_exclusive=*/true);
    params.shoot_half_light = reader.number("shoot_half_light", params.shoot_half_light, 0.0, kBig);
    params.architecture.skeleton.band_edges = reader.number("shoot_band_edges", params.architecture.skeleton.band_edges,
                                                            0.0, kBig, /*min_exclusive=*/true);
    return std::make_unique<PlantFunction>(std::move(params));
}

double vertex_count(MeshView mesh) { return static_cast<double>(mesh.positions.size()); }
double face_count(MeshView mesh) { return static_cast<double>(mesh.faces.size()); }
std::unique_ptr<FitnessFunction> read_self_intersecting(ObjectReader&) {
    return std::make_unique<SelfIntersectingFunction>();
}
double trunk_ratio(MeshView mesh) { return tree_sections(mesh).trunk_ratio; }
double upper_loops(MeshView mesh) { return static_cast<double>(tree_sections(mesh).upper_loops); }

std::unique_ptr<FitnessFunction> read_sum(ObjectReader& reader);

// A type is read either by `read` (its own keys) or, for a measure without
// keys, built from `measure`.
struct TypeEntry {
    const char* name;
    std::unique_ptr<FitnessFunction> (*read)(ObjectReader&);
    MeasureFunction::Measure measure;
};

const TypeEntry kTypes[] = {
    {"canopy", read_canopy, nullptr},
    {"light", read_light, nullptr},
    {"tree", read_tree, nullptr},
    {"plant", read_plant, nullptr},
    {"sum", read_sum, nullptr},
    {"height", nullptr, mesh_height},
    {"footprint", nullptr, mesh_footprint},
    {"area", nullptr, mesh_area},
    {"volume", nullptr, mesh_volume},
    {"vertices", nullptr, vertex_count},
    {"faces", nullptr, face_count},
    {"self_intersecting", read_self_intersecting, nullptr},
    {"trunk_ratio", nullptr, trunk_ratio},
    {"upper_loops", nullptr, upper_loops},
};

// The built-in types, then the registered ones.
std::vector<FitnessType>& types() {
    static std::vector<FitnessType> list = [] {
        std::vector<FitnessType> built_in;
        for (const TypeEntry& entry : kTypes) {
            if (entry.read) {
                built_in.push_back({entry.name, entry.read});
            } else {
                const std::string name = entry.name;
                const MeasureFunction::Measure measure = entry.measure;
                built_in.push_back({name, [name, measure](ObjectReader&) -> std::unique_ptr<FitnessFunction> {
                                        return std::make_unique<MeasureFunction>(name, measure);
                                    }});
            }
        }
        return built_in;
    }();
    return list;
}

struct ReadResult {
    std::unique_ptr<FitnessFunction> function;  // null if there were issues
    bool type_known = false;                     // false: the other keys were not checked
};

ReadResult read_typed(ObjectReader& reader) {
    ConfigIssues& issues = reader.issues();
    const std::size_t before = issues.list().size();
    const std::string type = reader.choice("type", "canopy", fitness_type_names());
    ReadResult result;
    if (issues.list().size() != before) return result;
    result.type_known = true;
    for (const FitnessType& entry : types()) {
        if (type == entry.name) {
            result.function = entry.read(reader);
            break;
        }
    }
    if (issues.list().size() != before) result.function.reset();
    return result;
}

std::unique_ptr<FitnessFunction> read_sum(ObjectReader& reader) {
    ConfigIssues& issues = reader.issues();
    const std::size_t before = issues.list().size();
    const std::string path = reader.path_of("terms");
    const json* terms = reader.raw("terms");
    json resolved_terms = json::array();
    std::vector<SumFunction::Term> built;
    if (terms == nullptr) {
        issues.add(path, "a sum needs \"terms\": a non-empty list of fitness objects");
    } else if (!terms->is_array() || terms->empty()) {
        issues.add(path, "expected a non-empty list of fitness objects, got " + terms->dump());
    } else {
        for (std::size_t i = 0; i < terms->size(); ++i) {
            ObjectReader term(&(*terms)[i], path + "[" + std::to_string(i) + "]", issues);
            const double weight = term.number("weight", 1.0, -kBig, kBig);
            ReadResult read = read_typed(term);
            if (read.type_known) term.finish();
            if (read.function) built.emplace_back(weight, std::move(read.function));
            resolved_terms.push_back(term.resolved());
        }
    }
    reader.set_resolved("terms", std::move(resolved_terms));
    if (issues.list().size() != before) return nullptr;
    return std::make_unique<SumFunction>(std::move(built));
}

}  // namespace

void register_fitness_type(FitnessType type) {
    if (type.name.empty()) throw std::invalid_argument("a fitness type needs a name");
    if (!type.read) throw std::invalid_argument("fitness type \"" + type.name + "\" needs a reader");
    for (const FitnessType& entry : types())
        if (entry.name == type.name) throw std::invalid_argument("fitness type \"" + type.name + "\" is already registered");
    types().push_back(std::move(type));
}

std::vector<std::string> fitness_type_names() {
    std::vector<std::string> names;
    for (const FitnessType& entry : types()) names.push_back(entry.name);
    return names;
}

std::unique_ptr<FitnessFunction> read_fitness_function(ObjectReader& reader) { return read_typed(reader).function; }

std::unique_ptr<Fitness> read_fitness(ObjectReader& reader) {
    const std::size_t before = reader.issues().list().size();
    const bool reject = reader.boolean("reject_self_intersecting", false);
    ReadResult read = read_typed(reader);
    if (read.type_known) reader.finish();
    if (reader.issues().list().size() != before || !read.function) return nullptr;
    return std::make_unique<Fitness>(std::move(read.function), reject);
}

}  // namespace morphogen
