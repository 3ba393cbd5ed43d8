#!/usr/bin/env bash
# Every shipped scene's reflectors against the exact (Embree) reference: the course's setting,
# the default (planned), the hierarchical search and the exact mode: frame time (interleaved
# frame by frame, every-frame capture),
# reflector PSNR and pixels off by more than 32 levels, at held-out times (the constants were
# tuned at t = 0..7 s in whole seconds on the default scene). A Markdown table from
# `reflect bench --sweep --only original,default,hierarchical,exact` per scene.
#   tools/scene_accuracy.sh [SIZE] [TIMES]   (default 400x400 and 0.5,2.5,4.5,6.5; SCENES="a b")
set -euo pipefail
cd "$(dirname "$0")/.."
reflect=build/native/reflect
size="${1:-400x400}"
times="${2:-0.5,2.5,4.5,6.5}"
scenes=${SCENES:-}
[ -n "$scenes" ] || scenes=$(cd assets/scenes && ls -- *.json | sed 's/\.json$//')
echo "| scene | setting | frame ms (median) | ratio | mean PSNR dB | worst PSNR dB | pixels > 32 levels per frame (mean; worst) |"
echo "|---|---|---|---|---|---|---|"
for scene in $scenes; do
  "$reflect" bench --sweep --only original,default,hierarchical,exact --scene "$scene" --size "$size" \
    --times "$times" --frames 40 |
    awk -F'|' -v scene="$scene" '
      # Sweep rows: | name | setting | face | ms (p10-p90) | CPU | PSNR (worst) | >32 (worst) | ...
      $2 ~ /^ (original|default|hierarchical|exact) $/ {
        name = $2; gsub(/ /, "", name)
        split($5, ms, " "); split($7, psnr, "[ ()]+"); split($8, vis, "[ ()]+")
        label = name
        if (name == "original") { base = ms[1]; label = "course" }
        printf "| %s | %s | %s | %.2fx | %s | %s | %s; %s |\n", scene, label, ms[1], ms[1] / base,
               psnr[2], psnr[3], vis[2], vis[3]
      }'
done
