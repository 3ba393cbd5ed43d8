#!/usr/bin/env python3
"""Generate cube-map skybox test images (standard library only, deterministic).

Writes into assets/skybox/:
  grid_{px,nx,py,ny,pz,nz}.png  six 256x256 labelled debug faces (grid, border,
                                big face name, "up" arrow near the top edge)
  sky_{px,nx,py,ny,pz,nz}.png   six 256x256 procedural sky faces
  sky_cross.png                 1024x768 horizontal cross of the same sky faces

Orientation follows the OpenGL cube-map convention with images stored top row
first (row 0 is uploaded first, i.e. t = 0).  For a texel (x, y) of an n x n
face, s = 2*(x+0.5)/n - 1 grows to the right and t = 2*(y+0.5)/n - 1 grows
downward, and the world direction is:

  +X: ( 1, -t, -s)   -X: (-1, -t,  s)
  +Y: ( s,  1,  t)   -Y: ( s, -1, -t)
  +Z: ( s, -t,  1)   -Z: (-s, -t, -1)

(This is the inverse of the sc/tc/ma table in the GL spec, section "Cube Map
Texture Selection".)  Grid labels are drawn upright in image space, so faces
with camera up (0,-1,0) show upside-down text from an upright viewer: expected.

Usage:
  python3 tools/make_skybox.py            # write the images
  python3 tools/make_skybox.py --check    # re-read and verify them
"""

import os
import sys

# The generator lives in tools/skybox/: cubemap (face layout and mapping), png, grid, sky and
# check (--check).
from skybox.check import check
from skybox.cubemap import self_test_mapping
from skybox.png import write_png
from skybox.sky import build

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT_DIR = os.path.join(ROOT, "assets", "skybox")


def main(argv):
    if "--check" in argv[1:]:
        return 0 if check(OUT_DIR) else 1
    if not self_test_mapping():
        print("mapping self-test failed", file=sys.stderr)
        return 1
    os.makedirs(OUT_DIR, exist_ok=True)
    for name, (w, h, rows) in sorted(build().items()):
        path = os.path.join(OUT_DIR, name)
        data = write_png(path, w, h, rows)
        print("wrote %s (%dx%d, %d bytes)" % (os.path.relpath(path, ROOT), w, h, len(data)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
