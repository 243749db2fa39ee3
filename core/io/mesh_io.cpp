// Mesh file writers and readers (see mesh_io.hpp): choosing the format, file
// access and dispatch through the table of mesh_formats.cpp. Each format lives
// in its own mesh_io_<format>.cpp.
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
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

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

// "a, b or c": the table's extensions.
std::string listed() {
    std::vector<std::string_view> items;
    for (const MeshFormat& format : mesh_formats()) items.push_back(format.extension);
    return or_list(items);
}

}  // namespace

const MeshFormat& mesh_format_from_path(const std::string& path) {
    const std::string ext = lower(std::filesystem::path(path).extension().string());
    if (const MeshFormat* format = find_mesh_format(ext)) return *format;
    fail(path, "unknown mesh file extension " + excerpt(ext.empty() ? std::string("(none)") : ext) + " (expected " +
                   listed() + ")");
}

const MeshFormat& mesh_format(std::string_view extension) {
    if (const MeshFormat* format = find_mesh_format(extension)) return *format;
    throw std::invalid_argument("no mesh format has the extension " + std::string(extension));
}

void write_mesh(MeshView mesh, const std::string& path, const MeshWriteOptions& options) {
    write_mesh(mesh, path, mesh_format_from_path(path), options);
}

void write_mesh(MeshView mesh, const std::string& path, const MeshFormat& format, const MeshWriteOptions& options) {
    write_file(path, encode_mesh(mesh, format, options, path));
}

std::string encode_mesh(MeshView mesh, const MeshFormat& format, const MeshWriteOptions& options,
                        const std::string& source) {
    check_indices(mesh, source);
    return format.write(mesh, options, source);
}

MeshArrays parse_mesh(std::string_view bytes, const MeshFormat& format, const std::string& source) {
    if (bytes.size() > kMaxMeshFileBytes)
        fail(source, std::to_string(bytes.size()) + " bytes, more than the limit of " +
                         std::to_string(kMaxMeshFileBytes) + " bytes for mesh files");
    return format.read(source, bytes);
}

MeshArrays read_mesh(const std::string& path) {
    const MeshFormat& format = mesh_format_from_path(path);
    return parse_mesh(read_file(path), format, path);
}

ColouredMesh read_coloured_mesh(const std::string& path) {
    if (mesh_format_from_path(path).extension != ".glb") return {read_mesh(path), {}};
    const std::string bytes = read_file(path);
    ColouredMesh out;
    out.mesh = read_glb(path, bytes, &out.colours);
    return out;
}

}  // namespace morphogen
