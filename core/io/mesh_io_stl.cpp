// STL: binary writer; reader of binary and ASCII STL that welds corners at
// exactly equal positions into shared vertices (STL stores none).
#include "core/io/mesh_io_detail.hpp"

#include <cstdint>
#include <string>
#include <unordered_map>

namespace morphogen::mesh_io_detail {

namespace {

Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const double len = n.norm();
    return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

// Corners -> shared vertices, numbered in order of first appearance.
class Welder {
public:
    Welder(MeshArrays& mesh, const std::string& path, std::size_t expected_corners)
        : mesh_(mesh), path_(path) {
        index_.reserve(std::min<std::size_t>(expected_corners, kMaxMeshVertices));
    }

    int vertex(Vec3 p) {
        p.array() += 0.0;  // -0 becomes +0: equal positions get equal keys
        Key key;
        std::memcpy(key.bits, p.data(), sizeof key.bits);
        const auto [it, added] = index_.try_emplace(key, static_cast<int>(mesh_.positions.size()));
        if (added) {
            check_vertex_count(static_cast<long long>(mesh_.positions.size()) + 1, path_);
            mesh_.positions.push_back(p);
        }
        return it->second;
    }

private:
    struct Key {
        std::uint64_t bits[3];
        bool operator==(const Key& o) const { return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2]; }
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            std::uint64_t h = 0x9e3779b97f4a7c15ULL;
            for (std::uint64_t b : k.bits) h = (h ^ b) * 0x100000001b3ULL + (h >> 29);
            return static_cast<std::size_t>(h);
        }
    };
    MeshArrays& mesh_;
    const std::string& path_;
    std::unordered_map<Key, int, KeyHash> index_;
};

float load_float_le(const char* p) {
    unsigned char b[4];
    std::memcpy(b, p, 4);
    if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + 4);
    float v;
    std::memcpy(&v, b, 4);
    return v;
}

std::uint32_t load_u32_le(const char* p) {
    unsigned char b[4];
    std::memcpy(b, p, 4);
    return std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 | std::uint32_t{b[3]} << 24;
}

MeshArrays read_binary_stl(const std::string& path, std::string_view bytes, std::uint32_t count) {
    MeshArrays mesh;
    if (count > kMaxMeshTriangles)
        fail(path, "more than " + std::to_string(kMaxMeshTriangles) + " triangles (the limit for mesh files)");
    mesh.faces.reserve(count);  // the file holds them all (its size was checked)
    Welder welder(mesh, path, std::size_t{3} * count);
    for (std::uint32_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + 84 + std::size_t{50} * t;  // normal, 3 corners, attribute
        Face face;
        for (int k = 0; k < 3; ++k) {
            const char* c = record + 12 + 12 * k;
            const Vec3 p(load_float_le(c), load_float_le(c + 4), load_float_le(c + 8));
            check_position(p, path, "triangle", t);
            face[k] = welder.vertex(p);
        }
        mesh.faces.push_back(face);
    }
    return mesh;
}

// Tokens of an ASCII STL across lines, with the line of the last one.
class StlTokens {
public:
    explicit StlTokens(std::string_view text) : reader_(text) {}
    std::string_view next() {
        std::string_view tok = take_token(line_);
        while (tok.empty() && reader_.next(line_, 0)) tok = take_token(line_);
        return tok;
    }
    void skip_line() { line_ = {}; }  // a solid's name
    std::size_t line() const { return reader_.line_number(); }

private:
    LineReader reader_;
    std::string_view line_;
};

MeshArrays read_ascii_stl(const std::string& path, std::string_view text) {
    StlTokens in(text);
    const auto expect = [&](std::string_view word) {
        const std::string_view tok = in.next();
        if (tok.empty()) fail(path, "truncated: file ends where '" + std::string(word) + "' was expected");
        if (tok != word) fail_line(path, in.line(), "expected '" + std::string(word) + "', found " + excerpt(tok));
    };
    const auto number = [&](std::string_view tok) {
        if (tok.empty()) fail(path, "truncated: file ends inside a facet");
        return coordinate(tok, path, in.line());
    };
    MeshArrays mesh;
    Welder welder(mesh, path, 0);
    std::vector<int> corners(3);
    expect("solid");
    in.skip_line();
    while (true) {
        const std::string_view tok = in.next();
        if (tok.empty()) fail(path, "truncated: no 'endsolid'");
        if (tok == "endsolid") {
            in.skip_line();
            const std::string_view after = in.next();
            if (after.empty()) break;
            if (after != "solid") fail_line(path, in.line(), "expected 'solid' or the end after 'endsolid', found " + excerpt(after));
            in.skip_line();
            continue;
        }
        if (tok != "facet") fail_line(path, in.line(), "expected 'facet' or 'endsolid', found " + excerpt(tok));
        expect("normal");
        for (int k = 0; k < 3; ++k) {  // read and checked, not used: the corners' order decides orientation
            const std::string_view n = in.next();
            double v = 0;
            if (n.empty()) fail(path, "truncated: file ends inside a facet");
            if (!parse_double(n, v)) fail_line(path, in.line(), "bad number " + excerpt(n));
        }
        expect("outer");
        expect("loop");
        for (int k = 0; k < 3; ++k) {
            expect("vertex");
            Vec3 p;
            for (int c = 0; c < 3; ++c) p[c] = number(in.next());
            corners[k] = welder.vertex(p);
        }
        expect("endloop");  // a fourth 'vertex' here is refused: STL facets are triangles
        expect("endfacet");
        add_polygon(mesh.faces, corners, path, in.line());
    }
    return mesh;
}

bool starts_with_solid(std::string_view bytes) {
    std::size_t i = 0;
    while (i < bytes.size() && (is_space(bytes[i]) || bytes[i] == '\n')) ++i;
    return bytes.substr(i, 5) == "solid" && (i + 5 == bytes.size() || is_space(bytes[i + 5]) || bytes[i + 5] == '\n');
}

}  // namespace

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

// Binary when the size matches the triangle count at byte 80 exactly (some
// binary files also start with "solid"); else ASCII if it starts with "solid".
MeshArrays read_stl(const std::string& path, std::string_view bytes) {
    const bool solid = starts_with_solid(bytes);
    if (bytes.size() >= 84) {
        const std::uint32_t count = load_u32_le(bytes.data() + 80);
        const std::uint64_t size = 84 + std::uint64_t{50} * count;
        if (size == bytes.size()) return read_binary_stl(path, bytes, count);
        if (!solid)
            fail(path, "binary STL declares " + std::to_string(count) + " triangles, which need " +
                           std::to_string(size) + " bytes, but the file has " + std::to_string(bytes.size()));
    }
    if (!solid)
        fail(path, "not an STL file: " + std::to_string(bytes.size()) +
                       " bytes, too short for binary STL (84-byte header) and no ASCII 'solid' line");
    return read_ascii_stl(path, bytes);
}

}  // namespace morphogen::mesh_io_detail
