#include "core/base/append_file.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace morphogen {

namespace {
std::string why() { return std::strerror(errno); }

void write_all(int fd, std::string_view text, const std::filesystem::path& path) {
    std::size_t written = 0;
    while (written < text.size()) {
        const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw IoError(path.string() + ": cannot write: " + why());
        }
        written += static_cast<std::size_t>(n);
    }
}

// The file's first `length` bytes, checked against `hash_hex`.
std::string checked_prefix(const std::filesystem::path& path, std::uint64_t length, const std::string& hash_hex) {
    std::string bytes = read_file_head(path, length);  // rows after them are not read
    if (bytes.size() < length)
        throw CheckpointError("checkpoint does not match " + path.filename().string() + ": the file has " +
                              std::to_string(bytes.size()) + " bytes, the checkpoint recorded " +
                              std::to_string(length));
    Fnv1a64 hash;
    hash.update(std::string_view(bytes).substr(0, length));
    if (hash.hex() != hash_hex)
        throw CheckpointError("checkpoint does not match " + path.filename().string() +
                              ": its first " + std::to_string(length) + " bytes changed since the checkpoint");
    bytes.resize(length);
    return bytes;
}
}  // namespace

AppendFile::AppendFile(std::filesystem::path path, int fd, std::uint64_t size, Fnv1a64 hash)
    : path_(std::move(path)), fd_(fd), size_(size), hash_(hash) {}

AppendFile::AppendFile(AppendFile&& other) noexcept
    : path_(std::move(other.path_)), fd_(other.fd_), size_(other.size_), hash_(other.hash_) {
    other.fd_ = -1;
}

AppendFile::~AppendFile() {
    if (fd_ >= 0) ::close(fd_);
}

AppendFile AppendFile::create(const std::filesystem::path& path, std::string_view initial) {
    write_file_atomically(path, initial);
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd < 0) throw IoError(path.string() + ": cannot open for appending: " + why());
    Fnv1a64 hash;
    hash.update(initial);
    return AppendFile(path, fd, initial.size(), hash);
}

std::string AppendFile::check_prefix(const std::filesystem::path& path, std::uint64_t length,
                                     const std::string& hash_hex) {
    return checked_prefix(path, length, hash_hex);
}

AppendFile AppendFile::resume(const std::filesystem::path& path, std::uint64_t length, const std::string& hash_hex) {
    Fnv1a64 hash;
    hash.update(checked_prefix(path, length, hash_hex));
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd < 0) throw IoError(path.string() + ": cannot open for appending: " + why());
    AppendFile file(path, fd, length, hash);
    if (::ftruncate(fd, static_cast<off_t>(length)) != 0)
        throw IoError(path.string() + ": cannot truncate: " + why());
    return file;
}

void AppendFile::write(std::string_view text) {
    write_all(fd_, text, path_);
    size_ += text.size();
    hash_.update(text);
}

void AppendFile::sync() {
    if (::fsync(fd_) != 0) throw IoError(path_.string() + ": fsync failed: " + why());
}

}  // namespace morphogen
