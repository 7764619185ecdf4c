// crspline command line: output written as it is computed.
//
// eval, bezier and sample on 10^6 points write tens of megabytes; holding the
// whole text (or a JSON tree of it) before writing cost hundreds of
// megabytes. An output_stream takes the text piece by piece:
//  - to a file (-o FILE): through a temporary file beside the target, renamed
//    over it by commit(); anything that fails first (an error, an exception,
//    a full disk) removes the temporary file, so FILE is whole or untouched;
//    (a device or a pipe, like /dev/null, is written directly);
//  - to stdout: the first MiB is held back, so that a short output is still
//    all or nothing; past it the text is written as it comes, and an error
//    after that leaves the output cut short (exit status 2 says so).
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace crspline::cli {

/// How numbers are written: the shortest text that reads back to the same
/// double (precision 0), or rounded to `precision` significant digits first.
struct number_format {
    int precision = 0;  ///< 0: shortest round trip; else 1..17 significant digits
};

/// x rounded to `precision` significant digits (x itself for precision 0).
double round_to_precision(double x, int precision);

/// Appends x: the shortest text that reads back to x after rounding to the
/// format's precision ("0.1", "2", "1e-05").
void append_number(std::string& s, double x, const number_format& f);

/// Like append_number, but as JSON writes doubles (nlohmann::json's form:
/// a whole number keeps ".0", so that "2.0" stays a float).
void append_json_number(std::string& s, double x, const number_format& f);

class output_stream {
public:
    /// "" or "-": stdout; else a file, opened (as a temporary) on the first
    /// write that leaves the held-back buffer.
    explicit output_stream(std::string path);
    /// Text kept in memory, for take() (the fuzz target, figures).
    static output_stream in_memory() {
        output_stream s("-");
        s.in_memory_ = true;
        return s;
    }
    output_stream(output_stream&& o) noexcept
        : path_(std::move(o.path_)), tmp_(std::move(o.tmp_)), to_stdout_(o.to_stdout_), in_memory_(o.in_memory_),
          fd_(o.fd_), committed_(o.committed_), started_(o.started_), direct_(o.direct_), buf_(std::move(o.buf_)) {
        o.fd_ = -1;
        o.tmp_.clear();
    }
    std::string take() && { return std::move(buf_); }
    ~output_stream();  ///< removes the temporary file unless committed
    output_stream(const output_stream&) = delete;
    output_stream& operator=(const output_stream&) = delete;

    /// The text not yet written: append to it, then call written().
    std::string& buffer() noexcept { return buf_; }
    /// Writes the buffer out when it is large enough.
    void written() {
        if (!in_memory_ && buf_.size() >= (to_stdout_ && !started_ ? hold_ : chunk_)) flush();
    }
    void put(std::string_view s) {
        buf_ += s;
        written();
    }
    /// Writes what is left and, for a file, renames the temporary onto the
    /// target. Throws input_error "PATH: cannot write: <reason>".
    void commit();

    /// The text of one number (see number_format) in JSON or plain form;
    /// throws input_error "<where()>: the result is not finite ..." for NaN
    /// or infinity (JSON cannot hold them; they arise only when the input's
    /// scale overflows double arithmetic).
    template <class Where>
    void number(double x, const number_format& f, bool json, Where&& where) {
        if (!std::isfinite(x)) not_finite(where());
        if (json) append_json_number(buf_, x, f);
        else append_number(buf_, x, f);
    }
    [[noreturn]] static void not_finite(const std::string& where);
    /// "key":[x0,x1,...] in JSON, each number checked and written as number()
    /// does (a non-finite one named key[i]).
    void json_list(std::string_view key, std::span<const double> xs, const number_format& f) {
        buf_ += '"';
        buf_ += key;
        buf_ += "\":[";
        for (std::size_t i = 0; i < xs.size(); ++i) {
            if (i) buf_ += ',';
            number(xs[i], f, true, [&] { return std::string(key) + "[" + std::to_string(i) + "]"; });
            written();
        }
        buf_ += ']';
    }

private:
    void flush();
    [[noreturn]] void fail(int err);

    std::string path_, tmp_;
    bool to_stdout_, in_memory_ = false;
    int fd_ = -1;
    bool committed_ = false, started_ = false, direct_ = false;
    std::string buf_;
    static constexpr std::size_t chunk_ = std::size_t(1) << 16;  // 64 KiB writes to a file
    static constexpr std::size_t hold_ = std::size_t(1) << 20;   // 1 MiB held back on stdout
};

}  // namespace crspline::cli
