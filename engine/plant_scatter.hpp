#pragma once
// The scatter of a species pack (docs/species-pack.md, "scatter.glb"): a
// small field of every species, laid out the same way every time. Each
// species stands on a square grid, one node at the centre of its square,
// which every glTF client draws; with EXT_mesh_gpu_instancing a client also
// draws kScatterCopies - 1 more copies around it, turned and scaled. The
// first copy is the node itself (the identity), so a client without the
// extension shows one plant of every species, each in its own square, and
// a client with it shows the same plants plus the copies: never a plant
// twice at one place, never all species piled at the origin.
#include "engine/plant_export.hpp"

#include <span>
#include <string>

namespace morphogen {

// Copies of each species with the extension, the node's own included.
inline constexpr int kScatterCopies = 4;

// The scatter.glb bytes of `plants` (their LOD0 and its wind data, their
// names and extras), in order along the grid's rows. `run` goes into the
// root node's extras. Throws std::invalid_argument for no plants; IoError
// naming `source` when it cannot be encoded.
std::string plant_scatter_bytes(std::span<const EnginePlant> plants, const std::string& run, const std::string& source);

}  // namespace morphogen
