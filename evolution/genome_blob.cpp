#include "evolution/genome_blob.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace morphogen {

namespace {
static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559, "doubles must be IEEE-754 binary64");

// Copies doubles to little-endian bytes (a plain copy on little-endian hosts).
void to_little_endian(const double* in, std::size_t n, char* out) {
    if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(out, in, n * 8);
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            const auto bits = std::bit_cast<std::uint64_t>(in[i]);
            for (int b = 0; b < 8; ++b) out[i * 8 + b] = static_cast<char>((bits >> (8 * b)) & 0xff);
        }
    }
}

void from_little_endian(const char* in, std::size_t n, double* out) {
    if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(out, in, n * 8);
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            std::uint64_t bits = 0;
            for (int b = 0; b < 8; ++b) bits |= std::uint64_t{static_cast<unsigned char>(in[i * 8 + b])} << (8 * b);
            out[i] = std::bit_cast<double>(bits);
        }
    }
}
}  // namespace

std::uint64_t GenomeBlobWriter::add(std::span<const double> params) {
    if (count_ == 0) dimension_ = params.size();
    if (params.size() != dimension_)
        throw std::invalid_argument("genome of " + std::to_string(params.size()) + " parameters among genomes of " +
                                    std::to_string(dimension_));
    const std::size_t at = bytes_.size();
    bytes_.resize(at + params.size() * 8);
    to_little_endian(params.data(), params.size(), bytes_.data() + at);
    return count_++;
}

GenomeBlobReader::GenomeBlobReader(std::string_view bytes, std::uint64_t count, std::size_t dimension)
    : bytes_(bytes), count_(count), dimension_(dimension) {
    // count x dimension x 8 == size, checked without overflow.
    const std::uint64_t size = bytes.size();
    const bool fits = dimension == 0 ? size == 0 : (size % (8 * dimension) == 0 && size / (8 * dimension) == count);
    if (!fits || (dimension == 0 && count != 0))
        throw std::invalid_argument(std::to_string(size) + " bytes of genomes, expected " + std::to_string(count) +
                                    " genomes x " + std::to_string(dimension) + " parameters x 8");
    taken_.assign(count, false);
}

std::vector<double> GenomeBlobReader::take(std::uint64_t index, const std::string& path) {
    if (index >= count_)
        throw std::invalid_argument(path + ": genome " + std::to_string(index) + " does not exist (there are " +
                                    std::to_string(count_) + ")");
    if (taken_[index]) throw std::invalid_argument(path + ": genome " + std::to_string(index) + " is used twice");
    taken_[index] = true;
    ++taken_count_;
    std::vector<double> params(dimension_);
    from_little_endian(bytes_.data() + index * dimension_ * 8, dimension_, params.data());
    for (std::size_t i = 0; i < params.size(); ++i)
        if (!std::isfinite(params[i]))
            throw std::invalid_argument(path + ": parameter " + std::to_string(i) + " of genome " +
                                        std::to_string(index) + " is not finite");
    return params;
}

void GenomeBlobReader::check_all_taken(const std::string& path) const {
    if (taken_count_ != count_)
        throw std::invalid_argument(path + ": " + std::to_string(count_ - taken_count_) + " of its " +
                                    std::to_string(count_) + " genomes belong to no individual");
}

}  // namespace morphogen
