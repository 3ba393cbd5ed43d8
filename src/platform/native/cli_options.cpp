#include "platform/native/cli_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace reflect {
namespace {

bool parseNumber(const std::string& text, double* out) {
  char* end = nullptr;
  double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value)) return false;
  *out = value;
  return true;
}

bool parseInt(const std::string& text, int lo, int hi, int* out) {
  double value = 0;
  if (!parseNumber(text, &value) || value != std::floor(value) || value < lo || value > hi) {
    return false;
  }
  *out = static_cast<int>(value);
  return true;
}

bool parseSize(const std::string& text, int* w, int* h) {
  size_t x = text.find('x');
  return x != std::string::npos && parseInt(text.substr(0, x), 1, 16384, w) &&
         parseInt(text.substr(x + 1), 1, 16384, h);
}

}  // namespace

const char* cliHelp() {
  return "reflect - dynamic cube-map reflection (the course's Ex12-2), rendered headless\n"
         "\n"
         "usage: reflect <command> [options]\n"
         "\n"
         "commands:\n"
         "  render   render one frame to a PNG\n"
         "  bench    time the capture update policies on the default scene (or one policy\n"
         "           with --policy) and compare their pictures with the every-frame policy\n"
         "  help     show this text (also --help)\n"
         "\n"
         "options:\n"
         "  --size WxH       frame size in pixels (default 800x800)\n"
         "  --time T         scene time in seconds (default 0); the figures orbit 27 deg/s\n"
         "  --out FILE       PNG to write (render; default frame.png)\n"
         "  --scene S        a scene: a name from assets/scenes (ex12-2, ex12-1, glass-sphere,\n"
         "                   two-mirrors, shared-probe, skybox, skybox-grid, ex12-2-fresnel)\n"
         "                   or a .json file\n"
         "                   (default ex12-2)\n"
         "  --reference FILE render: also write the exact (ray-traced, Embree) frame and\n"
         "                   print the reflector's error against it\n"
         "  --assets DIR     take the models from DIR by the course's file names\n"
         "                   (mario.obj sonic.obj sphere.obj quad.obj)\n"
         "  --cube N         cube-map face size (default 256)\n"
         "  --yaw D          camera yaw in degrees (default 0)\n"
         "  --pitch D        camera pitch in degrees, clamped to +/-89 (default 0)\n"
         "  --frames N       bench: frames to time (default 120)\n"
         "  --warmup N       bench: frames before timing (default 10)\n"
         "  --growth         bench: frame ms for 1/4/16 reflectors x 10k/100k/1M triangles,\n"
         "                   with a probe each and with neighbours sharing probes\n"
         "accuracy (see README, Speed and accuracy):\n"
         "  --distance K     distance-corrected lookup with K secant steps (default 2;\n"
         "                   0 = plain lookup, the course's)\n"
         "  --origin         capture at (0,0,0) as the course does, not the reflector's centre\n"
         "  --depth B        capture depth bits, 16 or 24 (default 24)\n"
         "  --mipmaps        trilinear lookup from mipmapped captures\n"
         "  --half-float     RGBA16F captures instead of RGBA8\n"
         "  --mediump        fragment shaders at mediump precision\n"
         "  --sweep          bench: every accuracy setting (capture point, distance-corrected\n"
         "                   lookup, face size, depth bits, filtering, RGBA16F, precision):\n"
         "                   frame ms and error against the ray-traced reference\n"
         "  --csv FILE       sweep: write the rows as CSV (name, ms, psnr_db, rmse, p95, ...)\n"
         "  --svg FILE       sweep: write a plot of error against time with the Pareto front\n"
         "  --accuracy-frames N  bench: frames compared with every-frame (default 60)\n"
         "  --policy P       capture update policy: every-frame (the course), when-changed\n"
         "                   (default), time-sliced, every-n\n"
         "  --slice K        time-sliced: faces per frame (default 2)\n"
         "  --every N        every-n: capture every N-th frame (default 4)\n"
         "  --lod D          capture LOD: in each face use the coarsest mesh level with at\n"
         "                   least D triangles per pixel of the object's projected disc\n"
         "                   (default 0 = off, full detail)\n"
         "  --view-lod D     view LOD: the same rule for the main camera's pass (default 0 =\n"
         "                   off); bench adds a row with captures and view at D (0.5 if 0)\n";
}

Result<CliOptions> parseCli(const std::vector<std::string>& args) {
  using Out = Result<CliOptions>;
  CliOptions o;
  if (args.empty()) return Out::failure("no command given (try: reflect --help)");
  o.command = args[0];
  if (o.command == "--help" || o.command == "-h") o.command = "help";
  if (o.command != "render" && o.command != "bench" && o.command != "help") {
    return Out::failure("unknown command '" + o.command + "' (try: reflect --help)");
  }
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--help" || flag == "-h") {
      o.command = "help";
      continue;
    }
    if (flag == "--growth" || flag == "--sweep") {
      (flag == "--growth" ? o.growth : o.sweep) = true;
      continue;
    }
    if (flag == "--origin" || flag == "--mipmaps" || flag == "--half-float" ||
        flag == "--mediump") {
      bool& on = flag == "--origin"       ? o.accuracy.captureAtOrigin
                 : flag == "--mipmaps"    ? o.accuracy.mipmaps
                 : flag == "--half-float" ? o.accuracy.halfFloat
                                          : o.accuracy.mediump;
      on = true;
      continue;
    }
    if (i + 1 >= args.size()) return Out::failure(flag + ": missing value");
    const std::string& value = args[++i];
    double number = 0;
    bool ok = true;
    if (flag == "--size") {
      ok = parseSize(value, &o.width, &o.height);
    } else if (flag == "--time") {
      ok = parseNumber(value, &o.time);
    } else if (flag == "--out") {
      o.out = value;
    } else if (flag == "--search") {
      ok = parseSearch(value, &o.accuracy.search);
    } else if (flag == "--layers") {
      ok = parseInt(value, 1, 2, &o.accuracy.layers);
    } else if (flag == "--glass-surfaces") {
      ok = parseInt(value, 1, 2, &o.accuracy.glassSurfaces);
    } else if (flag == "--depth") {
      ok = parseInt(value, 16, 24, &o.accuracy.depthBits) &&
           (o.accuracy.depthBits == 16 || o.accuracy.depthBits == 24);
    } else if (flag == "--reference") {
      o.referenceOut = value;
    } else if (flag == "--csv") {
      o.csv = value;
    } else if (flag == "--svg") {
      o.svg = value;
    } else if (flag == "--scene") {
      o.scene = value;
    } else if (flag == "--assets") {
      o.assets = value;
    } else if (flag == "--frames") {
      ok = parseInt(value, 1, 1000000, &o.frames);
    } else if (flag == "--warmup") {
      ok = parseInt(value, 0, 1000000, &o.warmup);
    } else if (flag == "--cube") {
      ok = parseInt(value, 1, 16384, &o.cubeSize);
      o.cubeSizeSet = true;
    } else if (flag == "--accuracy-frames") {
      ok = parseInt(value, 0, 100000, &o.accuracyFrames);
    } else if (flag == "--policy") {
      ok = parsePolicy(value, &o.planner.policy);
      o.policySet = true;
    } else if (flag == "--slice") {
      ok = parseInt(value, 1, 6, &o.planner.facesPerFrame);
    } else if (flag == "--every") {
      ok = parseInt(value, 1, 1000, &o.planner.everyN);
    } else if (flag == "--lod" || flag == "--view-lod") {
      ok = parseNumber(value, &number) && number >= 0;
      (flag == "--lod" ? o.planner.captureLod : o.planner.viewLod) = static_cast<float>(number);
    } else if (flag == "--yaw" || flag == "--pitch") {
      ok = parseNumber(value, &number);
      (flag == "--yaw" ? o.yawDeg : o.pitchDeg) = static_cast<float>(number);
    } else {
      return Out::failure("unknown option '" + flag + "' (try: reflect --help)");
    }
    if (!ok) return Out::failure(flag + ": invalid value '" + value + "'");
  }
  return o;
}

}  // namespace reflect
