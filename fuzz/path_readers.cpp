#include "fuzz/path_readers.hpp"

#include "fuzz/fuzz_target.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace morphogen::fuzz {
namespace {

namespace fs = std::filesystem;

// A file of this process's own (several fuzzers or replays may run at once),
// removed as soon as the reader is done with it, also when it throws; only a
// hard crash or a hang leaves one behind. In /dev/shm where there is one: a
// file per input on disk made the mesh and checkpoint targets 14 times slower
// (214 against 3000 inputs/s).
fs::path scratch_base() {
    std::error_code ec;
    if (fs::is_directory("/dev/shm", ec) && ::access("/dev/shm", W_OK) == 0) return "/dev/shm";
    const fs::path temp = fs::temp_directory_path(ec);
    return ec ? fs::path("/tmp") : temp;
}

class ScratchFile {
public:
    ScratchFile(std::string_view bytes, const std::string& extension)
        : path_(scratch_base() / ("morphogen-fuzz-" + std::to_string(::getpid()) + extension)) {
        std::ofstream out(path_, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) finding("harness: cannot write scratch file " + path_.string());
    }
    ~ScratchFile() {
        std::error_code ignored;
        fs::remove(path_, ignored);
    }
    ScratchFile(const ScratchFile&) = delete;
    ScratchFile& operator=(const ScratchFile&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};


}  // namespace

MeshArrays read_mesh_bytes(std::string_view bytes, const MeshFormat& format) {
    return parse_mesh(bytes, format, "fuzz input");
}

RunState load_checkpoint_bytes(std::string_view bytes) {
    const ScratchFile file(bytes, ".json");
    return load_checkpoint(file.path());
}

}  // namespace morphogen::fuzz
