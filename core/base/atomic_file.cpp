#include "core/base/atomic_file.hpp"

#include "core/base/errors.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

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
    Fd out(::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC));
    if (out.fd < 0) throw IoError(path.string() + ": cannot open for writing: " + why(errno));
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

std::string read_file_bytes(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw IoError(path.string() + ": cannot read: it is a directory");
    Fd in(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (in.fd < 0) throw IoError(path.string() + ": cannot open for reading: " + why(errno));
    // Read straight into the string (a checkpoint can be 150 MB): sized from
    // fstat for a regular file, growing for anything else (a pipe, /dev/stdin).
    struct stat info {};
    std::size_t capacity = 1 << 16;
    if (::fstat(in.fd, &info) == 0 && S_ISREG(info.st_mode)) capacity = static_cast<std::size_t>(info.st_size) + 1;
    std::string bytes(capacity, '\0');
    std::size_t size = 0;
    while (true) {
        if (size == bytes.size()) bytes.resize(2 * bytes.size());
        const ssize_t n = ::read(in.fd, bytes.data() + size, bytes.size() - size);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw IoError(path.string() + ": read failed: " + why(errno));
        }
        if (n == 0) break;
        size += static_cast<std::size_t>(n);
    }
    bytes.resize(size);
    return bytes;
}

}  // namespace morphogen
