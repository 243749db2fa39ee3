#pragma once
// The fitness interface (pagmo2's `problem` lesson: checks in one place).
// A FitnessFunction scores a mesh (larger is better); Fitness wraps the one a
// config chose, checks that scores are finite, turns exceptions and
// non-finite values into an invalid outcome, applies
// `reject_self_intersecting`, guards functions that are not thread-safe, and
// counts evaluations. CGAL never appears in this header.
#include "core/base/config_reader.hpp"
#include "fitness/canopy.hpp"
#include "core/mesh/mesh.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
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

// The registry: every `type` a config may name, in documentation order.
std::vector<std::string> fitness_type_names();
// Reads `type` and that type's own keys from `reader` (a fitness section or a
// sum term) and builds the function; does not call reader.finish(). Returns
// null when the type is unknown or its keys have issues.
std::unique_ptr<FitnessFunction> read_fitness_function(ObjectReader& reader);

// The canopy parameters a resolved fitness section uses: those of the section
// itself if its type is canopy, else of its first canopy term (depth first),
// else the defaults (height 10, cell 0.1).
CanopyParams canopy_params_of(const nlohmann::json& resolved_fitness);

// Every metric of a mesh, for reports: canopy (with `canopy`), height,
// footprint, area, volume, vertices, faces (numbers) and self_intersecting
// (bool). Throws std::invalid_argument for a malformed view or no vertices.
nlohmann::json mesh_metrics(MeshView mesh, const CanopyParams& canopy = {});

}  // namespace morphogen
