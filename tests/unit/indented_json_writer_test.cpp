// IndentedJsonWriter lays a document out exactly as nlohmann's dump(2) does, which the
// reflection files have always been: nesting, empty containers, escapes, invalid UTF-8
// and numbers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "compiler/indented_json_writer.hpp"
#include "compiler/json_text.hpp"

namespace wg {
namespace {

std::string nlohmannText(const nlohmann::ordered_json& document) { return jsonText(document, 2) + "\n"; }

TEST(IndentedJsonWriter, WritesWhatNlohmannDumps) {
  IndentedJsonWriter w;
  w.beginObject();
  w.key("plain").text("rock_01");
  w.key("escaped \"key\"").text("quote \" backslash \\ tab \t newline \n bell \x07 del \x7f");
  w.key("utf8").text("雪 é \u2028");
  w.key("c1").text("csi \u009b2J nel \u0085 next \u00a0");
  w.key("invalid").text("a\xff" "b\xc3");
  w.key("empty object").beginObject();
  w.endObject();
  w.key("empty array").beginArray();
  w.endArray();
  w.key("numbers").beginArray();
  for (float x : {0.1f, 1.0f, -0.0f, 1e-7f, 3e20f, 0.5f}) w.number(x);
  w.integer(-3);
  w.integer(4294967295);
  w.endArray();
  w.key("nested").beginArray();
  w.beginObject();
  w.key("flag").boolean(true);
  w.key("off").boolean(false);
  w.endObject();
  w.beginArray();
  w.endArray();
  w.endArray();
  w.endObject();

  nlohmann::ordered_json expected = {
      {"plain", "rock_01"},
      {"escaped \"key\"", "quote \" backslash \\ tab \t newline \n bell \x07 del \x7f"},
      {"utf8", "雪 é \u2028"},
      {"c1", "csi \u009b2J nel \u0085 next \u00a0"},
      {"invalid", "a\xff" "b\xc3"},
      {"empty object", nlohmann::ordered_json::object()},
      {"empty array", nlohmann::ordered_json::array()},
      {"numbers", {0.1f, 1.0f, -0.0f, 1e-7f, 3e20f, 0.5f, -3, 4294967295u}},
      {"nested", {{{"flag", true}, {"off", false}}, nlohmann::ordered_json::array()}},
  };
  EXPECT_EQ(w.finish(), nlohmannText(expected));
}

// U+0080..U+009F are escaped (U+009B is a CSI to a terminal), everything else is as
// nlohmann dumps it: U+00A0 and other text stay as they are.
TEST(JsonText, EscapesTheC1ControlsAlone) {
  EXPECT_EQ(jsonText(nlohmann::json("a\u009bb\u0080\u009f\u00a0\u00c2")), "\"a\\u009bb\\u0080\\u009f\u00a0\u00c2\"");
  EXPECT_EQ(jsonText(nlohmann::json("\xc2")), "\"\xef\xbf\xbd\"");  // a cut sequence: U+FFFD
  EXPECT_EQ(escapeC1Controls("plain"), "plain");
}

TEST(IndentedJsonWriter, WritesAnNlohmannValueInItsKeyOrder) {
  const nlohmann::json options = {{"scale", 8}, {"colorA", {0.2, 0.19, 0.18}}, {"octaves", 6u},
                                  {"name", "f\"bm"}, {"none", nullptr}, {"deep", {{"b", {}}, {"a", true}}}};
  IndentedJsonWriter w;
  w.beginObject();
  w.key("options").json(options);
  w.endObject();
  const nlohmann::ordered_json expected = {{"options", nlohmann::ordered_json::parse(options.dump())}};
  EXPECT_EQ(w.finish(), nlohmannText(expected));
}

}  // namespace
}  // namespace wg
