// The browser build's floating-point to_chars and from_chars (third_party/web/libcxx_compat.hpp,
// where libc++ 13 has none) against the desktop's libstdc++: the same text for every double the
// tests try, and the same reading of every string.
#define ISOPARM_WEB_COMPAT_TEST 1
#include "third_party/web/libcxx_compat.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

std::string std_text(double x, bool scientific) {
    char buf[64];
    const auto r = scientific
                       ? std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific)
                       : std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}

std::vector<double> doubles() {
    std::vector<double> v = {0.0,
                             -0.0,
                             1.0,
                             -1.0,
                             0.1,
                             0.2,
                             0.3,
                             1.0 / 3.0,
                             2.0 / 3.0,
                             100.0,
                             1e21,
                             1e22,
                             1e23,
                             123456789012345680.0,
                             5e-324,
                             2.2250738585072014e-308,
                             2.2250738585072009e-308,
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::epsilon(),
                             9007199254740993.0,
                             0.0001,
                             0.00001,
                             1234.5,
                             0.6666666666666666,
                             0.8722604191027171};
    for (int e = -30; e <= 30; ++e) {
        v.push_back(std::pow(10.0, e));
        v.push_back(3.0 * std::pow(10.0, e));
        v.push_back(-1.5 * std::pow(10.0, e));
    }
    for (int k = -1000; k <= 1000; ++k) v.push_back(k), v.push_back(k / 8.0), v.push_back(k / 10.0);
    std::mt19937_64 random(36);
    for (int k = 0; k < 40000; ++k) { // bit patterns: every exponent, subnormals included
        const double x = std::bit_cast<double>(random());
        if (std::isfinite(x)) v.push_back(x);
    }
    std::uniform_real_distribution<double> unit(-2.0, 2.0);
    for (int k = 0; k < 20000; ++k) v.push_back(unit(random)); // geometry's usual range
    return v;
}

TEST(WebCharconvCompat, ShortestTextIsLibstdcxxs) {
    for (const double x : doubles()) {
        ASSERT_EQ(isoparm_web_compat::shortest_text(x, 0), std_text(x, false)) << x;
        ASSERT_EQ(isoparm_web_compat::shortest_text(x, 1), std_text(x, true)) << x;
    }
}

TEST(WebCharconvCompat, SpecialValuesAreSpeltAsTheStandardSays) {
    EXPECT_EQ(isoparm_web_compat::shortest_text(std::numeric_limits<double>::infinity(), 0), "inf");
    EXPECT_EQ(isoparm_web_compat::shortest_text(-std::numeric_limits<double>::infinity(), 0),
              "-inf");
    EXPECT_EQ(isoparm_web_compat::shortest_text(std::numeric_limits<double>::quiet_NaN(), 0),
              "nan");
    EXPECT_EQ(isoparm_web_compat::shortest_text(0.0, 1), std_text(0.0, true));
}

TEST(WebCharconvCompat, ParsingIsLibstdcxxs) {
    const std::vector<std::string> inputs = {"0",
                                             "-0",
                                             "1",
                                             "1.5",
                                             ".5",
                                             "5.",
                                             "1e3",
                                             "1E-3",
                                             "1e",
                                             "1e+",
                                             "1e+x",
                                             "-1.25e-7x",
                                             "+1",
                                             " 1",
                                             "0x10",
                                             "inf",
                                             "-INF",
                                             "infinity",
                                             "infinit",
                                             "nan",
                                             "nan(123)",
                                             "nan(",
                                             "1e400",
                                             "-1e400",
                                             "1e-400",
                                             "4.9e-324",
                                             "2.4703282292062328e-324",
                                             ".",
                                             "-",
                                             "e5",
                                             "123456789012345678901234567890",
                                             "0.1000000000000000055511151231257827",
                                             "12abc",
                                             ""};
    for (const std::string& s : inputs) {
        for (const auto fmt : {std::chars_format::general, std::chars_format::scientific,
                               std::chars_format::fixed}) {
            double ours = -7, theirs = -7;
            const char* end = nullptr;
            const int e =
                isoparm_web_compat::parse_double(s.data(), s.data() + s.size(), ours, fmt, end);
            const auto r = std::from_chars(s.data(), s.data() + s.size(), theirs, fmt);
            const std::errc ec = e == 0        ? std::errc{}
                                 : e == ERANGE ? std::errc::result_out_of_range
                                               : std::errc::invalid_argument;
            EXPECT_EQ(ec, r.ec) << '"' << s << '"' << " format " << static_cast<int>(fmt);
            if (r.ec == std::errc{} || r.ec == std::errc::result_out_of_range) {
                EXPECT_EQ(end, r.ptr) << '"' << s << '"';
            }
            if (r.ec == std::errc{}) {
                EXPECT_EQ(std::bit_cast<std::uint64_t>(ours), std::bit_cast<std::uint64_t>(theirs))
                    << '"' << s << '"';
            }
        }
    }
}

TEST(WebCharconvCompat, EveryShortestTextReadsBackToItsDouble) {
    for (const double x : doubles()) {
        const std::string s = isoparm_web_compat::shortest_text(x, 0);
        double back = 0;
        const char* end = nullptr;
        ASSERT_EQ(isoparm_web_compat::parse_double(s.data(), s.data() + s.size(), back,
                                                   std::chars_format::general, end),
                  0)
            << s;
        ASSERT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(x)) << s;
    }
}

} // namespace
