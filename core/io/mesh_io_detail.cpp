// Shared internals of the mesh files (see mesh_io_detail.hpp).
#include "core/io/mesh_io_detail.hpp"

#include "core/base/errors.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <cstdio>

namespace morphogen::mesh_io_detail {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw IoError(path + ": " + what);
}

[[noreturn]] void fail_line(const std::string& path, std::size_t line, const std::string& what) {
    throw IoError(path + ":" + std::to_string(line) + ": " + what);
}

[[noreturn]] void fail_at(const std::string& path, std::size_t line, const std::string& what) {
    if (line) fail_line(path, line, what);
    fail(path, what);
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

void append_float(std::string& out, float value) {
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, value + 0.0f);  // + 0: -0 becomes 0
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

void check_colours(MeshView mesh, std::span<const float> colours) {
    if (!colours.empty() && colours.size() != 4 * mesh.positions.size())
        throw std::invalid_argument("mesh colours: " + std::to_string(colours.size()) + " floats for " +
                                    std::to_string(mesh.positions.size()) + " vertices (4 each)");
}

void append_vertex_lines(std::string& out, MeshView mesh, std::string_view prefix) {
    for (const Vec3& p : mesh.positions) {
        out += prefix;
        append_double(out, p.x());
        out += ' ';
        append_double(out, p.y());
        out += ' ';
        append_double(out, p.z());
        out += '\n';
    }
}

void append_text_body(std::string& out, MeshView mesh, std::string_view vertex_prefix, std::string_view face_prefix,
                      long long first_index) {
    append_vertex_lines(out, mesh, vertex_prefix);
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

std::vector<Vec3> stored_normals(MeshView mesh) {
    std::vector<Vec3> normals = vertex_normals(mesh);
    for (Vec3& n : normals)
        if (n == Vec3::Zero()) n = Vec3::UnitZ();
    return normals;
}

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

// from_chars takes no '+'; one is allowed here, but not "+-1" or "++1".
bool parse_double(std::string_view tok, double& value) {
    if (!tok.empty() && tok.front() == '+') {
        tok.remove_prefix(1);
        if (!tok.empty() && (tok.front() == '-' || tok.front() == '+')) return false;
    }
    const auto res = std::from_chars(tok.data(), tok.data() + tok.size(), value);
    return res.ec == std::errc() && res.ptr == tok.data() + tok.size();
}

bool parse_long(std::string_view tok, long long& value) {
    if (!tok.empty() && tok.front() == '+') {
        tok.remove_prefix(1);
        if (!tok.empty() && (tok.front() == '-' || tok.front() == '+')) return false;
    }
    const auto res = std::from_chars(tok.data(), tok.data() + tok.size(), value);
    return res.ec == std::errc() && res.ptr == tok.data() + tok.size();
}

namespace {
// kMaxMeshCoordinate as written in docs and messages.
std::string limit_text() {
    static_assert(kMaxMeshCoordinate == 1e9, "update the text below");
    return "1e9";
}
}  // namespace

double coordinate(std::string_view tok, const std::string& path, std::size_t line) {
    double v = 0;
    if (!parse_double(tok, v)) fail_line(path, line, "bad number " + excerpt(tok));
    if (!std::isfinite(v)) fail_line(path, line, "coordinate " + excerpt(tok) + " is not finite");
    if (!(std::abs(v) <= kMaxMeshCoordinate))
        fail_line(path, line, "coordinate " + excerpt(tok) + " is beyond the limit of ±" + limit_text());
    return v;
}

void check_position(const Vec3& p, const std::string& path, const char* kind, long long index, std::size_t line) {
    const auto within = [](double v) { return std::abs(v) <= kMaxMeshCoordinate; };  // false for NaN
    if (within(p.x()) && within(p.y()) && within(p.z())) return;
    std::string what = kind;  // appends: GCC 12 warns (-Wrestrict) on char* + std::string
    what += ' ';
    what += std::to_string(index);
    if (!p.allFinite()) fail_at(path, line, what + " has a coordinate that is not finite");
    fail_at(path, line, what + " has a coordinate beyond the limit of ±" + limit_text());
}

void check_vertex_count(long long count, const std::string& path) {
    if (count > kMaxMeshVertices)
        fail(path, "more than " + std::to_string(kMaxMeshVertices) + " vertices (the limit for mesh files)");
}

void check_room(long double needed, std::size_t available, const std::string& path, const std::string& declared,
                const char* hint, std::size_t line) {
    if (needed <= static_cast<long double>(available)) return;
    char text[200];
    std::snprintf(text, sizeof text, ", which need at least %.0Lf bytes, but only %zu follow (%s)", needed, available,
                  hint);
    fail_at(path, line, declared + text);
}

void check_triangle_count(std::size_t triangles, long long corners, const std::string& path, std::size_t line) {
    if (static_cast<long double>(triangles) + static_cast<long double>(corners) - 2 > kMaxMeshTriangles)
        fail_at(path, line, "more than " + std::to_string(kMaxMeshTriangles) +
                                " triangles (the limit for mesh files, after splitting polygons)");
}

void add_polygon(std::vector<Face>& faces, const std::vector<int>& corners, const std::string& path,
                 std::size_t line) {
    check_triangle_count(faces.size(), static_cast<long long>(corners.size()), path, line);
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
        faces.push_back({corners[0], corners[i], corners[i + 1]});
}

}  // namespace morphogen::mesh_io_detail
