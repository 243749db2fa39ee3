// Mesh file writers and readers (see mesh_io.hpp): choosing the format, file
// access and dispatch. Each format lives in its own mesh_io_<format>.cpp.
// Writers build the whole file in memory and write it with one call, so a
// failed write is detected in one place and the partial file is removed.
// Readers load the whole file and parse it from memory; every error names the
// file (and line for text).
#include "core/io/mesh_io.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "core/io/mesh_io_detail.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>

namespace morphogen {

double srgb_encode(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

using namespace mesh_io_detail;

namespace {

void write_file(const std::string& path, std::string_view bytes) {
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        if (!out) fail(path, std::string("cannot open for writing: ") + std::strerror(errno));
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (out) return;
    }
    // Do not leave a half-written file behind (but never remove a device or
    // anything else that is not a plain file we were writing).
    std::error_code ignored;
    if (std::filesystem::is_regular_file(path, ignored)) std::filesystem::remove(path, ignored);
    fail(path, "write failed (disk full or device error?)");
}

// The whole file, refused before reading when it is not a regular file (a
// device or pipe could be endless) or larger than kMaxMeshFileBytes.
std::string read_file(const std::string& path) { return read_file_bytes(path, {kMaxMeshFileBytes, "mesh files"}); }

void check_indices(MeshView mesh, const std::string& path) {
    const auto nv = static_cast<long long>(mesh.positions.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int v : mesh.faces[f])
            if (v < 0 || v >= nv)
                fail(path, "cannot write: face " + std::to_string(f) + " has vertex index " +
                               std::to_string(v) + " out of range [0, " + std::to_string(nv) + ")");
}

}  // namespace

MeshFormat mesh_format_from_path(const std::string& path) {
    const std::string ext = lower(std::filesystem::path(path).extension().string());
    if (ext == ".obj") return MeshFormat::obj;
    if (ext == ".ply") return MeshFormat::ply;
    if (ext == ".off") return MeshFormat::off;
    if (ext == ".stl") return MeshFormat::stl;
    if (ext == ".glb") return MeshFormat::glb;
    fail(path, "unknown mesh file extension " + excerpt(ext.empty() ? std::string("(none)") : ext) +
                   " (expected .obj, .ply, .off, .stl or .glb)");
}

void write_mesh(MeshView mesh, const std::string& path, const MeshWriteOptions& options) {
    write_mesh(mesh, path, mesh_format_from_path(path), options);
}

void write_mesh(MeshView mesh, const std::string& path, MeshFormat format, const MeshWriteOptions& options) {
    write_file(path, encode_mesh(mesh, format, options, path));
}

std::string encode_mesh(MeshView mesh, MeshFormat format, const MeshWriteOptions& options, const std::string& source) {
    check_indices(mesh, source);
    switch (format) {
        case MeshFormat::obj: return obj_bytes(mesh, options.colours);
        case MeshFormat::ply: return ply_bytes(mesh, options);
        case MeshFormat::off: return off_bytes(mesh);
        case MeshFormat::stl: return stl_bytes(mesh);
        case MeshFormat::glb: return glb_bytes(mesh, source, options.colours);
    }
    fail(source, "unknown mesh format");
}

MeshArrays parse_mesh(std::string_view bytes, MeshFormat format, const std::string& source) {
    if (bytes.size() > kMaxMeshFileBytes)
        fail(source, std::to_string(bytes.size()) + " bytes, more than the limit of " +
                         std::to_string(kMaxMeshFileBytes) + " bytes for mesh files");
    switch (format) {
        case MeshFormat::obj: return read_obj(source, bytes);
        case MeshFormat::off: return read_off(source, bytes);
        case MeshFormat::ply: return read_ply(source, bytes);
        case MeshFormat::stl: return read_stl(source, bytes);
        case MeshFormat::glb: return read_glb(source, bytes);
    }
    fail(source, "unknown mesh format");
}

MeshArrays read_mesh(const std::string& path) {
    const MeshFormat format = mesh_format_from_path(path);
    return parse_mesh(read_file(path), format, path);
}

ColouredMesh read_coloured_mesh(const std::string& path) {
    if (mesh_format_from_path(path) != MeshFormat::glb) return {read_mesh(path), {}};
    const std::string bytes = read_file(path);
    ColouredMesh out;
    out.mesh = read_glb(path, bytes, &out.colours);
    return out;
}

}  // namespace morphogen
