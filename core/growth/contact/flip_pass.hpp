#pragma once
// The flip of docs/algorithm.md §5.4: the criteria under which an edge flip
// is taken, one edge at a time (try_flip) and a pass over every edge
// (flip_pass). The mesh only knows whether a flip is possible and how to do
// it (TriMesh::can_flip, TriMesh::flip); what makes a flip worth doing, and
// the order edges are visited in, is the growth model's.
#include "core/mesh/mesh.hpp"

namespace morphogen {

// A rule from outside the criteria that may refuse a flip every criterion of
// docs/algorithm.md §5.4 allows (growth.collisions "prevent", §5.7:
// CollisionGuard in core/growth/contact/collision.hpp).
class FlipGuard {
public:
    virtual ~FlipGuard() = default;
    // Asked last: true means faces f and g are now rewritten to new_f, new_g.
    virtual bool allows(const TriMesh& mesh, int f, int g, const Face& new_f, const Face& new_g) = 0;
};

// The conditions of docs/algorithm.md §5.4 under which an edge flip is taken.
struct FlipCriteria {
    double min_normal_dot = 0.8660254037844387;  // cos(flip_max_angle_deg)
    int min_valence = 4;                          // both B and D need valence > this
    FlipGuard* guard = nullptr;                   // none: every criterion met flips
};

// Tries to flip local edge e of face f (docs/algorithm.md §5.4): with
// B = f[e], D = f[e+1], A = f[e+2] and g the face across B-D with third
// vertex C, flips only if f < g and every criterion holds, in this order:
// the valences of B and D, |AC| < |BD|, the normals' angle, the new faces'
// orientation, A and C not joined yet (TriMesh::can_flip), the guard; then
// TriMesh::flip makes f := (A,B,C), g := (C,D,A). Returns whether it
// flipped; never throws.
bool try_flip(TriMesh& mesh, int f, int e, const FlipCriteria& criteria);

// One flip pass (docs/algorithm.md §5.4): try_flip(f, e) for f = 0..F-1 and
// e = 0, 1, 2 in order, each flip taking effect at once. Returns the
// number of flips.
int flip_pass(TriMesh& mesh, const FlipCriteria& criteria);

}  // namespace morphogen
