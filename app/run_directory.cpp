#include "run_directory.hpp"

#include "errors.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <system_error>

namespace morphogen {

namespace fs = std::filesystem;

fs::path RunPaths::best_stem(std::uint64_t generation) const {
    char name[32];
    std::snprintf(name, sizeof name, "gen_%04llu", static_cast<unsigned long long>(generation));
    return best / name;
}

RunPaths run_paths(const fs::path& dir) {
    return {dir,
            dir / "config.json",
            dir / "history.csv",
            dir / "lineage.csv",
            dir / "checkpoint.json",
            dir / "best",
            dir / "log.txt"};
}

fs::path default_run_dir(const std::string& name, std::chrono::system_clock::time_point now) {
    const std::time_t t = std::chrono::system_clock::to_time_t(now);
    std::tm local{};
    localtime_r(&t, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    return fs::path("runs") / (name + "-" + stamp);
}

void create_run_dir(const RunPaths& paths, bool force) {
    std::error_code ec;
    if (fs::exists(paths.dir, ec)) {
        if (!fs::is_directory(paths.dir, ec))
            throw IoError(paths.dir.string() + " exists and is not a directory");
        if (!fs::is_empty(paths.dir, ec) && !force)
            throw IoError("run directory " + paths.dir.string() +
                          " already exists and is not empty (use --force to overwrite it, or resume it)");
    }
    fs::create_directories(paths.dir, ec);
    if (ec) throw IoError(paths.dir.string() + ": cannot create: " + ec.message());
}

void clear_run_files(const RunPaths& paths) {
    std::error_code ec;
    for (const fs::path& p : {paths.config, paths.history, paths.lineage, paths.checkpoint, paths.log,
                              fs::path(paths.checkpoint.string() + ".tmp"), fs::path(paths.config.string() + ".tmp")})
        fs::remove(p, ec);
    if (fs::is_directory(paths.best, ec)) {
        for (const auto& entry : fs::directory_iterator(paths.best, ec))
            if (entry.path().filename().string().rfind("gen_", 0) == 0) fs::remove(entry.path(), ec);
    }
    fs::create_directories(paths.best, ec);
    if (ec) throw IoError(paths.best.string() + ": cannot create: " + ec.message());
}

RunLock::RunLock(const fs::path& dir) {
    const fs::path path = dir / ".lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw IoError(path.string() + ": cannot open the run lock");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd_);
        fd_ = -1;
        throw IoError("run directory " + dir.string() + " is in use by another morphogen process");
    }
}

RunLock::~RunLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace morphogen
