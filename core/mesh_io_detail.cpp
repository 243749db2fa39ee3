// Shared internals of the mesh files (see mesh_io_detail.hpp).
#include "mesh_io_detail.hpp"

#include "errors.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

namespace morphogen::mesh_io_detail {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw IoError(path + ": " + what);
}

[[noreturn]] void fail_line(const std::string& path, std::size_t line, const std::string& what) {
    throw IoError(path + ":" + std::to_string(line) + ": " + what);
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

void append_double(std::string& out, double value) {
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, 17);
    out.append(buf, res.ptr);
}

void append_int(std::string& out, long long value) {
    char buf[24];
    const auto res = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, res.ptr);
}

std::string header_comment(MeshView mesh) {
    return "morphogen mesh: " + std::to_string(mesh.positions.size()) + " vertices, " +
           std::to_string(mesh.faces.size()) + " triangles, Z up";
}

void append_text_body(std::string& out, MeshView mesh, std::string_view vertex_prefix, std::string_view face_prefix,
                      long long first_index) {
    for (const Vec3& p : mesh.positions) {
        out += vertex_prefix;
        append_double(out, p.x());
        out += ' ';
        append_double(out, p.y());
        out += ' ';
        append_double(out, p.z());
        out += '\n';
    }
    for (const Face& f : mesh.faces) {
        out += face_prefix;
        for (int v : f) {
            out += ' ';
            append_int(out, v + first_index);
        }
        out += '\n';
    }
}

std::size_t text_size_guess(MeshView mesh) { return 64 + mesh.positions.size() * 60 + mesh.faces.size() * 24; }

std::string_view take_token(std::string_view& s) {
    std::size_t b = 0;
    while (b < s.size() && is_space(s[b])) ++b;
    std::size_t e = b;
    while (e < s.size() && !is_space(s[e])) ++e;
    const std::string_view tok = s.substr(b, e - b);
    s.remove_prefix(e);
    return tok;
}

std::vector<std::string_view> tokens(std::string_view s) {
    std::vector<std::string_view> out;
    for (std::string_view t = take_token(s); !t.empty(); t = take_token(s)) out.push_back(t);
    return out;
}

std::string excerpt(std::string_view s) {
    constexpr std::size_t max = 40;
    std::string out(1, '\'');  // built by appends: GCC 12 warns (-Wrestrict) on "'" + std::string
    out.append(s.substr(0, max));
    out.append(s.size() > max ? "...'" : "'");
    return out;
}

bool parse_double(std::string_view tok, double& value) {
    if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
    const auto res = std::from_chars(tok.data(), tok.data() + tok.size(), value);
    return res.ec == std::errc() && res.ptr == tok.data() + tok.size();
}

bool parse_long(std::string_view tok, long long& value) {
    if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
    const auto res = std::from_chars(tok.data(), tok.data() + tok.size(), value);
    return res.ec == std::errc() && res.ptr == tok.data() + tok.size();
}

double coordinate(std::string_view tok, const std::string& path, std::size_t line) {
    double v = 0;
    if (!parse_double(tok, v)) fail_line(path, line, "bad number " + excerpt(tok));
    if (!std::isfinite(v)) fail_line(path, line, "coordinate " + excerpt(tok) + " is not finite");
    return v;
}

void add_polygon(std::vector<Face>& faces, const std::vector<int>& corners) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
        faces.push_back({corners[0], corners[i], corners[i + 1]});
}

}  // namespace morphogen::mesh_io_detail
