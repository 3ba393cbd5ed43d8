#!/usr/bin/env bash
# A shipped scene beside a three.js peer page (issue 35): the project's page (default settings)
# and the peer, timed in one browser run and compared with the Embree reference over the
# pixels that matter: the probe-lit objects where the scene has any ("ambient"), else its mirrors
# and glass.
#   tools/scene_peers.sh SCENE PEER [TIME] [SIZE]
#     probe-lit probelit    tools/peers/probelit.js: CubeCamera and an order-2 projection a figure
#     frosted-glass frosted tools/peers/frosted.js: MeshPhysicalMaterial's transmission
#   (TIME default 2, SIZE 800x800; ROUNDS=N in the environment for peer_bench's rounds, e.g. 1
#   where a peer's page does not survive a second; needs build/native and build/web built, as
#   ./test.sh builds them). Output in build/scene-peers/SCENE/.
# The mask is the scene drawn natively with those objects white and everything else black: a copy
# of the scene file with the light's ambient 1 and no diffuse or specular, every colour black but
# theirs, every material Phong and every ambient constant.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:?scene name}
peer=${2:?peer page key}
time=${3:-2}
size=${4:-800x800}
out=build/scene-peers/$scene
mkdir -p "$out"
node -e '
const fs = require("fs");
const s = JSON.parse(fs.readFileSync(`assets/scenes/${process.argv[1]}.json`, "utf8"));
const lit = (o) => o.ambient && o.ambient !== "constant";
const anyLit = s.objects.some(lit);
const reflector = (o) => o.material && ["mirror", "glass"].includes(o.material.type || o.material);
s.light = { ...s.light, ambient: 1, diffuse: 0, specular: 0 };
s.background = [0, 0, 0];
for (const o of s.objects) {
  o.colour = (anyLit ? lit(o) : reflector(o)) ? [1, 1, 1] : [0, 0, 0];
  delete o.ambient;
  delete o.ambientRadius;
  delete o.material;
}
fs.writeFileSync(process.argv[2], JSON.stringify(s));
' "$scene" "$out/mask-scene.json"
build/native/reflect render --scene "$scene" --time "$time" --size "$size" \
  --out "$out/frame.png" --reference "$out/reference.png" >/dev/null
build/native/reflect render --scene "$out/mask-scene.json" --time "$time" --size "$size" \
  --out "$out/mask.png" >/dev/null
node tools/peer_bench.mjs --scene "$scene" --pages "default,$peer" --size "$size" \
  --reference "$out/reference.png" --mask "$out/mask.png" --time "$time" \
  ${ROUNDS:+--rounds "$ROUNDS"}
