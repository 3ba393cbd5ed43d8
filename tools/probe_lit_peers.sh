#!/usr/bin/env bash
# Probe-lit figures beside three.js (issue 35): the project's page (default settings) and the
# probelit peer (tools/peers/probelit.js: CubeCamera and an order-2 projection a figure), timed in
# one browser run and compared with the Embree reference over the figures' own pixels.
#   tools/probe_lit_peers.sh [TIME] [SIZE]   (default 2 and 800x800; needs build/native and
#                                            build/web built, as ./test.sh builds them)
# The mask is the scene drawn natively with the figures white and everything else black: a copy
# of probe-lit.json with the light's ambient 1 and no diffuse or specular, every colour black
# but the figures', the mirror made Phong and the figures' ambient constant.
set -euo pipefail
cd "$(dirname "$0")/.."
time=${1:-2}
size=${2:-800x800}
out=build/probe-lit-peers
mkdir -p "$out"
node -e '
const fs = require("fs");
const s = JSON.parse(fs.readFileSync("assets/scenes/probe-lit.json", "utf8"));
s.light = { ...s.light, ambient: 1, diffuse: 0, specular: 0 };
s.background = [0, 0, 0];
for (const o of s.objects) {
  const figure = o.ambient && o.ambient !== "constant";
  o.colour = figure ? [1, 1, 1] : [0, 0, 0];
  delete o.ambient;
  delete o.material;
}
fs.writeFileSync(process.argv[1], JSON.stringify(s));
' "$out/mask-scene.json"
build/native/reflect render --scene probe-lit --time "$time" --size "$size" \
  --out "$out/frame.png" --reference "$out/reference.png" >/dev/null
build/native/reflect render --scene "$out/mask-scene.json" --time "$time" --size "$size" \
  --out "$out/mask.png" >/dev/null
node tools/peer_bench.mjs --scene probe-lit --pages default,probelit --size "$size" \
  --reference "$out/reference.png" --mask "$out/mask.png" --time "$time"
