// The CLI's --effects grammar (cli/effect_overrides_option.hpp): NAME=on|off items,
// comma-separated, across repeated options; every malformed form is a usage message
// that says what to write, and user text in it is escaped.
#include <gtest/gtest.h>

#include "cli/effect_overrides_option.hpp"

namespace wg {
namespace {

TEST(EffectOverridesOption, ReadsEachItemInOrderAcrossOptions) {
  WeatherEffectOverrides effects;
  EXPECT_EQ(addEffectOverrides("relief=off,ripple=on", effects), "");
  EXPECT_EQ(addEffectOverrides("specularAntiAliasing=off", effects), "");
  const WeatherEffectOverrides expected{{"relief", false}, {"ripple", true}, {"specularAntiAliasing", false}};
  EXPECT_EQ(effects, expected);
  EXPECT_EQ(effectOverridesText(effects), "relief=off, ripple=on, specularAntiAliasing=off");
}

TEST(EffectOverridesOption, MalformedItemsSayWhatToWrite) {
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      {"", "--effects takes NAME=on|off[,NAME=on|off...], e.g. specularAntiAliasing=off"},
      {"relief", "'relief' has no '='"},
      {"relief=off,", "'' has no '='"},
      {"relif=off", "unknown effect 'relif' (effects: snow, displacement,"},
      {"relief=no", "relief takes on or off, not 'no'"},
      {"relief=off,relief=on", "names 'relief' twice"},
      {"\x1b[2J=off", "unknown effect '\\x1b[2J'"},
  };
  for (const Case& c : cases) {
    WeatherEffectOverrides effects;
    const std::string error = addEffectOverrides(c.text, effects);
    EXPECT_NE(error.find(c.message), std::string::npos) << c.text << " -> " << error;
  }
}

TEST(EffectOverridesOption, AnEffectNamedInAnEarlierOptionCannotComeBack) {
  WeatherEffectOverrides effects;
  EXPECT_EQ(addEffectOverrides("moss=off", effects), "");
  EXPECT_NE(addEffectOverrides("moss=on", effects).find("twice"), std::string::npos);
}

}  // namespace
}  // namespace wg
