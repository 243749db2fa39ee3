#pragma once
// Internals shared by the per-format mesh files (mesh_io_*.cpp): error helpers,
// a line/token reader for the text formats, number parsing and formatting.
// Not part of the public interface (see mesh_io.hpp).
#include "core/io/mesh_file_types.hpp"
#include "core/mesh/mesh.hpp"
#include "core/mesh/vertex_normals.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace morphogen::mesh_io_detail {

static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big,
              "mixed-endian hosts are not supported");

// Throw IoError("<path>: <what>") / IoError("<path>:<line>: <what>").
[[noreturn]] void fail(const std::string& path, const std::string& what);
[[noreturn]] void fail_line(const std::string& path, std::size_t line, const std::string& what);
// fail_line, or fail where `line` is 0 (binary data has no lines).
[[noreturn]] void fail_at(const std::string& path, std::size_t line, const std::string& what);

std::string lower(std::string s);
// A token quoted for an error message, cut to 40 characters.
std::string excerpt(std::string_view s);

// ---------------------------------------------------------------- writing

// 17 significant digits: enough to read back every double exactly.
void append_double(std::string& out, double value);
// The shortest text that reads back as this float (normals); -0 written as 0.
void append_float(std::string& out, float value);
void append_int(std::string& out, long long value);

template <class T>
void append_le(std::string& out, T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

std::string header_comment(MeshView mesh);

// One line per vertex: "<prefix>x y z" with 17 significant digits.
void append_vertex_lines(std::string& out, MeshView mesh, std::string_view prefix);
// The text formats share their body: one line per vertex ("<prefix>x y z")
// and one per face ("<prefix>i j k", indices from `first_index`).
void append_text_body(std::string& out, MeshView mesh, std::string_view vertex_prefix, std::string_view face_prefix,
                      long long first_index);
std::size_t text_size_guess(MeshView mesh);

// vertex_normals() with "up" (+z) where a vertex has none: what files store.
std::vector<Vec3> stored_normals(MeshView mesh);

// ---------------------------------------------------------------- text parsing

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Splits text into lines (any of \n, \r\n) and whitespace-separated tokens.
class LineReader {
public:
    LineReader(std::string_view text, std::size_t first_line = 1, std::size_t offset = 0)
        : text_(text), pos_(offset), line_(first_line - 1) {}

    // Next line with its comment ('#' to end) removed; false at end of text.
    bool next(std::string_view& line, char comment = '#') {
        if (pos_ >= text_.size()) return false;
        const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
        line = text_.substr(pos_, end - pos_);
        pos_ = end + 1;
        ++line_;
        if (comment) line = line.substr(0, std::min(line.find(comment), line.size()));
        return true;
    }
    // Next line holding at least one token.
    bool next_nonblank(std::string_view& line, char comment = '#') {
        while (next(line, comment))
            if (std::any_of(line.begin(), line.end(), [](char c) { return !is_space(c); }))
                return true;
        return false;
    }
    std::size_t line_number() const { return line_; }
    std::size_t offset() const { return std::min(pos_, text_.size()); }

private:
    std::string_view text_;
    std::size_t pos_;
    std::size_t line_;
};

// Cuts the next token off the front of `s`; empty when none is left.
std::string_view take_token(std::string_view& s);
std::vector<std::string_view> tokens(std::string_view s);

bool parse_double(std::string_view tok, double& value);
bool parse_long(std::string_view tok, long long& value);

// A coordinate within ±kMaxMeshCoordinate; throws naming the line otherwise.
double coordinate(std::string_view tok, const std::string& path, std::size_t line);
// The same check for a position read as a whole ("<kind> <index> has ...").
void check_position(const Vec3& p, const std::string& path, const char* kind, long long index, std::size_t line = 0);

// Throws unless the mesh may hold `count` vertices (kMaxMeshVertices).
void check_vertex_count(long long count, const std::string& path);

// Throws, naming what a header declares and what the file can hold, when
// `needed` bytes (the least that `declared` needs) exceed the `available` ones.
void check_room(long double needed, std::size_t available, const std::string& path, const std::string& declared,
                const char* hint = "a truncated file or a header that lies", std::size_t line = 0);

// Throws when a polygon of `corners` corners would take the triangles past
// kMaxMeshTriangles (readers call it while collecting a huge polygon's corners).
void check_triangle_count(std::size_t triangles, long long corners, const std::string& path, std::size_t line);

// Appends polygon `corners` as a triangle fan (0,i,i+1); throws past
// kMaxMeshTriangles. `line` 0: no line to name.
void add_polygon(std::vector<Face>& faces, const std::vector<int>& corners, const std::string& path,
                 std::size_t line);

// ---------------------------------------------------------------- formats

std::string obj_bytes(MeshView mesh, std::span<const float> colours = {});
// Throws std::invalid_argument unless `colours` is empty or 4 per vertex.
void check_colours(MeshView mesh, std::span<const float> colours);
std::string off_bytes(MeshView mesh);
std::string ply_bytes(MeshView mesh, const MeshWriteOptions& options);
std::string stl_bytes(MeshView mesh);
// With colours (4 per vertex): COLOR_0 and the white plant material.
std::string glb_bytes(MeshView mesh, const std::string& path, std::span<const float> colours = {});

MeshArrays read_obj(const std::string& path, std::string_view text);
MeshArrays read_off(const std::string& path, std::string_view text);
MeshArrays read_ply(const std::string& path, std::string_view text);
MeshArrays read_stl(const std::string& path, std::string_view bytes);
// The first mesh's triangles (every primitive of it), in its own coordinates
// turned to z up.
// `colours`, when given: COLOR_0 as 4 linear floats per vertex (RGBA; A = 1
// for VEC3) where a primitive has float COLOR_0 (primitives without it, such
// as leaf cards, take their material's colour, a leaf green where it is
// textured); left empty where none has it.
MeshArrays read_glb(const std::string& path, std::string_view bytes, std::vector<float>* colours = nullptr);

}  // namespace morphogen::mesh_io_detail
