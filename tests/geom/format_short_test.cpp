// The one formatter of numbers a person reads: about 4 significant digits, no spaces.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/status.hpp"

using isoparm::geom::format_short;

TEST(FormatShort, FourSignificantDigitsInPlainDecimals) {
    EXPECT_EQ(format_short(0.7626262626262627), "0.7626");
    EXPECT_EQ(format_short(0.7020202279090881), "0.702");
    EXPECT_EQ(format_short(0.5), "0.5");
    EXPECT_EQ(format_short(5), "5");
    EXPECT_EQ(format_short(-1), "-1");
    EXPECT_EQ(format_short(0.41025641), "0.4103");
    EXPECT_EQ(format_short(12345.6), "12346");
    EXPECT_EQ(format_short(9.99996), "10");
    EXPECT_EQ(format_short(0.000314159), "0.0003142");
    EXPECT_EQ(format_short(1.0 / 3.0, 3), "0.333");
}

TEST(FormatShort, ScientificOnlyForTinyAndHugeWithAPlainExponent) {
    EXPECT_EQ(format_short(6.3e-16), "6.3e-16");
    EXPECT_EQ(format_short(-2.5e-7), "-2.5e-7");
    EXPECT_EQ(format_short(1.5e8), "1.5e8");
    EXPECT_EQ(format_short(165000000.0), "1.65e8");
}

TEST(FormatShort, NoMinusZeroNoSpacesAndNonFiniteNamed) {
    EXPECT_EQ(format_short(-0.0), "0");
    EXPECT_EQ(format_short(-0.00000001), "-1e-8");
    EXPECT_EQ(format_short(std::nan("")), "NaN");
    EXPECT_EQ(format_short(-INFINITY), "-inf");
    for (double x : {1e-300, -7.77e-5, 0.1 + 0.2, 123456789.0, 1e300})
        EXPECT_EQ(format_short(x).find(' '), std::string::npos) << x;
}
