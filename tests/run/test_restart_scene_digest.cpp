// The scene identity a restart dump is checked against (config/scene_digest.hpp): independent of
// layout, comments and the keys a continuation may change (termination time, max_cycles, threads,
// output intervals), and changed by anything else, including an override of another key.
#include <gtest/gtest.h>

#include "config/scene_digest.hpp"
#include "core/error.hpp"

namespace plyimpact {
namespace {

using config::scene_digest_from_string;

const std::string kBlock =
    "units: SI\ncontrol:\n  termination_time: 2.0e-4\n  tssfac: 0.8\noutput: {interval: 1.0e-5}\n"
    "materials:\n  m: {card: MAT_001, RO: 7800, E: 200e9, PR: 0.3}\n";

std::uint64_t digest(const std::string& yaml, const std::vector<config::SceneOverride>& overrides = {}) {
  return scene_digest_from_string(yaml, "d.yaml", overrides);
}

TEST(SceneDigest, LayoutCommentsAndContinuationKeysDoNotCount) {
  const std::uint64_t base = digest(kBlock);
  EXPECT_EQ(digest("# a comment\n" + kBlock), base);
  EXPECT_EQ(digest("units: SI\ncontrol: {termination_time: 9.0e-4, tssfac: 0.8, max_cycles: 7, threads: 2}\n"
                   "materials:\n  m:\n    card: MAT_001\n    RO: 7800\n    E: 200e9\n    PR: 0.3\n"),
            base);
  EXPECT_EQ(digest(kBlock, {config::parse_set_argument("output.restart_interval=1e-5"),
                            config::parse_set_argument("control.termination_time=1.0")}),
            base);
}

TEST(SceneDigest, AnyOtherChangeCounts) {
  const std::uint64_t base = digest(kBlock);
  EXPECT_NE(digest(kBlock, {config::parse_set_argument("control.tssfac=0.7")}), base);
  EXPECT_NE(digest(kBlock, {config::parse_set_argument("materials.m.PR=0.25")}), base);
  std::string renamed = kBlock;
  renamed.replace(renamed.find("  m: "), 5, "  n: ");
  EXPECT_NE(digest(renamed), base);
  // A value and a key joined differently are not the same text.
  EXPECT_NE(digest("a: {b: 'c: d'}\n"), digest("a: {'b: c': d}\n"));
}

}  // namespace
}  // namespace plyimpact
