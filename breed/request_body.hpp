#pragma once
// The body of a request to the breed server, read within a limit whatever
// its framing. cpp-httplib 0.11.4 (Debian's) holds only a body with a
// Content-Length to its payload limit: a chunked body is read whole into
// memory, and a body with neither header is waited for until the client
// closes. Here a chunked body stops at the limit, a Content-Length over it is
// refused before a byte of the body is read, and a request with neither
// header has an empty body (RFC 9112, section 6.3).
#include <httplib.h>

#include <cstddef>
#include <string>

namespace morphogen {

struct RequestBody {
    enum class Outcome { whole, too_large, unreadable };
    Outcome outcome = Outcome::whole;
    std::string bytes;  // the body when whole
};

// Reads the body of `request` through httplib's content reader, at most `limit` bytes.
RequestBody read_request_body(const httplib::Request& request, const httplib::ContentReader& reader,
                              std::size_t limit);

// Answers `status` with the JSON `body` and closes the connection after it:
// the rest of a body left unread must not be taken for the next request.
void answer_and_close(httplib::Response& response, int status, const std::string& body);

}  // namespace morphogen
