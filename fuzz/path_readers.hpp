#pragma once
// The one place where fuzz targets go through a file: today's mesh and
// checkpoint readers take a path (core/mesh_io.hpp read_mesh, app/checkpoint.hpp
// load_checkpoint), so the bytes are written to a per-process scratch file
// first. When an in-memory reader exists (parse_mesh(bytes, format, source)),
// only these functions change.
#include "checkpoint.hpp"
#include "mesh.hpp"
#include "mesh_io.hpp"

#include <string_view>

namespace morphogen::fuzz {

// read_mesh() of a file holding `bytes` with the extension of `format`.
MeshArrays read_mesh_bytes(std::string_view bytes, MeshFormat format);
// load_checkpoint() of a file holding `bytes`.
RunState load_checkpoint_bytes(std::string_view bytes);

}  // namespace morphogen::fuzz
