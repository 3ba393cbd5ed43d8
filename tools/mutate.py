#!/usr/bin/env python3
"""Mutation check: do the tests catch the bugs they exist for?

Each mutation below is a deliberate bug in a rule that matters. One at a time, it is applied to a
scratch copy of the committed tree (a git worktree under build/mutate), the native build there
is brought up to date, and the tests that should catch it run. A mutation the tests miss is a
survivor. A mutation of the page's JavaScript (web/) runs its Playwright specs instead, against a
copy of the checkout's web build (build/web/site: build it first) with the file replaced. Not
part of ./test.sh: it rebuilds once per mutation (about 15-25 s each, 15 minutes in all on two
cores, after a first full build of the scratch tree).

    tools/mutate.sh [--list] [ID ...]

Prints one line per mutation (caught by which tests, or SURVIVED) and the score. The last run's
report is in docs/mutations.md.
"""
import os
import shutil
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCRATCH = os.path.join(REPO, "build", "mutate")

# (id, file, the exact text, its replacement, ctest regex of the tests that should catch it, why)
UNIT = "unit"
MUTATIONS = [
    ("mix-weight", "shaders/shading.glsl",
     "  return Blend(baseWeight * colour, reflectionWeight);",
     "  return Blend(baseWeight * colour, 0.9 * reflectionWeight);",
     "MatchesGolden|ExactMode|AccuracyFloors|ShadingEquivalence",
     "the course's mix, 0.78 -> 0.70 (every program's: the traced default and the cube-map lookup)"),
    ("mix-weight-reference", "src/core/reference_shading.cpp",
     "  return Blend{baseWeight * colour, reflectionWeight};",
     "  return Blend{baseWeight * colour, 0.9f * reflectionWeight};",
     "ShadingEquivalence|AccuracyTargets|AccuracyFloors|Reference", "the course's mix in the reference"),
    ("schlick-power", "shaders/shading.glsl",
     "  return f0 + (1.0 - f0) * pow(1.0 - clamp(dot(toViewer, normal), 0.0, 1.0), 5.0);",
     "  return f0 + (1.0 - f0) * pow(1.0 - clamp(dot(toViewer, normal), 0.0, 1.0), 4.0);",
     "MatchesGolden|ExactMode|AccuracyFloors|ShadingEquivalence", "Schlick's exponent"),
    ("phong-specular-always", "shaders/shading.glsl",
     "  if (nDotL > 0.0) {", "  if (nDotL > -1.0) {",
     "MatchesGolden|Reference|Shading", "specular only where the light reaches the front"),
    ("face-table-z", "src/core/cube_faces.h",
     '    {"+Z", {0, 0, 1}, {0, -1, 0}},\n    {"-Z", {0, 0, -1}, {0, -1, 0}},',
     '    {"+Z", {0, 0, -1}, {0, -1, 0}},\n    {"-Z", {0, 0, 1}, {0, -1, 0}},',
     "CubeFaces|CubeRoundTrip|MatchesGolden", "the +Z and -Z rows of the face table swapped"),
    ("face-up-vector", "src/core/cube_faces.h",
     '    {"+Y", {0, 1, 0}, {0, 0, 1}},', '    {"+Y", {0, 1, 0}, {0, 0, -1}},',
     "CubeFaces|CubeRoundTrip|CubeSeams", "+Y's up vector flipped"),
    ("slice-cursor", "src/core/update_policy.cpp",
     "memory.sliceCursor = (chosen.back() + 1) % 6;", "memory.sliceCursor = (chosen.back() + 2) % 6;",
     "FramePlanner", "time-sliced capture skips a face each frame"),
    ("every-n-phase", "src/core/update_policy.cpp",
     "if (frameIndex_ % static_cast<uint64_t>(std::max(settings.everyN, 1)) == 0) return stale;",
     "if (frameIndex_ % static_cast<uint64_t>(std::max(settings.everyN, 1)) == 1) return stale;",
     "FramePlanner", "every-n captures on the wrong frames (none on the first)"),
    ("dirty-colour", "src/core/frame_planner.cpp",
     "  return a.model == b.model && a.colour == b.colour && a.look == b.look &&",
     "  return a.model == b.model && a.look == b.look &&",
     "FramePlanner|PolicyEquivalence", "a colour change does not redraw the faces that show it"),
    ("pyramid-faces", "src/gfx/probe_capture.cpp",
     "    t.finish(pyramid_, captured);", "    t.finish(pyramid_, (captured << 1 | captured >> 5) & 63u);",
     "DepthPyramid|PolicyEquivalence", "the depth pyramid rebuilt for the wrong faces"),
    ("lod-choice", "src/core/planner_draws.cpp",
     "         static_cast<float>(o.levels[static_cast<size_t>(level + 1)].triangles) >= wanted) {",
     "         static_cast<float>(o.levels[static_cast<size_t>(level + 1)].triangles) >= 0.1f * wanted) {",
     "FramePlanner|CaptureLod", "capture LOD picks levels ten times too coarse"),
    ("plain-bound", "src/core/probe_storage.cpp",
     "  return 0.4082f / static_cast<float>(std::max(faceSize, 1));",
     "  return 4.082f / static_cast<float>(std::max(faceSize, 1));",
     "PlainLookupBound|FramePlanner|AccuracyTargets", "the plain lookup's half-texel bound ten times too loose"),
    ("layers-off", "src/core/probe_storage.cpp",
     "  probe.layers = search == Search::Hierarchical && context.accuracy.layers >= 2 && occlusion &&",
     "  probe.layers = search == Search::Hierarchical && context.accuracy.layers >= 3 && occlusion &&",
     "FramePlanner|DepthPyramid|AccuracyTargets", "the second layer never stored"),
    ("peel-slack", "shaders/capture_output.glsl",
     "const uint kPeelSlack = 2u;", "const uint kPeelSlack = 2000u;",
     "DepthPyramid|AccuracyTargets|AccuracyFloors|ThinObject",
     "the peel skips 2000 depth codes behind the first layer (9 units, 3 units from a 0.1 near plane)"),
    ("glass-sphere-exit", "shaders/environment_lookup.glsl",
     "    float t = -b + sqrt(max(b * b - c, 0.0));  // the far root: the ray starts on the surface",
     "    float t = -b - sqrt(max(b * b - c, 0.0));  // the far root: the ray starts on the surface",
     "AccuracyTargets|GlassPath|AccuracyFloors", "glass leaves at the near root, not the far side"),
    ("bvh-triangle-edge", "src/core/bvh_traverse.cpp",
     "  if (bv < 0.0f || bu + bv > 1.0f) return false;", "  if (bv < 0.0f || bu + bv > 1.1f) return false;",
     "Bvh", "the CPU triangle test lets rays past an edge"),
    ("trace-triangle-edge", "shaders/exact_trace.glsl",
     "  if (det != 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > tMin && t < best.t) {",
     "  if (det != 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.5 && t > tMin && t < best.t) {",
     "ExactMode|MatchesGolden|AccuracyFloors", "the traced triangle test lets rays past an edge"),
    ("trace-far-plane", "shaders/exact_shade.glsl",
     "  return max(away.x, max(away.y, away.z)) > u_exactFar;",
     "  return max(away.x, max(away.y, away.z)) < 0.0;",
     "TransformExtremes|ExactMode", "traced rays see past the capture's far distance"),
    ("trace-skip-self", "src/core/bvh_traverse.cpp",
     "      if (index == skip || (only >= 0 && index != only)) continue;",
     "      if (index == skip + 1000000 || (only >= 0 && index != only)) continue;",
     "Bvh", "the CPU trace does not leave the reflector out"),
    ("atlas-child-refs", "src/core/bvh_atlas.cpp",
     "        const PackedRef ref = refOf(part, child);",
     "        const PackedRef ref = refOf(part, nodes[part.interiorNodes[k]].first + (within >= 2 ? 0 : 1));",
     "Bvh|ExactMode", "a packed node's children's references swapped under their boxes"),
    ("method-hysteresis", "src/core/method_cost.cpp",
     "    return capture * costs.hysteresis < trace ? Method::Capture : current;",
     "    return capture < trace * costs.hysteresis ? Method::Capture : current;",
     "MethodCost|MethodChoice", "the hysteresis works against the current method"),
    ("method-pixels", "src/core/planner_draws.cpp",
     "  return std::min(3.14159265f * pixels * pixels, view.pixels);",
     "  return std::min(3.14159265f * pixels, view.pixels);",
     "MethodCost|MethodChoice", "a reflector's pixels on screen estimated wrong"),
    ("obj-relative-index", "src/core/obj_corners.cpp",
     "    out->position = static_cast<uint32_t>(index > 0 ? index - 1 : count + index);",
     "    out->position = static_cast<uint32_t>(index > 0 ? index - 1 : count + index - 1);",
     "Obj", "negative (relative) OBJ indices off by one"),
    ("obj-quad-diagonal", "src/core/obj_faces.cpp",
     "      emit(face[0], face[1], face[3], vertices, indices);\n      emit(face[1], face[2], face[3], vertices, indices);",
     "      emit(face[0], face[1], face[3], vertices, indices);\n      emit(face[1], face[3], face[2], vertices, indices);",
     "Obj", "a quad's second triangle wound the wrong way"),
    ("schema-range", "src/core/settings_schema.cpp",
     "      if (!(v >= min && v <= max)) {", "      if (!(v >= min && v <= max + 1)) {",
     "SettingsSchema|CliOptions", "a setting one past its range accepted"),
    ("camera-drag", "src/core/camera.h",
     "  static constexpr float kDegreesPerCanvasHeight = 100.0f;",
     "  static constexpr float kDegreesPerCanvasHeight = 90.0f;",
     "LookCamera", "the course's 100 degrees per canvas height"),
    ("frustum-near", "src/core/frustum.cpp",
     "  if (maxAlong(d, centre, local, model) < near) return false;   // wholly before the near plane",
     "  if (maxAlong(d, centre, local, model) < 2.0f * near) return false;   // wholly before the near plane",
     "FramePlanner|PolicyEquivalence|CubeRoundTrip", "a face culls what lies just past its near plane"),
    ("depth-code", "shaders/depth_encoding.glsl",
     "  return uint(clamp(floor(e * 65535.0 + 0.5), 0.0, 65534.0));",
     "  return uint(clamp(floor(e * 65535.0 + 0.5) + 40.0, 0.0, 65534.0));",
     "DepthPyramid|AccuracyTargets|DepthPrecision", "stored depths pushed back"),
    ("search-behind", "shaders/depth_search.glsl",
     "    bool passes = free || (eNear > eBack && eFar < behind.x);",
     "    bool passes = free || eNear > eBack;",
     "ThinObject|AccuracyTargets|AccuracyFloors|DepthPyramid",
     "the hierarchical search passes behind the first layer without looking at the second"),
    # The page's own rules (JavaScript): the site built from the checkout, the file replaced in a
    # copy of it, and the Playwright specs named after "web:" run against that copy.
    ("url-old-keys", "web/url_state.js",
     "const RENAMED = { slice: 'facesPerFrame', every: 'everyN', lod: 'captureLod', vlod: 'viewLod' };",
     "const RENAMED = { slice: 'everyN', every: 'facesPerFrame', lod: 'captureLod', vlod: 'viewLod' };",
     "web:url.spec.mjs", "an old link's slice= and every= read as each other"),
    ("url-flag", "web/url_state.js",
     "    if (['', 'true', '1'].includes(text)) return true;",
     "    if (['true', '1'].includes(text)) return true;",
     "web:url.spec.mjs", "a bare flag in a link (?paused) not read as on"),
    ("url-rounding", "web/url_state.js",
     "  if (typeof value === 'number') return round(value, 4);",
     "  if (typeof value === 'number') return round(value, 2);",
     "web:url.spec.mjs", "numbers written to the link to two decimals (the camera moves on reload)"),
]


def run(cmd, cwd, log, timeout=3600):
    with open(log, "a") as f:
        f.write(f"$ {' '.join(cmd)}\n")
        f.flush()
        return subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, timeout=timeout).returncode


def run_web(path, mutated, specs, log):
    """The page with one file of web/ mutated: a copy of the checkout's built site (build/web/site,
    ./test.sh's web build) with that file replaced, served on a port the system picks, and the
    Playwright specs run against it. Non-zero when a spec fails."""
    site = os.path.join(REPO, "build", "web", "site")
    if not os.path.isfile(os.path.join(site, "reflect.wasm")):
        raise SystemExit("web mutations need the web build: cmake --build --preset web")
    copy = os.path.join(REPO, "build", "mutate-site")
    subprocess.run(["rm", "-rf", copy], check=True)
    shutil.copytree(site, copy)
    with open(os.path.join(copy, os.path.basename(path)), "w") as f:
        f.write(mutated)
    port_file = os.path.join(REPO, "build", "mutate-site.port")
    if os.path.exists(port_file):
        os.remove(port_file)
    server = subprocess.Popen(["node", "tools/serve.mjs", copy, "0", "--port-file", port_file],
                              cwd=REPO, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        for _ in range(100):
            if os.path.exists(port_file) and open(port_file).read().strip():
                break
            time.sleep(0.1)
        env = dict(os.environ, TEST_BASE_URL=f"http://127.0.0.1:{open(port_file).read().strip()}/")
        with open(log, "a") as f:
            return subprocess.run(["npx", "playwright", "test"] + [f"tests/web/{s}" for s in specs],
                                  cwd=REPO, env=env, stdout=f, stderr=subprocess.STDOUT,
                                  timeout=1800).returncode
    finally:
        server.kill()


def main(argv):
    if "--list" in argv:
        for m in MUTATIONS:
            print(f"{m[0]:24} {m[1]:34} {m[5]}")
        return 0
    wanted = [a for a in argv if not a.startswith("-")]
    chosen = [m for m in MUTATIONS if not wanted or m[0] in wanted]
    os.makedirs(os.path.join(REPO, "build"), exist_ok=True)
    log = os.path.join(REPO, "build", "mutate.log")
    open(log, "w").close()
    if not os.path.isdir(SCRATCH):
        run(["git", "worktree", "add", "--force", "--detach", SCRATCH, "HEAD"], REPO, log)
    run(["git", "checkout", "--force", "--detach", subprocess.check_output(
        ["git", "rev-parse", "HEAD"], cwd=REPO, text=True).strip()], SCRATCH, log)
    if not os.path.islink(os.path.join(SCRATCH, "node_modules")):
        os.symlink(os.path.join(REPO, "node_modules"), os.path.join(SCRATCH, "node_modules"))
    if run(["cmake", "--preset", "native"], SCRATCH, log) or run(
            ["cmake", "--build", "--preset", "native"], SCRATCH, log):
        print(f"the unmutated tree does not build: see {log}")
        return 1
    survivors, caught = [], 0
    for ident, path, old, new, tests, why in chosen:
        target = os.path.join(SCRATCH, path)
        text = open(target).read()
        if text.count(old) != 1:
            print(f"{ident:24} NOT APPLIED: the text is not in {path} exactly once")
            survivors.append(ident)
            continue
        start = time.time()
        try:
            open(target, "w").write(text.replace(old, new))
            if tests.startswith("web:"):
                built = True
                failed = run_web(path, text.replace(old, new), tests[4:].split(","), log) != 0
            else:
                built = run(["cmake", "--build", "--preset", "native"], SCRATCH, log) == 0
                failed = not built or run(["ctest", "--preset", "native", "-R", tests, "-LE",
                                           "longrun", "-j2"], SCRATCH, log) != 0
        finally:
            open(target, "w").write(text)
        took = time.time() - start
        if failed:
            caught += 1
            print(f"{ident:24} caught ({'build' if not built else tests}), {took:.0f} s: {why}")
        else:
            survivors.append(ident)
            print(f"{ident:24} SURVIVED ({tests}), {took:.0f} s: {why}")
        sys.stdout.flush()
    run(["cmake", "--build", "--preset", "native"], SCRATCH, log)  # back to the unmutated build
    print(f"\n{caught} of {len(chosen)} mutations caught; survivors: {', '.join(survivors) or 'none'}")
    return 0 if not survivors else 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
