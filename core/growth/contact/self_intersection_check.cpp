#include "core/growth/contact/self_intersection_check.hpp"

#include "core/mesh/face_pair.hpp"
#include "core/mesh/fan_certificate.hpp"

#include <algorithm>

namespace morphogen {

bool SelfIntersectionCheck::intersects(const TriMesh& mesh) {
    const std::vector<Vec3>& x = mesh.positions();
    const std::vector<Face>& faces = mesh.faces();
    const int F = mesh.num_faces();
    certified_.resize(static_cast<std::size_t>(mesh.num_vertices()));
    for (int v = 0; v < mesh.num_vertices(); ++v) certified_[v] = fan_certified(mesh, v, scratch_) ? 1 : 0;
    // A certified fan has no degenerate face; the others are tested.
    for (const Face& f : faces)
        if (!certified_[f[0]] && !certified_[f[1]] && !certified_[f[2]] && triangle_degenerate(x[f[0]], x[f[1]], x[f[2]]))
            return true;

    boxes_.resize(static_cast<std::size_t>(F));
    for (int f = 0; f < F; ++f) boxes_[f] = Box3::of(x[faces[f][0]], x[faces[f][1]], x[faces[f][2]]);
    grid_.build(SpatialHash::cell_size_for(boxes_), boxes_);

    seen_.assign(static_cast<std::size_t>(F), 0);
    for (int f = 0; f < F; ++f) {
        const Face& a = faces[f];
        const auto query = static_cast<std::uint32_t>(f) + 1;
        bool hit = false;
        grid_.for_each_candidate(boxes_[f], [&](int g, const Box3& box) {
            // Each pair once (g > f), each candidate once per query.
            if (hit || g <= f || seen_[g] == query || !box.overlaps(boxes_[f])) return;
            seen_[g] = query;
            const Face& b = faces[g];
            for (const int v : a)
                if (certified_[v] && (v == b[0] || v == b[1] || v == b[2])) return;  // proven apart
            hit = faces_intersect(IndexedTriangle::of(x, a), IndexedTriangle::of(x, b));
        });
        if (hit) return true;
    }
    return false;
}

}  // namespace morphogen
