#pragma once
// Per-vertex values that grow with the mesh, as pmp-library's vertex
// properties do. A channel holds its values vertex after vertex; when a split
// makes a vertex inside a face (a, b, c), every channel appends that vertex's
// values by its own rule. GrowthState::channels() lists the state's channels,
// so the split phase grows them all with one call and appends nothing by hand:
// a new per-vertex value is a member of GrowthState and one line there.
#include "core/mesh/mesh.hpp"

#include <cstdint>
#include <vector>

namespace morphogen {

class VertexChannels {
public:
    // A value computed from the corners: make(context, a, b, c).
    using MakeVec3 = Vec3 (*)(const void* context, int a, int b, int c);

    // The corners' mean, value by value ((a + b + c) / 3), `width` per vertex.
    void mean(std::vector<double>& values, int width);
    // 1 where every corner is 1 (bitwise and of the corners).
    void all(std::vector<std::uint8_t>& values);
    // 1 where any corner is 1 (bitwise or of the corners).
    void any(std::vector<std::uint8_t>& values);
    void computed(std::vector<Vec3>& values, MakeVec3 make, const void* context);

    // Appends the values of a vertex made inside face (a, b, c) to every
    // channel. A channel empty when registered is switched off and stays
    // empty. a, b and c are vertices that were there before.
    void add_vertex_in(int a, int b, int c) const;

private:
    enum class Rule : std::uint8_t { mean, all, any, computed };
    struct Channel {
        Rule rule;
        int width;
        void* values;  // std::vector<double>, <std::uint8_t> or <Vec3>, by the rule
        MakeVec3 make = nullptr;
        const void* context = nullptr;
    };
    void add(Channel channel, bool empty);
    std::vector<Channel> channels_;
};

}  // namespace morphogen
