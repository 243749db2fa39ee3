// PLY: binary little-endian writer (float32 or double, with normals); reader
// of ascii and both binary encodings.
#include "core/io/mesh_io_detail.hpp"

#include <cstdint>
#include <limits>
#include <string>

namespace morphogen::mesh_io_detail {

namespace {

enum class PlyType { i8, u8, i16, u16, i32, u32, f32, f64 };

bool ply_type(std::string_view name, PlyType& type) {
    static constexpr std::pair<std::string_view, PlyType> names[] = {
        {"char", PlyType::i8},    {"int8", PlyType::i8},     {"uchar", PlyType::u8},
        {"uint8", PlyType::u8},   {"short", PlyType::i16},   {"int16", PlyType::i16},
        {"ushort", PlyType::u16}, {"uint16", PlyType::u16},  {"int", PlyType::i32},
        {"int32", PlyType::i32},  {"uint", PlyType::u32},    {"uint32", PlyType::u32},
        {"float", PlyType::f32},  {"float32", PlyType::f32}, {"double", PlyType::f64},
        {"float64", PlyType::f64}};
    for (const auto& [n, t] : names)
        if (n == name) {
            type = t;
            return true;
        }
    return false;
}

std::size_t ply_size(PlyType t) {
    switch (t) {
        case PlyType::i8: case PlyType::u8: return 1;
        case PlyType::i16: case PlyType::u16: return 2;
        case PlyType::i32: case PlyType::u32: case PlyType::f32: return 4;
        case PlyType::f64: return 8;
    }
    return 0;
}

bool ply_integral(PlyType t) { return t != PlyType::f32 && t != PlyType::f64; }

// Range of an integer type (what an ascii value of that type may hold).
long long ply_min(PlyType t) {
    switch (t) {
        case PlyType::i8: return -128;
        case PlyType::i16: return -32768;
        case PlyType::i32: return std::numeric_limits<std::int32_t>::min();
        default: return 0;
    }
}
long long ply_max(PlyType t) {
    switch (t) {
        case PlyType::i8: return 127;
        case PlyType::u8: return 255;
        case PlyType::i16: return 32767;
        case PlyType::u16: return 65535;
        case PlyType::i32: return std::numeric_limits<std::int32_t>::max();
        default: return std::numeric_limits<std::uint32_t>::max();
    }
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::f32;  // item type for lists
    bool is_list = false;
    PlyType count_type = PlyType::u8;
};

struct PlyElement {
    std::string name;
    long long count = 0;
    std::size_t line = 0;  // of its header line
    std::vector<PlyProperty> properties;
};

enum class PlyFormat { ascii, binary_le, binary_be };

struct PlyHeader {
    PlyFormat format = PlyFormat::ascii;
    std::vector<PlyElement> elements;
    std::size_t body_offset = 0;  // byte offset of the data after end_header
    std::size_t body_line = 0;    // line number of the first data line (ascii)
};

// An element with entries but no properties would take no bytes per entry:
// its count could never be checked against the file, so it is refused.
void close_element(const PlyHeader& header, const std::string& path) {
    if (header.elements.empty()) return;
    const PlyElement& e = header.elements.back();
    if (e.count > 0 && e.properties.empty())
        fail_line(path, e.line, "element " + excerpt(e.name) + " declares " + std::to_string(e.count) +
                                    " entries but no properties");
}

PlyHeader read_ply_header(const std::string& path, std::string_view text) {
    PlyHeader header;
    LineReader reader(text);
    std::string_view line;
    if (!reader.next(line, 0) || take_token(line) != "ply") fail(path, "not a PLY file (no 'ply' magic line)");
    bool have_format = false;
    while (true) {
        if (!reader.next(line, 0)) fail(path, "truncated header (no end_header)");
        const std::size_t ln = reader.line_number();
        const auto t = tokens(line);
        if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
        if (t[0] == "end_header") break;
        if (t[0] == "format") {
            if (t.size() < 2) fail_line(path, ln, "format line without a format");
            if (t[1] == "ascii") header.format = PlyFormat::ascii;
            else if (t[1] == "binary_little_endian") header.format = PlyFormat::binary_le;
            else if (t[1] == "binary_big_endian") header.format = PlyFormat::binary_be;
            else fail_line(path, ln, "unknown PLY format " + excerpt(t[1]));
            have_format = true;
        } else if (t[0] == "element") {
            if (t.size() < 3) fail_line(path, ln, "expected 'element NAME COUNT'");
            close_element(header, path);
            PlyElement e;
            e.name = std::string(t[1]);
            e.line = ln;
            if (!parse_long(t[2], e.count) || e.count < 0 || e.count > std::numeric_limits<int>::max())
                fail_line(path, ln, "bad element count " + excerpt(t[2]));
            for (const PlyElement& other : header.elements)
                if (other.name == e.name)
                    fail_line(path, ln, "element " + excerpt(e.name) + " declared twice (first on line " +
                                            std::to_string(other.line) + ")");
            header.elements.push_back(std::move(e));
        } else if (t[0] == "property") {
            if (header.elements.empty()) fail_line(path, ln, "property before any element");
            PlyProperty p;
            if (t.size() >= 2 && t[1] == "list") {
                if (t.size() < 5) fail_line(path, ln, "expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
                p.is_list = true;
                if (!ply_type(t[2], p.count_type) || !ply_integral(p.count_type))
                    fail_line(path, ln, "bad list count type " + excerpt(t[2]));
                if (!ply_type(t[3], p.type)) fail_line(path, ln, "unknown property type " + excerpt(t[3]));
                p.name = std::string(t[4]);
            } else {
                if (t.size() < 3) fail_line(path, ln, "expected 'property TYPE NAME'");
                if (!ply_type(t[1], p.type)) fail_line(path, ln, "unknown property type " + excerpt(t[1]));
                p.name = std::string(t[2]);
            }
            header.elements.back().properties.push_back(std::move(p));
        } else {
            fail_line(path, ln, "unknown header keyword " + excerpt(t[0]));
        }
    }
    close_element(header, path);
    if (!have_format) fail(path, "header has no format line");
    header.body_offset = reader.offset();
    header.body_line = reader.line_number() + 1;
    return header;
}

// Reads values of the PLY body one at a time, in either encoding.
class PlySource {
public:
    PlySource(const std::string& path, std::string_view text, const PlyHeader& header)
        : path_(path), text_(text), format_(header.format),
          reader_(text, header.body_line, header.body_offset), pos_(header.body_offset) {}

    // `what` names the value for error messages, e.g. "vertex 12".
    double value(PlyType type, const char* what, long long index) {
        return format_ == PlyFormat::ascii ? ascii_value(type, what, index) : binary_value(type, what, index);
    }

    // The line of the last value read (ascii), 0 for binary data.
    std::size_t line() const { return format_ == PlyFormat::ascii ? reader_.line_number() : 0; }

    // Bytes not read yet, and the least one value of `type` takes: binary
    // its size; ascii one character and a separator (the last one none).
    std::size_t remaining() const {
        return format_ == PlyFormat::ascii ? text_.size() - reader_.offset() + line_.size() : text_.size() - pos_;
    }
    long double least_bytes(PlyType type, long double values) const {
        if (values <= 0) return 0;
        return format_ == PlyFormat::ascii ? 2 * values - 1 : values * static_cast<long double>(ply_size(type));
    }

private:
    double ascii_value(PlyType type, const char* what, long long index) {
        std::string_view tok = take_token(line_);
        while (tok.empty()) {
            if (!reader_.next_nonblank(line_, 0))
                fail(path_, std::string("truncated: data ends in ") + what + " " + std::to_string(index));
            tok = take_token(line_);
        }
        const std::size_t ln = reader_.line_number();
        double v = 0;
        if (ply_integral(type)) {
            long long i = 0;
            if (!parse_long(tok, i)) fail_line(path_, ln, std::string("bad integer ") + excerpt(tok) + " in " + what);
            if (i < ply_min(type) || i > ply_max(type))
                fail_line(path_, ln, std::string("integer ") + excerpt(tok) + " in " + what +
                                         " is out of range for its type");
            v = static_cast<double>(i);
        } else if (!parse_double(tok, v)) {
            fail_line(path_, ln, std::string("bad number ") + excerpt(tok) + " in " + what);
        }
        return v;
    }

    double binary_value(PlyType type, const char* what, long long index) {
        const std::size_t n = ply_size(type);
        if (pos_ + n > text_.size())
            fail(path_, std::string("truncated binary data in ") + what + " " + std::to_string(index) +
                            " (file has " + std::to_string(text_.size()) + " bytes)");
        unsigned char b[8];
        std::memcpy(b, text_.data() + pos_, n);
        pos_ += n;
        const bool file_le = format_ == PlyFormat::binary_le;
        if (file_le != (std::endian::native == std::endian::little)) std::reverse(b, b + n);
        switch (type) {
            case PlyType::i8: return load<std::int8_t>(b);
            case PlyType::u8: return load<std::uint8_t>(b);
            case PlyType::i16: return load<std::int16_t>(b);
            case PlyType::u16: return load<std::uint16_t>(b);
            case PlyType::i32: return load<std::int32_t>(b);
            case PlyType::u32: return load<std::uint32_t>(b);
            case PlyType::f32: return load<float>(b);
            case PlyType::f64: return load<double>(b);
        }
        return 0;
    }

    template <class T>
    static double load(const unsigned char* b) {
        T v;
        std::memcpy(&v, b, sizeof(T));
        return static_cast<double>(v);
    }

    const std::string& path_;
    std::string_view text_;
    PlyFormat format_;
    LineReader reader_;
    std::string_view line_;
    std::size_t pos_;
};

int property_index(const PlyElement& e, std::initializer_list<std::string_view> names) {
    for (std::size_t i = 0; i < e.properties.size(); ++i)
        for (std::string_view n : names)
            if (e.properties[i].name == n) return static_cast<int>(i);
    return -1;
}

}  // namespace

// float32 unless options.ply_double: the normals take the same type.
std::string ply_bytes(MeshView mesh, const MeshWriteOptions& options) {
    const std::string type = options.ply_double ? "double" : "float";
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment " + header_comment(mesh) +
                      "\nelement vertex " + std::to_string(mesh.positions.size()) + "\n";
    check_colours(mesh, options.colours);
    for (const char* name : {"x", "y", "z", "nx", "ny", "nz"}) out += "property " + type + " " + name + "\n";
    if (!options.colours.empty())
        for (const char* name : {"red", "green", "blue"}) out += std::string("property uchar ") + name + "\n";
    out += "element face " + std::to_string(mesh.faces.size()) +
           "\nproperty list uchar int vertex_indices\nend_header\n";
    const std::size_t scalar = options.ply_double ? 8 : 4;
    out.reserve(out.size() + mesh.positions.size() * 6 * scalar + mesh.faces.size() * 13);
    const std::vector<Vec3> normals = stored_normals(mesh);
    const auto put = [&](const Vec3& v) {
        for (int k = 0; k < 3; ++k) {
            if (options.ply_double) append_le(out, v[k]);
            else append_le(out, static_cast<float>(v[k]));
        }
    };
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        put(mesh.positions[i]);
        put(normals[i]);
        if (!options.colours.empty())
            for (int k = 0; k < 3; ++k)
                append_le(out, static_cast<std::uint8_t>(std::lround(255.0 * srgb_encode(options.colours[4 * i + k]))));
    }
    for (const Face& f : mesh.faces) {
        append_le(out, std::uint8_t{3});
        for (int v : f) append_le(out, static_cast<std::int32_t>(v));
    }
    return out;
}

MeshArrays read_ply(const std::string& path, std::string_view text) {
    const PlyHeader header = read_ply_header(path, text);
    const auto find = [&](std::string_view name) -> const PlyElement* {
        for (const PlyElement& e : header.elements)
            if (e.name == name) return &e;
        return nullptr;
    };
    const PlyElement* vertex = find("vertex");
    if (!vertex) fail(path, "no 'vertex' element");
    int xyz[3];
    for (int k = 0; k < 3; ++k) {
        const char* name[] = {"x", "y", "z"};
        xyz[k] = property_index(*vertex, {name[k]});
        if (xyz[k] < 0 || vertex->properties[xyz[k]].is_list)
            fail(path, std::string("vertex element has no scalar property '") + name[k] + "'");
    }
    const PlyElement* face = find("face");
    int indices = -1;
    if (face) {
        indices = property_index(*face, {"vertex_indices", "vertex_index"});
        if (indices < 0 || !face->properties[indices].is_list)
            fail(path, "face element has no list property 'vertex_indices'");
        if (!ply_integral(face->properties[indices].type))
            fail(path, "vertex_indices must have an integer item type");
    }
    check_vertex_count(vertex->count, path);

    PlySource src(path, text, header);
    // Every count the header declares, against the bytes after it, before
    // anything is allocated or looped over (lists count as empty here).
    {
        long double needed = 0;
        long double values = 0;
        for (const PlyElement& e : header.elements) {
            long double entry = 0;
            for (const PlyProperty& p : e.properties) entry += src.least_bytes(p.is_list ? p.count_type : p.type, 1);
            needed += entry * e.count;
            values += static_cast<long double>(e.properties.size()) * e.count;
        }
        if (header.format == PlyFormat::ascii) needed = src.least_bytes(PlyType::u8, values);
        std::string declared = "header declares";
        std::size_t named = 0;
        for (const PlyElement& e : header.elements)
            if (e.count > 0 && named++ < 4) declared += (named > 1 ? ", " : " ") + std::to_string(e.count) + " " + e.name;
        if (named > 4) declared += " and " + std::to_string(named - 4) + " more elements";
        check_room(needed, src.remaining(), path, declared);
    }

    MeshArrays mesh;
    mesh.positions.reserve(static_cast<std::size_t>(vertex->count));  // bounded by the file size (checked above)
    std::vector<int> corners;
    for (const PlyElement& e : header.elements) {
        const bool is_vertex = &e == vertex;
        const bool is_face = &e == face;
        const std::string what = e.name;
        for (long long i = 0; i < e.count; ++i) {
            Vec3 p = Vec3::Zero();
            for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
                const PlyProperty& prop = e.properties[k];
                if (!prop.is_list) {
                    const double v = src.value(prop.type, what.c_str(), i);
                    if (is_vertex)
                        for (int c = 0; c < 3; ++c)
                            if (xyz[c] == k) p[c] = v;
                    continue;
                }
                const double n = src.value(prop.count_type, what.c_str(), i);  // an integer type: exact
                if (n < 0) fail_at(path, src.line(), what + " " + std::to_string(i) + ": negative list length");
                const auto items = static_cast<long long>(n);
                const long double least = src.least_bytes(prop.type, n);
                if (least > src.remaining())  // the message is only built when it is needed
                    check_room(least, src.remaining(), path,
                               what + " " + std::to_string(i) + " declares a list of " + std::to_string(items) +
                                   " items",
                               "a truncated file or a count that lies", src.line());
                const bool keep = is_face && k == indices;
                if (keep) {
                    if (n < 3)
                        fail_at(path, src.line(), "face " + std::to_string(i) + " has " + std::to_string(items) +
                                       " corners (needs at least 3)");
                    check_triangle_count(mesh.faces.size(), items, path, src.line());
                    corners.clear();
                }
                for (long long j = 0; j < items; ++j) {
                    const double v = src.value(prop.type, what.c_str(), i);  // indices: an integer type, exact
                    if (!keep) continue;
                    if (!(v >= 0 && v < static_cast<double>(vertex->count)))
                        fail_at(path, src.line(), "face " + std::to_string(i) + ": vertex index " +
                                       std::to_string(static_cast<long long>(v)) + " out of range [0, " +
                                       std::to_string(vertex->count) + ")");
                    corners.push_back(static_cast<int>(v));
                }
                if (keep) add_polygon(mesh.faces, corners, path, src.line());
            }
            if (is_vertex) {
                check_position(p, path, "vertex", i, src.line());
                mesh.positions.push_back(p);
            }
        }
    }
    return mesh;
}

}  // namespace morphogen::mesh_io_detail
