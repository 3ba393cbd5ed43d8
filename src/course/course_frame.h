// The course's Ex12-2 frame in one file: course_frame.cpp, C++ and GLSL together, to read top to
// bottom. The `course` preset draws with it (Demo::frame), and a GL test holds its pictures
// pixel-identical to the general renderer's under the same settings (tests/gl/course_frame_test).
#pragma once

#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "core/result.h"
#include "core/scene.h"
#include "gfx/mesh_buffer.h"
#include "gfx/scene_renderer.h"

namespace reflect {

class CourseFrame {
 public:
  // "" when `scene` is the course's kind of scene (one mirror with its own live probe, the fixed
  // mix, no roughness; every other object Phong; no skybox), else why not (course_scene.cpp).
  static std::string whyNot(const Scene& scene);
  // The programs, the cube texture, its depth buffer and the framebuffer, made once.
  static Result<CourseFrame> create(int faceSize);
  CourseFrame(const CourseFrame&) = delete;
  CourseFrame& operator=(const CourseFrame&) = delete;
  CourseFrame(CourseFrame&&) = default;
  CourseFrame& operator=(CourseFrame&&) = default;

  // One frame is these two in turn. 1: the six faces of the cube map, lit as seen from `eye`.
  PassCounts captureFaces(const Scene& scene, double seconds, const MeshBuffers& meshes,
                          const glm::vec3& eye);
  // 2: the main pass into `framebuffer` (width x height), seen with `view` and `projection`
  // from `eye`.
  PassCounts drawMain(const Scene& scene, double seconds, const MeshBuffers& meshes,
                      const glm::mat4& view, const glm::mat4& projection, const glm::vec3& eye,
                      unsigned framebuffer, int width, int height);

 private:
  struct State;  // course_frame.cpp: the programs, the cube texture and its framebuffer
  CourseFrame() = default;
  std::shared_ptr<State> state_;  // shared_ptr: its deleter is made where State is complete
};

}  // namespace reflect
