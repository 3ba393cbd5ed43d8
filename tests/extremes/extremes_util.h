// Helpers shared by the extremes tests: demos with custom meshes, flat lighting, rendering into a
// framebuffer with a chosen depth precision, cube-map sampling, and pixel classification.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/demo.h"
#include "core/image.h"
#include "core/result.h"
#include "core/scene.h"
#include "cube_sampler.h"
#include "gfx/gl.h"

namespace reflect::extremes {

// A Demo of `scene`: meshes named in `objTexts` come from that OBJ text, the rest from the
// project's models. Fails the calling test (and returns null) on any load or GL error.
std::unique_ptr<Demo> makeDemoWith(Scene scene,
                                   const std::map<std::string, std::string>& objTexts = {});

// Ambient 1, no diffuse, no specular: every Phong object renders exactly its colour.
void useFlatLighting(Scene& scene);

glm::mat4 translateScale(const glm::vec3& t, const glm::vec3& s);

// A still object with the course's Phong material, and one with its mirror material.
SceneObject phongObject(const std::string& mesh, const glm::mat4& placement,
                        const glm::vec3& colour);
SceneObject mirrorObject(const std::string& mesh, const glm::mat4& placement,
                         const glm::vec3& colour);

// One frame (capture and main pass) at scene time `seconds`, rendered into a framebuffer whose
// depth buffer is DEPTH_COMPONENT16 or DEPTH_COMPONENT24 (`depthBits`), read back top row first.
Result<RgbaImage> renderWithDepthBits(Demo& demo, double seconds, int width, int height,
                                      int depthBits);

// texture(cube, d) for each direction, as RGB bytes (any number of directions).
using testing::sampleCube;  // tests/gl/cube_sampler.h

glm::u8vec3 rgbAt(const RgbaImage& image, int x, int y);
glm::u8vec3 toBytes(const glm::vec3& colour);  // round(c * 255), as GL's unorm conversion

// Pixels whose colour is exactly `colour`, as a mask (1 = match), and how many there are.
std::vector<uint8_t> maskOf(const RgbaImage& image, const glm::u8vec3& colour,
                            int* count = nullptr);
// The mask without its border: pixels whose four neighbours are all in the mask.
std::vector<uint8_t> interiorOf(const std::vector<uint8_t>& mask, int width, int height);
// Mask pixels with at least one 4-neighbour outside the mask (the silhouette's inner ring).
std::vector<uint8_t> borderOf(const std::vector<uint8_t>& mask, int width, int height);

std::string describe(const glm::u8vec3& c);

}  // namespace reflect::extremes
