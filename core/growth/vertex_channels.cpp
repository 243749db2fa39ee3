#include "core/growth/vertex_channels.hpp"

#include <cstddef>

namespace morphogen {

void VertexChannels::add(Channel channel, bool empty) {
    if (!empty) channels_.push_back(channel);
}

void VertexChannels::mean(std::vector<double>& values, int width) { add({Rule::mean, width, &values}, values.empty()); }
void VertexChannels::all(std::vector<std::uint8_t>& values) { add({Rule::all, 1, &values}, values.empty()); }
void VertexChannels::any(std::vector<std::uint8_t>& values) { add({Rule::any, 1, &values}, values.empty()); }
void VertexChannels::computed(std::vector<Vec3>& values, MakeVec3 make, const void* context) {
    add({Rule::computed, 1, &values, make, context}, values.empty());
}

void VertexChannels::add_vertex_in(int a, int b, int c) const {
    for (const Channel& channel : channels_) {
        switch (channel.rule) {
            case Rule::mean: {
                auto& w = *static_cast<std::vector<double>*>(channel.values);
                const std::size_t N = static_cast<std::size_t>(channel.width);
                const std::size_t end = w.size();
                w.resize(end + N);
                for (std::size_t k = 0; k < N; ++k) w[end + k] = (w[N * a + k] + w[N * b + k] + w[N * c + k]) / 3.0;
                break;
            }
            case Rule::all: {
                auto& v = *static_cast<std::vector<std::uint8_t>*>(channel.values);
                v.push_back(v[a] & v[b] & v[c]);
                break;
            }
            case Rule::any: {
                auto& v = *static_cast<std::vector<std::uint8_t>*>(channel.values);
                v.push_back(v[a] | v[b] | v[c]);
                break;
            }
            case Rule::computed:
                static_cast<std::vector<Vec3>*>(channel.values)->push_back(channel.make(channel.context, a, b, c));
                break;
        }
    }
}

}  // namespace morphogen
