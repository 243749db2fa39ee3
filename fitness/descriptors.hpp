#pragma once
// Named shape measures of a grown mesh for MAP-Elites descriptors
// (docs/fitness-measures.md "Descriptor measures" defines each exactly). Each is a
// pure function of the mesh and the canopy parameters of the run's fitness
// (Fitness::canopy_params), thread-safe. A measure may be non-finite for a
// degenerate mesh (e.g. slenderness of a zero footprint); a DescriptorSet
// refuses such a value, so descriptors that reach a search are finite.
#include "fitness/functions/canopy.hpp"
#include "core/mesh/mesh.hpp"

#include <span>
#include <string>
#include <vector>

namespace morphogen {

struct DescriptorMeasure {
    const char* name;
    double (*measure)(MeshView mesh, const CanopyParams& canopy);
    const char* meaning;  // one line, for messages and docs
};

// Every measure, in documentation order.
std::span<const DescriptorMeasure> descriptor_measures();
std::vector<std::string> descriptor_measure_names();

// The measure called `name`; throws std::invalid_argument
// `unknown measure "heigth" (did you mean "height"?)` (the suggestion only
// when one is near enough), listing the known names otherwise.
const DescriptorMeasure& find_descriptor_measure(const std::string& name);

// The measures a config chose, evaluated in order on one mesh.
class DescriptorSet {
public:
    // Throws std::invalid_argument for an unknown name (as find_descriptor_measure).
    DescriptorSet(const std::vector<std::string>& names, CanopyParams canopy);
    // One value per name, in order, each finite. Throws std::invalid_argument
    // for a malformed mesh, one without vertices, or a measure that is not
    // finite on it ("non-finite descriptor 1 (spread = inf)"), naming the
    // measure; evolution's evaluate_safely guards any other Problem the same way.
    std::vector<double> operator()(MeshView mesh) const;
    const std::vector<std::string>& names() const { return names_; }

private:
    std::vector<std::string> names_;
    std::vector<const DescriptorMeasure*> measures_;
    CanopyParams canopy_;
};

// The measures that are not plain measures.hpp functions, for tests and reports.
double mesh_slenderness(MeshView mesh);
double mesh_crown_height(MeshView mesh, const CanopyParams& canopy);
double mesh_spread(MeshView mesh);
double mesh_lean(MeshView mesh);
double mesh_sphericity(MeshView mesh);

}  // namespace morphogen
