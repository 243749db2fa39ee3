#pragma once
// Mesh files. Writers: OBJ, PLY (binary little-endian), OFF, STL (binary) and
// GLB (glTF 2.0 binary, Y-up, double-sided material). The format is chosen by
// the file extension. OBJ and OFF keep the mesh's vertex and face order and
// write coordinates with 17 significant digits: an exact record. PLY stores
// float32 by default (what WebGL viewers can draw; exact with
// MeshWriteOptions::ply_double). OBJ, PLY and GLB carry smooth per-vertex
// normals (vertex_normals below); OFF stays plain OFF; STL has facet normals.
// Readers: OBJ, OFF, PLY (ASCII and binary), STL (ASCII and binary).
// Every reader refuses, with an IoError naming the file (and line where there
// is one), anything malformed or beyond the limits below, before allocating
// or looping over what a file merely declares (docs/limits.md, "Mesh files").
#include "mesh.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

enum class MeshFormat { obj, ply, off, stl, glb };

// What a mesh file may hold. The file size bounds the memory a read takes
// (the file, plus at most the vertex and triangle arrays below); the
// coordinate bound keeps areas, volumes and cross products of any two
// coordinates finite and canopy cell indices exact.
inline constexpr std::size_t kMaxMeshFileBytes = std::size_t{1} << 31;  // 2 GiB
inline constexpr long long kMaxMeshVertices = 1LL << 26;                // 67,108,864
inline constexpr long long kMaxMeshTriangles = 1LL << 27;               // 134,217,728 (after triangulation)
inline constexpr double kMaxMeshCoordinate = 1e9;                       // |x|, |y|, |z|

struct MeshWriteOptions {
    // PLY only: 64-bit coordinates and normals (an exact record) instead of
    // float32. three.js and other WebGL viewers cannot draw doubles.
    bool ply_double = false;
};

// By extension (case-insensitive); throws IoError for an unknown extension.
MeshFormat mesh_format_from_path(const std::string& path);

void write_mesh(MeshView mesh, const std::string& path, const MeshWriteOptions& options = {});
void write_mesh(MeshView mesh, const std::string& path, MeshFormat format, const MeshWriteOptions& options = {});

// The bytes write_mesh writes (`source` names the mesh in errors).
std::string encode_mesh(MeshView mesh, MeshFormat format, const MeshWriteOptions& options = {},
                        const std::string& source = "mesh");

// Reads vertices and triangles (polygons with more than three corners are
// fan-triangulated; STL corners at exactly equal positions become one
// vertex); does not check topology. Throws IoError naming `path`.
MeshArrays read_mesh(const std::string& path);

// read_mesh without the file: parses `bytes` in `format` (GLB is refused);
// errors name `source`. Never crashes, hangs or allocates beyond the limits
// above, whatever the bytes (the fuzz targets call this).
MeshArrays parse_mesh(std::string_view bytes, MeshFormat format, const std::string& source);

// Unit area-weighted vertex normals (Z-up), the smooth normals every writer
// stores; exactly zero where a vertex has none (no faces, zero area or
// overflow), where writers store "up". Faces must index existing vertices.
std::vector<Vec3> vertex_normals(MeshView mesh);

}  // namespace morphogen
