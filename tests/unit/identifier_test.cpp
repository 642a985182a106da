// The one identifier function against hostile names.
#include <gtest/gtest.h>

#include <regex>

#include "compiler/identifier.hpp"

namespace wg {
namespace {

bool isValidIdentifier(const std::string& s) {
  static const std::regex kIdentifier("^[A-Za-z][A-Za-z0-9_]*$");
  return std::regex_match(s, kIdentifier) && s.find("__") == std::string::npos && !IdentifierScope::isReserved(s) &&
         s.size() <= IdentifierScope::kMaxLength + 8;
}

TEST(Identifier, HostileNamesBecomeValidIdentifiers) {
  const std::vector<std::string> hostile = {
      "a;discard;//", "else", "gl_Position", "GL_FragCoord", "__x", "x__y", "_leading", "trailing_", "9lives",
      "SV_Target", "main", "float3", "cbuffer", "texture", "Sample", "", "   ", "\n#define x", "*/ evil /*",
      "caf\xc3\xa9 \xe9\x9b\xaa", "\xf0\x9f\x8c\xa7", std::string(10000, 'a'), std::string(10000, '_'),
      std::string("nul\0byte", 8)};
  for (const auto& name : hostile) {
    IdentifierScope scope;
    std::string id = scope.make(name);
    EXPECT_TRUE(isValidIdentifier(id)) << "'" << id << "' from a " << name.size() << "-byte name";
  }
}

TEST(Identifier, ReservedWordsOfBothLanguagesAreAvoided) {
  for (std::string word : {"else", "discard", "sampler", "packoffset", "register", "matrix", "lerp", "mix", "out", "in"}) {
    IdentifierScope scope;
    EXPECT_NE(scope.make(word), word);
    EXPECT_TRUE(IdentifierScope::isReserved(word)) << word;
  }
  EXPECT_TRUE(IdentifierScope::isReserved("gl_anything"));
  EXPECT_TRUE(IdentifierScope::isReserved("a__b"));
  EXPECT_TRUE(IdentifierScope::isReserved("_a"));
  EXPECT_FALSE(IdentifierScope::isReserved("roughness"));
}

TEST(Identifier, CollisionsResolveDeterministically) {
  IdentifierScope scope;
  EXPECT_EQ(scope.make("mat_a b"), "mat_a_b");
  EXPECT_EQ(scope.make("mat_a_b"), "mat_a_b_2");
  EXPECT_EQ(scope.make("mat_a-b"), "mat_a_b_3");
  IdentifierScope again;
  EXPECT_EQ(again.make("mat_a b"), "mat_a_b");
  EXPECT_EQ(again.make("mat_a_b"), "mat_a_b_2");
}

TEST(Identifier, ReservedInternalNamesAreNotReused) {
  IdentifierScope scope;
  scope.reserve("frame_time");
  EXPECT_EQ(scope.make("frame_time"), "frame_time_2");
}

TEST(Identifier, LongNamesAreTruncatedButStayUnique) {
  IdentifierScope scope;
  std::string a = scope.make(std::string(10000, 'a'));
  std::string b = scope.make(std::string(10000, 'a') + "b");
  EXPECT_LE(a.size(), IdentifierScope::kMaxLength);
  EXPECT_NE(a, b);
}

}  // namespace
}  // namespace wg
