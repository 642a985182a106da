// Making a name safe never merges two names: file stems and C++ namespaces keep
// distinct materials apart across runs.
#include "compiler/name_mark.hpp"

#include <gtest/gtest.h>

#include <set>

#include "compiler/cpp_header.hpp"
#include "driver/material_compiler.hpp"

namespace wg {
namespace {

TEST(NameMark, SafeFileStemsAreKeptAsWritten) {
  EXPECT_EQ(fileStemFor("rock"), "rock");
  EXPECT_EQ(fileStemFor("Rock-2_b"), "Rock-2_b");
}

TEST(NameMark, SanitisedFileStemsKeepWhichNameTheyWere) {
  const std::string snow = fileStemFor("\xe9\x9b\xaa"), rain = fileStemFor("\xe9\x9b\xa8");
  EXPECT_NE(snow, rain);
  EXPECT_EQ(snow, fileStemFor("\xe9\x9b\xaa"));  // the same in every run
  EXPECT_NE(fileStemFor("a b"), fileStemFor("a_b"));
  EXPECT_NE(fileStemFor("a/b"), fileStemFor("a_b"));
  EXPECT_NE(fileStemFor(std::string(70, 'x')), fileStemFor(std::string(71, 'x')));
  for (const std::string& stem : {snow, rain, fileStemFor("a/../b"), fileStemFor(std::string(200, 'y'))}) {
    EXPECT_TRUE(endsWithNameMark(stem, '.')) << stem;
    EXPECT_EQ(stem.find('/'), std::string::npos);
    EXPECT_LE(stem.size(), 64u);
  }
}

TEST(NameMark, CppNamespacesOfDistinctNamesDiffer) {
  const std::vector<std::string> names = {"a-b", "a_b", "class", "class_v", "ROCK", "ROCK_material", "rock",
                                          "rock_h0123abcd", "\xe9\x9b\xaa", "\xe9\x9b\xa8"};
  std::set<std::string> namespaces;
  for (const auto& name : names) namespaces.insert(cppMaterialNamespace(name));
  EXPECT_EQ(namespaces.size(), names.size());
  EXPECT_EQ(cppMaterialNamespace("rock"), "rock");
  EXPECT_EQ(cppMaterialNamespace("a_b"), "a_b");
}

TEST(NameMark, MarksAreShortHexOfTheExactBytes) {
  EXPECT_EQ(nameMark("x").size(), 9u);
  EXPECT_NE(nameMark("x"), nameMark("x "));
  EXPECT_TRUE(endsWithNameMark("abc." + nameMark("abc"), '.'));
  EXPECT_FALSE(endsWithNameMark("abc.hxyz", '.'));
}

// "CON.reflect.json" cannot be made on Windows, whatever follows the dot.
TEST(NameMark, NamesWindowsReservesAreMarked) {
  for (const char* name : {"CON", "con", "Prn", "AUX", "nul", "COM1", "com9", "LPT1", "lpt9", "con.txt"})
    EXPECT_TRUE(isWindowsReservedName(name)) << name;
  for (const char* name : {"CONS", "COM0", "COM10", "LPT", "icon", "NUL_", "rock"})
    EXPECT_FALSE(isWindowsReservedName(name)) << name;
  const std::string stem = fileStemFor("CON");
  EXPECT_TRUE(endsWithNameMark(stem, '.')) << stem;
  EXPECT_FALSE(isWindowsReservedName(stem)) << stem;
  EXPECT_NE(fileStemFor("con"), stem);
}

}  // namespace
}  // namespace wg
