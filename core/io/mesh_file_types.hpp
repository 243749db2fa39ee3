#pragma once
// What a mesh file may hold and how it is written: shared by the public
// reader/writer (mesh_io.hpp), the table of formats (mesh_formats.hpp) and the
// per-format files (mesh_io_detail.hpp).
#include <cstddef>

#include <span>

namespace morphogen {

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
    // OBJ, PLY and GLB: vertex colours, 4 linear floats per vertex (RGBA, as
    // engine/plant_colour.hpp makes them) or empty. OBJ and PLY write them
    // sRGB-encoded, as viewers read them: PLY red/green/blue uchar, OBJ
    // `v x y z r g b`; GLB as COLOR_0 (linear) with a white material.
    std::span<const float> colours{};
};

// A linear colour channel in [0, 1] encoded as sRGB in [0, 1].
double srgb_encode(double linear);

}  // namespace morphogen
