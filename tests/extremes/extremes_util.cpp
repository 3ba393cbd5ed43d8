#include "extremes_util.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gfx/gl_handle.h"
#include "gfx/offscreen_target.h"
#include "gfx/shader_program.h"
#include "platform/native/model_paths.h"

namespace reflect::extremes {

std::unique_ptr<Demo> makeDemoWith(Scene scene,
                                   const std::map<std::string, std::string>& objTexts) {
  auto demo = std::make_unique<Demo>(std::move(scene));
  for (const std::string& name : demo->scene().meshNames()) {
    auto text = objTexts.find(name);
    const std::string error = text != objTexts.end()
                                  ? demo->loadMeshText(name, text->second, name)
                                  : demo->loadMesh(name, builtInModelDirectory() + "/" + name);
    EXPECT_EQ(error, "") << name;
    if (!error.empty()) return nullptr;
  }
  const std::string error = demo->initGraphics();
  EXPECT_EQ(error, "");
  if (!error.empty()) return nullptr;
  demo->waitForLevels();  // chunks and levels in from the first frame: repeatable pictures
  return demo;
}

void useFlatLighting(Scene& scene) {
  scene.light.ambient = 1.0f;
  scene.light.diffuse = 0.0f;
  scene.light.specular = 0.0f;
}

glm::mat4 translateScale(const glm::vec3& t, const glm::vec3& s) {
  return glm::scale(glm::translate(glm::mat4(1.0f), t), s);
}

SceneObject phongObject(const std::string& mesh, const glm::mat4& placement,
                        const glm::vec3& colour) {
  SceneObject o;
  o.mesh = mesh;
  o.placement = placement;
  o.colour = colour;
  return o;
}

SceneObject mirrorObject(const std::string& mesh, const glm::mat4& placement,
                         const glm::vec3& colour) {
  SceneObject o = phongObject(mesh, placement, colour);
  o.material = Material::Mirror;
  return o;
}

Result<RgbaImage> renderWithDepthBits(Demo& demo, double seconds, int width, int height,
                                      int depthBits) {
  if (depthBits != 16 && depthBits != 24) {
    return Result<RgbaImage>::failure("depth bits must be 16 or 24");
  }
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height, false, depthBits);
  if (!target) return Result<RgbaImage>::failure(target.error());
  demo.clock().set(seconds);
  demo.frame(0.0, target.value().framebuffer(), width, height, true);
  RgbaImage image = target.value().readPixels();
  if (!checkGlError("render with depth bits")) return Result<RgbaImage>::failure("GL error");
  return image;
}

glm::u8vec3 rgbAt(const RgbaImage& image, int x, int y) {
  const uint8_t* p = image.at(x, y);
  return {p[0], p[1], p[2]};
}

glm::u8vec3 toBytes(const glm::vec3& colour) {
  return glm::u8vec3(glm::round(glm::clamp(colour, 0.0f, 1.0f) * 255.0f));
}

std::vector<uint8_t> maskOf(const RgbaImage& image, const glm::u8vec3& colour, int* count) {
  std::vector<uint8_t> mask(static_cast<size_t>(image.width) * static_cast<size_t>(image.height),
                            0);
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (rgbAt(image, x, y) == colour) {
        mask[static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x)] =
            1;
        ++n;
      }
    }
  }
  if (count) *count = n;
  return mask;
}

namespace {

int neighboursIn(const std::vector<uint8_t>& mask, int width, int height, int x, int y) {
  int n = 0;
  const int dx[4] = {1, -1, 0, 0};
  const int dy[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int nx = x + dx[k], ny = y + dy[k];
    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
    n += mask[static_cast<size_t>(ny) * static_cast<size_t>(width) + static_cast<size_t>(nx)];
  }
  return n;
}

}  // namespace

std::vector<uint8_t> interiorOf(const std::vector<uint8_t>& mask, int width, int height) {
  std::vector<uint8_t> out(mask.size(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
      out[i] = mask[i] && neighboursIn(mask, width, height, x, y) == 4;
    }
  }
  return out;
}

std::vector<uint8_t> borderOf(const std::vector<uint8_t>& mask, int width, int height) {
  std::vector<uint8_t> interior = interiorOf(mask, width, height);
  std::vector<uint8_t> out(mask.size(), 0);
  for (size_t i = 0; i < mask.size(); ++i) out[i] = mask[i] && !interior[i];
  return out;
}

std::string describe(const glm::u8vec3& c) {
  return "(" + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + ")";
}

}  // namespace reflect::extremes
