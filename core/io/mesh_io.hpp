#pragma once
// Mesh files. Writers: OBJ, PLY (binary little-endian), OFF, STL (binary) and
// GLB (glTF 2.0 binary, Y-up, double-sided material). The format is chosen by
// the file extension, from the table of mesh_formats.hpp. OBJ and OFF keep the mesh's vertex and face order and
// write coordinates with 17 significant digits: an exact record. PLY stores
// float32 by default (what WebGL viewers can draw; exact with
// MeshWriteOptions::ply_double). OBJ, PLY and GLB carry smooth per-vertex
// normals (vertex_normals.hpp); OFF stays plain OFF; STL has facet normals.
// Readers: OBJ, OFF, PLY (ASCII and binary), STL (ASCII and binary), GLB (its
// first mesh: a plant's body, LOD0 of an engine export).
// Every reader refuses, with an IoError naming the file (and line where there
// is one), anything malformed or beyond the limits of mesh_file_types.hpp, before allocating
// or looping over what a file merely declares (docs/limits-mesh-files.md, "Mesh files").
#include "core/io/mesh_file_types.hpp"
#include "core/io/mesh_formats.hpp"
#include "core/mesh/mesh.hpp"
#include "core/mesh/vertex_normals.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

// By extension (case-insensitive); throws IoError for an unknown extension.
const MeshFormat& mesh_format_from_path(const std::string& path);
// The format of `extension` (".glb"); throws std::invalid_argument where no
// row has it (a mistake in the calling code, not in a user's file).
const MeshFormat& mesh_format(std::string_view extension);

void write_mesh(MeshView mesh, const std::string& path, const MeshWriteOptions& options = {});
void write_mesh(MeshView mesh, const std::string& path, const MeshFormat& format,
                const MeshWriteOptions& options = {});

// The bytes write_mesh writes (`source` names the mesh in errors).
std::string encode_mesh(MeshView mesh, const MeshFormat& format, const MeshWriteOptions& options = {},
                        const std::string& source = "mesh");

// Reads vertices and triangles (polygons with more than three corners are
// fan-triangulated; STL corners at exactly equal positions become one
// vertex); does not check topology. Throws IoError naming `path`.
MeshArrays read_mesh(const std::string& path);

// read_mesh and, for a GLB with float COLOR_0, its vertex colours: 4 linear
// floats per vertex (RGBA; primitives without COLOR_0, such as leaf cards,
// take their material's colour, a leaf green where it is textured);
// otherwise no colours.
struct ColouredMesh {
    MeshArrays mesh;
    std::vector<float> colours;
};
ColouredMesh read_coloured_mesh(const std::string& path);

// read_mesh without the file: parses `bytes` in `format`;
// errors name `source`. Never crashes, hangs or allocates beyond the limits
// of mesh_file_types.hpp, whatever the bytes (the fuzz targets call this).
MeshArrays parse_mesh(std::string_view bytes, const MeshFormat& format, const std::string& source);

}  // namespace morphogen
