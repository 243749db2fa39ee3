#pragma once
// An append-only text file (history.csv, lineage.csv) that knows its length
// and the FNV-1a hash of its contents, so a checkpoint can record exactly
// which prefix belongs to it; rows written after the checkpoint are cut off
// on resume.
#include "core/base/fnv_hash.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace morphogen {

class AppendFile {
public:
    // Creates (or replaces) the file holding `initial` (a header, or a header
    // and rows), atomically (atomic_file.hpp), and opens it for appending.
    static AppendFile create(const std::filesystem::path& path, std::string_view initial);
    // Opens an existing file whose first `length` bytes must hash to
    // `hash_hex`; cuts it to that length. Throws CheckpointError if the file is
    // shorter or its prefix differs (it is not touched then), IoError if it
    // cannot be opened.
    static AppendFile resume(const std::filesystem::path& path, std::uint64_t length, const std::string& hash_hex);
    // Checks what resume() would, without changing anything; returns those
    // first `length` bytes.
    static std::string check_prefix(const std::filesystem::path& path, std::uint64_t length,
                                    const std::string& hash_hex);

    AppendFile(AppendFile&& other) noexcept;
    AppendFile& operator=(AppendFile&&) = delete;
    AppendFile(const AppendFile&) = delete;
    ~AppendFile();

    void write(std::string_view text);  // throws IoError naming the file and the reason
    void sync();                        // fsync; throws IoError
    std::uint64_t size() const { return size_; }
    std::string hash_hex() const { return hash_.hex(); }
    const std::filesystem::path& path() const { return path_; }

private:
    AppendFile(std::filesystem::path path, int fd, std::uint64_t size, Fnv1a64 hash);

    std::filesystem::path path_;
    int fd_ = -1;
    std::uint64_t size_ = 0;
    Fnv1a64 hash_;
};

}  // namespace morphogen
