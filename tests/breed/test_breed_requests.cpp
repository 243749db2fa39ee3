// Requests to `morphogen breed` framed or encoded as a careless or hostile
// client sends them, on a raw socket (docs/breed.md, "Errors"): a chunked or
// declared body over 64 KiB, a body without a length, invalid UTF-8, and a
// NUL byte in an id.
#include "tests/breed/breed_test_support.hpp"
#include "tests/breed/server_process.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>

using namespace morphogen::testing;
using nlohmann::json;

namespace {

// A connection to the server, closed by the destructor.
struct RawConnection {
    int fd = -1;
    explicit RawConnection(int port) {
        fd = ::socket(AF_INET, SOCK_STREAM, 0);
        REQUIRE(fd >= 0);
        timeval timeout{30, 0};  // a server that never answers fails the test, not hangs it
        ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(static_cast<std::uint16_t>(port));
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        REQUIRE(::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
    }
    ~RawConnection() { ::close(fd); }
    RawConnection(const RawConnection&) = delete;
    RawConnection& operator=(const RawConnection&) = delete;

    // false once the server has closed the connection
    bool send_all(const std::string& bytes) {
        for (std::size_t at = 0; at < bytes.size();) {
            const ssize_t n = ::send(fd, bytes.data() + at, bytes.size() - at, MSG_NOSIGNAL);
            if (n <= 0) return false;
            at += static_cast<std::size_t>(n);
        }
        return true;
    }
    // What the server sent until it closed the connection or 30 s passed.
    std::string receive_all() {
        std::string out;
        char buffer[4096];
        for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) out.append(buffer, static_cast<std::size_t>(n));
        return out;
    }
    // One answer: the status line and headers, then Content-Length bytes of body.
    std::string receive_answer() {
        std::string out;
        char c = 0;
        while (out.find("\r\n\r\n") == std::string::npos && ::recv(fd, &c, 1, 0) == 1) out += c;
        const std::size_t at = out.find("Content-Length: ");
        if (at == std::string::npos) return out;
        std::size_t length = std::stoul(out.substr(at + 16));
        while (length > 0 && ::recv(fd, &c, 1, 0) == 1) {
            out += c;
            --length;
        }
        return out;
    }
};

int answer_status(const std::string& answer) {
    INFO(answer.substr(0, 200));
    REQUIRE(answer.starts_with("HTTP/1.1 "));
    return std::stoi(answer.substr(9, 3));
}

// The answer's {"error": ...}, after checking it is one.
std::string answer_error(const std::string& answer) {
    const std::size_t at = answer.find("\r\n\r\n");
    REQUIRE(at != std::string::npos);
    const json body = json::parse(answer.substr(at + 4), nullptr, false);
    INFO(answer);
    REQUIRE(body.is_object());
    REQUIRE(body.contains("error"));
    return body.at("error").get<std::string>();
}

std::string head(const BreedProcess& server, const std::string& request_line) {
    return request_line + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(server.port()) +
           "\r\nAuthorization: Bearer " + server.token() + "\r\n";
}

// One field of /proc/PID/status, in kB.
long proc_status_kb(pid_t pid, const std::string& field) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string line;
    while (std::getline(status, line))
        if (line.starts_with(field + ":")) return std::stol(line.substr(field.size() + 1));
    FAIL("no " << field << " in /proc/" << pid << "/status");
    return 0;
}

// POSTs to /api/breed `headers`, then `piece` (64 KiB of body, framed as the
// headers say) again and again up to `total` bytes of body or until the
// server closes the connection; returns the body bytes sent, and the answer.
std::pair<std::uint64_t, std::string> post_big(const BreedProcess& server, const std::string& headers,
                                               const std::string& piece, std::uint64_t total) {
    RawConnection connection(server.port());
    REQUIRE(connection.send_all(head(server, "POST /api/breed") + headers + "\r\n"));
    std::uint64_t sent = 0;
    while (sent < total && connection.send_all(piece)) sent += 64 * 1024;
    return {sent, connection.receive_all()};
}

}  // namespace

TEST_CASE("a body over 64 KiB is cut off, chunked or not: 413, the rest unread, memory flat", "[breed][server]") {
    TempDir tmp("breed_requests");
    BreedProcess server({tmp.write("tiny.json", kTinyBreedConfig), "--out", tmp.file("s")});
    const std::uint64_t total = std::uint64_t{100} << 20;  // 100 MB
    const std::string spaces(64 * 1024, ' ');
    const std::string chunk = "10000\r\n" + spaces + "\r\n";

    // Peak memory from here on: writing 5 to clear_refs resets VmHWM to VmRSS.
    std::ofstream(("/proc/" + std::to_string(server.pid()) + "/clear_refs").c_str()) << "5";
    const long before = proc_status_kb(server.pid(), "VmRSS");
    const auto [chunked_sent, chunked_answer] =
        post_big(server, "Content-Type: application/json\r\nTransfer-Encoding: chunked\r\n", chunk, total);
    const long growth = proc_status_kb(server.pid(), "VmHWM") - before;
    INFO("chunked: the server's peak memory grew by " << growth << " kB; the client sent " << chunked_sent
                                                      << " bytes before the server closed");
    CHECK(answer_status(chunked_answer) == 413);
    CHECK(answer_error(chunked_answer) == "the request body is larger than 65536 bytes");
    CHECK(growth < 10 * 1024);
    // The server stopped reading: the client could not send it all (the
    // kernel's socket buffers hold a few MB).
    CHECK(chunked_sent < total / 2);

    // A Content-Length over the limit: refused before a byte is read.
    const auto [declared_sent, declared_answer] =
        post_big(server, "Content-Type: application/json\r\nContent-Length: " + std::to_string(total) + "\r\n", spaces, total);
    CHECK(answer_status(declared_answer) == 413);
    CHECK(declared_sent < total / 2);

    // A chunked body within the limit is read as any other.
    httplib::Client client("127.0.0.1", server.port());
    client.set_read_timeout(60, 0);
    const httplib::Headers auth = {{"Authorization", "Bearer " + server.token()}};
    auto state = client.Get("/api/state", auth);
    REQUIRE(state);
    const std::string parent = grid_ids(json::parse(state->body))[3];
    const std::string body = json{{"parents", {parent}}, {"strength", 0.5}}.dump() + spaces.substr(0, 60000);
    auto bred = client.Post(
        "/api/breed", auth,
        [&](std::size_t offset, httplib::DataSink& sink) {
            if (offset < body.size()) sink.write(body.data() + offset, std::min<std::size_t>(1000, body.size() - offset));
            else sink.done();
            return true;
        },
        "application/json");
    REQUIRE(bred);
    CHECK(bred->status == 200);
    CHECK(json::parse(bred->body).at("generation") == 1);
    server.signal(SIGTERM);
    CHECK(server.wait() == 0);
}

TEST_CASE("a body without a length, with invalid UTF-8, or with a NUL in an id gets its sentence", "[breed][server]") {
    TempDir tmp("breed_requests");
    BreedProcess server({tmp.write("tiny.json", kTinyBreedConfig), "--out", tmp.file("s")});
    auto exchange = [&](const std::string& request) {
        RawConnection connection(server.port());
        REQUIRE(connection.send_all(request));
        return connection.receive_answer();  // the connection stays open, as a browser's does
    };

    // No Content-Length: the same answer as an empty body (nothing to undo: 409).
    for (const char* path : {"/api/undo", "/api/redo", "/api/explore/stop", "/api/breed"}) {
        INFO(path);
        const std::string without = exchange(head(server, std::string("POST ") + path) + "\r\n");
        const std::string empty = exchange(head(server, std::string("POST ") + path) + "Content-Length: 0\r\n\r\n");
        CHECK(answer_status(without) == answer_status(empty));
        CHECK(answer_error(without) == answer_error(empty));
        CHECK(answer_status(without) == (std::string(path) == "/api/breed" ? 400 : 409));
    }

    // Invalid UTF-8 in a body, in a key, in a path: 400 or 404 with a sentence.
    const std::string bad_value = "{\"parents\": [\"p\xff\xfe\"]}";
    const std::string answer =
        exchange(head(server, "POST /api/breed") + "Content-Length: " + std::to_string(bad_value.size()) + "\r\n\r\n" +
                 bad_value);
    CHECK(answer_status(answer) == 400);
    CHECK(answer_error(answer).starts_with("the body is not a JSON object: line 1, column 16"));
    CHECK(answer_error(answer).find("UTF-8") != std::string::npos);
    const std::string bad_key = "{\"parents\": [\"p000000\"], \"\xc3\x28\": 1}";
    const std::string key_answer =
        exchange(head(server, "POST /api/breed") + "Content-Length: " + std::to_string(bad_key.size()) + "\r\n\r\n" +
                 bad_key);
    CHECK(answer_status(key_answer) == 400);
    CHECK(answer_error(key_answer).find("UTF-8") != std::string::npos);
    const std::string path_answer = exchange(head(server, "GET /api/mesh/p%FF%FE.glb") + "\r\n");
    CHECK(answer_status(path_answer) == 404);
    CHECK(answer_error(path_answer) == "no plant \"p\xef\xbf\xbd\xef\xbf\xbd\" in this session");

    // A NUL in an id or a key: the whole message, the NUL escaped.
    const std::string nul_id = R"({"parents": ["p000000\u0000x"]})";
    const std::string nul_answer =
        exchange(head(server, "POST /api/breed") + "Content-Length: " + std::to_string(nul_id.size()) + "\r\n\r\n" + nul_id);
    CHECK(answer_status(nul_answer) == 404);
    CHECK(answer_error(nul_answer) == R"(no plant "p000000\u0000x" in this session)");
    const std::string nul_key = R"({"parents": ["p000000"], "a\u0000b": 1})";
    const std::string key_nul_answer =
        exchange(head(server, "POST /api/breed") + "Content-Length: " + std::to_string(nul_key.size()) + "\r\n\r\n" + nul_key);
    CHECK(answer_status(key_nul_answer) == 400);
    CHECK(answer_error(key_nul_answer) == R"(unknown field "a\u0000b")");
    const std::string nul_path = exchange(head(server, "GET /api/thumb/p000000%00x.png") + "\r\n");
    CHECK(answer_status(nul_path) == 404);
    CHECK(answer_error(nul_path) == R"(no plant "p000000\u0000x" in this session)");

    // None of it changed the session.
    const std::string state = exchange(head(server, "GET /api/state") + "\r\n");
    CHECK(answer_status(state) == 200);
    CHECK(state.find("\"generation\":0") != std::string::npos);
    server.signal(SIGTERM);
    CHECK(server.wait() == 0);
}
