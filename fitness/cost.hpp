#pragma once
// What scoring one mesh costs, stated by each fitness type
// (FitnessFunction::add_cost), so that the resource estimate
// (run/limits/resource_estimate.hpp) costs every type, one added later
// included, by what the type says, and never by a guess from its name.
//
// Contract: a cost is an upper bound for the largest mesh a config allows
// (CostScope). Memory is in bytes of this build's data structures and work in
// seconds of one core of the development machine, both measured (the
// constants in cost.cpp; docs/limits.md). The building blocks below are what
// the built-in types are made of; a new type uses them or states its own
// numbers.
#include "core/mesh/mesh.hpp"
#include "fitness/functions/canopy.hpp"
#include "fitness/functions/light.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace morphogen {

// One contribution to an estimate, with the config keys that decide it.
struct CostPart {
    std::string what;               // e.g. "canopy grid of up to 1,024 cells (fitness)"
    std::vector<std::string> keys;  // config key paths, most responsible first
    double amount = 0;              // bytes or seconds
};

// A bound the fitness code enforces itself while scoring (a plant beyond it
// scores invalid): the estimate refuses a config that could pass it.
struct CostCap {
    std::string what;  // e.g. "light rays per sun (fitness.spacing 0.1 over a plant up to 21 wide)"
    std::vector<std::string> keys;
    double needed = 0, cap = 0;
};

// The largest mesh a fitness section is costed for.
struct CostScope {
    double faces = 0;                      // the most faces a mesh can have
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // the box every plant stays in
    std::vector<std::string> extent_keys;  // the config keys that decide the box
    std::string path = "fitness";          // key path of the section ("fitness.terms[1]")

    double width() const { return (hi - lo).norm(); }  // the box's diagonal
    // The scope of a sum's term i.
    CostScope term(std::size_t i) const;
};

// Memory and time of scoring one mesh.
struct FitnessCost {
    double bytes = 0;  // the most any part needs at once (parts run one after another)
    std::vector<CostPart> work;
    std::vector<CostCap> caps;

    void need_bytes(double b);  // bytes = max(bytes, b)
};

// A measure that walks the mesh `passes` times (height, area, the sections
// of a tree, ...): "<what>", blamed on <path>.type.
void add_measure_cost(FitnessCost& cost, const CostScope& scope, const std::string& what, double passes = 1);
// The self-intersection test of every face pair's candidates, blamed on
// `why_key` and growth.max_vertices.
void add_self_intersection_cost(FitnessCost& cost, double faces, const std::string& why_key);
// The canopy grid over the plant's box (canopy_max_cells is its cap).
void add_canopy_cost(FitnessCost& cost, const CanopyParams& params, const CostScope& scope);
// The rays of every sun over the plant's box, through an AABB tree of the
// plant (and its eight copies in a stand); light_max_rays_per_sun is its cap.
void add_light_cost(FitnessCost& cost, const LightParams& params, const CostScope& scope);

// 1234567 as "1,234,567"; a number that is not a whole one as "%.3g".
std::string group_digits(double n);

}  // namespace morphogen
