// The bad-spec catalogue (bad_specs.json) against the core: every case the
// catalogue says the core rejects ("core": true) throws spec_error from
// validate() or make_curve(), with the catalogue's field and index and a
// message carrying its words. The front ends are held to the same words by
// tests/frontends/test_bad_specs.py (CLI, Python) and
// web/test/bad_specs.test.mjs (WASM), so all of them speak the core's text.
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <crspline/dispatch.hpp>
#include <crspline/spec.hpp>

namespace {

using json = nlohmann::json;

// The catalogue writes an infinite number as 1e999 (Python's json and
// JavaScript's JSON.parse read it as infinity); nlohmann-json refuses it, so
// it is read here as the string "inf".
json catalogue() {
    std::ifstream f(std::string(CRSPLINE_REFERENCE_DIR) + "/bad_specs.json");
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    // (Only where it is an array element: the "about" text mentions it too.)
    return json::parse(std::regex_replace(text, std::regex(R"(([\[,]\s*)1e999)"), "$1\"inf\""));
}

// JSON null (allowed at the ends of an open curve's kb lists) is NaN.
std::vector<double> values(const json& a) {
    std::vector<double> out;
    for (const auto& v : a)
        out.push_back(v.is_null()     ? std::numeric_limits<double>::quiet_NaN()
                      : v.is_string() ? std::numeric_limits<double>::infinity()
                                      : v.get<double>());
    return out;
}

crspline::end_spec end_of(const json& e) {
    crspline::end_spec r;
    if (e.is_array()) {
        r.type = crspline::end_spec::kind::tangent;
        r.velocity = values(e);
    } else if (e == "reflect") {
        r.type = crspline::end_spec::kind::reflect;
    }
    return r;
}

// The curve file as a curve_spec (only what the core's cases use).
crspline::curve_spec spec_of(const json& s) {
    crspline::curve_spec c;
    const json& pts = s.at("points");
    c.dimension = pts.empty() ? 2 : pts[0].size();
    for (const auto& p : pts)
        for (const double x : values(p)) c.points.push_back(x);
    if (s.contains("alpha")) c.alpha = s["alpha"].get<double>();
    if (s.contains("grid")) c.grid = values(s["grid"]);
    if (s.contains("tension")) c.tension = s["tension"].get<double>();
    if (s.contains("strict")) c.strict = s["strict"].get<bool>();
    if (s.contains("end")) {
        const json& e = s["end"];
        if (e == "closed") {
            c.closed = true;
        } else if (e.is_string()) {
            c.start = c.end = end_of(e);
        } else {
            if (e.contains("start")) c.start = end_of(e["start"]);
            if (e.contains("end")) c.end = end_of(e["end"]);
        }
    }
    if (s.contains("kb")) {
        const json& kb = s["kb"];
        if (kb.contains("tension")) c.kb.tension = values(kb["tension"]);
        if (kb.contains("continuity")) c.kb.continuity = values(kb["continuity"]);
        if (kb.contains("bias")) c.kb.bias = values(kb["bias"]);
    }
    if (!s.contains("alpha") && !s.contains("grid")) c.alpha = 0.5;
    return c;
}

void build(const crspline::curve_spec& s) {
    crspline::validate(s);
    crspline::with_dimension(s.dimension, [&](auto dim) { (void)crspline::make_curve<decltype(dim)::value>(s); },
                             [](std::size_t) {});
}

TEST(BadSpecs, TheCoreSpeaksTheCataloguesWords) {
    const json cases = catalogue().at("cases");
    ASSERT_EQ(cases.size(), 25u);
    std::size_t checked = 0;
    for (const auto& c : cases) {
        if (!c.at("core").get<bool>()) continue;
        const std::string name = c.at("name");
        SCOPED_TRACE(name);
        try {
            build(spec_of(c.at("spec")));
            ADD_FAILURE() << "no error";
        } catch (const crspline::spec_error& e) {
            const std::string what = e.what();
            EXPECT_EQ(e.field(), c.at("field").get<std::string>()) << what;
            if (!c.at("index").is_null()) {
                const std::size_t index = c["index"].get<std::size_t>();
                EXPECT_EQ(e.index(), index) << what;
                EXPECT_TRUE(std::regex_search(what, std::regex("(^|[^0-9.])" + std::to_string(index) + "($|[^0-9.])")))
                    << what;
            }
            for (const auto& w : c.at("words")) EXPECT_NE(what.find(w.get<std::string>()), std::string::npos) << what;
        }
        ++checked;
    }
    // 16 of the 25 cases reach the core's validation; the others are refused
    // by the front ends' readers (a wrong type, a ragged point, an unknown
    // field, a bad end name, a dimension out of range) or by the
    // constructor (strict mode's coincident points: invalid_input).
    EXPECT_EQ(checked, 16u);
}

}  // namespace
