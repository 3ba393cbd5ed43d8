#include <gtest/gtest.h>

#include "platform/native/cli_options.h"

namespace reflect {
namespace {

TEST(CliOptions, ParsesRender) {
  auto r = parseCli(
      {"render", "--size", "640x480", "--time", "2.5", "--out", "a.png", "--assets", "/course"});
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r.value().command, "render");
  EXPECT_EQ(r.value().width, 640);
  EXPECT_EQ(r.value().height, 480);
  EXPECT_DOUBLE_EQ(r.value().time, 2.5);
  EXPECT_EQ(r.value().out, "a.png");
  EXPECT_EQ(r.value().assets, "/course");
}

TEST(CliOptions, HelpInAnyPosition) {
  EXPECT_EQ(parseCli({"--help"}).value().command, "help");
  EXPECT_EQ(parseCli({"render", "--help"}).value().command, "help");
  EXPECT_NE(std::string(cliHelp()).find("render"), std::string::npos);
  EXPECT_NE(std::string(cliHelp()).find("bench"), std::string::npos);
}

TEST(CliOptions, ErrorsSayWhatIsWrong) {
  EXPECT_EQ(parseCli({}).error(), "no command given (try: reflect --help)");
  EXPECT_EQ(parseCli({"draw"}).error(), "unknown command 'draw' (try: reflect --help)");
  EXPECT_EQ(parseCli({"render", "--size", "800"}).error(), "--size: invalid value '800'");
  EXPECT_EQ(parseCli({"render", "--size", "0x10"}).error(), "--size: invalid value '0x10'");
  EXPECT_EQ(parseCli({"render", "--time", "nan"}).error(), "--time: invalid value 'nan'");
  EXPECT_EQ(parseCli({"render", "--time"}).error(), "--time: missing value");
  EXPECT_EQ(parseCli({"render", "--fast", "1"}).error(),
            "unknown option '--fast' (try: reflect --help)");
  EXPECT_EQ(parseCli({"bench", "--frames", "1.5"}).error(), "--frames: invalid value '1.5'");
}

}  // namespace
}  // namespace reflect
