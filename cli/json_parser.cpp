// crspline command line: reading an input, and a JSON parser that knows the
// path of every value it reads. See json_parser.hpp.
#include "json_parser.hpp"

#include <crspline/dispatch.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

namespace crspline::cli {

using nlohmann::json;

// --- reading -------------------------------------------------------------------

input_text read_input(const std::string& path) {
    input_text in;
    if (path.empty() || path == "-") {
        // stdin: read everything, bytes as they are.
        in.name = "<stdin>";
        std::array<char, 1 << 16> buf;
        std::size_t got;
        while ((got = std::fread(buf.data(), 1, buf.size(), stdin)) > 0) in.text.append(buf.data(), got);
        if (std::ferror(stdin)) throw input_error(in.name + ": cannot read: " + std::strerror(errno));
        return in;
    }
    in.name = path;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw input_error(path + ": cannot open: " + std::strerror(errno));
    std::array<char, 1 << 16> buf;
    std::size_t got;
    while ((got = std::fread(buf.data(), 1, buf.size(), f)) > 0) in.text.append(buf.data(), got);
    const bool failed = std::ferror(f) != 0;
    const int err = errno;  // a directory opens but fails to read (EISDIR)
    std::fclose(f);
    if (failed) throw input_error(path + ": cannot read: " + std::strerror(err));
    return in;
}

// --- parsing -------------------------------------------------------------------

namespace {

// Builds the document like nlohmann's own DOM parser, but knows at every
// moment the path of the value being read ("points[3][1]"), so that a number
// too large for a double is reported by its field, and rejects duplicate keys
// (nlohmann would silently keep the last one).
class path_tracking_parser final : public nlohmann::json_sax<json> {
public:
    explicit path_tracking_parser(const input_text& in, bool fast_points = false)
        : in_(in), fast_enabled_(fast_points) {}

    json root;
    std::string error;            // set when parsing stopped
    std::optional<point_set> flat;  // the top-level "points", read flat

    bool null() override { return leave_fast() && add(json(nullptr)); }
    bool boolean(bool v) override { return leave_fast() && add(json(v)); }
    bool number_integer(number_integer_t v) override { return number(double(v)) || add(json(v)); }
    bool number_unsigned(number_unsigned_t v) override { return number(double(v)) || add(json(v)); }
    bool number_float(number_float_t v, const string_t&) override { return number(v) || add(json(v)); }
    bool string(string_t& v) override { return leave_fast() && add(json(std::move(v))); }
    bool binary(binary_t& v) override { return leave_fast() && add(json::binary(std::move(v))); }

    bool start_object(std::size_t) override { return leave_fast() && open(json::object()); }
    bool key(string_t& k) override {
        frame& f = stack_.back();
        if (f.value->contains(k)) {
            error = prefix(path_of_parent()) + "duplicate field '" + k + "'";
            return false;
        }
        f.key = k;
        // The top-level "points": read flat if it turns out well-formed.
        if (fast_enabled_ && stack_.size() == 1 && k == "points") fast_ = fast::armed;
        return true;
    }
    bool end_object() override { return leave_fast() && close(); }
    bool start_array(std::size_t) override {
        if (fast_ == fast::armed) {
            fast_ = fast::on;
            fast_depth_ = 1;
            flat.emplace();
            place(json::array());  // a placeholder: "points" is present
            return true;
        }
        if (fast_ == fast::on && fast_depth_ == 1) {
            fast_depth_ = 2;
            fast_count_ = 0;
            return true;
        }
        return leave_fast() && open(json::array());
    }
    bool end_array() override {
        if (fast_ == fast::on) {
            if (fast_depth_ == 1) {  // the end of "points": all of it was well-formed
                fast_ = fast::off;
                return true;
            }
            const bool first = fast_points_ == 0;
            if (fast_count_ > 0 && (first || fast_count_ == flat->dimension)) {
                if (first) flat->dimension = fast_count_;
                ++fast_points_;
                fast_depth_ = 1;
                return true;
            }
            fallback();
        }
        return close();
    }

    bool parse_error(std::size_t position, const std::string& last_token,
                     const nlohmann::detail::exception& ex) override {
        if (ex.id == 406) {
            // "number overflow parsing '1e999'": a literal beyond the double range.
            const std::string at = fast_ != fast::on ? path_of_next()
                                   : fast_depth_ == 1 ? "points[" + std::to_string(fast_points_) + "]"
                                   : "points[" + std::to_string(fast_points_) + "][" + std::to_string(fast_count_) + "]";
            error = prefix(at) + "expected a finite number, got " + last_token;
            return false;
        }
        error = in_.name + ": " + line_column(position) + ": " + strip_prefix(ex.what());
        return false;
    }

private:
    struct frame {
        json* value;
        std::string key;  // objects: the key of the value being read
    };
    const input_text& in_;
    std::vector<frame> stack_;

    // Fast path: armed after the top-level key "points", on inside its array
    // (depth 1: between points, depth 2: inside one point).
    enum class fast { off, armed, on };
    bool fast_enabled_ = false;
    fast fast_ = fast::off;
    int fast_depth_ = 0;
    std::size_t fast_count_ = 0;   // coordinates read in the current point
    std::size_t fast_points_ = 0;  // points completed

    // A number on the fast path; false when it is not (the caller adds it).
    bool number(double v) {
        if (fast_ == fast::on && fast_depth_ == 2 && fast_count_ < max_runtime_dimension) {
            flat->coords.push_back(v);
            ++fast_count_;
            return true;
        }
        leave_fast();
        return false;
    }

    // Anything but a number inside a point ends the fast path.
    bool leave_fast() {
        if (fast_ == fast::armed) fast_ = fast::off;  // "points" is not an array
        if (fast_ == fast::on) fallback();
        return true;
    }

    // Rebuilds the tree for what the fast path has read so far, so that the
    // rest of "points" goes into the tree and validation sees all of it.
    void fallback() {
        const std::size_t d = flat->dimension;
        json outer = json::array();
        for (std::size_t i = 0; i < fast_points_; ++i) {
            json p = json::array();
            for (std::size_t k = 0; k < d; ++k) p.push_back(flat->coords[i * d + k]);
            outer.push_back(std::move(p));
        }
        json* o = &(root["points"] = std::move(outer));
        stack_.push_back({o, {}});
        if (fast_depth_ == 2) {
            json p = json::array();
            for (std::size_t k = fast_points_ * d; k < flat->coords.size(); ++k) p.push_back(flat->coords[k]);
            o->push_back(std::move(p));
            stack_.push_back({&o->back(), {}});
        }
        flat.reset();
        fast_ = fast::off;
    }

    // The value just read goes into the innermost container, or is the root.
    json* place(json&& v) {
        if (stack_.empty()) {
            root = std::move(v);
            return &root;
        }
        frame& f = stack_.back();
        if (f.value->is_array()) {
            f.value->push_back(std::move(v));
            return &f.value->back();
        }
        return &((*f.value)[f.key] = std::move(v));
    }
    bool add(json&& v) {
        place(std::move(v));
        return true;
    }
    bool open(json&& container) {
        json* p = place(std::move(container));
        stack_.push_back({p, {}});
        return true;
    }
    bool close() {
        stack_.pop_back();
        return true;
    }

    // Path of the value being read now ("points[3][1]"), or of the innermost
    // container itself. A container below the innermost one was the last
    // value added to its parent, at index size - 1.
    std::string path(bool include_next) const {
        std::string p;
        const std::size_t n = stack_.size(), upto = include_next ? n : (n == 0 ? 0 : n - 1);
        for (std::size_t i = 0; i < upto; ++i) {
            const frame& f = stack_[i];
            if (f.value->is_array()) p += "[" + std::to_string(i + 1 == n ? f.value->size() : f.value->size() - 1) + "]";
            else p += (p.empty() ? "" : ".") + f.key;
        }
        return p;
    }
    std::string path_of_next() const { return path(true); }
    std::string path_of_parent() const { return path(false); }
    // A field of a named file after the file's name ("curve.json:
    // points[1][1]: ..."); on stdin the field's path alone.
    std::string prefix(const std::string& path) const {
        if (path.empty()) return in_.name + ": ";
        return (in_.name == "<stdin>" ? path : in_.name + ": " + path) + ": ";
    }

    // nlohmann counts the end of input as one character read; the offending
    // character is the last one read, at byte index position - 1.
    std::string line_column(std::size_t position) const {
        const std::size_t at = std::min(position == 0 ? 0 : position - 1, in_.text.size());
        const std::size_t line = 1 + std::size_t(std::count(in_.text.begin(), in_.text.begin() + std::ptrdiff_t(at), '\n'));
        const std::size_t nl = at == 0 ? std::string::npos : in_.text.rfind('\n', at - 1);
        const std::size_t column = nl == std::string::npos ? at + 1 : at - nl;
        return "line " + std::to_string(line) + ", column " + std::to_string(column);
    }

    // "[json.exception.parse_error.101] parse error at line 2, column 11: syntax
    // error ..." -> "syntax error ...": the position is given by ourselves.
    static std::string strip_prefix(std::string msg) {
        if (const auto c = msg.find("column "); c != std::string::npos)
            if (const auto colon = msg.find(": ", c); colon != std::string::npos) return msg.substr(colon + 2);
        if (const auto b = msg.find("] "); b != std::string::npos) return msg.substr(b + 2);
        return msg;
    }
};

}  // namespace

json parse_json(const input_text& in) {
    path_tracking_parser p(in);
    const bool ok = json::sax_parse(in.text, &p);
    if (!ok) throw input_error(p.error.empty() ? in.name + ": not valid JSON" : p.error);
    return std::move(p.root);
}

document parse_json_document(const input_text& in) {
    path_tracking_parser p(in, true);
    const bool ok = json::sax_parse(in.text, &p);
    if (!ok) throw input_error(p.error.empty() ? in.name + ": not valid JSON" : p.error);
    document d;
    d.root = std::move(p.root);
    if (d.root.is_object()) d.points = std::move(p.flat);
    return d;
}

// --- numbers in messages ---------------------------------------------------------

std::string format_number(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    std::array<char, 64> buf;
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), x);
    return std::string(buf.data(), r.ptr);
}


}  // namespace crspline::cli
