#pragma once
// FNV-1a 64-bit: a small, dependency-free content hash. Used to make
// checkpoints self-checking and to tie a checkpoint to the lineage.csv prefix
// it was written with. It detects corruption, not tampering.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace morphogen {

class Fnv1a64 {
public:
    Fnv1a64() = default;
    explicit Fnv1a64(std::uint64_t state) : state_(state) {}
    void update(std::string_view bytes) {
        for (unsigned char c : bytes) {
            state_ ^= c;
            state_ *= 0x100000001b3ULL;
        }
    }
    std::uint64_t value() const { return state_; }
    // 16 lower-case hex digits.
    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_));
        return text;
    }

private:
    std::uint64_t state_ = 0xcbf29ce484222325ULL;
};

inline std::string fnv1a64_hex(std::string_view bytes) {
    Fnv1a64 h;
    h.update(bytes);
    return h.hex();
}

}  // namespace morphogen
