// The ordered JSON builder behind summary.json (studies/runner/output/json_writer.hpp), against
// its header comment and RFC 8259: keys in insertion order (not sorted), two-space indentation
// at every nesting level (objects, arrays of objects), numbers in the shortest text that reads
// back to the same double, non-finite numbers as null, strings and keys escaped (quote,
// backslash, every control character), and a string can never pass for the builder's internal
// nested-value marker. The truth is the exact bytes (hand-checked to parse with Python's json).
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {
namespace {

TEST(OutputJsonWriter, ScalarsInInsertionOrder) {
  JsonObject o;
  o.set("status", "ok")
      .set("kind", std::string("trim"))
      .set("converged", true)
      .set("bounded", false)
      .set("cycles", 12)
      .set("evaluations", 3000000000L)
      .set("speed_mps", 10.5)
      .setNull("free_flight");
  EXPECT_EQ(o.toString(),
            "{\n"
            "  \"status\": \"ok\",\n"
            "  \"kind\": \"trim\",\n"
            "  \"converged\": true,\n"
            "  \"bounded\": false,\n"
            "  \"cycles\": 12,\n"
            "  \"evaluations\": 3000000000,\n"
            "  \"speed_mps\": 10.5,\n"
            "  \"free_flight\": null\n"
            "}");
}

TEST(OutputJsonWriter, NumbersRoundTripAndNonFiniteAreNull) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  JsonObject o;
  o.set("a", 0.1 + 0.2).set("b", -0.0).set("c", 5e-324).set("d", 1e21).set("e", 1e-5);
  o.set("nan", nan).set("inf", inf).set("minus_inf", -inf);
  o.set("i", INT_MIN).set("l", LONG_MAX);
  o.set("list", std::vector<double>{1.0, nan, -2.5, inf, 1.7976931348623157e308});
  o.set("empty", std::vector<double>{});
  EXPECT_EQ(o.toString(),
            "{\n"
            "  \"a\": 0.30000000000000004,\n"
            "  \"b\": 0,\n"
            "  \"c\": 5e-324,\n"
            "  \"d\": 1e+21,\n"
            "  \"e\": 1e-05,\n"
            "  \"nan\": null,\n"
            "  \"inf\": null,\n"
            "  \"minus_inf\": null,\n"
            "  \"i\": -2147483648,\n"
            "  \"l\": 9223372036854775807,\n"
            "  \"list\": [1, null, -2.5, null, 1.7976931348623157e+308],\n"
            "  \"empty\": []\n"
            "}");
}

TEST(OutputJsonWriter, StringsAndKeysAreEscaped) {
  EXPECT_EQ(jsonEscape(""), "\"\"");
  EXPECT_EQ(jsonEscape("say \"hi\" C:\\dir"), "\"say \\\"hi\\\" C:\\\\dir\"");
  EXPECT_EQ(jsonEscape("a\nb\tc\rd"), "\"a\\nb\\tc\\rd\"");
  EXPECT_EQ(jsonEscape(std::string("\x00\x01\x08\x0c\x1f", 5)),
            "\"\\u0000\\u0001\\u0008\\u000c\\u001f\"");
  EXPECT_EQ(jsonEscape("/ \x7f \xc2\xb0"), "\"/ \x7f \xc2\xb0\"");  // DEL and UTF-8 as they are
  JsonObject o;
  o.set("key \"q\"\n", "v\\");
  o.setStrings("names", {"a", "b,\"c\"", ""});
  o.setStrings("none", {});
  EXPECT_EQ(o.toString(),
            "{\n"
            "  \"key \\\"q\\\"\\n\": \"v\\\\\",\n"
            "  \"names\": [\"a\", \"b,\\\"c\\\"\", \"\"],\n"
            "  \"none\": []\n"
            "}");
}

TEST(OutputJsonWriter, NestedObjectsAreIndentedByLevel) {
  JsonObject deep;
  deep.set("z", 1).set("list", std::vector<double>{1.5});
  JsonObject mid;
  mid.set("b", true).set("deep", deep).set("empty", JsonObject{});
  JsonObject top;
  top.set("kind", "trim").set("mid", mid).set("after", 2);
  EXPECT_EQ(top.toString(),
            "{\n"
            "  \"kind\": \"trim\",\n"
            "  \"mid\": {\n"
            "    \"b\": true,\n"
            "    \"deep\": {\n"
            "      \"z\": 1,\n"
            "      \"list\": [1.5]\n"
            "    },\n"
            "    \"empty\": {\n"
            "    }\n"
            "  },\n"
            "  \"after\": 2\n"
            "}");
  EXPECT_EQ(JsonObject().toString(), "{\n}");
  // toString(indent) is the text at that depth: items at indent + 2, the brace at indent.
  EXPECT_EQ(deep.toString(4), "{\n      \"z\": 1,\n      \"list\": [1.5]\n    }");
  // A nested object is copied when set: changing it later does not change the parent.
  deep.set("late", 3);
  EXPECT_EQ(top.toString().find("late"), std::string::npos);
}

TEST(OutputJsonWriter, ArraysOfObjectsAreIndentedByLevel) {
  JsonObject inner;
  inner.set("v", 0.5);
  JsonObject a;
  a.set("x", 1);
  JsonObject b;
  b.set("y", "s").set("o", inner).setObjects("more", {inner});
  JsonObject top;
  top.setObjects("multipliers", {a, b}).setObjects("none", {});
  JsonObject outer;
  outer.set("floquet", top);
  EXPECT_EQ(outer.toString(),
            "{\n"
            "  \"floquet\": {\n"
            "    \"multipliers\": [\n"
            "      {\n"
            "        \"x\": 1\n"
            "      },\n"
            "      {\n"
            "        \"y\": \"s\",\n"
            "        \"o\": {\n"
            "          \"v\": 0.5\n"
            "        },\n"
            "        \"more\": [\n"
            "          {\n"
            "            \"v\": 0.5\n"
            "          }\n"
            "        ]\n"
            "      }\n"
            "    ],\n"
            "    \"none\": []\n"
            "  }\n"
            "}");
}

TEST(OutputJsonWriter, AStringCannotPassForANestedValue) {
  // Nested values are stored behind a \x01 marker; a string value starting with that byte is
  // escaped (\u0001) and so never re-indented as a nested object.
  JsonObject o;
  o.set("s", std::string("\x01{\nx}"));
  o.setStrings("l", {std::string("\x01")});
  EXPECT_EQ(o.toString(), "{\n  \"s\": \"\\u0001{\\nx}\",\n  \"l\": [\"\\u0001\"]\n}");
}

}  // namespace
}  // namespace orni::studies
