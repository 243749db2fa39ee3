// OBJ: the exact text record (writer) and a reader of v/f lines.
#include "mesh_io_detail.hpp"

#include <string>

namespace morphogen::mesh_io_detail {

std::string obj_bytes(MeshView mesh) {
    std::string out;
    out.reserve(text_size_guess(mesh));
    out += "# " + header_comment(mesh) + "\n";
    append_text_body(out, mesh, "v ", "f", 1);
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
            mesh.positions.emplace_back(coordinate(t[0], path, ln), coordinate(t[1], path, ln),
                                        coordinate(t[2], path, ln));
        } else if (key == "f") {
            corners.clear();
            const auto nv = static_cast<long long>(mesh.positions.size());
            for (std::string_view t : tokens(line)) {
                const std::string_view index = t.substr(0, t.find('/'));  // v, v/vt, v//vn, v/vt/vn
                long long i = 0;
                if (!parse_long(index, i)) fail_line(path, ln, "bad vertex index " + excerpt(t));
                // 1-based; negative counts back from the last vertex read so far.
                const long long v = i > 0 ? i - 1 : nv + i;
                if (i == 0 || v < 0 || v >= nv)
                    fail_line(path, ln, "vertex index " + std::to_string(i) + " out of range (" +
                                            std::to_string(nv) + " vertices defined so far)");
                corners.push_back(static_cast<int>(v));
            }
            if (corners.size() < 3)
                fail_line(path, ln, "face with " + std::to_string(corners.size()) + " corners (needs at least 3)");
            add_polygon(mesh.faces, corners);
        }
        // Everything else (vt, vn, o, g, s, usemtl, mtllib, l, ...) is ignored.
    }
    return mesh;
}

}  // namespace morphogen::mesh_io_detail
