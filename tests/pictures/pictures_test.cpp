// The pictures' words and colour scales: what a person reads off them.
#include <gtest/gtest.h>

#include "pictures/tilt_chart.h"

namespace facetlight {
namespace {

TiltSeries switchedOf(uint64_t switched, uint64_t pixelPairs) {
  TiltSeries series;
  series.switched = switched;
  series.pixelPairs = pixelPairs;
  return series;
}

// The scintillation is written to its standard error's digits: a small error is
// not rounded to "0.0", a larger one keeps its second digit when it starts with
// 1, and a share with no error is written alone.
TEST(TiltChart, SubtitleWritesTheErrorToItsDigits) {
  // 7.4 % of a million pixel pairs: +- 0.026 %.
  EXPECT_EQ(tiltChartSubtitle(switchedOf(74'000, 1'000'000)),
            "ASET view, lit = bright or low light; scintillation 7.40 +- 0.03 "
            "% per frame");
  // 20 % of 10 000: +- 0.4 %.
  EXPECT_EQ(tiltChartSubtitle(switchedOf(2'000, 10'000)),
            "ASET view, lit = bright or low light; scintillation 20.0 +- 0.4 % "
            "per frame");
  // 50 % of 2 000 000: +- 0.035 %; 0.05 % of 2 000 000: +- 0.0016 %, two digits
  // as it starts with 1.
  EXPECT_NE(tiltChartSubtitle(switchedOf(1'000'000, 2'000'000))
                .find(" 50.00 +- 0.04 %"),
            std::string::npos);
  EXPECT_NE(tiltChartSubtitle(switchedOf(1'000, 2'000'000))
                .find(" 0.0500 +- 0.0016 %"),
            std::string::npos);
  // No pixel switched: a share, no error.
  EXPECT_EQ(
      tiltChartSubtitle(switchedOf(0, 1000)),
      "ASET view, lit = bright or low light; scintillation 0.0 % per frame");
  for (const uint64_t n : {10ull, 1'000ull, 100'000ull, 10'000'000ull}) {
    EXPECT_EQ(tiltChartSubtitle(switchedOf(n / 3, n)).find("+- 0.0 "),
              std::string::npos)
        << n;
    EXPECT_EQ(tiltChartSubtitle(switchedOf(n / 3, n)).find("+- 0 "),
              std::string::npos)
        << n;
  }
}

} // namespace
} // namespace facetlight
