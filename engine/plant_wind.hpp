#pragma once
// Wind data for game engines: the `_WIND` vertex attribute of an engine-ready
// GLB (docs/wind.md, "Wind data", with the sway formula), four
// floats per vertex in [0, 1]:
//   x  bend: 0 at the foot rising to 1 at the farthest tip, as the square of
//      the distance from the foot along the surface over its largest value
//   y  flutter: when the vertex was born, birth step / steps (the seed's 0,
//      the youngest tips 1)
//   z  phase: the azimuth of the vertex around the vertical axis through the
//      foot, over 2 pi, so limbs leaning different ways sway out of step
//      (sin(2 pi z) is continuous where z wraps from 1 to 0)
//   w  stiffness: how much of the plant the vertex carries, log(1 + carried)
//      / log(1 + vertices) along the shortest paths to the foot, smoothed
//      over each vertex's neighbours: near 1 low on the trunk, near 0 at tips
//
// Wind presets (`--wind-preset`, docs/game-engines.md) copy these values,
// besides _WIND, where particular engines read per-vertex data:
//   color  COLOR_0 = (flutter, phase, bend, stiffness), CryEngine's detail
//          bending channels (R edge flutter, G phase, B branch bend); glTF
//          makes COLOR_0 a colour multiplier, so viewers tint the plant
//   uv     TEXCOORD_0 = (bend, flutter), TEXCOORD_1 = (phase, stiffness):
//          UV channels 0 and 1 in Unity, Unreal and Godot (UV, UV2)
//   godot  _CUSTOM0 = (bend, flutter, phase, stiffness): Godot's CUSTOM0
//          in builds with godotengine/godot#120040
#include "core/io/plant_glb.hpp"
#include "core/mesh/mesh.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

// `placed` is the plant placed at its foot (plant_frame.hpp: Z-up, lowest
// point z = 0); birth_steps[v] is the step after which vertex v first
// existed (0 for the seed's), `steps` the steps growth did. Returns 4 floats
// per vertex. Throws std::invalid_argument when birth_steps does not have one
// entry per vertex. The same mesh and births give the same values.
std::vector<float> plant_wind(MeshView placed, std::span<const int> birth_steps, int steps);

enum class WindPreset { color, uv, godot };

// The presets by name, in the order their attributes are written.
inline constexpr std::string_view kWindPresetNames[] = {"color", "uv", "godot"};

// The preset called `name`, or none.
std::optional<WindPreset> wind_preset_named(std::string_view name);
std::string_view wind_preset_name(WindPreset preset);

// The attributes `presets` add for wind data `wind` (4 floats per vertex),
// in the order of kWindPresetNames whatever the order of `presets`; a preset
// named twice is written once. Throws std::invalid_argument when wind's
// length is not a multiple of 4.
std::vector<VertexAttribute> wind_preset_attributes(std::span<const float> wind, std::span<const WindPreset> presets);

}  // namespace morphogen
