#pragma once
// Genomes kept outside a search state's JSON (checkpoint format 2): each
// genome is `dimension` IEEE-754 doubles, little-endian, 8 bytes each, the
// genomes one after another; the JSON refers to genome k by "genome": k. The
// bytes are the exact bits (-0.0, denormals, 1e308 stay what they were), and
// writing or reading them never goes through a JSON number.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

class GenomeBlobWriter {
public:
    // Appends a genome and returns its index. Throws std::invalid_argument if
    // its length differs from the first genome's.
    std::uint64_t add(std::span<const double> params);
    // Room for `doubles` parameters in all (saves regrowing a 150 MB buffer).
    void reserve(std::size_t doubles) { bytes_.reserve(doubles * 8); }
    std::uint64_t count() const { return count_; }
    // Doubles per genome (0 while there is none).
    std::size_t dimension() const { return dimension_; }
    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
    std::uint64_t count_ = 0;
    std::size_t dimension_ = 0;
};

class GenomeBlobReader {
public:
    // `bytes` must stay alive while this reader is used. Throws
    // std::invalid_argument unless it holds exactly count x dimension doubles.
    GenomeBlobReader(std::string_view bytes, std::uint64_t count, std::size_t dimension);
    std::uint64_t count() const { return count_; }
    std::size_t dimension() const { return dimension_; }

    // Genome `index`, refused (std::invalid_argument "<path>: ...") if it is
    // out of range, was taken before (every genome belongs to one
    // individual), or holds a non-finite value.
    std::vector<double> take(std::uint64_t index, const std::string& path);
    // Throws std::invalid_argument naming `path` unless every genome was taken.
    void check_all_taken(const std::string& path) const;

private:
    std::string_view bytes_;
    std::uint64_t count_;
    std::size_t dimension_;
    std::vector<bool> taken_;
    std::uint64_t taken_count_ = 0;
};

}  // namespace morphogen
