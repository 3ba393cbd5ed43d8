// What is in the scene, as data: meshes by name, transforms and simple animations, colours,
// materials, light, camera, background and capture settings. Scenes come from JSON files
// (scene_file.h); the renderer draws whatever this describes.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/camera.h"

namespace reflect {

struct PhongLight {
  glm::vec3 position{5.0f, 1.0f, 7.0f};
  float ambient = 0.2f;   // Ka
  float diffuse = 0.7f;   // Kd
  float specular = 1.0f;  // Ks
  float shininess = 10.0f;
  bool operator==(const PhongLight&) const = default;
};

enum class Material {
  Phong,         // lit with the course's Phong constants
  Mirror,        // reflection of the environment mixed with the base colour
  Glass,         // refraction (reflection on total internal reflection) mixed with the base colour
  CubeTextured,  // Ex12-1: the environment sampled along the object-space position, unlit
};

// Where a mirror, glass or cube-textured object gets its environment from.
enum class Environment {
  LiveProbe,  // a cube map captured from the object's centre (or its probe group's)
  Skybox,     // the scene's static skybox
};

// Where a Phong object's ambient light comes from.
enum class Ambient {
  Constant,  // the course: the light's ambient constant, the same from every direction
  Probe,     // what the nearest live probe sees, as irradiance (docs/rough.md, "Diffuse light")
  OwnProbe,  // the same from a small probe of its own, at its centre, that leaves it out
};

enum class Motion {
  None,
  Orbit,  // M = R(axis, rate * t) * placement: circles the world origin
  Spin,   // M = placement * R(axis, rate * t): turns about its own origin
};

struct SceneObject {
  std::string mesh;  // model file name, e.g. "mario.obj"
  glm::mat4 placement{1.0f};
  Motion motion = Motion::None;
  glm::vec3 axis{0.0f, 1.0f, 0.0f};
  double degreesPerSecond = 27.0;  // the course's 0.45 degrees a frame at 60 Hz
  glm::vec3 colour{1.0f};
  Material material = Material::Phong;
  Environment environment = Environment::LiveProbe;
  // Mirror and glass: weight * environment + base * colour (the course: 0.78 and 0.3).
  float reflection = 0.78f;
  float base = 0.3f;
  float ior = 1.52f;     // glass (air to glass); also sets Fresnel's F0
  bool fresnel = false;  // Schlick weighting instead of the fixed mix
  // Mirror and glass: 0 a perfect surface (the course), up to 1; what the surface shows is
  // averaged over a GGX lobe of alpha = roughness^2 (core/ggx.h, docs/rough.md): a mirror's
  // reflection, and glass's reflection and the light it lets through (frosted glass).
  float roughness = 0.0f;
  // Objects with the same probe group >= 0 share one live probe; -1 = a probe of its own.
  int probeGroup = -1;
  // Where its live probe captures from, in world space; unset = the centre of the mesh bounds.
  // (Ex12-1 captures its cube's environment from the origin.)
  std::optional<glm::vec3> probeCentre;
  // Phong: its ambient light. Probe: the irradiance the nearest live probe's capture gives its
  // normal (order-2 spherical harmonics), in place of the light's ambient constant, in the main
  // pass; what mirrors and captures show of it keeps the constant (one bounce). OwnProbe: the
  // same from a probe of its own (kIrradianceFaceSize texels a face, at its bounds' centre,
  // without itself in it).
  Ambient ambient = Ambient::Constant;
  // A probe-lit object's surroundings taken to lie on a sphere of this radius (world units)
  // about its probe's centre: each point reads the irradiance along the direction from the
  // centre to where its normal's ray meets that sphere, not along the normal itself (parallax
  // correction, as box projection does for reflections). 0: infinitely far, no correction.
  // Unset (the default): each point's own view, from the distances the probe captured
  // (core/irradiance_parallax.h).
  std::optional<float> ambientRadius;

  bool usesEnvironment() const { return material != Material::Phong; }
  // What a capture of this object depends on besides its mesh, place and colour (compared by
  // value).
  struct Look {
    Material material;
    Environment environment;
    float reflection, base, ior;
    bool fresnel;
    float roughness;
    bool operator==(const Look&) const = default;
    // A mirror or glass whose view is blurred by a lobe (and so reads a prefiltered probe).
    bool rough() const {
      return (material == Material::Mirror || material == Material::Glass) && roughness > 0.0f;
    }
  };
  Look look() const { return {material, environment, reflection, base, ior, fresnel, roughness}; }
  bool rough() const { return look().rough(); }
  bool needsLiveProbe() const { return usesEnvironment() && environment == Environment::LiveProbe; }
  bool probeLit() const { return material == Material::Phong && ambient != Ambient::Constant; }
  // A probe-lit object with an irradiance probe of its own (Ambient::OwnProbe).
  bool ownsLightProbe() const { return probeLit() && ambient == Ambient::OwnProbe; }
};

struct CaptureSettings {
  int faceSize = 256;
  float near = 1.0f;
  float far = 100.0f;
};

// Six images in GL face order (+X, -X, +Y, -Y, +Z, -Z), or one horizontal cross.
struct SkyboxSource {
  std::array<std::string, 6> faces;  // empty when `cross` is used
  std::string cross;
  bool empty() const { return cross.empty() && faces[0].empty(); }
};

struct Scene {
  std::string name = "ex12-2";
  std::string title = "Ex12-2: dynamic reflection";
  std::vector<SceneObject> objects;
  PhongLight light;
  CameraSettings camera;
  CaptureSettings capture;
  glm::vec3 clearColour{0.4f, 0.4f, 0.4f};
  SkyboxSource skybox;  // drawn behind everything (and into captures) when set

  glm::mat4 modelMatrix(const SceneObject& object, double seconds) const;
  // The distinct mesh names the scene uses, in first-use order.
  std::vector<std::string> meshNames() const;
  // Index of the first object with a live probe, or -1 when the scene has none.
  int reflectorIndex() const;
};

// The course's Ex12-2 ("dynamic reflection"), with its values (docs/course.md). The same scene
// ships as assets/scenes/ex12-2.json; a test keeps the two equal.
Scene makeDynamicReflectionScene();

}  // namespace reflect
