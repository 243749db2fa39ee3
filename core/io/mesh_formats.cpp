#include "core/io/mesh_formats.hpp"

#include "core/io/mesh_io_detail.hpp"

#include <algorithm>
#include <cctype>

namespace morphogen {

using namespace mesh_io_detail;

namespace {

// One row per format: its name, extension, writer, reader, fuzz tag (GLB's reader is not fuzzed: 0) and
// whether it holds vertex colours.
constexpr MeshFormat kFormats[] = {
    {"OBJ", ".obj", [](MeshView m, const MeshWriteOptions& o, const std::string&) { return obj_bytes(m, o.colours); },
     &read_obj, 'o', true},
    {"PLY", ".ply", [](MeshView m, const MeshWriteOptions& o, const std::string&) { return ply_bytes(m, o); }, &read_ply,
     'p', true},
    {"OFF", ".off", [](MeshView m, const MeshWriteOptions&, const std::string&) { return off_bytes(m); }, &read_off, 'f', false},
    {"STL", ".stl", [](MeshView m, const MeshWriteOptions&, const std::string&) { return stl_bytes(m); }, &read_stl, 's', false},
    {"GLB", ".glb", [](MeshView m, const MeshWriteOptions& o, const std::string& s) { return glb_bytes(m, s, o.colours); },
     [](const std::string& source, std::string_view bytes) { return read_glb(source, bytes); }, 0, true},
};

bool same_letters(std::string_view a, std::string_view b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](unsigned char x, unsigned char y) {
        return std::tolower(x) == std::tolower(y);
    });
}

}  // namespace

std::span<const MeshFormat> mesh_formats() { return kFormats; }

const MeshFormat* find_mesh_format(std::string_view extension) {
    for (const MeshFormat& format : kFormats)
        if (same_letters(format.extension, extension)) return &format;
    return nullptr;
}

std::string mesh_extensions() {
    std::string out;
    for (const MeshFormat& format : kFormats) {
        if (!out.empty()) out += ' ';
        out += format.extension;
    }
    return out;
}

std::string colour_extensions() {
    std::vector<std::string_view> items;
    for (const MeshFormat& format : kFormats)
        if (format.colours) items.push_back(format.extension);
    return or_list(items);
}

std::string or_list(const std::vector<std::string_view>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += i + 1 == items.size() ? " or " : ", ";
        out += items[i];
    }
    return out;
}

}  // namespace morphogen
