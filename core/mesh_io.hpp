#pragma once
// Mesh files. Writers: OBJ, PLY (binary little-endian), OFF, STL (binary) and
// GLB (glTF 2.0 binary, Y-up, double-sided material). The format is chosen by
// the file extension. OBJ and OFF keep the mesh's vertex and face order and
// write coordinates with 17 significant digits: an exact record. PLY stores
// doubles, so it is exact too. Readers: OBJ, OFF, PLY (ASCII and binary).
// Errors throw IoError naming the file and what is wrong (line number where
// there is one).
#include "mesh.hpp"

#include <string>

namespace morphogen {

enum class MeshFormat { obj, ply, off, stl, glb };

// By extension (case-insensitive); throws IoError for an unknown extension.
MeshFormat mesh_format_from_path(const std::string& path);

void write_mesh(MeshView mesh, const std::string& path);
void write_mesh(MeshView mesh, const std::string& path, MeshFormat format);
// The bytes write_mesh would write, for callers that write them their own way
// (run exports go through write_file_atomically); `path` only names the file
// in errors.
std::string mesh_bytes(MeshView mesh, MeshFormat format, const std::string& path);

// Reads vertices and triangles (polygons with more than three corners are
// fan-triangulated); does not check topology.
MeshArrays read_mesh(const std::string& path);

}  // namespace morphogen
