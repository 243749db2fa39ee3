// OFF: the exact text record (writer) and a reader of OFF and its variants.
// The writer stays plain OFF, without normals: NOFF (normals after each
// vertex) is a variant that many simple OFF readers refuse (they want the
// magic word "OFF") or misread (they take three numbers per vertex line).
#include "core/io/mesh_io_detail.hpp"

#include <limits>
#include <string>

namespace morphogen::mesh_io_detail {

std::string off_bytes(MeshView mesh) {
    std::string out;
    out.reserve(text_size_guess(mesh));
    out += "OFF\n# " + header_comment(mesh) + "\n";
    append_int(out, static_cast<long long>(mesh.positions.size()));
    out += ' ';
    append_int(out, static_cast<long long>(mesh.faces.size()));
    out += " 0\n";
    append_text_body(out, mesh, "", "3", 0);
    return out;
}

long long off_count(std::string_view tok, const std::string& path, std::size_t line, const char* what) {
    long long n = 0;
    if (!parse_long(tok, n) || n < 0 || n > std::numeric_limits<int>::max())
        fail_line(path, line, std::string("bad ") + what + " count " + excerpt(tok));
    return n;
}

MeshArrays read_off(const std::string& path, std::string_view text) {
    LineReader reader(text);
    std::string_view line;
    if (!reader.next_nonblank(line)) fail(path, "empty file (expected an OFF header)");
    std::string_view rest = line;
    const std::string_view magic = take_token(rest);
    // OFF, and the per-vertex-colour/normal variants COFF, NOFF, CNOFF, STOFF...
    if (magic.size() < 3 || magic.substr(magic.size() - 3) != "OFF" || magic.find("4") != std::string_view::npos)
        fail_line(path, reader.line_number(), "not an OFF file (first word is " + excerpt(magic) + ")");
    auto counts = tokens(rest);  // counts may follow the keyword on the same line
    if (counts.empty()) {
        if (!reader.next_nonblank(line)) fail(path, "missing vertex/face counts");
        counts = tokens(line);
    }
    const std::size_t counts_line = reader.line_number();
    if (counts.size() < 2) fail_line(path, counts_line, "expected 'vertices faces [edges]'");
    const long long nv = off_count(counts[0], path, counts_line, "vertex");
    const long long nf = off_count(counts[1], path, counts_line, "face");
    check_vertex_count(nv, path);
    // One line per vertex ("x y z", 6 bytes at least) and per face ("3 a b c",
    // 8 bytes): refuse counts the rest of the file cannot hold before looping.
    check_room(6.0L * nv + 8.0L * nf - 1, text.size() - reader.offset(), path,
               "header line " + std::to_string(counts_line) + " declares " + std::to_string(nv) + " vertices and " +
                   std::to_string(nf) + " faces");

    MeshArrays mesh;
    mesh.positions.reserve(static_cast<std::size_t>(nv));  // bounded by the file size (checked above)
    for (long long i = 0; i < nv; ++i) {
        if (!reader.next_nonblank(line))
            fail(path, "truncated: found " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
        const std::size_t ln = reader.line_number();
        std::string_view t[3];
        for (int k = 0; k < 3; ++k)
            if ((t[k] = take_token(line)).empty())
                fail_line(path, ln, "vertex needs 3 coordinates, found " + std::to_string(k));
        mesh.positions.emplace_back(coordinate(t[0], path, ln), coordinate(t[1], path, ln),
                                    coordinate(t[2], path, ln));
    }
    std::vector<int> corners;
    for (long long i = 0; i < nf; ++i) {
        if (!reader.next_nonblank(line))
            fail(path, "truncated: found " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
        const std::size_t ln = reader.line_number();
        const std::string_view count = take_token(line);
        long long n = 0;
        if (!parse_long(count, n) || n < 0) fail_line(path, ln, "bad corner count " + excerpt(count));
        if (n < 3) fail_line(path, ln, "face with " + std::to_string(n) + " corners (needs at least 3)");
        // Each corner takes two bytes at least: a count beyond the line is a lie.
        if (n > static_cast<long long>(line.size() / 2) + 1)
            fail_line(path, ln, "face declares " + std::to_string(n) + " corners, more than its line can hold");
        check_triangle_count(mesh.faces.size(), n, path, ln);
        corners.clear();
        for (long long k = 0; k < n; ++k) {  // tokens after the n indices (colours) are ignored
            const std::string_view tok = take_token(line);
            if (tok.empty())
                fail_line(path, ln, "face lists " + std::to_string(k) + " of its " + std::to_string(n) + " corners");
            long long v = 0;
            if (!parse_long(tok, v)) fail_line(path, ln, "bad vertex index " + excerpt(tok));
            if (v < 0 || v >= nv)
                fail_line(path, ln, "vertex index " + std::to_string(v) + " out of range [0, " + std::to_string(nv) + ")");
            corners.push_back(static_cast<int>(v));
        }
        add_polygon(mesh.faces, corners, path, ln);
    }
    return mesh;
}

}  // namespace morphogen::mesh_io_detail
