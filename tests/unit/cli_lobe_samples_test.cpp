// --lobe-samples: the reference's lobe rays a rough pixel, for render --reference and the sweep;
// its range, its wording and where it is allowed.
#include <gtest/gtest.h>

#include "platform/native/cli_options.h"

namespace reflect {
namespace {

Result<CliOptions> parsed(const std::vector<std::string>& args) {
  return parseCli(args);
}

std::string errorOf(const std::vector<std::string>& args) {
  Result<CliOptions> r = parseCli(args);
  EXPECT_FALSE(r) << "should not parse";
  return r ? std::string() : r.error();
}

TEST(CliLobeSamples, RenderWithAReferenceTakesTheCount) {
  Result<CliOptions> r = parsed({"render", "--reference", "ref.png", "--lobe-samples", "64"});
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r.value().lobeSamples, 64);
  r = parsed({"render", "--reference", "ref.png", "--lobe-samples", "1"});
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r.value().lobeSamples, 1);
  r = parsed({"render", "--reference", "ref.png", "--lobe-samples", "4096"});
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r.value().lobeSamples, 4096);
}

TEST(CliLobeSamples, UnsetLeavesTheReferenceItsOwnDefault) {
  Result<CliOptions> r = parsed({"render", "--reference", "ref.png"});
  ASSERT_TRUE(r) << r.error();
  EXPECT_FALSE(r.value().lobeSamples.has_value());
  EXPECT_FALSE(r.value().benchOptions().lobeSamples.has_value());
}

TEST(CliLobeSamples, TheSweepHandsItToTheBench) {
  Result<CliOptions> r = parsed({"bench", "--sweep", "--lobe-samples", "128"});
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r.value().lobeSamples, 128);
  EXPECT_EQ(r.value().benchOptions().lobeSamples, 128);
}

TEST(CliLobeSamples, OutOfRangeOrNotANumberIsRefused) {
  const std::vector<std::string> render = {"render", "--reference", "ref.png", "--lobe-samples"};
  const auto with = [&render](const std::string& value) {
    std::vector<std::string> args = render;
    args.push_back(value);
    return args;
  };
  EXPECT_EQ(errorOf(with("0")), "--lobe-samples: 0 is not in 1..4096");
  EXPECT_EQ(errorOf(with("4097")), "--lobe-samples: 4097 is not in 1..4096");
  EXPECT_EQ(errorOf(with("-3")), "--lobe-samples: -3 is not in 1..4096");
  EXPECT_EQ(errorOf(with("2.5")), "--lobe-samples: 2.5 is not a whole number");
  EXPECT_EQ(errorOf(with("many")), "--lobe-samples: many is not a whole number from 1 to 4096");
  EXPECT_EQ(errorOf({"bench", "--sweep", "--lobe-samples", "5000"}),
            "--lobe-samples: 5000 is not in 1..4096");
}

TEST(CliLobeSamples, OnlyWhereAReferenceIsRendered) {
  EXPECT_EQ(errorOf({"render", "--lobe-samples", "64"}),
            "render: --lobe-samples sets the reference's lobe rays; add --reference FILE");
  EXPECT_EQ(errorOf({"bench", "--lobe-samples", "64"}),
            "bench: --lobe-samples sets the reference's lobe rays; add --sweep");
  EXPECT_EQ(errorOf({"explain", "--pixel", "1,1", "--lobe-samples", "64"}),
            "explain: unknown option --lobe-samples");
}

TEST(CliLobeSamples, TheHelpNamesIt) {
  EXPECT_NE(cliHelp("render").find("--lobe-samples N"), std::string::npos);
  EXPECT_NE(cliHelp("bench").find("--lobe-samples N"), std::string::npos);
  EXPECT_EQ(cliHelp("explain").find("--lobe-samples"), std::string::npos);
}

}  // namespace
}  // namespace reflect
