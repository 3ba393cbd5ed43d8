#include "gl_fixture.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "platform/native/egl_context.h"
#include "platform/native/model_paths.h"

namespace reflect::testing {
namespace {

class HeadlessGlEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    auto context = HeadlessGlContext::create();
    ASSERT_TRUE(context) << context.error();
    context_ = context.take();
  }
  void TearDown() override { context_.reset(); }

 private:
  std::unique_ptr<HeadlessGlContext> context_;
};

const auto* const kEnvironment = ::testing::AddGlobalTestEnvironment(new HeadlessGlEnvironment);

}  // namespace

std::unique_ptr<Demo> makeDemo(Scene scene) {
  auto demo = std::make_unique<Demo>(std::move(scene));
  std::string error = loadSceneModels(*demo, "");
  EXPECT_EQ(error, "");
  error = demo->initGraphics();
  EXPECT_EQ(error, "");
  demo->waitForLevels();  // chunks and levels in from the first frame: every picture is repeatable
  return demo;
}

std::unique_ptr<Demo> makeCapturingDemo(Scene scene) {
  auto demo = makeDemo(std::move(scene));
  AccuracySettings capturing;
  capturing.search = Search::Hierarchical;
  EXPECT_EQ(demo->setAccuracySettings(capturing), "");
  return demo;
}

std::string saveOutput(const RgbaImage& image, const std::string& fileName) {
  std::filesystem::create_directories(OUTPUT_DIR);
  const std::string path = std::string(OUTPUT_DIR) + "/" + fileName;
  EXPECT_EQ(writePng(image, path), "");
  return path;
}

}  // namespace reflect::testing
