#include "app/frame_step_files.h"

#include <unistd.h>

#include <filesystem>

#include "app/frame_step_view.h"
#include "app/headless_frames.h"

namespace reflect {
namespace {

std::string checkWritableFolder(const std::string& dir) {
  std::error_code error;
  if (!std::filesystem::is_directory(dir, error)) return dir + " is not a folder";
  if (access(dir.c_str(), W_OK) != 0) return dir + " is not writable";
  return {};
}

}  // namespace

std::string stepFileName(const std::string& dir, int index, int count) {
  const int digits = std::max(2, static_cast<int>(std::to_string(count).size()));
  std::string number = std::to_string(index + 1);
  number.insert(0, static_cast<size_t>(std::max(0, digits - static_cast<int>(number.size()))), '0');
  return (std::filesystem::path(dir) / ("step-" + number + ".png")).string();
}

Result<RgbaImage> renderFrameInSteps(Demo& demo, double seconds, int width, int height,
                                     const std::string& dir, std::vector<std::string>& lines) {
  using Out = Result<RgbaImage>;
  if (std::string error = checkWritableFolder(dir); !error.empty()) return Out::failure(error);
  std::string error;
  int written = 0;
  demo.setStepCallback([&](const FrameStep& step, int index, int count) {
    Result<RgbaImage> image = captureStepImage(*demo.renderer(), step, index, count, width, height);
    error = image ? writePng(image.value(), stepFileName(dir, index, count)) : image.error();
    if (!error.empty()) return false;
    lines.push_back(stepTitle(step, index, count));
    written = index + 1;
    return true;
  });
  Result<RgbaImage> frame = renderFrameAt(demo, seconds, width, height);
  demo.setStepCallback(nullptr);
  if (!error.empty()) return Out::failure(error);
  if (!frame) return frame;
  const std::vector<FrameStep> steps = demo.lastSteps();
  const int count = static_cast<int>(steps.size());
  if (written != count - 1) {
    return Out::failure("the renderer drew " + std::to_string(written) + " capture steps, the " +
                        "frame's step list has " + std::to_string(count - 1));
  }
  error = writePng(frame.value(), stepFileName(dir, count - 1, count));
  if (!error.empty()) return Out::failure(error);
  lines.push_back(stepTitle(steps.back(), count - 1, count));
  return frame;
}

}  // namespace reflect
