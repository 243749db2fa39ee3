// Mesh file writers and readers (see mesh_io.hpp). Writers build the whole
// file in memory and write it with one call, so a failed write is detected in
// one place and the partial file is removed. Readers load the whole file and
// parse it from memory; every error names the file (and line for text).
#include "mesh_io.hpp"

#include "errors.hpp"

#include <Eigen/Geometry>
#include <tiny_gltf.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>
#include <system_error>

namespace morphogen {
namespace {

static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big,
              "mixed-endian hosts are not supported");

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

// ---------------------------------------------------------------- file access

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

// ---------------------------------------------------------------- writers

void check_indices(MeshView mesh, const std::string& path) {
    const auto nv = static_cast<long long>(mesh.positions.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int v : mesh.faces[f])
            if (v < 0 || v >= nv)
                fail(path, "cannot write: face " + std::to_string(f) + " has vertex index " +
                               std::to_string(v) + " out of range [0, " + std::to_string(nv) + ")");
}

// 17 significant digits: enough to read back every double exactly.
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

template <class T>
void append_le(std::string& out, T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

std::string header_comment(MeshView mesh) {
    return "morphogen mesh: " + std::to_string(mesh.positions.size()) + " vertices, " +
           std::to_string(mesh.faces.size()) + " triangles, Z up";
}

// The text formats share their body: one line per vertex ("<prefix>x y z")
// and one per face ("<prefix>i j k", indices from `first_index`).
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

std::string obj_bytes(MeshView mesh) {
    std::string out;
    out.reserve(text_size_guess(mesh));
    out += "# " + header_comment(mesh) + "\n";
    append_text_body(out, mesh, "v ", "f", 1);
    return out;
}

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

std::string ply_bytes(MeshView mesh) {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment " + header_comment(mesh) +
                      "\nelement vertex " + std::to_string(mesh.positions.size()) +
                      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                      std::to_string(mesh.faces.size()) +
                      "\nproperty list uchar int vertex_indices\nend_header\n";
    out.reserve(out.size() + mesh.positions.size() * 24 + mesh.faces.size() * 13);
    for (const Vec3& p : mesh.positions) {
        append_le(out, p.x());
        append_le(out, p.y());
        append_le(out, p.z());
    }
    for (const Face& f : mesh.faces) {
        append_le(out, std::uint8_t{3});
        for (int v : f) append_le(out, static_cast<std::int32_t>(v));
    }
    return out;
}

Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const double len = n.norm();
    return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

std::string stl_bytes(MeshView mesh) {
    std::string out(80, ' ');
    const std::string title = "binary STL, " + header_comment(mesh);
    out.replace(0, std::min<std::size_t>(title.size(), 80), title, 0, 80);
    out.reserve(84 + mesh.faces.size() * 50);
    append_le(out, static_cast<std::uint32_t>(mesh.faces.size()));
    const auto put = [&out](const Vec3& v) {
        append_le(out, static_cast<float>(v.x()));
        append_le(out, static_cast<float>(v.y()));
        append_le(out, static_cast<float>(v.z()));
    };
    for (const Face& f : mesh.faces) {
        const Vec3& a = mesh.positions[f[0]];
        const Vec3& b = mesh.positions[f[1]];
        const Vec3& c = mesh.positions[f[2]];
        put(unit_normal(a, b, c));
        put(a);
        put(b);
        put(c);
        append_le(out, std::uint16_t{0});
    }
    return out;
}

// glTF is Y-up, right-handed; our meshes are Z-up: (x, y, z) -> (x, z, -y)
// is a proper rotation, so orientation (and outward normals) are kept.
Vec3 to_y_up(const Vec3& p) { return {p.x(), p.z(), -p.y()}; }

// Area-weighted vertex normals (smooth shading for viewers), already Y-up.
std::vector<Vec3> smooth_normals_y_up(MeshView mesh) {
    std::vector<Vec3> normals(mesh.positions.size(), Vec3::Zero());
    for (const Face& f : mesh.faces) {
        const Vec3 n = (mesh.positions[f[1]] - mesh.positions[f[0]])
                           .cross(mesh.positions[f[2]] - mesh.positions[f[0]]);
        for (int v : f) normals[v] += n;
    }
    for (Vec3& n : normals) {
        const double len = n.norm();
        n = len > 0 && std::isfinite(len) ? Vec3(to_y_up(n / len)) : Vec3(0, 1, 0);
    }
    return normals;
}

template <class T>
void append_raw(std::vector<unsigned char>& out, T value) {
    const auto size = out.size();
    out.resize(size + sizeof(T));
    std::memcpy(out.data() + size, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big)
        std::reverse(out.begin() + static_cast<std::ptrdiff_t>(size), out.end());
}

int add_view(tinygltf::Model& model, std::size_t offset, std::size_t length, int target) {
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = length;
    view.target = target;
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component, int type, std::size_t count) {
    tinygltf::Accessor acc;
    acc.bufferView = view;
    acc.byteOffset = 0;
    acc.componentType = component;
    acc.type = type;
    acc.count = count;
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size()) - 1;
}

tinygltf::Model gltf_model(MeshView mesh) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "morphogen";

    tinygltf::Material material;
    material.name = "plant";
    material.doubleSided = true;  // grown meshes are viewed from inside too (open canopies)
    material.pbrMetallicRoughness.baseColorFactor = {0.33, 0.62, 0.24, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.8;
    model.materials.push_back(material);

    tinygltf::Node node;
    node.name = "morphogen";
    // glTF requires count >= 1 in accessors and byteLength >= 1 in buffers:
    // an empty mesh becomes a scene with one empty node.
    if (!mesh.positions.empty() && !mesh.faces.empty()) {
        const std::size_t nv = mesh.positions.size();
        std::vector<unsigned char> data;
        data.reserve(nv * 24 + mesh.faces.size() * 12);
        Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
        Eigen::Vector3f hi = -lo;
        for (const Vec3& p : mesh.positions) {
            const Eigen::Vector3f q = to_y_up(p).cast<float>();
            lo = lo.cwiseMin(q);
            hi = hi.cwiseMax(q);
            for (int k = 0; k < 3; ++k) append_raw(data, q[k]);
        }
        for (const Vec3& n : smooth_normals_y_up(mesh))
            for (int k = 0; k < 3; ++k) append_raw(data, static_cast<float>(n[k]));
        for (const Face& f : mesh.faces)
            for (int v : f) append_raw(data, static_cast<std::uint32_t>(v));

        const int pos_view = add_view(model, 0, nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
        const int nrm_view = add_view(model, nv * 12, nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
        const int idx_view = add_view(model, nv * 24, mesh.faces.size() * 12,
                                      TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        const int pos = add_accessor(model, pos_view, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                     TINYGLTF_TYPE_VEC3, nv);
        model.accessors[pos].minValues = {lo.x(), lo.y(), lo.z()};
        model.accessors[pos].maxValues = {hi.x(), hi.y(), hi.z()};
        const int nrm = add_accessor(model, nrm_view, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                     TINYGLTF_TYPE_VEC3, nv);
        const int idx = add_accessor(model, idx_view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                     TINYGLTF_TYPE_SCALAR, mesh.faces.size() * 3);
        tinygltf::Buffer buffer;
        buffer.data = std::move(data);
        model.buffers.push_back(std::move(buffer));

        tinygltf::Primitive prim;
        prim.attributes["POSITION"] = pos;
        prim.attributes["NORMAL"] = nrm;
        prim.indices = idx;
        prim.material = 0;
        prim.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh gmesh;
        gmesh.name = "morphogen";
        gmesh.primitives.push_back(prim);
        model.meshes.push_back(gmesh);
        node.mesh = 0;
    }
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    return model;
}

std::string glb_bytes(MeshView mesh, const std::string& path) {
    const tinygltf::Model model = gltf_model(mesh);
    std::ostringstream stream;
    tinygltf::TinyGLTF gltf;
    if (!gltf.WriteGltfSceneToStream(&model, stream, false, true))
        fail(path, "cannot encode glTF binary");
    return std::move(stream).str();
}

// ---------------------------------------------------------------- text parsing

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

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
    return "'" + std::string(s.substr(0, max)) + (s.size() > max ? "...'" : "'");
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

// A finite coordinate; throws naming the line otherwise.
double coordinate(std::string_view tok, const std::string& path, std::size_t line) {
    double v = 0;
    if (!parse_double(tok, v)) fail_line(path, line, "bad number " + excerpt(tok));
    if (!std::isfinite(v)) fail_line(path, line, "coordinate " + excerpt(tok) + " is not finite");
    return v;
}

// Counts in headers are only trusted this far for preallocation.
constexpr long long kMaxReserve = 1 << 20;

// Appends polygon `corners` as a triangle fan (0,i,i+1).
void add_polygon(std::vector<Face>& faces, const std::vector<int>& corners) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
        faces.push_back({corners[0], corners[i], corners[i + 1]});
}

// ---------------------------------------------------------------- OBJ

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

// ---------------------------------------------------------------- OFF

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

    MeshArrays mesh;
    mesh.positions.reserve(static_cast<std::size_t>(std::min(nv, kMaxReserve)));  // a header may lie
    for (long long i = 0; i < nv; ++i) {
        if (!reader.next_nonblank(line))
            fail(path, "truncated: found " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
        const std::size_t ln = reader.line_number();
        const auto t = tokens(line);
        if (t.size() < 3) fail_line(path, ln, "vertex needs 3 coordinates, found " + std::to_string(t.size()));
        mesh.positions.emplace_back(coordinate(t[0], path, ln), coordinate(t[1], path, ln),
                                    coordinate(t[2], path, ln));
    }
    std::vector<int> corners;
    for (long long i = 0; i < nf; ++i) {
        if (!reader.next_nonblank(line))
            fail(path, "truncated: found " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
        const std::size_t ln = reader.line_number();
        const auto t = tokens(line);
        long long n = 0;
        if (!parse_long(t[0], n) || n < 0) fail_line(path, ln, "bad corner count " + excerpt(t[0]));
        if (n < 3) fail_line(path, ln, "face with " + std::to_string(n) + " corners (needs at least 3)");
        if (static_cast<long long>(t.size()) - 1 < n)
            fail_line(path, ln, "face lists " + std::to_string(t.size() - 1) + " of its " + std::to_string(n) + " corners");
        corners.clear();
        for (long long k = 1; k <= n; ++k) {  // tokens after the n indices (colours) are ignored
            long long v = 0;
            if (!parse_long(t[k], v)) fail_line(path, ln, "bad vertex index " + excerpt(t[k]));
            if (v < 0 || v >= nv)
                fail_line(path, ln, "vertex index " + std::to_string(v) + " out of range [0, " + std::to_string(nv) + ")");
            corners.push_back(static_cast<int>(v));
        }
        add_polygon(mesh.faces, corners);
    }
    return mesh;
}

// ---------------------------------------------------------------- PLY

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

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::f32;  // item type for lists
    bool is_list = false;
    PlyType count_type = PlyType::u8;
};

struct PlyElement {
    std::string name;
    long long count = 0;
    std::vector<PlyProperty> properties;
};

enum class PlyFormat { ascii, binary_le, binary_be };

struct PlyHeader {
    PlyFormat format = PlyFormat::ascii;
    std::vector<PlyElement> elements;
    std::size_t body_offset = 0;  // byte offset of the data after end_header
    std::size_t body_line = 0;    // line number of the first data line (ascii)
};

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
            PlyElement e;
            e.name = std::string(t[1]);
            if (!parse_long(t[2], e.count) || e.count < 0 || e.count > std::numeric_limits<int>::max())
                fail_line(path, ln, "bad element count " + excerpt(t[2]));
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
    int indices = -1;
    if (const PlyElement* face = find("face")) {
        indices = property_index(*face, {"vertex_indices", "vertex_index"});
        if (indices < 0 || !face->properties[indices].is_list)
            fail(path, "face element has no list property 'vertex_indices'");
        if (!ply_integral(face->properties[indices].type))
            fail(path, "vertex_indices must have an integer item type");
    }

    MeshArrays mesh;
    PlySource src(path, text, header);
    std::vector<int> corners;
    for (const PlyElement& e : header.elements) {
        const bool is_vertex = &e == vertex;
        const bool is_face = e.name == "face" && indices >= 0;
        const std::string what = e.name;
        if (is_vertex) mesh.positions.reserve(static_cast<std::size_t>(std::min(e.count, kMaxReserve)));
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
                const double n = src.value(prop.count_type, what.c_str(), i);
                if (n < 0) fail(path, what + " " + std::to_string(i) + ": negative list length");
                const bool keep = is_face && k == indices;
                if (keep) {
                    if (n < 3)
                        fail(path, "face " + std::to_string(i) + " has " + std::to_string(static_cast<long long>(n)) +
                                       " corners (needs at least 3)");
                    corners.clear();
                }
                for (long long j = 0; j < static_cast<long long>(n); ++j) {
                    const double v = src.value(prop.type, what.c_str(), i);
                    if (!keep) continue;
                    if (v < 0 || v >= static_cast<double>(vertex->count))
                        fail(path, "face " + std::to_string(i) + ": vertex index " +
                                       std::to_string(static_cast<long long>(v)) + " out of range [0, " +
                                       std::to_string(vertex->count) + ")");
                    corners.push_back(static_cast<int>(v));
                }
                if (keep) add_polygon(mesh.faces, corners);
            }
            if (is_vertex) {
                if (!p.allFinite())
                    fail(path, "vertex " + std::to_string(i) + " has a coordinate that is not finite");
                mesh.positions.push_back(p);
            }
        }
    }
    return mesh;
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

std::string mesh_bytes(MeshView mesh, MeshFormat format, const std::string& path) {
    check_indices(mesh, path);
    switch (format) {
        case MeshFormat::obj: return obj_bytes(mesh);
        case MeshFormat::ply: return ply_bytes(mesh);
        case MeshFormat::off: return off_bytes(mesh);
        case MeshFormat::stl: return stl_bytes(mesh);
        case MeshFormat::glb: return glb_bytes(mesh, path);
    }
    fail(path, "unknown mesh format");
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
