#pragma once
// Durable file updates: a reader (or a resume after kill -9 or power loss)
// sees either the old file or the new one, never a mix, and a failed write
// leaves nothing behind but the old file.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace morphogen {

// The temporary name write_file_atomically uses for `path` (<path>.tmp).
std::filesystem::path temporary_path(const std::filesystem::path& path);

// Writes `bytes` to temporary_path(path), fsyncs it, renames it over `path`
// and fsyncs the directory. On any failure the temporary file is removed,
// `path` keeps its old contents (or stays absent), and IoError names `path`
// and the system's reason ("<path>: cannot write: No space left on device").
// A `path` that exists and is not a regular file (a device such as
// /dev/stdout, a FIFO) is written in place instead: it cannot be replaced.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);
// The same for a file made of `parts` one after another (no copy to join them).
void write_file_atomically(const std::filesystem::path& path, std::span<const std::string_view> parts);
// fsync a directory (so a rename or new file in it is durable). Throws IoError.
void sync_directory(const std::filesystem::path& dir);

// The most bytes a reader takes from one file, and what the bound is for
// ("checkpoints"), as its refusal says.
struct FileBound {
    std::uint64_t bytes = 0;
    const char* of = "";
};
// A bound for a file held whole in memory and nothing smaller bounds: this
// machine's physical memory (16 GiB where it cannot be read).
FileBound memory_bound(const char* of);

// The whole file as bytes. Throws IoError naming the file and the reason:
// anything but a regular file (a FIFO, a directory, a device: "is not a
// regular file", since reading one could block or never end; checked on the
// open descriptor, which never waits for a FIFO's writer), a file of more than
// `bound.bytes` (naming the bound), one the memory cannot hold (no bare
// std::bad_alloc), and any system error.
std::string read_file_bytes(const std::filesystem::path& path, FileBound bound);
// The first `length` bytes (all of a shorter file), with the same refusals.
std::string read_file_head(const std::filesystem::path& path, std::uint64_t length);

}  // namespace morphogen
