// What a CAD file's text says about itself (core/exchange/cad_text_check.hpp): isoparm's own
// IGES and STEP exports are whole and clean; a cut file says where it ends; an IGES B-spline
// whose numbers are garbled, whose degree passes OpenCASCADE's 25 or whose data stops short is
// named with the offending value; text that is no file of the format is told apart.
#include <gtest/gtest.h>

#include "core/exchange/cad_text_check.hpp"
#include "core/exchange/iges_writer.hpp"
#include "core/exchange/step_writer.hpp"

using namespace isoparm;
using namespace isoparm::exchange;

namespace {

std::vector<ExactShape> shapes() {
    geom::Surface s;
    s.type = geom::SplineType::nurbs;
    s.degree_u = 2;
    s.degree_v = 2;
    s.n_u = 3;
    s.n_v = 3;
    s.knots_u = s.knots_v = {0, 0, 0, 1, 1, 1};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            s.points.push_back({i, j, (i - 1) * (j - 1) * 0.5});
            s.weights.push_back(1 + 0.25 * (i + j));
        }
    geom::Curve c;
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 1}, {3, 1, 1}, {4, 0, 0}};
    c.weights = {1, 1, 1, 1, 1};
    return {s, c};
}

std::string iges() {
    return *iges_text(shapes(), "check");
}

std::string step() {
    return *step_text(shapes(), "check");
}

// The text of IGES entity `de` (1: the surface, 3: the curve) with its parameter `k`
// (1-based, after the type) replaced.
std::string with_iges_parameter(int de, int k, const std::string& value) {
    std::string text = iges();
    const std::string start = de == 1 ? "128," : "126,";
    std::size_t at = text.find(start);
    for (int n = 0; n < k; ++n) at = text.find(',', at) + 1;
    const std::size_t end = text.find_first_of(",;", at);
    const long grow = static_cast<long>(value.size()) - static_cast<long>(end - at);
    text.replace(at, end - at, value);
    // Keep the record 80 columns: take the difference from the blanks before column 65.
    const std::size_t line = text.rfind('\n', at) + 1;
    if (grow > 0) text.erase(line + 64, static_cast<std::size_t>(grow));
    if (grow < 0) text.insert(line + 64 + grow, static_cast<std::size_t>(-grow), ' ');
    return text;
}

TEST(CadTextCheck, IsoparmsOwnExportsAreWholeAndClean) {
    for (const auto& [text, format] :
         {std::pair{iges(), CadFormat::iges}, {step(), CadFormat::step}}) {
        const CadTextCheck c = check_cad_text(text, format);
        EXPECT_FALSE(c.not_the_format) << c.why_not;
        EXPECT_TRUE(c.notes.empty()) << c.notes.front().reason;
        EXPECT_TRUE(c.bad_entities.empty()) << c.bad_entities.front().reason;
    }
}

TEST(CadTextCheck, AGarbledIgesNumberNamesTheEntityAndTheParameter) {
    // Parameter 20 of the 128 is a knot: 9 integers, then the u knots.
    const CadTextCheck c = check_cad_text(with_iges_parameter(1, 12, "0.6X5"), CadFormat::iges);
    ASSERT_EQ(c.bad_entities.size(), 1u);
    EXPECT_EQ(c.bad_entities[0].directory_line, 1);
    EXPECT_EQ(c.bad_entities[0].reason, "parameter 12 '0.6X5' is not a number");
    // IGES numbers: exponents E or D, a point anywhere, signs.
    for (const char* fine : {"1.", ".5", "-2D-3", "+4E2", "7"})
        EXPECT_TRUE(
            check_cad_text(with_iges_parameter(1, 12, fine), CadFormat::iges).bad_entities.empty())
            << fine;
    for (const char* bad : {"1..2", "e5", "1E", "--1", "0x10", "nan", "1 2"})
        EXPECT_EQ(
            check_cad_text(with_iges_parameter(1, 12, bad), CadFormat::iges).bad_entities.size(),
            1u)
            << bad;
}

TEST(CadTextCheck, IgesDegreesAndCountsOutsideWhatAReaderTakes) {
    const CadTextCheck degree = check_cad_text(with_iges_parameter(1, 3, "999"), CadFormat::iges);
    ASSERT_EQ(degree.bad_entities.size(), 1u);
    EXPECT_NE(degree.bad_entities[0].reason.find("degree 999 is above 25"), std::string::npos)
        << degree.bad_entities[0].reason;
    const CadTextCheck curve = check_cad_text(with_iges_parameter(3, 2, "0"), CadFormat::iges);
    ASSERT_EQ(curve.bad_entities.size(), 1u);
    EXPECT_EQ(curve.bad_entities[0].directory_line, 3);
    EXPECT_NE(curve.bad_entities[0].reason.find("degree 0 is below 1"), std::string::npos);
    const CadTextCheck negative = check_cad_text(with_iges_parameter(1, 1, "-4"), CadFormat::iges);
    ASSERT_EQ(negative.bad_entities.size(), 1u);
    EXPECT_NE(negative.bad_entities[0].reason.find("negative"), std::string::npos);
    // More control points than the data holds.
    const CadTextCheck count = check_cad_text(with_iges_parameter(1, 1, "9"), CadFormat::iges);
    ASSERT_EQ(count.bad_entities.size(), 1u);
    EXPECT_NE(count.bad_entities[0].reason.find("holds"), std::string::npos)
        << count.bad_entities[0].reason;
}

TEST(CadTextCheck, ACutIgesFileSaysSo) {
    const std::string text = iges();
    const std::string cut = text.substr(0, text.size() * 2 / 3);
    const CadTextCheck c = check_cad_text(cut, CadFormat::iges);
    ASSERT_FALSE(c.notes.empty());
    EXPECT_NE(c.notes[0].reason.find("without its Terminate section"), std::string::npos);
    // A whole record removed from the middle: the Terminate section's counts disagree.
    std::string missing = text;
    const std::size_t p = missing.find("P      2");
    const std::size_t line = missing.rfind('\n', p) + 1;
    missing.erase(line, missing.find('\n', p) + 1 - line);
    const CadTextCheck m = check_cad_text(missing, CadFormat::iges);
    ASSERT_FALSE(m.notes.empty());
    EXPECT_NE(m.notes[0].reason.find("counts"), std::string::npos) << m.notes[0].reason;
}

TEST(CadTextCheck, ACutStepFileSaysSoAndIsCompletedAfterItsLastEntity) {
    const std::string text = step();
    const std::string cut = text.substr(0, text.find("#20="));
    const CadTextCheck c = check_cad_text(cut, CadFormat::step);
    EXPECT_TRUE(c.step_cut_short);
    ASSERT_EQ(c.notes.size(), 1u);
    EXPECT_NE(c.notes[0].reason.find("without END-ISO-10303-21;"), std::string::npos);
    const std::string completed = step_completed(cut + "#20=CARTESIAN_PO");
    EXPECT_EQ(completed.find("#20="), std::string::npos);
    EXPECT_NE(completed.find("ENDSEC;\nEND-ISO-10303-21;"), std::string::npos);
    EXPECT_TRUE(check_cad_text(completed, CadFormat::step).notes.empty());
    // Whole, with blanks after the end: nothing to say.
    EXPECT_TRUE(check_cad_text(text + "\n\n  ", CadFormat::step).notes.empty());
}

TEST(CadTextCheck, TextThatIsNoFileOfTheFormat) {
    for (const char* text : {"", "not IGES\n", "ISO-10303-21;\n"})
        EXPECT_TRUE(check_cad_text(text, CadFormat::iges).not_the_format) << text;
    for (const char* text : {"", "not STEP\n", "HEADER;"})
        EXPECT_TRUE(check_cad_text(text, CadFormat::step).not_the_format) << text;
    EXPECT_FALSE(
        check_cad_text("/* a comment */ ISO-10303-21;\nHEADER;", CadFormat::step).not_the_format);
}

TEST(CadTextCheck, BadIgesEntitiesBecomeNullEntities) {
    const std::string text = with_iges_parameter(1, 12, "0.6X5");
    const CadTextCheck c = check_cad_text(text, CadFormat::iges);
    const std::string cleaned = iges_without_entities(text, c.bad_entities);
    ASSERT_EQ(cleaned.size(), text.size());
    // Both directory records of entity 1 now say type 0; entity 3 is untouched.
    std::size_t d = cleaned.find("D      1");
    EXPECT_EQ(cleaned.substr(cleaned.rfind('\n', d) + 1, 8), "       0");
    d = cleaned.find("D      2");
    EXPECT_EQ(cleaned.substr(cleaned.rfind('\n', d) + 1, 8), "       0");
    d = cleaned.find("D      3");
    EXPECT_EQ(cleaned.substr(cleaned.rfind('\n', d) + 1, 8), "     126");
}

} // namespace
