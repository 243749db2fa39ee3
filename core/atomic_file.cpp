#include "atomic_file.hpp"

#include "errors.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace morphogen {

namespace {
std::string why() { return std::strerror(errno); }

// Closes a descriptor on scope exit.
struct Fd {
    int fd = -1;
    explicit Fd(int d) : fd(d) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};
}  // namespace

void sync_directory(const std::filesystem::path& dir) {
    Fd d(::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY));
    if (d.fd < 0) throw IoError(dir.string() + ": cannot open directory: " + why());
    if (::fsync(d.fd) != 0) throw IoError(dir.string() + ": fsync failed: " + why());
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
    const std::filesystem::path temp = path.string() + ".tmp";
    {
        Fd out(::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
        if (out.fd < 0) throw IoError(temp.string() + ": cannot create: " + why());
        std::size_t written = 0;
        while (written < bytes.size()) {
            const ssize_t n = ::write(out.fd, bytes.data() + written, bytes.size() - written);
            if (n < 0) {
                if (errno == EINTR) continue;
                throw IoError(temp.string() + ": write failed: " + why());
            }
            written += static_cast<std::size_t>(n);
        }
        if (::fsync(out.fd) != 0) throw IoError(temp.string() + ": fsync failed: " + why());
    }
    if (::rename(temp.c_str(), path.c_str()) != 0)
        throw IoError(path.string() + ": cannot replace with " + temp.string() + ": " + why());
    sync_directory(path.parent_path());
}

std::string read_file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path.string() + ": cannot open for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw IoError(path.string() + ": read failed");
    return buffer.str();
}

}  // namespace morphogen
