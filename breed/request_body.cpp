#include "breed/request_body.hpp"

#include <charconv>
#include <strings.h>

namespace morphogen {

RequestBody read_request_body(const httplib::Request& request, const httplib::ContentReader& reader,
                              std::size_t limit) {
    using Outcome = RequestBody::Outcome;
    RequestBody body;
    const bool framed_by_chunks = request.has_header("Transfer-Encoding");
    if (framed_by_chunks && ::strcasecmp(request.get_header_value("Transfer-Encoding").c_str(), "chunked") != 0)
        return {Outcome::unreadable, {}};  // httplib would read it to the end of the connection
    if (!framed_by_chunks) {
        if (!request.has_header("Content-Length")) return body;
        const std::string text = request.get_header_value("Content-Length");
        std::size_t length = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), length);
        if (error == std::errc::result_out_of_range) return {Outcome::too_large, {}};
        if (error != std::errc() || end != text.data() + text.size()) return {Outcome::unreadable, {}};
        if (length > limit) return {Outcome::too_large, {}};
        if (length == 0) return body;
    }
    bool over = false;
    const bool read = reader([&](const char* data, std::size_t size) {
        if (size > limit - body.bytes.size()) {
            over = true;
            return false;  // stops httplib reading: the rest stays unread
        }
        body.bytes.append(data, size);
        return true;
    });
    if (over) return {Outcome::too_large, {}};
    if (!read) return {Outcome::unreadable, {}};
    return body;
}

void answer_and_close(httplib::Response& response, int status, const std::string& body) {
    response.status = status;
    response.set_header("Connection", "close");
    response.set_header("Cache-Control", "no-store");
    response.set_header("X-Content-Type-Options", "nosniff");
    // httplib 0.11.4 lets a handler close its connection in one way only: a
    // content provider that fails. This one writes the whole body, then
    // fails, so httplib ends the connection after the answer.
    response.set_content_provider(body.size(), "application/json",
                                  [body](std::size_t offset, std::size_t, httplib::DataSink& sink) {
                                      sink.write(body.data() + offset, body.size() - offset);
                                      return false;
                                  });
}

}  // namespace morphogen
