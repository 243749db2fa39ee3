#include "fitness/architecture/architecture.hpp"

#include "fitness/geometry/convex_hull.hpp"
#include "fitness/measures.hpp"
#include "fitness/architecture/welded_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace morphogen {

namespace {

// The skeleton with pruned nodes marked dead; nodes are ordered by band, so
// a child's index is above its parent's.
class PrunedTree {
public:
    explicit PrunedTree(const Skeleton& skeleton) : s_(skeleton), alive_(skeleton.nodes.size(), true) {}

    const SkeletonNode& node(int n) const { return s_.nodes[n]; }
    double band_width() const { return s_.band_width; }
    int size() const { return static_cast<int>(s_.nodes.size()); }
    bool alive(int n) const { return alive_[n]; }
    void remove(int n) { alive_[n] = false; }
    std::vector<int> children(int n) const {
        std::vector<int> out;
        for (int c : s_.nodes[n].children)
            if (alive_[c]) out.push_back(c);
        return out;
    }
    bool is_fork(int n) const { return children(n).size() >= 2; }
    bool is_leaf(int n) const { return n != 0 && alive_[n] && children(n).empty(); }

private:
    const Skeleton& s_;
    std::vector<bool> alive_;
};

// A fork and the nodes after it, down to the next fork or an end node.
struct Branch {
    int fork = 0;
    std::vector<int> nodes;
    double length = 0.0, thickness = 0.0, tube_length = 0.0;
    // What the slenderness rules compare with the thickness (architecture.hpp).
    double reach() const { return std::min(length, 2.0 * tube_length); }
};

void measure_branch(const PrunedTree& tree, Branch& branch) {
    // The length along the surface: how much farther from the base its end lies than its fork.
    branch.length = tree.node(branch.nodes.back()).distance - tree.node(branch.fork).distance;
    std::vector<double> along;  // the same for each node
    double area = 0.0;
    for (int n : branch.nodes) {
        along.push_back(tree.node(n).distance - tree.node(branch.fork).distance);
        area += tree.node(n).area;
    }
    std::size_t count = branch.nodes.size();
    if (count >= 2 && tree.is_fork(branch.nodes.back())) --count;  // the next fork's saddle
    // The stem's girth: the narrowest node of the branch's first half (at
    // least one node), so neither a crown at its end nor a lump counts.
    branch.thickness = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < count && (i == 0 || along[i] <= 0.5 * branch.length); ++i)
        branch.thickness = std::min(branch.thickness, tree.node(branch.nodes[i]).diameter);
    branch.tube_length = branch.thickness > 0 ? area / (std::numbers::pi * branch.thickness) : 0.0;
}

// The branch ending at `leaf`, or none when no fork lies below it (the trunk).
std::optional<Branch> branch_to(const PrunedTree& tree, int leaf) {
    Branch branch;
    int n = leaf;
    while (n != 0 && !tree.is_fork(tree.node(n).parent)) {
        branch.nodes.push_back(n);
        n = tree.node(n).parent;
    }
    if (n == 0) return std::nullopt;
    branch.nodes.push_back(n);
    branch.fork = tree.node(n).parent;
    std::reverse(branch.nodes.begin(), branch.nodes.end());
    measure_branch(tree, branch);
    return branch;
}

// Removes the end branches shorter than `slenderness` x their thickness,
// all of one round at once, until none is.
void prune(PrunedTree& tree, double slenderness) {
    for (bool pruned = true; pruned;) {
        pruned = false;
        std::vector<int> doomed;
        for (int n = 0; n < tree.size(); ++n) {
            if (!tree.is_leaf(n)) continue;
            const std::optional<Branch> branch = branch_to(tree, n);
            if (branch && branch->reach() < std::max(slenderness * branch->thickness, 0.5 * tree.band_width()))
                doomed.insert(doomed.end(), branch->nodes.begin(), branch->nodes.end());
        }
        for (int n : doomed) tree.remove(n), pruned = true;
    }
}

// Every branch of the pruned tree, by fork and child.
std::vector<Branch> branches_of(const PrunedTree& tree) {
    std::vector<Branch> branches;
    for (int fork = 0; fork < tree.size(); ++fork) {
        if (!tree.alive(fork) || !tree.is_fork(fork)) continue;
        for (int n : tree.children(fork)) {
            Branch branch{.fork = fork, .nodes = {n}};
            for (std::vector<int> next = tree.children(n); next.size() == 1; next = tree.children(n)) {
                n = next[0];
                branch.nodes.push_back(n);
            }
            measure_branch(tree, branch);
            branches.push_back(std::move(branch));
        }
    }
    return branches;
}

int strahler_order(const PrunedTree& tree) {
    std::vector<int> order(tree.size(), 1);
    for (int n = tree.size() - 1; n >= 0; --n) {
        if (!tree.alive(n)) continue;
        int highest = 0, sharing = 0;
        for (int c : tree.children(n)) {
            if (order[c] > highest) highest = order[c], sharing = 0;
            if (order[c] == highest) ++sharing;
        }
        if (highest > 0) order[n] = highest + (sharing >= 2 ? 1 : 0);
    }
    return order[0];
}

// Whether every edge is crossed as often in one direction as in the other:
// a surface without boundary, consistently oriented (two closed parts
// touching along an edge count as closed).
bool closed(const MeshArrays& mesh) {
    std::vector<std::pair<int, int>> directed;
    directed.reserve(mesh.faces.size() * 3);
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) directed.emplace_back(f[k], f[(k + 1) % 3]);
    std::sort(directed.begin(), directed.end());
    for (auto run = directed.begin(); run != directed.end();) {
        const auto end = std::upper_bound(run, directed.end(), *run);
        const auto [first, last] = std::equal_range(directed.begin(), directed.end(), std::pair{run->second, run->first});
        if (last - first != end - run) return false;
        run = end;
    }
    return true;
}

}  // namespace

double mesh_solidity(MeshView mesh) {
    check_mesh_view(mesh);
    const MeshArrays welded = welded_mesh(mesh);
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    if (welded.faces.empty() || !closed(welded)) return nan;
    const double hull = convex_hull_volume(welded.positions);
    return hull > 0 ? std::abs(mesh_volume(welded.view())) / hull : nan;
}

Architecture measure_architecture(MeshView mesh, const ArchitectureParams& params) {
    if (!(params.limb_slenderness > 0) || !(params.tip_slenderness >= 0) || !std::isfinite(params.limb_slenderness) ||
        !std::isfinite(params.tip_slenderness))
        throw std::invalid_argument("architecture limb_slenderness must be positive and tip_slenderness >= 0, both finite");
    const Skeleton skeleton = level_set_skeleton(mesh, params.skeleton);
    PrunedTree tree(skeleton);
    prune(tree, params.tip_slenderness);

    Architecture out;
    out.band_width = skeleton.band_width;
    out.first_fork_height = std::numeric_limits<double>::infinity();
    for (int n = 0; n < tree.size(); ++n) {
        if (!tree.alive(n)) continue;
        ++out.nodes;
        if (tree.is_leaf(n)) out.tip_points.push_back(tree.node(n).centroid);
        if (tree.is_fork(n)) {
            ++out.forks;
            out.first_fork_height = std::min(out.first_fork_height, tree.node(n).centroid.z() - skeleton.zmin);
        }
    }
    if (out.forks == 0) out.first_fork_height = skeleton.zmax - skeleton.zmin;
    out.tips = static_cast<int>(out.tip_points.size());
    for (const Branch& b : branches_of(tree))
        if (b.reach() >= params.limb_slenderness * b.thickness)
            out.limbs.push_back({.length = b.length,
                                 .thickness = b.thickness,
                                 .tube_length = b.tube_length,
                                 .base = tree.node(b.fork).centroid,
                                 .tip = tree.node(b.nodes.back()).centroid});
    out.strahler = strahler_order(tree);
    out.solidity = params.with_solidity ? mesh_solidity(mesh) : std::numeric_limits<double>::quiet_NaN();
    return out;
}

}  // namespace morphogen
