// STL: binary writer.
#include "mesh_io_detail.hpp"

#include <cstdint>
#include <string>

namespace morphogen::mesh_io_detail {

namespace {

Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const double len = n.norm();
    return len > 0 ? Vec3(n / len) : Vec3::Zero();
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

}  // namespace morphogen::mesh_io_detail
