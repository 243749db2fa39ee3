// Fuzz target "mesh": the bytes as a mesh file, read as `score --mesh` and a
// seed file are read: core/io/mesh_io.hpp read_mesh, then TriMesh::from_arrays
// (the topology checks) and the seed's growth directions.
//
// The first byte picks the format, the rest is the file: the fuzz_tag of a
// row of core/io/mesh_formats.cpp ('o' OBJ, 'p' PLY, 'f' OFF, 's' STL; any
// other byte: its value mod the readers' count, in the table's order). Corpus
// files in tests/corpus/mesh/ are plain mesh files; the replay and
// scripts/fuzz.sh prefix the byte their extension names (input_from_file).
#include "fuzz/fuzz_target.hpp"
#include "fuzz/path_readers.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "core/mesh/mesh.hpp"

#include <cmath>
#include <filesystem>
#include <vector>

namespace morphogen::fuzz {
namespace {

// The formats with a reader, in the table's order.
std::vector<const MeshFormat*> readers() {
    std::vector<const MeshFormat*> out;
    for (const MeshFormat& format : mesh_formats())
        if (format.fuzz_tag != 0) out.push_back(&format);
    return out;
}

const MeshFormat& format_of(std::uint8_t tag) {
    static const std::vector<const MeshFormat*> formats = readers();
    for (const MeshFormat* format : formats)
        if (static_cast<std::uint8_t>(format->fuzz_tag) == tag) return *format;
    return *formats[tag % formats.size()];
}

}  // namespace

std::string input_from_file(const std::string& filename, std::string bytes) {
    const MeshFormat* format = find_mesh_format(std::filesystem::path(filename).extension().string());
    if (format == nullptr || format->fuzz_tag == 0)
        finding("harness: mesh corpus file " + filename + " has no extension of a fuzzed mesh reader");
    return format->fuzz_tag + bytes;
}

}  // namespace morphogen::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace morphogen;
    using namespace morphogen::fuzz;
    if (size == 0) return 0;
    const MeshFormat& format = format_of(data[0]);
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
