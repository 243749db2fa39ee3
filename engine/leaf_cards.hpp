#pragma once
// Foliage cards (`--leaves`, docs/game-engines.md "Leaves"): small textured
// quads at the plant's exposed young vertices, each rooted at its vertex and
// facing out along the surface normal. An export-time pass over what growth
// left; it changes nothing growth computes.
//
// A vertex is eligible when it is young (born in the later half of the
// growth: birth step >= steps / 2) and lit (light >= 0.5: the branching
// mode's exposure, §5.9, or in the paper's mode its height as a fraction of
// the plant's, as the colours use it, §13). Each eligible vertex draws a key
// u in [0, 1) from a counter-based hash of (the genome's hash, the vertex);
// vertices with u < density are candidates, taken in order of u, and a
// candidate within half a card length of a card already placed is skipped.
// The same genome therefore gives the same cards, whatever else ran.
//
// A card of length L (size x the plant's height) and width L / 2 stands on
// its vertex, lifted L / 20 along the normal n. Its blade leans away from
// the surface by a lift angle in [25°, 50°] and turns about n by up to ±60°
// from the plant's up direction (both hashed), so its face normal m has
// m·n = cos(lift) >= 0.64: it faces outward.
#include "core/growth/growth.hpp"
#include "core/mesh/mesh.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

inline constexpr double kDefaultLeafSize = 0.06;     // card length / plant height
inline constexpr double kMaxLeafSize = 0.5;
inline constexpr double kDefaultLeafDensity = 0.5;   // candidates per eligible vertex
inline constexpr double kLeafYoung = 0.5;            // birth step / steps at least this
inline constexpr double kLeafLight = 0.5;            // light at least this
inline constexpr double kLeafAspect = 0.5;           // width / length
inline constexpr double kLeafLiftOffset = 0.05;      // base above the surface, in lengths
inline constexpr double kMaxLodLeafScale = 2.0;      // LOD cards grow at most this much

struct LeafParams {
    double size = kDefaultLeafSize;
    double density = kDefaultLeafDensity;
};

// Why `params` cannot be used, naming `size_name` or `density_name` (the
// option or key the value came from), or "".
std::string leaf_params_problem(const LeafParams& params, std::string_view size_name, std::string_view density_name);

struct LeafInputs {
    MeshView placed;                   // the plant at its foot, Z-up (engine/plant_frame.hpp)
    std::span<const int> birth_steps;  // one per vertex (engine/birth_steps.hpp)
    int steps = 0;                     // steps grown
    std::span<const double> light;     // one per vertex in [0, 1]; empty: height stands in
    std::uint64_t seed = 0;            // leaf_seed() of the genome
};

// One card: where it stands and how it is turned.
struct LeafCard {
    int vertex = 0;   // its anchor vertex in `placed`
    double key = 0;   // its hash key u: LODs keep the cards of least key
    Vec3 base;        // centre of its base edge
    Vec3 axis;        // unit, base to tip
    Vec3 across;      // unit, left to right; axis x across = the face normal
    Vec3 normal;      // unit face normal (m)
    double length = 0;
};

// The seed of a genome's cards: FNV-1a of its hash text (PlantRecord::genome_hash).
std::uint64_t leaf_seed(std::string_view genome_hash);

// The cards, in order of key. Throws std::invalid_argument when birth_steps
// or light (when given) do not have one entry per vertex, or for bad params.
std::vector<LeafCard> leaf_cards(const LeafInputs& inputs, const LeafParams& params);

// The light leaf_cards reads for a grown state: the final exposure in the
// branching mode, empty (height stands in) in the paper's.
std::vector<double> leaf_light(const GrowthState& state, const GrowthParams& params);

// The cards of one level, as geometry: 4 vertices and 2 triangles a card,
// texture coordinates (the leaf's base at v = 1, its tip at v = 0) and, when
// `anchor_wind` (4 floats per vertex of `placed`) is given, wind data: each
// card vertex takes its anchor's, and the tip's flutter is 1.
struct LeafMesh {
    MeshArrays mesh;
    std::vector<float> uv;    // 2 per vertex
    std::vector<float> wind;  // 4 per vertex, or empty
    std::size_t cards() const { return mesh.positions.size() / 4; }
};

// The first `count` cards, each scaled by `scale` about its base.
LeafMesh leaf_mesh(std::span<const LeafCard> cards, std::size_t count, double scale, std::span<const float> anchor_wind);

// How many cards a level keeps, and how much larger they are drawn: a level
// with `fraction` of LOD0's triangles keeps round(fraction x cards) (at
// least 1 when there are any) and scales them by sqrt(1 / fraction), at most
// kMaxLodLeafScale, so the foliage keeps about its area.
struct LodLeaves {
    std::size_t count = 0;
    double scale = 1.0;
};
LodLeaves lod_leaves(std::size_t cards, double fraction);

}  // namespace morphogen
