#pragma once
// FNV-1a 64-bit: a small, dependency-free content hash. Used to make
// checkpoints self-checking and to tie a checkpoint to the lineage.csv prefix
// it was written with. It detects corruption, not tampering.
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
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
    // The same step over 64-bit little-endian words instead of bytes: 8 times
    // fewer multiplications, for large binary data. Each step is a bijection
    // of the state for a given word and of the word for a given state, so a
    // change confined to one word always changes the result. The length must
    // be a multiple of 8 (the caller checks; a tail is hashed bytewise).
    void update_words(std::string_view bytes) {
        const std::size_t words = bytes.size() / 8;
        for (std::size_t i = 0; i < words; ++i) {
            std::uint64_t word = 0;
            if constexpr (std::endian::native == std::endian::little) {
                std::memcpy(&word, bytes.data() + 8 * i, 8);
            } else {
                for (int b = 0; b < 8; ++b)
                    word |= std::uint64_t{static_cast<unsigned char>(bytes[8 * i + b])} << (8 * b);
            }
            state_ ^= word;
            state_ *= 0x100000001b3ULL;
        }
        update(bytes.substr(8 * words));
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
