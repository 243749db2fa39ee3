#pragma once
// The mesh file formats as one table, one row each: a format is its file
// (mesh_io_<format>.cpp) and its row in mesh_formats.cpp. The choice by
// extension, the dispatch of mesh_io.hpp, the commands' help and the fuzz
// target read this table; none lists the formats itself.
#include "core/io/mesh_file_types.hpp"
#include "core/mesh/mesh.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

struct MeshFormat {
    std::string_view name;       // "PLY", in messages
    std::string_view extension;  // ".ply", lower case; a path's is matched case-insensitively
    // The file's bytes; `source` names the mesh in errors. Indices are checked before.
    std::string (*write)(MeshView mesh, const MeshWriteOptions& options, const std::string& source);
    // The mesh in `bytes` (every limit of mesh_file_types.hpp checked), errors
    // naming `source`.
    MeshArrays (*read)(const std::string& source, std::string_view bytes);
    char fuzz_tag;  // the byte that picks this reader in fuzz/fuzz_mesh.cpp (0: none)
    bool colours;   // holds vertex colours (grow --colour)
};

// Every format, in the order the help texts list them.
std::span<const MeshFormat> mesh_formats();

// The format whose extension is `extension` (".glb"), case-insensitive; null when none is.
const MeshFormat* find_mesh_format(std::string_view extension);

// The extensions, space-separated (".obj .ply .off .stl .glb"), for help texts.
std::string mesh_extensions();

// "a, b or c": the extensions of the formats that hold vertex colours.
std::string colour_extensions();

// "a, b or c" (for messages that list formats).
std::string or_list(const std::vector<std::string_view>& items);

}  // namespace morphogen
