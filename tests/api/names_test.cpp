// lutbake::Suggest and DidYouMean: the "did you mean" of every closed list
// the command line refuses a name from, on the registries' own lists.
#include "lutbake/api/names.h"

#include <gtest/gtest.h>

#include "lutbake/api/bake.h"

namespace lutbake {
namespace {

using Names = std::vector<std::string>;

TEST(Names, SuggestPrefersTheSameNameIgnoringCase) {
  EXPECT_EQ(Suggest("DFG", TableNames()), Names{"dfg"});
  EXPECT_EQ(Suggest("Filament", PresetNames()), Names{"filament"});
  EXPECT_EQ(Suggest("EXR", FormatNames()), Names{"exr"});
  // "e" is one edit from many names, but only E is the same ignoring case.
  EXPECT_EQ(Suggest("e", TableNames()), Names{"E"});
}

TEST(Names, SuggestFindsNearNamesFewestEditsFirst) {
  EXPECT_EQ(Suggest("png", FormatNames()), (Names{"png8", "png16"}));
  EXPECT_EQ(Suggest("bak", {"bake", "plan", "eval", "check"}), Names{"bake"});
  EXPECT_EQ(Suggest("beckman", {"ggx", "beckmann"}), Names{"beckmann"});
  EXPECT_EQ(Suggest("seperable", {"correlated", "separable"}), Names{"separable"});
  EXPECT_EQ(Suggest("vndf-randon", EstimatorNames()), Names{"vndf-random"});
  // Two letters swapped are one edit.
  EXPECT_EQ(Suggest("vdnf", EstimatorNames()), Names{"vndf"});
  EXPECT_EQ(Suggest("hlsl", {"glsl", "hsll"}), (Names{"glsl", "hsll"}));
  // Two edits only from six characters on: "inc" is two from "png".
  EXPECT_EQ(Suggest("wgls", {"glsl", "wgsl"}), Names{"wgsl"});
  // Three edits are too many even so.
  EXPECT_EQ(Suggest("hlsl-arary", {"wgsl-array", "glsl-array", "hlsl-array"}),
            (Names{"hlsl-array", "glsl-array"}));
  // Same edits: the candidates' order.
  EXPECT_EQ(Suggest("ab", {"abcd", "abxy", "a"}), (Names{"a", "abcd", "abxy"}));
}

TEST(Names, SuggestCompletesAPrefixOfTwoCharactersOrMore) {
  EXPECT_EQ(Suggest("ktx", {"exr", "ktx2", "ktx2-half"}), (Names{"ktx2", "ktx2-half"}));
  EXPECT_EQ(Suggest("sheen", {"E", "sheen_E", "sheen_Eavg"}), (Names{"sheen_E", "sheen_Eavg"}));
  EXPECT_EQ(Suggest("k", {"ktx2", "ktx2-half"}), Names{});
}

TEST(Names, SuggestNothingForNamesFarFromEveryCandidate) {
  EXPECT_EQ(Suggest("nope", TableNames()), Names{});
  EXPECT_EQ(Suggest("magic", EstimatorNames()), Names{});
  EXPECT_EQ(Suggest("", {"a", "bc"}), Names{});
  // One character replaced whole is no suggestion, though one edit.
  EXPECT_EQ(Suggest("x", {"E", "dfg"}), Names{});
  EXPECT_EQ(Suggest("anything", {}), Names{});
}

TEST(Names, SuggestGivesAtMostFour) {
  EXPECT_EQ(Suggest("aaa", {"aab", "aac", "aad", "aae", "aaf"}).size(), 4u);
}

TEST(Names, DidYouMeanListsTheSuggestions) {
  EXPECT_EQ(DidYouMean("DFG", TableNames()), "; did you mean dfg?");
  EXPECT_EQ(DidYouMean("png", FormatNames()), "; did you mean png8 or png16?");
  EXPECT_EQ(DidYouMean("ab", {"abcd", "abxy", "a"}), "; did you mean a, abcd or abxy?");
  EXPECT_EQ(DidYouMean("nope", TableNames()), "");
}

// The namespace of the generated headers: what --namespace accepts.
TEST(Names, NamespaceProblemRefusesWhatIsNoCppNamespace) {
  EXPECT_EQ(NamespaceProblem("lutbake_luts"), "");
  EXPECT_EQ(NamespaceProblem("my_engine::luts2"), "");
  for (const char *bad : {"", "9bad", "a:::b", "a::", "::a", "a-b", "a b"})
    EXPECT_NE(NamespaceProblem(bad).find("is not a C++ namespace name"), std::string::npos) << bad;
  EXPECT_NE(NamespaceProblem("engine::int").find("int is a C++ keyword"), std::string::npos);
}

}  // namespace
}  // namespace lutbake
