// Grid specs "A:B:N" of the aero-map axes: values (exact ends, exact integer steps), descending
// and single-value specs, the canonical text, and the malformed specs that must be rejected.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/grid/grid_spec.hpp"

namespace orni {
namespace {

TEST(GridSpecText, ParsesAndSpacesEvenly) {
  const GridSpec s = parseGridSpec("10:20:6");
  EXPECT_EQ(s.first, 10.0);
  EXPECT_EQ(s.last, 20.0);
  EXPECT_EQ(s.count, 6);
  EXPECT_EQ(gridValues(s), (std::vector<double>{10, 12, 14, 16, 18, 20}));
  EXPECT_EQ(gridValues(parseGridSpec("0:20:5")), (std::vector<double>{0, 5, 10, 15, 20}));
  EXPECT_EQ(gridValues(parseGridSpec("20:10:3")), (std::vector<double>{20, 15, 10}));
  EXPECT_EQ(gridValues(parseGridSpec("-5:5:3")), (std::vector<double>{-5, 0, 5}));
  EXPECT_EQ(gridValues(parseGridSpec("12.5:12.5:1")), (std::vector<double>{12.5}));
  EXPECT_EQ(gridValues(parseGridSpec("1e1:2e1:2")), (std::vector<double>{10, 20}));
}

TEST(GridSpecText, EndsAreExactForAnySpacing) {
  for (int n = 2; n <= 40; ++n) {
    const std::vector<double> v = gridValues(GridSpec{0.1, 0.7, n});
    ASSERT_EQ(v.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(v.front(), 0.1);
    EXPECT_EQ(v.back(), 0.7);
    for (std::size_t i = 1; i < v.size(); ++i) EXPECT_LT(v[i - 1], v[i]);
  }
}

TEST(GridSpecText, CanonicalTextRoundTrips) {
  for (const char* text : {"10:20:6", "0:20:5", "-5:5:3", "0.1:0.7:13", "12.5:12.5:1"}) {
    const GridSpec s = parseGridSpec(text);
    EXPECT_EQ(toString(s), text);
    const GridSpec back = parseGridSpec(toString(s));
    EXPECT_EQ(back.first, s.first);
    EXPECT_EQ(back.last, s.last);
    EXPECT_EQ(back.count, s.count);
  }
  EXPECT_EQ(toString(parseGridSpec("1e1:2e1:2")), "10:20:2");
}

TEST(GridSpecText, RejectsMalformedSpecs) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"", "three fields"},
      {"10:20", "three fields"},
      {"10:20:3:4", "three fields"},
      {"10;20;3", "three fields"},
      {"a:20:3", "A is not"},
      {"10:b:3", "B is not"},
      {":20:3", "A is not"},
      {"10:20:", "N is not"},
      {"10:20:2.5", "N is not"},
      {"10:20:x", "N is not"},
      {"10 :20:3", "A is not"},
      {"10:20: 3", "N is not"},
      {"nan:20:3", "A is not"},
      {"10:inf:3", "B is not"},
      {"10:20:0", "N must be in"},
      {"10:20:-3", "N must be in"},
      {"10:20:100001", "N must be in"},
      {"10:20:1", "N = 1 needs A == B"},
      {"10:20:99999999999", "N is not"},
  };
  for (const auto& [text, reason] : bad) {
    SCOPED_TRACE(text);
    GridSpec s;
    std::string why;
    EXPECT_FALSE(tryParseGridSpec(text, &s, &why));
    EXPECT_NE(why.find(reason), std::string::npos) << why;
    try {
      (void)parseGridSpec(text);
      ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("expected A:B:N"), std::string::npos) << what;
      EXPECT_NE(what.find("got '" + text + "'"), std::string::npos) << what;
    }
  }
  EXPECT_THROW((void)gridValues(GridSpec{1.0, 2.0, 1}), std::invalid_argument);
  EXPECT_THROW((void)gridValues(GridSpec{1.0, 2.0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace orni
