// Laminate notation against hand-written tables, and bad notation with the position and message.
#include <gtest/gtest.h>

#include "config/layup_notation.hpp"

using plyimpact::config::expand_layup;
using plyimpact::config::LayupNotationError;
using V = std::vector<double>;

TEST(LayupNotation, HandWrittenTables) {
  EXPECT_EQ(expand_layup("[0/90]"), (V{0, 90}));
  EXPECT_EQ(expand_layup("[0/90]s"), (V{0, 90, 90, 0}));
  EXPECT_EQ(expand_layup("[0_2/90]s"), (V{0, 0, 90, 90, 0, 0}));
  EXPECT_EQ(expand_layup("[0/45/-45/90]2s"),
            (V{0, 45, -45, 90, 0, 45, -45, 90, 90, -45, 45, 0, 90, -45, 45, 0}));
  EXPECT_EQ(expand_layup("[0/45/-45/90]_2"), (V{0, 45, -45, 90, 0, 45, -45, 90}));
  EXPECT_EQ(expand_layup("[±45/0]s"), (V{45, -45, 0, 0, -45, 45}));
  EXPECT_EQ(expand_layup("[+-45]"), (V{45, -45}));
  EXPECT_EQ(expand_layup("[∓30]"), (V{-30, 30}));
  EXPECT_EQ(expand_layup("[0/[45/-45]_2/90]"), (V{0, 45, -45, 45, -45, 90}));
  EXPECT_EQ(expand_layup(" [ 0 / 22.5 ] S "), (V{0, 22.5, 22.5, 0}));
  // Symmetric with a barred middle ply (written '~'): the middle ply appears once.
  EXPECT_EQ(expand_layup("[0/90/0~]s"), (V{0, 90, 0, 90, 0}));
  EXPECT_EQ(expand_layup("[0/90~]s"), (V{0, 90, 0}));
}

// Expects a LayupNotationError at `position` whose message contains `what`.
void expect_bad(const std::string& text, std::size_t position, const std::string& what) {
  try {
    expand_layup(text);
    FAIL() << "accepted bad notation " << text;
  } catch (const LayupNotationError& e) {
    EXPECT_EQ(e.position(), position) << text << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << text << ": " << e.what();
    EXPECT_NE(e.allowed().find("[0/45/-45/90]2s"), std::string::npos);
  }
}

TEST(LayupNotation, BadNotationIsRefusedWithPosition) {
  expect_bad("", 0, "empty");
  expect_bad("0/90", 0, "starts with '['");
  expect_bad("[0/90", 5, "missing closing ']'");
  expect_bad("[0//90]", 3, "expected a ply angle");
  expect_bad("[0/90]x", 6, "unexpected 'x'");
  expect_bad("[0/90]0s", 6, "repeat count");
  expect_bad("[0_0]", 3, "repeat count");
  expect_bad("[0/200]", 3, "within [-180, 180]");
  expect_bad("[0/4e1]", 3, "plain decimal");
  expect_bad("[0~/90]s", 3, "last ply");
  expect_bad("[0/90~]", 7, "needs a symmetric group");
  expect_bad("[0;90]", 2, "expected '/' or ']'");
}
