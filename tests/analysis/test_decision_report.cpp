// The analysis report's "verdict" key (issue 27, point 5): written first, by
// report.hpp's one writer, in the held report, the streamed report and the
// summary, and always decide()'s verdict for a plane curve (null for other
// dimensions). The report's decision stops at the first proved crossing
// (decision_options::first_crossing): that must never change the verdict.
#include <map>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "json_tree_builder.hpp"

#include <crspline/decision.hpp>
#include <crspline/report.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using P = vec<2>;
using json = nlohmann::json;

using tree_builder = crspline_test::json_tree_builder;

template <std::size_t D, class T>
json held(const catmull_rom<D, T>& c, const report_options& opt = {}) {
    tree_builder b;
    return report(b, make_report(c, opt));
}

template <std::size_t D, class T>
json streamed(const catmull_rom<D, T>& c, const report_options& opt = {}) {
    tree_builder b;
    detail::tree_sink<tree_builder> sink{b};
    write_report(b, sink, c, opt);
    return sink.o;
}

std::vector<P> report_walk(std::mt19937_64& rng, std::size_t n) {
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<P> p(n);
    for (std::size_t i = 1; i < n; ++i) p[i] = p[i - 1] + P{{g(rng), g(rng)}};
    return p;
}

TEST(DecisionReport, VerdictIsDecideVerdict) {
    CRSPLINE_SEEDED(seed, 2730);
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::size_t> npts(5, 14);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::map<std::string, std::size_t> by_verdict;
    std::size_t checked = 0;
    for (std::size_t i = 0; i < 240; ++i) {
        SCOPED_TRACE("curve " + std::to_string(i));
        const double alphas[] = {0.0, 0.5, 1.0, U(rng)};
        const catmull_rom<2> c(report_walk(rng, npts(rng)), {.alpha = alphas[i % 4], .closed = i % 7 == 0,
                                                       .tension = i % 5 == 0 ? 0.3 : 0.0});
        const decision full = decide(c);
        const std::string want = to_string(full.result);
        // Stopping at the first crossing gives the whole decision's verdict.
        decision_options first;
        first.first_crossing = true;
        first.record_pairs = false;
        EXPECT_EQ(decide(c, first).result, full.result);
        EXPECT_EQ(decide(c, {.fast_path = false, .first_crossing = true}).result, full.result);
        // The held report, the streamed report and the summary all carry it.
        EXPECT_EQ(held(c)["verdict"], want);
        EXPECT_EQ(streamed(c)["verdict"], want);
        tree_builder b;
        EXPECT_EQ(report_summary(b, c)["verdict"], want);
        ++by_verdict[want];
        ++checked;
    }
    EXPECT_EQ(checked, 240u);
    // Random walks of 5-14 points: both answers are common (the count keeps the test able to fail).
    EXPECT_GT(by_verdict["simple"], 20u);
    EXPECT_GT(by_verdict["crosses"], 20u);
    std::printf("240 walks: simple %zu, crosses %zu, touches %zu\n", by_verdict["simple"], by_verdict["crosses"],
                by_verdict["touches"]);
}

TEST(DecisionReport, VerdictComesFirstAndIsNullOffThePlane) {
    // First in every form (the CLI's text and Python's dict keep the order
    // of the sink's members; a tree sink over an ordered builder shows it).
    struct ordered_sink {
        std::vector<std::string> keys;
        void member(std::string_view k, json) { keys.emplace_back(k); }
        void open(std::string_view k) { keys.emplace_back(k); }
        void item(json) {}
        void close() {}
        void hold(int, json) {}
        void release(int) {}
    };
    const catmull_rom<2> x(std::vector<P>{P{{0, 0}}, P{{4, 0}}, P{{4, 3}}, P{{2, -2}}}, {.alpha = 0.0});
    tree_builder b;
    ordered_sink sink;
    write_report(b, sink, x);
    ASSERT_FALSE(sink.keys.empty());
    EXPECT_EQ(sink.keys.front(), "verdict");
    EXPECT_EQ(held(x)["verdict"], "crosses");
    // Not asked for: null.
    report_options off;
    off.decide_crossings = false;
    EXPECT_TRUE(held(x, off)["verdict"].is_null());
    EXPECT_TRUE(streamed(x, off)["verdict"].is_null());
    // 1-D and 3-D curves: the decision is for plane curves.
    const catmull_rom<3> c3(std::vector<vec<3>>{{{0, 0, 0}}, {{1, 0, 1}}, {{1, 1, 0}}, {{0, 1, 1}}});
    EXPECT_TRUE(held(c3)["verdict"].is_null());
    EXPECT_TRUE(report_summary(b, c3)["verdict"].is_null());
    const catmull_rom<1> c1(std::vector<vec<1>>{{{0}}, {{1}}, {{3}}});
    EXPECT_TRUE(held(c1)["verdict"].is_null());
    // A float curve is decided as built (its Bézier points are exact in double).
    const catmull_rom<2, float> xf(std::vector<vec<2, float>>{{{0, 0}}, {{4, 0}}, {{4, 3}}, {{2, -2}}},
                                   {.alpha = 0.0});
    EXPECT_EQ(held(xf)["verdict"], "crosses");
    // The example: a chordal curve that the certificate cannot
    // certify (not centripetal) and that does not cross.
    const catmull_rom<2> chordal(std::vector<P>{P{{0, 0}}, P{{1, 2}}, P{{3, 3}}, P{{4, 0}}}, {.alpha = 1.0});
    EXPECT_EQ(held(chordal)["verdict"], "simple");
}

}  // namespace
