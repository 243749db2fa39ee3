#pragma once
// The HTTP server of `morphogen breed` (cpp-httplib, Debian's
// libcpp-httplib-dev): the page, its assets, three.js and the JSON API over
// one BreedSession (docs/breed-api.md, "The API"). Every request needs the
// session token (query `token=` or `Authorization: Bearer`); a Host or
// Origin that is not the server's own gets 403 (DNS rebinding); bodies over
// kMaxBreedBody get 413, chunked ones too, with no more read than that;
// every error body is {"error": "..."}.
#include "breed/session.hpp"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

namespace morphogen {

inline constexpr std::size_t kMaxBreedBody = 64 * 1024;

struct BreedServerOptions {
    std::string bind = "127.0.0.1";
    int port = 0;       // 0: a free port
    std::string token;  // 32 hex characters (new_breed_token)
    std::filesystem::path three_dir = "/usr/share/javascript/three";  // served under /assets/three/
};

// 32 hex characters from std::random_device.
std::string new_breed_token();

class BreedServer {
public:
    // Binds (IoError naming the address if it cannot); serves after run().
    BreedServer(BreedSession& session, BreedServerOptions options);
    ~BreedServer();
    BreedServer(const BreedServer&) = delete;
    BreedServer& operator=(const BreedServer&) = delete;

    int port() const;
    // The page's address: http://HOST:PORT/?token=TOKEN (HOST 127.0.0.1, or
    // the --bind address when it is not a wildcard).
    std::string address() const;
    // Serves until stop() (from another thread or a signal watcher).
    void run();
    void stop();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace morphogen
