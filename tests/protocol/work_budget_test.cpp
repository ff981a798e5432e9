// The work budget: requests within the spec's caps that would take minutes
// or gigabytes are refused with `limit` before any work, naming what is too large; a batch
// shares one budget. The estimates themselves are checked against the formulas in
// docs/protocol.md; no test here measures time.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/json/reader.hpp"
#include "core/protocol/protocol.hpp"
#include "core/geom/work_budget.hpp"
#include "tests/support/protocol_shapes.hpp"

using nlohmann::json;
using namespace isoparm;
using namespace isoparm::protocol;

namespace {

using isoparm::test::bicubic;
using isoparm::test::curve_of_degree;

json params(std::size_t count) {
    json ts = json::array();
    for (std::size_t k = 0; k < count; ++k) ts.push_back(static_cast<double>(k) / count);
    return ts;
}

void expect_limit(const json& response, const std::string& path, const std::string& words) {
    ASSERT_EQ(response["ok"], false) << response.dump();
    EXPECT_EQ(response["error"]["code"], "limit");
    EXPECT_EQ(response["error"]["path"], path);
    EXPECT_NE(response["error"]["message"].get<std::string>().find(words), std::string::npos)
        << response["error"]["message"];
}

TEST(WorkBudget, EstimatesFollowTheDocumentedFormulas) {
    const double per_number = geom::steps_per_answer_number;
    // (p+1)^2 (d+1) + (p+1)(d+1) steps per curve parameter, plus the answer's numbers.
    EXPECT_DOUBLE_EQ(geom::estimate_curve_evaluation(10, 3, 0).steps, 10 * (16 + 4) + 30 * per_number);
    EXPECT_DOUBLE_EQ(geom::estimate_curve_evaluation(10, 3, 2).answer_numbers, 10 * 3 * 4);
    // ((p+1)^2 + (q+1)^2)(d+1) + (p+1)(q+1)(d+1)(d+2)/2 per surface parameter.
    EXPECT_DOUBLE_EQ(geom::estimate_surface_evaluation(1, 3, 2, 1, false).steps,
                     (16 + 9) * 2 + 12 * 3 + 3 * 5 * per_number);
    EXPECT_DOUBLE_EQ(geom::estimate_surface_evaluation(1, 3, 2, 1, true).answer_numbers, 3 * (1 + 4 + 1));
    EXPECT_DOUBLE_EQ(geom::estimate_tessellation(10, 20, 3, 3).answer_numbers, 10 * 20 * 6 + 9 * 19 * 6);
    EXPECT_DOUBLE_EQ(geom::estimate_polygonization(1000, 50).steps,
                     1000 * 50 * geom::steps_per_expression_instruction);
}

// Issue repro: evaluate on a degree-4095 curve took 0.15 s per parameter; 10,000 of them ran
// past 900 s. Now refused at once, naming the degree and the count.
TEST(WorkBudget, AHighDegreeCurveAtManyParametersIsRefusedBeforeAnyWork) {
    const json request = {
        {"op", "evaluate"}, {"curve", curve_of_degree(4095)}, {"params", params(10000)}};
    expect_limit(handle_request(request), "/params", "10,000 parameters of a degree-4095 curve");
    // A few parameters of the same curve are fine.
    const json few = {{"op", "evaluate"}, {"curve", curve_of_degree(4095)}, {"params", params(2)}};
    EXPECT_EQ(handle_request(few)["ok"], true);
}

// Issue repro: 10,000,000 parameters with derivatives built 7.2 GB. The answer estimate refuses
// far fewer already (400,000 with derivatives up to 3 and normals: 21.6 million numbers).
TEST(WorkBudget, AnAnswerAboveAGibibyteIsRefused) {
    json uv = json::array();
    for (int k = 0; k < 400000; ++k) uv.push_back({(k % 1000) / 1000.0, (k / 1000) / 400.0});
    const json request = {{"op", "evaluate"},
                          {"surface", bicubic()},
                          {"params", uv},
                          {"derivatives", 3},
                          {"normals", true}};
    expect_limit(handle_request(request), "/params", "400,000 parameters");
    EXPECT_GT(geom::estimate_surface_evaluation(1e7, 3, 3, 3, false).answer_numbers, geom::max_answer_numbers);
}

// Issue repro: polygonize with a 1,000-term expression took 13.6 s.
TEST(WorkBudget, ALongExpressionOnAFineGridIsRefused) {
    std::string expression = "sin(x*1)";
    for (int k = 2; k <= 1000; ++k) expression += "+sin(x*" + std::to_string(k) + "+y)";
    const json request = {{"op", "polygonize"},
                          {"implicit", expression},
                          {"bounds", {{-1, -1, -1}, {1, 1, 1}}},
                          {"cell", 0.02}};
    expect_limit(handle_request(request), "/implicit", "an expression of");
}

TEST(WorkBudget, TessellationWithinTheMeshCapsIsAllowed) {
    const json request = {{"op", "tessellate"}, {"surface", bicubic()}, {"samples", {50, 50}}};
    EXPECT_EQ(handle_request(request)["ok"], true);
}

// A batch shares one budget: each element is checked against what the batch has left.
TEST(WorkBudget, ABatchSharesOneBudget) {
    const geom::WorkEstimate big{0.6 * geom::max_work_steps, 0};
    {
        const geom::BatchBudget batch;
        EXPECT_TRUE(geom::spend_work(big, "/params", "the first"));
        const auto second = geom::spend_work(big, "/params", "the second");
        ASSERT_FALSE(second);
        EXPECT_NE(second.error().message.find("the batch has only"), std::string::npos);
        EXPECT_TRUE(geom::spend_work({0.3 * geom::max_work_steps, 0}, "/params", "a smaller one"));
    }
    // Outside a batch each request has the whole budget.
    EXPECT_TRUE(geom::spend_work(big, "/params", "alone"));
    EXPECT_TRUE(geom::spend_work(big, "/params", "alone again"));
}

// Through the text path: a batch whose elements each fit the budget but not together answers
// the first ones, refuses the next (naming the batch), and goes on with the rest. The batch
// runs inside a small outer budget so that the work itself stays tiny.
TEST(WorkBudget, ABatchThatWouldTakeTooLongStopsTakingWork) {
    const json evaluate = {
        {"op", "evaluate"}, {"curve", curve_of_degree(3, 4)}, {"params", params(1000)}};
    const double steps = geom::estimate_curve_evaluation(1000, 3, 0).steps;
    const json basis = {{"op", "basis"}, {"degree", 1}, {"knots", {0, 0, 1, 1}}, {"param", 0.5}};
    const json batch = json::array({evaluate, evaluate, evaluate, basis});
    std::ostringstream out, err;
    {
        const geom::BatchBudget outer(2.5 * steps);
        EXPECT_EQ(run_protocol_text(batch.dump(), out, err), 1);
    }
    const json answers = json::parse(out.str());
    ASSERT_EQ(answers.size(), 4u);
    EXPECT_EQ(answers[0]["ok"], true);
    EXPECT_EQ(answers[1]["ok"], true);
    expect_limit(answers[2], "/params", "the batch has only");
    EXPECT_EQ(answers[3]["ok"], true);
}

// Issue repro: an invalid 250 MB scene used 9 GB before it was refused. The reader stops at
// 2^24 values (about 1 GiB of tree), whatever the text.
TEST(WorkBudget, TheReaderStopsAtItsValueCap) {
    std::string text = "[0";
    text.reserve(2 * (json_io::max_json_values + 8));
    for (std::size_t k = 0; k < json_io::max_json_values; ++k) text += ",0"; // one value too many
    text += "]";
    std::ostringstream out, err;
    EXPECT_EQ(run_protocol_text(std::move(text), out, err), 1);
    const json answer = json::parse(out.str());
    EXPECT_EQ(answer["error"]["code"], "limit");
    EXPECT_NE(answer["error"]["message"].get<std::string>().find("16777216 JSON values"),
              std::string::npos);
}

} // namespace
