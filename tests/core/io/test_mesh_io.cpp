// Mesh files: exact round trips (OBJ, PLY, OFF), STL/GLB structure, and a
// clear IoError naming the file for every malformed input.
#include "core/base/errors.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/mesh_io_detail.hpp"
#include "core/mesh/mesh.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

using namespace morphogen;
using morphogen::testing::read_text;
using morphogen::testing::TempDir;
namespace fs = std::filesystem;

namespace {

// Unit cube with outward faces, corners at awkward (non-short) coordinates so
// that exactness is really tested.
MeshArrays awkward_cube() {
    MeshArrays m;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
    for (int i = 0; i < 8; ++i)
        m.positions.emplace_back((i & 1 ? 1.0 : 0.0) + jitter(rng) / 3.0, (i & 2 ? 1.0 : 0.0) + 1e-17 * i,
                                 (i & 4 ? 1.0 : 0.0) + std::nextafter(0.1, 1.0) * 1e-6 * i);
    m.positions[3].x() = -1.2345678901234567e-300;  // tiny, subnormal-adjacent magnitudes too
    m.positions[5].y() = 602214085.70000005;  // near the coordinate limit (1e9)
    m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
               {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

void require_identical(const MeshArrays& a, const MeshArrays& b) {
    REQUIRE(a.positions.size() == b.positions.size());
    REQUIRE(a.faces == b.faces);
    for (std::size_t i = 0; i < a.positions.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            INFO("vertex " << i << " coordinate " << k);
            REQUIRE(std::memcmp(&a.positions[i][k], &b.positions[i][k], sizeof(double)) == 0);
        }
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

template <class T>
T load_le(const std::string& bytes, std::size_t offset) {
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof(T));
    return v;  // test hosts are little-endian
}

std::string write_and_name(const MeshArrays& m, const std::string& path) {
    write_mesh(m.view(), path);
    return path;
}

// Reading `path` must throw IoError whose message names the file and contains `what`.
void require_read_error(const std::string& path, const std::string& what) {
    try {
        read_mesh(path);
        FAIL("no IoError for " << path);
    } catch (const IoError& e) {
        const std::string msg = e.what();
        INFO(msg);
        CHECK(msg.find(path) != std::string::npos);
        CHECK(msg.find(what) != std::string::npos);
    }
}

}  // namespace

TEST_CASE("mesh format is chosen by extension, case-insensitively", "[mesh_io]") {
    CHECK(mesh_format_from_path("a/b.OBJ").name == "OBJ");
    CHECK(mesh_format_from_path("x.ply").name == "PLY");
    CHECK(mesh_format_from_path("x.Off").name == "OFF");
    CHECK(mesh_format_from_path("x.stl").name == "STL");
    CHECK(mesh_format_from_path("x.glb").name == "GLB");
    CHECK(&mesh_format_from_path("x.GLB") == &mesh_format(".glb"));
    CHECK_THROWS_AS(mesh_format_from_path("x.txt"), IoError);
    CHECK_THROWS_WITH(mesh_format_from_path("noext"), Catch::Contains("noext"));
    CHECK_THROWS_WITH(mesh_format_from_path("x.txt"), Catch::Contains("(expected .obj, .ply, .off, .stl or .glb)"));
    CHECK_THROWS_AS(mesh_format(".txt"), std::invalid_argument);
}

TEST_CASE("the table of formats: one row per extension, each written and read back", "[mesh_io]") {
    TempDir tmp;
    const MeshArrays cube = awkward_cube();
    std::set<std::string_view> extensions;
    std::set<char> tags;
    for (const MeshFormat& format : mesh_formats()) {
        INFO(format.name);
        CHECK(extensions.insert(format.extension).second);
        CHECK(format.extension.starts_with('.'));
        REQUIRE(format.write != nullptr);
        REQUIRE(format.read != nullptr);
        // The dispatch reaches the row: write_mesh by extension gives the row's bytes.
        const std::string path = tmp.file("t" + std::string(format.extension));
        write_mesh(cube.view(), path);
        CHECK(read_text(path) == format.write(cube.view(), {}, path));
        if (format.fuzz_tag != 0) CHECK(tags.insert(format.fuzz_tag).second);
        CHECK(read_mesh(path).faces.size() == cube.faces.size());
    }
    CHECK(mesh_extensions() == ".obj .ply .off .stl .glb");
    CHECK(colour_extensions() == ".obj, .ply or .glb");
    CHECK(tags == std::set<char>{'o', 'p', 'f', 's'});  // the fuzz corpus's tags
}

TEST_CASE("OBJ, PLY (doubles) and OFF round trips are bit-exact and keep order", "[mesh_io]") {
    TempDir tmp;
    const MeshArrays cube = awkward_cube();
    MeshWriteOptions doubles;
    doubles.ply_double = true;
    for (const char* name : {"m.obj", "m.ply", "m.off"}) {
        SECTION(name) {
            const std::string path = tmp.file(name);
            write_mesh(cube.view(), path, doubles);
            require_identical(cube, read_mesh(path));
            // Writing what was read gives the same bytes.
            const std::string again = tmp.file(std::string("again_") + name);
            write_mesh(read_mesh(path).view(), again, doubles);
            CHECK(slurp(path) == slurp(again));
        }
    }
}

TEST_CASE("float32 PLY, GLB and STL read back as the float-rounded mesh", "[mesh_io]") {
    TempDir tmp;
    const MeshArrays cube = awkward_cube();
    MeshArrays rounded = cube;
    for (Vec3& p : rounded.positions) p = p.cast<float>().cast<double>();
    require_identical(rounded, read_mesh(write_and_name(cube, tmp.file("f.ply"))));
    // GLB: the first mesh, turned from glTF's y up back to z up.
    require_identical(rounded, read_mesh(write_and_name(cube, tmp.file("f.glb"))));
    // STL has no shared vertices: the reader welds equal corners back, in
    // order of first appearance, which is the original order for this cube.
    const MeshArrays stl = read_mesh(write_and_name(cube, tmp.file("f.stl")));
    REQUIRE(stl.faces.size() == cube.faces.size());
    REQUIRE(stl.positions.size() == cube.positions.size());
    for (std::size_t f = 0; f < cube.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            INFO("face " << f << " corner " << k);
            CHECK(stl.positions[stl.faces[f][k]] == rounded.positions[cube.faces[f][k]]);
        }
}

TEST_CASE("a GLB cut short or with any byte changed is read or refused naming the file", "[mesh_io]") {
    TempDir tmp;
    const std::string bytes = slurp(write_and_name(awkward_cube(), tmp.file("f.glb")));
    CHECK_THROWS_WITH(parse_mesh(std::string_view(bytes).substr(0, bytes.size() - 8), mesh_format(".glb"), "cut.glb"),
                      Catch::Contains("cut.glb"));
    // Every byte changed: read or refused with an IoError, never a crash or another exception.
    std::size_t refused = 0;
    for (std::size_t at = 0; at < bytes.size(); ++at) {
        std::string bad = bytes;
        bad[at] = static_cast<char>(bad[at] ^ 0x5a);
        try {
            (void)parse_mesh(bad, mesh_format(".glb"), "bad.glb");
        } catch (const IoError&) {
            ++refused;
        }
    }
    CHECK(refused > 0);
}

TEST_CASE("OBJ writes 17 significant digits, smooth normals and v//vn faces", "[mesh_io]") {
    TempDir tmp;
    MeshArrays m;
    m.positions = {{0.1, 1.0, -2.5}, {1.0 / 3.0, 0, 1e-20}, {0, 1, 0}};
    m.faces = {{0, 1, 2}};
    const std::string path = tmp.file("m.obj");
    write_mesh(m.view(), path);
    const std::string text = slurp(path);
    CHECK(text.rfind("# ", 0) == 0);
    CHECK(text.find("v 0.10000000000000001 1 -2.5\n") != std::string::npos);
    CHECK(text.find("v 0.33333333333333331 0 9.9999999999999995e-21\n") != std::string::npos);
    CHECK(text.find("\nf 1//1 2//2 3//3\n") != std::string::npos);
    // One vn per vertex (here all the face's unit normal), shortest float digits.
    CHECK(std::count(text.begin(), text.end(), '\n') == 1 + 3 + 3 + 1);
    const Vec3 n = vertex_normals(m.view())[0];
    std::istringstream lines(text);
    int normals = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("vn ", 0) != 0) continue;
        ++normals;
        std::istringstream values(line.substr(3));
        float x = 0, y = 0, z = 0;
        values >> x >> y >> z;
        CHECK(x == static_cast<float>(n.x()));
        CHECK(y == static_cast<float>(n.y()));
        CHECK(z == static_cast<float>(n.z()));
        CHECK(line.size() < 3 + 3 * 16);  // float digits, not 17
    }
    CHECK(normals == 3);
    CHECK(read_mesh(path).faces == m.faces);
}

TEST_CASE("vertex normals are unit, area-weighted, and zero where undefined", "[mesh_io]") {
    MeshArrays m = awkward_cube();
    for (const Vec3& n : vertex_normals(m.view())) CHECK(n.norm() == Approx(1.0).epsilon(1e-12));
    // Corner 0 of the near-unit cube points out along (-1,-1,-1).
    CHECK(vertex_normals(m.view())[0].dot(Vec3(-1, -1, -1).normalized()) > 0.99);
    m.positions.emplace_back(5, 5, 5);  // on no face
    m.positions.emplace_back(1e300, 1e300, 1e300);
    CHECK(vertex_normals(m.view())[8] == Vec3::Zero());
    MeshArrays flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};  // zero area
    flat.faces = {{0, 1, 2}};
    for (const Vec3& n : vertex_normals(flat.view())) CHECK(n == Vec3::Zero());
}

TEST_CASE("PLY is binary little-endian, float32 by default, doubles on request, with normals", "[mesh_io]") {
    TempDir tmp;
    const MeshArrays cube = awkward_cube();
    const std::vector<Vec3> normals = vertex_normals(cube.view());
    for (const bool doubles : {false, true}) {
        INFO("doubles " << doubles);
        MeshWriteOptions options;
        options.ply_double = doubles;
        const std::string path = tmp.file(doubles ? "d.ply" : "f.ply");
        write_mesh(cube.view(), path, options);
        const std::string bytes = slurp(path);
        const std::string end = "end_header\n";
        const auto body = bytes.find(end) + end.size();
        CHECK(bytes.rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
        const std::string type = doubles ? "double" : "float";
        CHECK(bytes.find("property " + type + " x\nproperty " + type + " y\nproperty " + type + " z\nproperty " +
                         type + " nx\nproperty " + type + " ny\nproperty " + type + " nz\n") != std::string::npos);
        const std::size_t scalar = doubles ? 8 : 4;
        CHECK(bytes.size() == body + 8 * 6 * scalar + 12 * 13);
        if (doubles) {
            CHECK(load_le<double>(bytes, body) == cube.positions[0].x());
            CHECK(load_le<double>(bytes, body + 24) == normals[0].x());
        } else {
            CHECK(load_le<float>(bytes, body) == static_cast<float>(cube.positions[0].x()));
            CHECK(load_le<float>(bytes, body + 12) == static_cast<float>(normals[0].x()));
        }
    }
}

TEST_CASE("STL is binary with one 50-byte record and a unit normal per face", "[mesh_io]") {
    TempDir tmp;
    const MeshArrays cube = awkward_cube();
    const std::string path = tmp.file("m.stl");
    write_mesh(cube.view(), path);
    const std::string bytes = slurp(path);
    REQUIRE(bytes.size() == 84 + 50 * cube.faces.size());
    CHECK(bytes.substr(0, 5) != "solid");  // an ASCII-STL sniffing reader must not be fooled
    CHECK(load_le<std::uint32_t>(bytes, 80) == cube.faces.size());
    for (std::size_t f = 0; f < cube.faces.size(); ++f) {
        const std::size_t rec = 84 + 50 * f;
        const float nx = load_le<float>(bytes, rec), ny = load_le<float>(bytes, rec + 4),
                    nz = load_le<float>(bytes, rec + 8);
        CHECK(std::sqrt(nx * nx + ny * ny + nz * nz) == Approx(1.0f).epsilon(1e-5));
        CHECK(load_le<float>(bytes, rec + 12) == static_cast<float>(cube.positions[cube.faces[f][0]].x()));
    }
    // Face 2 = (4,5,6) is the top z=1 face: normal +z.
    CHECK(load_le<float>(bytes, 84 + 100 + 8) == Approx(1.0f).margin(1e-2));
}

TEST_CASE("GLB parses back with Y-up positions, normals, indices and a double-sided material", "[mesh_io]") {
    TempDir tmp;
    const MeshArrays cube = awkward_cube();
    const std::string path = tmp.file("m.glb");
    write_mesh(cube.view(), path);
    const std::string bytes = slurp(path);
    REQUIRE(bytes.substr(0, 4) == "glTF");
    CHECK(load_le<std::uint32_t>(bytes, 4) == 2);
    CHECK(load_le<std::uint32_t>(bytes, 8) == bytes.size());

    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    REQUIRE(loader.LoadBinaryFromFile(&model, &err, &warn, path));
    INFO(err << warn);
    REQUIRE(model.meshes.size() == 1);
    REQUIRE(model.materials.size() == 1);
    CHECK(model.materials[0].doubleSided);
    const auto& prim = model.meshes[0].primitives.at(0);
    CHECK(prim.mode == TINYGLTF_MODE_TRIANGLES);
    CHECK(prim.material == 0);
    const auto& pos = model.accessors.at(prim.attributes.at("POSITION"));
    const auto& nrm = model.accessors.at(prim.attributes.at("NORMAL"));
    const auto& idx = model.accessors.at(prim.indices);
    CHECK(pos.count == cube.positions.size());
    CHECK(nrm.count == cube.positions.size());
    CHECK(idx.count == 3 * cube.faces.size());
    CHECK(pos.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
    CHECK(idx.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    REQUIRE(pos.minValues.size() == 3);
    REQUIRE(pos.maxValues.size() == 3);

    const auto& view = model.bufferViews.at(pos.bufferView);
    const auto* data = model.buffers.at(view.buffer).data.data() + view.byteOffset + pos.byteOffset;
    for (std::size_t i = 0; i < cube.positions.size(); ++i) {
        float q[3];
        std::memcpy(q, data + 12 * i, 12);
        const Vec3& p = cube.positions[i];
        // (x, y, z) Z-up -> (x, z, -y) Y-up
        CHECK(q[0] == static_cast<float>(p.x()));
        CHECK(q[1] == static_cast<float>(p.z()));
        CHECK(q[2] == static_cast<float>(-p.y()));
        for (int k = 0; k < 3; ++k) {
            CHECK(q[k] >= pos.minValues[k]);
            CHECK(q[k] <= pos.maxValues[k]);
        }
    }
    const auto& iview = model.bufferViews.at(idx.bufferView);
    std::uint32_t first[3];
    std::memcpy(first, model.buffers.at(iview.buffer).data.data() + iview.byteOffset + idx.byteOffset, 12);
    CHECK(first[0] == 0);
    CHECK(first[1] == 2);
    CHECK(first[2] == 1);
}

TEST_CASE("an empty mesh still writes valid files", "[mesh_io]") {
    TempDir tmp;
    const MeshArrays empty;
    for (const char* name : {"e.obj", "e.ply", "e.off", "e.stl", "e.glb"}) {
        INFO(name);
        CHECK_NOTHROW(write_mesh(empty.view(), tmp.file(name)));
    }
    CHECK(read_mesh(tmp.file("e.obj")).positions.empty());
    CHECK(read_mesh(tmp.file("e.ply")).faces.empty());
    CHECK(read_mesh(tmp.file("e.off")).faces.empty());
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    CHECK(loader.LoadBinaryFromFile(&model, &err, &warn, tmp.file("e.glb")));
}

TEST_CASE("writing fails with IoError naming the path and leaves no file", "[mesh_io]") {
    TempDir tmp;
    const MeshArrays cube = awkward_cube();
    const std::string path = tmp.file("no/such/dir/m.obj");
    CHECK_THROWS_WITH(write_mesh(cube.view(), path), Catch::Contains(path));
    MeshArrays bad = cube;
    bad.faces[3][1] = 8;
    const std::string bad_path = tmp.file("bad.obj");
    CHECK_THROWS_AS(write_mesh(bad.view(), bad_path), IoError);
    CHECK_FALSE(fs::exists(bad_path));
#ifdef __linux__
    // A full disk: the stream fails on close; the error must surface. Only as a
    // non-root user, who could never delete the device if the code regressed.
    if (::geteuid() != 0 && fs::exists("/dev/full")) {
        MeshArrays big = cube;
        big.positions.resize(100000, Vec3(0.1, 0.2, 0.3));
        CHECK_THROWS_WITH(write_mesh(big.view(), "/dev/full", mesh_format(".obj")), Catch::Contains("/dev/full"));
        CHECK(fs::exists("/dev/full"));
    }
#endif
}

TEST_CASE("OBJ reader: v/vt/vn forms, negative indices, polygons, other lines ignored", "[mesh_io]") {
    TempDir tmp;
    const std::string path = tmp.write("q.obj",
                                       "# comment\r\n"
                                       "mtllib x.mtl\n"
                                       "o thing\n"
                                       "v 0 0 0\n"
                                       "v 1 0 0 1.0\n"  // optional w
                                       "v 1 1 0\n"
                                       "v 0 1 +0.5e0\n"
                                       "vt 0 0\nvn 0 0 1\n"
                                       "s off\nusemtl green\n"
                                       "f 1/1/1 2/1/1 3/1/1 4/1/1\n"  // quad -> 2 triangles
                                       "f -4//1 -2//1 -1//1  \n"
                                       "f 1/1 3/1 4/1 # trailing comment\n"
                                       "l 1 2\n");
    const MeshArrays m = read_mesh(path);
    REQUIRE(m.positions.size() == 4);
    CHECK(m.positions[3].z() == 0.5);
    REQUIRE(m.faces.size() == 4);
    CHECK(m.faces[0] == Face{0, 1, 2});
    CHECK(m.faces[1] == Face{0, 2, 3});
    CHECK(m.faces[2] == Face{0, 2, 3});
    CHECK(m.faces[3] == Face{0, 2, 3});
}

TEST_CASE("OFF reader: comments, counts on the header line, polygons, colours", "[mesh_io]") {
    TempDir tmp;
    const std::string path = tmp.write("q.off",
                                       "# leading comment\n"
                                       "OFF 4 2 0\n"
                                       "\n"
                                       "0 0 0   # a vertex\n"
                                       "1 0 0\n1 1 0\n0 1 0\n"
                                       "4 0 1 2 3 255 0 0\n"
                                       "3 3 2 1\n");
    const MeshArrays m = read_mesh(path);
    REQUIRE(m.positions.size() == 4);
    REQUIRE(m.faces.size() == 3);
    CHECK(m.faces[1] == Face{0, 2, 3});
    CHECK(m.faces[2] == Face{3, 2, 1});
}

namespace {

std::string be_bytes(const void* p, std::size_t n) {
    std::string s(static_cast<const char*>(p), n);
    return std::string(s.rbegin(), s.rend());
}

}  // namespace

TEST_CASE("PLY reader: ascii, big-endian, any numeric types, extra properties and elements", "[mesh_io]") {
    TempDir tmp;
    SECTION("ascii with extra properties and a polygon") {
        const std::string path = tmp.write("a.ply",
                                           "ply\r\nformat ascii 1.0\r\ncomment hi\r\n"
                                           "element vertex 4\r\nproperty float y\r\nproperty uchar red\r\n"
                                           "property float x\r\nproperty double z\r\n"
                                           "element face 1\r\nproperty uchar flags\r\n"
                                           "property list uchar ushort vertex_indices\r\n"
                                           "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\n"
                                           "end_header\r\n"
                                           "0 255 0 0\r\n0 1 1 0\r\n1 2 1 0\r\n1 3 0 0.25\r\n"
                                           "7 4 0 1 2 3\r\n0 1\r\n");
        const MeshArrays m = read_mesh(path);
        REQUIRE(m.positions.size() == 4);
        CHECK(m.positions[3] == Vec3(0, 1, 0.25));
        REQUIRE(m.faces.size() == 2);
        CHECK(m.faces[1] == Face{0, 2, 3});
    }
    SECTION("binary big-endian with float vertices and an int16 list count") {
        std::string header =
            "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nproperty list uchar int extra\nelement face 1\n"
            "property list short uint vertex_indices\nend_header\n";
        std::string body;
        const float coords[3][3] = {{0, 0, 0}, {1.5f, 0, 0}, {0, 2.25f, -1}};
        for (const auto& v : coords) {
            for (float c : v) body += be_bytes(&c, 4);
            body += '\x01';  // one-item "extra" list
            const std::int32_t e = 99;
            body += be_bytes(&e, 4);
        }
        const std::int16_t n = 3;
        body += be_bytes(&n, 2);
        for (std::uint32_t i : {2u, 1u, 0u}) body += be_bytes(&i, 4);
        const MeshArrays m = read_mesh(tmp.write("b.ply", header + body));
        REQUIRE(m.positions.size() == 3);
        CHECK(m.positions[2] == Vec3(0, 2.25, -1));
        REQUIRE(m.faces.size() == 1);
        CHECK(m.faces[0] == Face{2, 1, 0});
    }
}

TEST_CASE("every malformed file gives an IoError naming the file and the problem", "[mesh_io]") {
    TempDir tmp;
    const std::string ply_head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n";
    const std::string bin_head =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
        "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

    require_read_error(tmp.file("missing.obj"), "cannot open");
    require_read_error(tmp.path.string() + "/.obj", "");
    fs::create_directories(tmp.file("dir.obj"));
    require_read_error(tmp.file("dir.obj"), "directory");
    require_read_error(tmp.write("x.stl", ""), "not an STL file");
    require_read_error(tmp.write("x.glb", ""), "not a valid GLB");

    // OBJ
    require_read_error(tmp.write("num.obj", "v 0 0 0\nv 1 x 0\n"), ":2: bad number 'x'");
    require_read_error(tmp.write("short.obj", "v 0 0\n"), ":1: vertex needs 3 coordinates");
    require_read_error(tmp.write("inf.obj", "v 0 0 inf\n"), "not finite");
    require_read_error(tmp.write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"), ":4: vertex index 4 out of range");
    require_read_error(tmp.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "vertex index 0 out of range");
    require_read_error(tmp.write("neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"), "out of range");
    require_read_error(tmp.write("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), ":3: face with 2 corners");
    require_read_error(tmp.write("badidx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n"), "bad vertex index '3x'");

    // OFF
    require_read_error(tmp.write("empty.off", ""), "empty file");
    require_read_error(tmp.write("magic.off", "PLY\n3 1 0\n"), ":1: not an OFF file");
    require_read_error(tmp.write("counts.off", "OFF\n3 x 0\n"), ":2: bad face count 'x'");
    require_read_error(tmp.write("trv.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n"), "header line 2 declares 3 vertices and 1 faces, which need at least 25 bytes, but only 12 follow");
    const std::string pad = "# padding: the counts fit the bytes, so the reader gets to the defect\n";
    require_read_error(tmp.write("trv2.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n" + pad), "truncated: found 2 of 3 vertices");
    require_read_error(tmp.write("trf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n" + pad), "truncated: found 0 of 1 faces");
    require_read_error(tmp.write("num.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n"), ":5: bad number 'one'");
    require_read_error(tmp.write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), ":6: vertex index 3 out of range");
    require_read_error(tmp.write("two.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n" + pad), ":6: face with 2 corners");
    require_read_error(tmp.write("few.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n" + pad), "face lists 2 of its 3 corners");

    // PLY
    require_read_error(tmp.write("magic.ply", "solid\n"), "not a PLY file");
    require_read_error(tmp.write("nohdr.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"), "no end_header");
    require_read_error(tmp.write("fmt.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n"), ":2: unknown PLY format");
    require_read_error(tmp.write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n"),
                       ":4: unknown property type 'quad'");
    require_read_error(tmp.write("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                            "property float y\nend_header\n0 0\n"),
                       "no scalar property 'z'");
    require_read_error(tmp.write("num.ply", ply_head + "0 0 0\n1 0 0\n0 1 zz\n3 0 1 2\n"), ":12: bad number 'zz'");
    require_read_error(tmp.write("tra.ply", ply_head + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n"), "truncated");
    require_read_error(tmp.write("range.ply", ply_head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n"), "vertex index 5 out of range");
    require_read_error(tmp.write("two.ply", ply_head + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n"), "face 0 has 2 corners");
    require_read_error(tmp.write("trb.ply", bin_head + std::string(3 * 24, '\0') + "\x03" + std::string(5, '\0')), "face 0 declares a list of 3 items, which need at least 12 bytes, but only 5 follow");
    require_read_error(tmp.write("trv.ply", bin_head + std::string(30, '\0')),
                       "header declares 3 vertex, 1 face, which need at least 73 bytes, but only 30 follow");
    require_read_error(tmp.write("fidx.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                                             "property float y\nproperty float z\nelement face 0\n"
                                             "property list uchar float vertex_indices\nend_header\n"),
                       "integer item type");
}

namespace {

const fs::path corpus_dir = fs::path(MORPHOGEN_SOURCE_DIR) / "tests" / "corpus" / "mesh";

std::string le_float(float v) {
    std::string s(4, '\0');
    std::memcpy(s.data(), &v, 4);
    return s;
}

std::string le_u32(std::uint32_t v) {
    std::string s(4, '\0');
    std::memcpy(s.data(), &v, 4);
    return s;
}

std::string stl_facet(const Vec3& a, const Vec3& b, const Vec3& c) {
    std::ostringstream s;
    s << "facet normal 0 0 0\n outer loop\n";
    for (const Vec3* p : {&a, &b, &c}) s << "  vertex " << p->x() << ' ' << p->y() << ' ' << p->z() << '\n';
    s << " endloop\nendfacet\n";
    return s.str();
}

}  // namespace

TEST_CASE("hostile mesh corpus: each file is refused at once with its defect, naming the file", "[mesh_io][corpus]") {
    // File -> what the message must say (exit 3 via IoError). Files named
    // invalid_mesh_* read fine and are refused later (score: exit 4).
    const std::pair<const char*, const char*> cases[] = {
        {"lying_ply_header.ply", ":3: element 'e0' declares 2147483647 entries but no properties"},
        {"lying_ply_header_binary.ply", "which need at least 107374182386 bytes, but only 36 follow"},
        {"lying_ply_list_length.ply", "face 0 declares a list of 4294967295 items"},
        {"ply_second_face_element_nan_index.ply", ":9: element 'face' declared twice"},
        {"ply_float_index_list.ply", "vertex_indices must have an integer item type"},
        {"ply_nan_coordinate_binary.ply", "vertex 1 has a coordinate that is not finite"},
        {"ply_count_out_of_type_range.ply", ":13: integer '300' in face is out of range for its type"},
        {"ply_negative_index.ply", ":13: face 0: vertex index -2147483648 out of range [0, 3)"},
        {"ply_coordinate_1e200.ply", ":10: vertex 0 has a coordinate beyond the limit of ±1e9"},
        {"obj_coordinates_1e200.obj", ":1: coordinate '1e200' is beyond the limit of ±1e9"},
        {"obj_nan_coordinate.obj", ":2: coordinate 'nan' is not finite"},
        {"obj_index_out_of_range.obj", ":4: vertex index 4 out of range"},
        {"obj_index_overflow.obj", ":4: bad vertex index '99999999999999999999'"},
        {"obj_index_wraps_int.obj", ":4: vertex index 4294967299 out of range"},
        {"obj_float_index.obj", ":4: bad vertex index '2.5'"},
        {"off_lying_counts.off", "header line 2 declares 3 vertices and 2147483647 faces"},
        {"off_negative_count.off", ":2: bad vertex count '-3'"},
        {"off_lying_corner_count.off", ":6: face declares 2147483647 corners"},
        {"off_inf_coordinate.off", ":4: coordinate 'inf' is not finite"},
        {"off_index_out_of_range.off", ":6: vertex index -1 out of range"},
        {"stl_lying_triangle_count.stl", "binary STL declares 4294967295 triangles"},
        {"stl_truncated_binary.stl", "binary STL declares 2 triangles, which need 184 bytes, but the file has 134"},
        {"stl_nan_coordinate_binary.stl", "triangle 0 has a coordinate that is not finite"},
        {"stl_too_short.stl", "not an STL file"},
        {"stl_ascii_nan_coordinate.stl", ":5: coordinate 'nan' is not finite"},
        {"stl_ascii_four_vertices.stl", ":7: expected 'endloop', found 'vertex'"},
        {"stl_ascii_truncated.stl", ":5: expected 'vertex'"},
        {"stl_ascii_coordinate_1e200.stl", ":5: coordinate '1e200' is beyond the limit"},
    };
    for (const auto& [name, what] : cases) {
        INFO(name);
        REQUIRE(fs::exists(corpus_dir / name));
        require_read_error((corpus_dir / name).string(), what);
    }
    // Every file there (the fuzzers add theirs): refused with an IoError that
    // names it, or read (only valid-* seeds and invalid_mesh_* files read); never a crash or another exception
    // (a hang is caught by the test's CTest timeout, not timed here).
    int files = 0;
    for (const auto& entry : fs::directory_iterator(corpus_dir)) {
        const std::string path = entry.path().string();
        INFO(path);
        ++files;
        try {
            const MeshArrays m = read_mesh(path);
            const std::string name = entry.path().filename().string();
            CHECK((name.rfind("invalid_mesh_", 0) == 0 || name.rfind("valid-", 0) == 0));
            for (const Face& f : m.faces)
                for (int v : f) CHECK((v >= 0 && v < static_cast<int>(m.positions.size())));
        } catch (const IoError& e) {
            CHECK(std::string(e.what()).find(path) != std::string::npos);
        }
    }
    CHECK(files >= static_cast<int>(std::size(cases)));
}

TEST_CASE("parse_mesh reads from memory like read_mesh and names the source", "[mesh_io]") {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    CHECK(parse_mesh(obj, mesh_format(".obj"), "mem").faces == std::vector<Face>{{0, 1, 2}});
    CHECK_THROWS_WITH(parse_mesh("v 0 0\n", mesh_format(".obj"), "from-fuzzer"), Catch::StartsWith("from-fuzzer:1:"));
    CHECK_THROWS_AS(parse_mesh("glTF", mesh_format(".glb"), "x"), IoError);
    for (const MeshFormat& format : mesh_formats()) {
        // Empty and tiny inputs: a result or an IoError, nothing else.
        for (const std::string& bytes : {std::string(), std::string("\0", 1), std::string("ply"), std::string("solid")}) {
            try {
                parse_mesh(bytes, format, "tiny");
            } catch (const IoError&) {
            }
        }
    }
    // The encoder and the parser agree on every format that can be read.
    const MeshArrays cube = awkward_cube();
    for (const MeshFormat& format : mesh_formats())
        CHECK(parse_mesh(encode_mesh(cube.view(), format), format, "encoded").faces.size() == cube.faces.size());
}

TEST_CASE("limits: coordinates up to 1e9, counts against the bytes that follow", "[mesh_io]") {
    TempDir tmp;
    CHECK(read_mesh(tmp.write("edge.obj", "v 1e9 -1e9 0\nv 0 0 0\nv 0 1 0\nf 1 2 3\n")).positions[0].x() == 1e9);
    require_read_error(tmp.write("over.obj", "v 1.0000001e9 0 0\n"), ":1: coordinate '1.0000001e9' is beyond the limit");
    require_read_error(tmp.write("sign.obj", "v +-1 0 0\n"), ":1: bad number '+-1'");
    // An element with no entries needs no properties; one with entries does.
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\n";
    CHECK(read_mesh(tmp.write("empty-el.ply", head + "element nothing 0\nend_header\n0 0 0\n1 0 0\n0 1 0\n"))
              .positions.size() == 3);
    // A list longer than the rest of an ascii file, caught before the loop.
    require_read_error(tmp.write("list.ply", head + "element face 1\nproperty list uchar int vertex_indices\n"
                                                    "end_header\n0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n"),
                       ":13: face 0 declares a list of 200 items, which need at least 399 bytes");
    // A count that fits the bytes but lies is a truncation, found by reading.
    require_read_error(tmp.write("short.off", "OFF\n2 0 0\n0 0 0 # 1 1 1\n"), "truncated: found 1 of 2 vertices");
    // Not a regular file: refused before reading (a device could be endless).
#ifdef __linux__
    if (fs::exists("/dev/zero")) {
        fs::create_symlink("/dev/zero", tmp.file("zero.obj"));
        require_read_error(tmp.file("zero.obj"), "is not a regular file");
    }
#endif
}

TEST_CASE("STL reader: ascii and binary, equal corners welded, -0 equal to 0", "[mesh_io]") {
    TempDir tmp;
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1);
    SECTION("ascii, two solids, welded in order of first appearance") {
        const std::string text = "solid one\n" + stl_facet(a, c, b) + stl_facet(a, b, d) + "endsolid one\nsolid two\n" +
                                 stl_facet(b, c, d) + stl_facet(Vec3(-0.0, 0, 0), d, c) + "endsolid two\n";
        const MeshArrays m = read_mesh(tmp.write("tet.stl", text));
        REQUIRE(m.positions.size() == 4);
        CHECK(m.positions[0] == a);
        CHECK(m.positions[1] == c);
        CHECK(m.positions[2] == b);
        CHECK(m.positions[3] == d);
        CHECK(m.faces == std::vector<Face>{{0, 1, 2}, {0, 2, 3}, {2, 1, 3}, {0, 3, 1}});
        CHECK_NOTHROW(TriMesh::from_arrays(m, "tet.stl"));
        require_read_error(tmp.write("noend.stl", "solid x\n" + stl_facet(a, b, c)), "no 'endsolid'");
        require_read_error(tmp.write("junk.stl", "solid x\n" + stl_facet(a, b, c) + "endsolid x\njunk\n"),
                           ":10: expected 'solid' or the end after 'endsolid'");
        require_read_error(tmp.write("word.stl", "solid x\nfacet normal 0 0 q\n"), ":2: bad number 'q'");
    }
    SECTION("binary, even when its header starts with 'solid'") {
        std::string bytes = "solid but binary";
        bytes.resize(80, ' ');
        bytes += le_u32(2);
        const float tris[2][9] = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}};
        for (const auto& t : tris) {
            for (int k = 0; k < 3; ++k) bytes += le_float(0);
            for (float v : t) bytes += le_float(v);
            bytes += std::string(2, '\0');
        }
        const MeshArrays m = read_mesh(tmp.write("bin.stl", bytes));
        CHECK(m.positions.size() == 4);
        CHECK(m.faces == std::vector<Face>{{0, 1, 2}, {1, 2, 3}});
        // One byte more: read as ASCII (it starts with "solid"), which it is not.
        // One byte before: no "solid", and the size does not match the count.
        require_read_error(tmp.write("bin1.stl", bytes + "x"), "no 'endsolid'");
        require_read_error(tmp.write("bin2.stl", "x" + bytes), "binary STL declares");
    }
}

TEST_CASE("vertex and triangle limits are enforced at their edge", "[mesh_io]") {
    // Files that reach them are too big for a test; the shared checks are tested directly.
    using namespace morphogen::mesh_io_detail;
    CHECK_NOTHROW(check_vertex_count(kMaxMeshVertices, "v.obj"));
    CHECK_THROWS_WITH(check_vertex_count(kMaxMeshVertices + 1, "v.obj"),
                      Catch::StartsWith("v.obj: more than 67108864 vertices"));
    CHECK_NOTHROW(check_triangle_count(kMaxMeshTriangles - 1, 3, "t.obj", 7));
    CHECK_THROWS_WITH(check_triangle_count(kMaxMeshTriangles, 3, "t.obj", 7),
                      Catch::StartsWith("t.obj:7: more than 134217728 triangles"));
    CHECK_THROWS_WITH(check_triangle_count(0, kMaxMeshTriangles + 3, "t.ply", 0),
                      Catch::StartsWith("t.ply: more than"));
    CHECK_NOTHROW(check_room(10, 10, "r.off", "x"));
    CHECK_THROWS_WITH(check_room(11, 10, "r.off", "x"), "r.off: x, which need at least 11 bytes, but only 10 follow "
                                                         "(a truncated file or a header that lies)");
}
