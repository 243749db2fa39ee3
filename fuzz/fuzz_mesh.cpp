// Fuzz target "mesh": the bytes as a mesh file, read as `score --mesh` and a
// seed file are read: core/io/mesh_io.hpp read_mesh, then TriMesh::from_arrays
// (the topology checks) and the seed's growth directions.
//
// The first byte picks the format, the rest is the file: 'o' OBJ, 'p' PLY,
// 'f' OFF, 's' STL (any other byte: its value mod 4 in that order). Corpus
// files in tests/corpus/mesh/ are plain mesh files; the replay and
// scripts/fuzz.sh prefix the byte their extension names (input_from_file).
#include "fuzz/fuzz_target.hpp"
#include "fuzz/path_readers.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "core/mesh/mesh.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace morphogen::fuzz {
namespace {

MeshFormat format_of(std::uint8_t tag) {
    switch (tag) {
        case 'o': return MeshFormat::obj;
        case 'p': return MeshFormat::ply;
        case 'f': return MeshFormat::off;
        case 's': return MeshFormat::stl;
        default: break;
    }
    constexpr MeshFormat order[] = {MeshFormat::obj, MeshFormat::ply, MeshFormat::off, MeshFormat::stl};
    return order[tag % 4];
}

}  // namespace

std::string input_from_file(const std::string& filename, std::string bytes) {
    std::string ext = std::filesystem::path(filename).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    char tag = 0;
    if (ext == ".obj") tag = 'o';
    else if (ext == ".ply") tag = 'p';
    else if (ext == ".off") tag = 'f';
    else if (ext == ".stl") tag = 's';
    else finding("harness: mesh corpus file " + filename + " has no .obj/.ply/.off/.stl extension");
    return tag + bytes;
}

}  // namespace morphogen::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace morphogen;
    using namespace morphogen::fuzz;
    if (size == 0) return 0;
    const MeshFormat format = format_of(data[0]);
    MeshArrays arrays;
    if (!accepts([&] { arrays = read_mesh_bytes(as_text(data + 1, size - 1), format); })) return 0;
    // What a reader hands on must be usable: finite coordinates, indices that
    // name a vertex (TriMesh and the fitness code index with them).
    for (const Vec3& p : arrays.positions)
        if (!p.allFinite()) finding("a mesh reader returned a coordinate that is not finite");
    const auto nv = static_cast<long long>(arrays.positions.size());
    for (const Face& f : arrays.faces)
        for (int v : f)
            if (v < 0 || v >= nv)
                finding("a mesh reader returned vertex index " + std::to_string(v) + " of " + std::to_string(nv));
    accepts([&] {
        const TriMesh mesh = TriMesh::from_arrays(std::move(arrays), "fuzz mesh");
        (void)area_weighted_normals(mesh, "fuzz mesh");
    });
    return 0;
}
