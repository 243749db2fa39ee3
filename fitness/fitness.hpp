#pragma once
// The fitness interface (pagmo2's `problem` lesson: checks in one place).
// A FitnessFunction scores a mesh (larger is better); Fitness wraps the one a
// config chose, checks that scores are finite, turns exceptions and
// non-finite values into an invalid outcome, applies
// `reject_self_intersecting`, guards functions that are not thread-safe, and
// counts evaluations. Each type states what scoring costs (add_cost) and
// the canopy parameters it uses, so nothing above reads its config section
// again. CGAL never appears in this header.
#include "core/base/config_reader.hpp"
#include "core/mesh/mesh.hpp"
#include "fitness/functions/canopy.hpp"
#include "fitness/cost.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace morphogen {

class FitnessFunction {
public:
    virtual ~FitnessFunction() = default;
    // The registry name ("canopy", "sum", ...).
    virtual std::string type() const = 0;
    // Score of a mesh; may throw. Need not be finite (the wrapper checks).
    virtual double evaluate(MeshView mesh) const = 0;
    // Whether evaluate() may run concurrently on one instance.
    virtual bool thread_safe() const { return true; }
    // The named parts the score is made of (for `morphogen score`: why a mesh
    // scores what it does), in a fixed order; empty for a type with no parts.
    // May throw what evaluate() throws.
    using Terms = std::vector<std::pair<std::string, double>>;
    virtual Terms terms(MeshView) const { return {}; }
    // Adds to `cost` the memory and time of scoring one mesh of `scope` and
    // the caps evaluate() enforces (fitness/cost.hpp). Every type states its
    // own: the resource estimate knows no type by name.
    virtual void add_cost(FitnessCost& cost, const CostScope& scope) const = 0;
    // The canopy parameters it scores with: a canopy's own, a sum's first
    // canopy term's (depth first); none for a type without a canopy.
    virtual std::optional<CanopyParams> canopy() const { return std::nullopt; }
};

struct FitnessOutcome {
    double score = 0.0;  // finite when valid
    bool valid = false;
    std::string error;   // why it is invalid (empty when valid)
};

class Fitness {
public:
    // Throws std::invalid_argument if `function` is null.
    Fitness(std::unique_ptr<FitnessFunction> function, bool reject_self_intersecting);
    // Never throws; safe to call from many threads at once (a function that
    // is not thread_safe() runs under a mutex). Invalid when the mesh view is
    // malformed (index out of range, non-finite coordinate), the function
    // throws or returns a non-finite score, or, with reject_self_intersecting,
    // the mesh self-intersects. Every call counts as an evaluation.
    FitnessOutcome evaluate(MeshView mesh) const noexcept;
    std::uint64_t evaluations() const { return evaluations_.load(); }
    const FitnessFunction& function() const { return *function_; }
    bool reject_self_intersecting() const { return reject_self_intersecting_; }
    // The function's cost and, with reject_self_intersecting, the test
    // (blamed on <scope.path>.reject_self_intersecting).
    void add_cost(FitnessCost& cost, const CostScope& scope) const;
    // The canopy parameters of the function, else the defaults (height 10,
    // cell 0.1): the canopy that descriptors and metrics measure.
    CanopyParams canopy_params() const { return function_->canopy().value_or(CanopyParams{}); }

private:
    std::unique_ptr<FitnessFunction> function_;
    bool reject_self_intersecting_;
    mutable std::mutex mutex_;  // used only when !function_->thread_safe()
    mutable std::atomic<std::uint64_t> evaluations_{0};
};

// Builds the fitness of a `fitness` config section. `reader` is positioned on
// the section (may be absent: the default is canopy, height 10, cell 0.1);
// every problem is added to reader.issues() with its key path, defaults are
// recorded in reader.resolved(), and reader.finish() is called. Returns null
// only when there were issues.
std::unique_ptr<Fitness> read_fitness(ObjectReader& reader);

// A type a config may name: its name and how it reads its own keys from a
// fitness section or a sum term (ObjectReader: every issue with its key path;
// null when its keys have issues; reader.finish() is not its job).
struct FitnessType {
    std::string name;
    std::function<std::unique_ptr<FitnessFunction>(ObjectReader&)> read;
};
// Adds a type after the built-in ones (docs/writing-a-fitness.md). Call it before
// any config is read (it is not synchronised with reading). Throws
// std::invalid_argument for an empty name, a name already taken or no reader.
void register_fitness_type(FitnessType type);

// The registry: every `type` a config may name, in documentation order, then
// the registered ones in the order registered.
std::vector<std::string> fitness_type_names();
// Reads `type` and that type's own keys from `reader` (a fitness section or a
// sum term) and builds the function; does not call reader.finish(). Returns
// null when the type is unknown or its keys have issues.
std::unique_ptr<FitnessFunction> read_fitness_function(ObjectReader& reader);

// Every metric of a mesh, for reports: canopy (with `canopy`), height,
// footprint, area, volume, vertices, faces (numbers) and self_intersecting
// (bool). Throws std::invalid_argument for a malformed view or no vertices.
nlohmann::json mesh_metrics(MeshView mesh, const CanopyParams& canopy = {});

}  // namespace morphogen
