#include "core/base/atomic_file.hpp"

#include "core/base/errors.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace morphogen {

namespace {
std::string why(int error) { return std::strerror(error); }

// Closes a descriptor on scope exit (close() reporting an error is handled
// by the caller before that).
struct Fd {
    int fd = -1;
    explicit Fd(int d) : fd(d) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

// Writes, fsyncs and closes the temporary file; returns 0 or the errno of
// the first failure, with `step` saying which.
int write_temporary(const std::filesystem::path& temp, std::span<const std::string_view> parts, const char*& step) {
    Fd out(::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    step = "cannot create";
    if (out.fd < 0) return errno;
    step = "cannot write";
    for (const std::string_view bytes : parts) {
        std::size_t written = 0;
        while (written < bytes.size()) {
            const ssize_t n = ::write(out.fd, bytes.data() + written, bytes.size() - written);
            if (n < 0) {
                if (errno == EINTR) continue;
                return errno;
            }
            written += static_cast<std::size_t>(n);
        }
    }
    if (::fsync(out.fd) != 0) return errno;  // delayed allocation reports a full disk here
    const int fd = out.fd;
    out.fd = -1;
    if (::close(fd) != 0) return errno;  // and NFS here
    return 0;
}

// For a target that is not a regular file (a device, a FIFO, a symlink to
// one): written in place, since replacing it would be wrong.
void write_in_place(const std::filesystem::path& path, std::span<const std::string_view> parts) {
    // O_NONBLOCK: a FIFO nobody reads is refused (ENXIO), not waited on.
    Fd out(::open(path.c_str(), O_WRONLY | O_TRUNC | O_NONBLOCK | O_CLOEXEC));
    if (out.fd < 0) throw IoError(path.string() + ": cannot open for writing: " + why(errno));
    const int flags = ::fcntl(out.fd, F_GETFL);
    if (flags < 0 || ::fcntl(out.fd, F_SETFL, flags & ~O_NONBLOCK) != 0)
        throw IoError(path.string() + ": cannot open for writing: " + why(errno));
    for (const std::string_view bytes : parts)
        for (std::size_t written = 0; written < bytes.size();) {
            const ssize_t n = ::write(out.fd, bytes.data() + written, bytes.size() - written);
            if (n < 0 && errno != EINTR) throw IoError(path.string() + ": cannot write: " + why(errno));
            if (n > 0) written += static_cast<std::size_t>(n);
        }
}
}  // namespace

std::filesystem::path temporary_path(const std::filesystem::path& path) { return path.string() + ".tmp"; }

void sync_directory(const std::filesystem::path& dir) {
    Fd d(::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (d.fd < 0) throw IoError(dir.string() + ": cannot open directory: " + why(errno));
    if (::fsync(d.fd) != 0) throw IoError(dir.string() + ": fsync failed: " + why(errno));
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
    write_file_atomically(path, std::span<const std::string_view>(&bytes, 1));
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::string_view> parts) {
    struct stat target {};
    if (::stat(path.c_str(), &target) == 0 && !S_ISREG(target.st_mode) && !S_ISDIR(target.st_mode))
        return write_in_place(path, parts);
    const std::filesystem::path temp = temporary_path(path);
    const char* step = "";
    int error = write_temporary(temp, parts, step);
    if (error == 0 && ::rename(temp.c_str(), path.c_str()) != 0) {
        error = errno;
        step = "cannot replace";
    }
    if (error != 0) {
        if (std::strcmp(step, "cannot create") != 0) ::unlink(temp.c_str());  // never a file we did not create
        throw IoError(path.string() + ": " + step + ": " + why(error));
    }
    sync_directory(path.parent_path());
}

FileBound memory_bound(const char* of) {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    const std::uint64_t memory = pages > 0 && page > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page)
                                                       : std::uint64_t{16} << 30;
    return {memory, of};
}

namespace {
const char* file_kind(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

[[noreturn]] void refuse_size(const std::filesystem::path& path, const std::string& size, const FileBound& bound) {
    throw IoError(path.string() + ": " + size + " bytes, more than the limit of " + std::to_string(bound.bytes) +
                  " bytes for " + bound.of);
}

// Up to `limit` bytes of a regular file; with `bound`, a file of more is
// refused (before anything is allocated when its size says so).
std::string read_regular(const std::filesystem::path& path, std::uint64_t limit, const FileBound* bound) {
    // O_NONBLOCK: opening a FIFO must not wait for a writer; the type is
    // checked on the descriptor, so nothing can be swapped in between.
    Fd in(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
    if (in.fd < 0) throw IoError(path.string() + ": cannot open for reading: " + why(errno));
    struct stat info {};
    if (::fstat(in.fd, &info) != 0) throw IoError(path.string() + ": cannot read its size: " + why(errno));
    if (!S_ISREG(info.st_mode))
        throw IoError(path.string() + ": is not a regular file (it is " + file_kind(info.st_mode) + ")");
    const auto size = static_cast<std::uint64_t>(info.st_size);
    if (bound != nullptr && size > limit) refuse_size(path, std::to_string(size), *bound);
    // Read straight into the string (a checkpoint can be 150 MB), sized from
    // fstat; one byte more tells a file that grew past the limit since.
    const std::uint64_t wanted = std::min(size, limit) + 1;
    std::string bytes;
    try {
        bytes.resize(static_cast<std::size_t>(wanted));
    } catch (const std::exception&) {  // std::bad_alloc, std::length_error
        throw IoError(path.string() + ": not enough memory to read its " + std::to_string(size) + " bytes");
    }
    std::size_t got = 0;
    while (got < bytes.size()) {
        const ssize_t n = ::read(in.fd, bytes.data() + got, bytes.size() - got);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw IoError(path.string() + ": read failed: " + why(errno));
        }
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    if (bound != nullptr && got > limit) refuse_size(path, "at least " + std::to_string(got), *bound);
    bytes.resize(std::min<std::uint64_t>(got, limit));
    return bytes;
}
}  // namespace

std::string read_file_bytes(const std::filesystem::path& path, FileBound bound) {
    return read_regular(path, bound.bytes, &bound);
}

std::string read_file_head(const std::filesystem::path& path, std::uint64_t length) {
    return read_regular(path, length, nullptr);
}

}  // namespace morphogen
