// OBJ: the exact text record with smooth normals (writer) and a reader of
// v/f lines.
#include "core/io/mesh_io_detail.hpp"

#include <string>

namespace morphogen::mesh_io_detail {

// Positions with 17 digits (exact), then one `vn` per vertex (float digits:
// shading needs no more), faces as `f a//a b//b c//c` (vertex a, normal a).
std::string obj_bytes(MeshView mesh, std::span<const float> colours) {
    check_colours(mesh, colours);
    std::string out;
    out.reserve(text_size_guess(mesh) + mesh.positions.size() * 32 + mesh.faces.size() * 24);
    out += "# " + header_comment(mesh) + "\n";
    if (colours.empty()) append_vertex_lines(out, mesh, "v ");
    for (std::size_t i = 0; !colours.empty() && i < mesh.positions.size(); ++i) {
        out += "v ";
        for (int k = 0; k < 3; ++k) {
            append_double(out, mesh.positions[i][k]);
            out += ' ';
        }
        for (int k = 0; k < 3; ++k) {  // sRGB, as viewers read `v x y z r g b`
            append_float(out, static_cast<float>(srgb_encode(colours[4 * i + k])));
            out += k < 2 ? ' ' : '\n';
        }
    }
    for (const Vec3& n : stored_normals(mesh)) {
        out += "vn ";
        append_float(out, static_cast<float>(n.x()));
        out += ' ';
        append_float(out, static_cast<float>(n.y()));
        out += ' ';
        append_float(out, static_cast<float>(n.z()));
        out += '\n';
    }
    for (const Face& f : mesh.faces) {
        out += 'f';
        for (int v : f) {
            out += ' ';
            append_int(out, v + 1);
            out += "//";
            append_int(out, v + 1);
        }
        out += '\n';
    }
    return out;
}

MeshArrays read_obj(const std::string& path, std::string_view text) {
    MeshArrays mesh;
    LineReader reader(text);
    std::string_view line;
    std::vector<int> corners;
    while (reader.next(line)) {
        const std::size_t ln = reader.line_number();
        const std::string_view key = take_token(line);
        if (key == "v") {
            const auto t = tokens(line);
            if (t.size() < 3) fail_line(path, ln, "vertex needs 3 coordinates, found " + std::to_string(t.size()));
            if (static_cast<long long>(mesh.positions.size()) >= kMaxMeshVertices)
                fail_line(path, ln, "more than " + std::to_string(kMaxMeshVertices) + " vertices (the limit for mesh files)");
            mesh.positions.emplace_back(coordinate(t[0], path, ln), coordinate(t[1], path, ln),
                                        coordinate(t[2], path, ln));
        } else if (key == "f") {
            corners.clear();
            const auto nv = static_cast<long long>(mesh.positions.size());
            // Token by token: a huge polygon costs its corners, not a token list too.
            for (std::string_view t = take_token(line); !t.empty(); t = take_token(line)) {
                const std::string_view index = t.substr(0, t.find('/'));  // v, v/vt, v//vn, v/vt/vn
                long long i = 0;
                if (!parse_long(index, i)) fail_line(path, ln, "bad vertex index " + excerpt(t));
                // 1-based; negative counts back from the last vertex read so far.
                const long long v = i > 0 ? i - 1 : nv + i;
                if (i == 0 || v < 0 || v >= nv)
                    fail_line(path, ln, "vertex index " + std::to_string(i) + " out of range (" +
                                            std::to_string(nv) + " vertices defined so far)");
                corners.push_back(static_cast<int>(v));
                if (corners.size() % 4096 == 0) check_triangle_count(mesh.faces.size(), corners.size(), path, ln);
            }
            if (corners.size() < 3)
                fail_line(path, ln, "face with " + std::to_string(corners.size()) + " corners (needs at least 3)");
            add_polygon(mesh.faces, corners, path, ln);
        }
        // Everything else (vt, vn, o, g, s, usemtl, mtllib, l, ...) is ignored.
    }
    return mesh;
}

}  // namespace morphogen::mesh_io_detail
