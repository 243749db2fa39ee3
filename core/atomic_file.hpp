#pragma once
// Durable file updates: a reader (or a resume after kill -9 or power loss)
// sees either the old file or the new one, never a mix.
#include <filesystem>
#include <string>
#include <string_view>

namespace morphogen {

// Writes `bytes` to a temporary file in the same directory, fsyncs it,
// renames it over `path` and fsyncs the directory. Throws IoError.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);
// fsync a directory (so a rename or new file in it is durable). Throws IoError.
void sync_directory(const std::filesystem::path& dir);
// The whole file as bytes. Throws IoError.
std::string read_file_bytes(const std::filesystem::path& path);

}  // namespace morphogen
