#include "cluster/protocol.hpp"

#include <cstring>

namespace morphogen::cluster {

namespace {
class Writer {
public:
    template <class T>
    void put(const T& value) {
        out_.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    void put_doubles(const std::vector<double>& values) {
        put<std::uint64_t>(values.size());
        if (!values.empty())
            out_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
    }
    void put_text(const std::string& text) {
        put<std::uint64_t>(text.size());
        out_ += text;
    }
    std::string take() { return std::move(out_); }

private:
    std::string out_;
};

class Reader {
public:
    explicit Reader(const std::string& bytes) : bytes_(bytes) {}
    template <class T>
    T get() {
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof value);
        at_ += sizeof value;
        return value;
    }
    std::vector<double> get_doubles() {
        const auto n = get<std::uint64_t>();
        if (n > (bytes_.size() - at_) / sizeof(double)) fail();
        std::vector<double> values(n);
        if (n > 0) std::memcpy(values.data(), bytes_.data() + at_, n * sizeof(double));  // data() may be null
        at_ += n * sizeof(double);
        return values;
    }
    std::string get_text() {
        const auto n = get<std::uint64_t>();
        need(n);
        std::string text = bytes_.substr(at_, n);
        at_ += n;
        return text;
    }
    void finish() const {
        if (at_ != bytes_.size()) throw ProtocolError("malformed message: " + std::to_string(bytes_.size() - at_) +
                                                      " bytes left over");
    }
    std::uint64_t count(std::size_t min_item_bytes) {
        const auto n = get<std::uint64_t>();
        if (n > (bytes_.size() - at_) / min_item_bytes) fail();
        return n;
    }

private:
    void need(std::uint64_t n) const {
        if (n > bytes_.size() - at_) fail();
    }
    [[noreturn]] void fail() const {
        throw ProtocolError("malformed message: truncated at byte " + std::to_string(at_) + " of " +
                            std::to_string(bytes_.size()));
    }
    const std::string& bytes_;
    std::size_t at_ = 0;
};
}  // namespace

std::string cpu_kind() {
#if defined(__x86_64__)
    return __builtin_cpu_supports("x86-64-v3") ? "x86-64-v3 (AVX2, FMA)" : "x86-64 (no AVX2/FMA)";
#else
    return "non-x86";
#endif
}

std::string encode_ready(const Ready& ready) {
    Writer w;
    w.put<std::int32_t>(ready.threads);
    w.put_text(ready.cpu);
    return w.take();
}

Ready decode_ready(const std::string& bytes) {
    Reader r(bytes);
    Ready ready;
    ready.threads = r.get<std::int32_t>();
    ready.cpu = r.get_text();
    r.finish();
    return ready;
}

std::string encode_int(int value) {
    Writer w;
    w.put<std::int32_t>(value);
    return w.take();
}

int decode_int(const std::string& bytes) {
    Reader r(bytes);
    const auto value = r.get<std::int32_t>();
    r.finish();
    return value;
}

std::string encode_work(const std::vector<WorkItem>& items) {
    Writer w;
    w.put<std::uint64_t>(items.size());
    for (const WorkItem& item : items) {
        w.put(item.index);
        w.put_doubles(item.params);
        w.put(item.keep_from);
    }
    return w.take();
}

std::vector<WorkItem> decode_work(const std::string& bytes) {
    Reader r(bytes);
    std::vector<WorkItem> items(r.count(3 * sizeof(std::uint64_t)));
    for (WorkItem& item : items) {
        item.index = r.get<std::uint64_t>();
        item.params = r.get_doubles();
        item.keep_from = r.get<double>();
    }
    r.finish();
    return items;
}

std::string encode_results(const std::vector<ResultItem>& items) {
    Writer w;
    w.put<std::uint64_t>(items.size());
    for (const ResultItem& item : items) {
        const Evaluation& e = item.evaluation;
        w.put(item.index);
        w.put<std::uint8_t>(e.valid ? 1 : 0);
        w.put(e.score);
        w.put(e.size);
        w.put_doubles(e.descriptors);
        w.put_text(e.error);
        w.put_text(e.kept);
    }
    return w.take();
}

std::vector<ResultItem> decode_results(const std::string& bytes) {
    Reader r(bytes);
    std::vector<ResultItem> items(r.count(sizeof(std::uint64_t) * 6 + 1));
    for (ResultItem& item : items) {
        item.index = r.get<std::uint64_t>();
        const auto valid = r.get<std::uint8_t>();
        if (valid > 1) throw ProtocolError("malformed message: validity byte " + std::to_string(valid));
        item.evaluation.valid = valid == 1;
        item.evaluation.score = r.get<double>();
        item.evaluation.size = r.get<double>();
        item.evaluation.descriptors = r.get_doubles();
        item.evaluation.error = r.get_text();
        item.evaluation.kept = r.get_text();
    }
    r.finish();
    return items;
}

}  // namespace morphogen::cluster
