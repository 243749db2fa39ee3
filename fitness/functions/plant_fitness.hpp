#pragma once
// The `plant` fitness (docs/fitness-plant.md "plant"): Niklas's simulated plant
// evolution (Niklas 1994, "Morphological evolution through complex domains of
// fitness", PNAS 91:6772), in which a plant must catch light, hold its
// reproductive tips high for dispersal, and pay for the mechanics of holding
// its body up. Scored as Niklas combines the tasks:
//
//   plant = sqrt(light · reproduction) / cost
//   light        = Σ_f area_f · (1 + K) · I_f / (I_f + K)      I_f = Σ_leaf light / Σ_leaf area
//   reproduction = Σ_tips (z_tip − z_min) · S_t / (S_t + H)
//   cost         = 1 + moment_cost · Σ_f area_f · r_f + volume_cost · V
//
// light_f is what face f catches of the suns (light_per_face, so the plant
// shades itself); the rectangular hyperbola is a leaf's light response:
// a face in full sun (I_f ≈ 1) yields its area, and more sun gains nothing
// more, so spreading the same light over more surface pays (K the relative
// irradiance at which a face yields half; K → ∞ gives the plain light).
// I_f is the mean irradiance of the face's leaf (the faces whose centroids
// share a cube of side leaf_size), not of the face alone: a face smaller
// than a ray's cross-section is hit by one ray or none, and the hyperbola,
// concave, undercounts such a sampled irradiance (a surface of 0.02-unit²
// faces caught a quarter of its light at the rays' spacing 0.25).
// Tips are the skeleton's (fitness/architecture/architecture.hpp). S_t is the tip's own
// light: the saturating light of the faces whose centroid is nearer to tip t
// than to any other tip and within shoot_radius of it (a shoot feeds its
// fruit from its own leaves: branch autonomy, Sprugel et al. 1991), so a tip
// in shade, or crowded among others, bears little; H = shoot_half_light is
// the light at which a tip bears half (H = 0: every tip bears in full, as
// before). r_f is the horizontal
// distance of face f's centroid from the foot's axis, so Σ area·r is the
// bending moment of a surface of even weight about the foot; V is the enclosed
// volume (the wood a solid body costs to build). A plant whose
// lowest vertex is above root_height floats, and scores 0.
#include "fitness/architecture/architecture.hpp"
#include "fitness/functions/light.hpp"
#include "core/mesh/mesh.hpp"

namespace morphogen {

struct PlantFitnessParams {
    LightParams light;            // the `light` keys and defaults
    double half_saturation = 0.25;  // K, > 0
    double leaf_size = 1.0;         // side of the cubes whose faces saturate together, >= 0 (0: each face alone)
    double moment_cost = 0.0002;   // per unit of area × lever arm, >= 0
    double volume_cost = 0.0;      // per unit of enclosed volume, >= 0
    double root_height = 0.1;     // the lowest vertex must be at or below this z
    double shoot_radius = 2.5;    // a tip is fed by the lit faces this near (and nearest to it), > 0
    double shoot_half_light = 4.0;  // H: a tip fed this much light bears half, >= 0 (0 = every tip in full)
    // The skeleton that finds the tips: bands one median edge wide
    // (shoot_band_edges), not the architecture measures' two, so a shoot about
    // as long as it is thick stays a tip on a 1,000-vertex mesh (it reads the
    // labelled controls' tips at 500-5,000 vertices, as the measures do).
    ArchitectureParams architecture{.skeleton = {.band_edges = 1.0}};
};

struct PlantScore {
    bool rooted = false;
    double light = 0, reproduction = 0, moment = 0, volume = 0, cost = 1, score = 0;
    int tips = 0;
    double bearing_tips = 0;  // Σ_t S_t / (S_t + H): the tips that bear, each weighted by its light
};

// Thread-safe. Throws what light_per_face and measure_architecture throw.
PlantScore plant_score(MeshView mesh, const PlantFitnessParams& params);

// What each face yields: its area through the hyperbola at the mean
// irradiance of its leaf, the faces whose centroids share a cube of side
// leaf_size (leaf_size 0: each face alone). A leaf's yield is the sum of its
// faces'; a face in a lit leaf yields even if no ray hit it.
std::vector<double> face_yields(MeshView mesh, const std::vector<double>& light_per_face, double half_saturation,
                                double leaf_size);

// The light term alone (the sum of face_yields), for tests.
double saturating_light(MeshView mesh, const std::vector<double>& light_per_face, double half_saturation,
                        double leaf_size = 0.0);

// S_t above: each tip's share of the saturating light (faces nearest to it
// within shoot_radius; a face equally near two tips goes to the first).
std::vector<double> shoot_light(MeshView mesh, const std::vector<double>& light_per_face, double half_saturation,
                                const std::vector<Vec3>& tips, double shoot_radius, double leaf_size = 0.0);

}  // namespace morphogen
