#pragma once
// How fuzz targets hand bytes to readers: meshes go to the in-memory
// parse_mesh (core/io/mesh_io.hpp, the same parser read_mesh uses); the
// checkpoint reader takes a path (run/persistence/checkpoint.hpp load_checkpoint), so its
// bytes are written to a per-process scratch file in /dev/shm first.
#include "core/io/mesh_io.hpp"
#include "core/mesh/mesh.hpp"
#include "run/persistence/checkpoint.hpp"

#include <string_view>

namespace morphogen::fuzz {

// parse_mesh() of `bytes` as `format`.
MeshArrays read_mesh_bytes(std::string_view bytes, const MeshFormat& format);
// load_checkpoint() of a file holding `bytes`.
RunState load_checkpoint_bytes(std::string_view bytes);

}  // namespace morphogen::fuzz
