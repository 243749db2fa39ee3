// Mesh file writers and readers (see mesh_io.hpp): choosing the format, file
// access and dispatch. Each format lives in its own mesh_io_<format>.cpp.
// Writers build the whole file in memory and write it with one call, so a
// failed write is detected in one place and the partial file is removed.
// Readers load the whole file and parse it from memory; every error names the
// file (and line for text).
#include "mesh_io.hpp"

#include "errors.hpp"
#include "mesh_io_detail.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>

namespace morphogen {

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

std::string read_file(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a mesh file");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, std::string("cannot open for reading: ") + std::strerror(errno));
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) fail(path, "read failed");
    return std::move(buffer).str();
}

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

void write_mesh(MeshView mesh, const std::string& path) {
    write_mesh(mesh, path, mesh_format_from_path(path));
}

void write_mesh(MeshView mesh, const std::string& path, MeshFormat format) {
    check_indices(mesh, path);
    switch (format) {
        case MeshFormat::obj: write_file(path, obj_bytes(mesh)); return;
        case MeshFormat::ply: write_file(path, ply_bytes(mesh)); return;
        case MeshFormat::off: write_file(path, off_bytes(mesh)); return;
        case MeshFormat::stl: write_file(path, stl_bytes(mesh)); return;
        case MeshFormat::glb: write_file(path, glb_bytes(mesh, path)); return;
    }
}

MeshArrays read_mesh(const std::string& path) {
    const MeshFormat format = mesh_format_from_path(path);
    if (format == MeshFormat::stl || format == MeshFormat::glb)
        fail(path, "reading STL/GLB is not supported (use OBJ, OFF or PLY)");
    const std::string text = read_file(path);
    switch (format) {
        case MeshFormat::obj: return read_obj(path, text);
        case MeshFormat::off: return read_off(path, text);
        default: return read_ply(path, text);
    }
}

}  // namespace morphogen
