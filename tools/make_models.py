#!/usr/bin/env python3
"""Deterministic generator for the demo's stand-in OBJ models and OBJ loader test fixtures.

Everything here is original: the figures are assembled from procedurally generated
primitives (UV spheres/ellipsoids, capsules, cylinders/cones, domes, boxes) and then
fitted to fixed bounding boxes with a per-axis affine map.

Usage (from the repository root):
    python3 tools/make_models.py                 # write assets/models/*.obj
    python3 tools/make_models.py --out DIR       # write models to DIR
    python3 tools/make_models.py --check         # write, then re-read and validate
    python3 tools/make_models.py --preview /tmp/p  # write, then render PNG previews
    python3 tools/make_models.py --fixtures      # write tests/data/obj/*.obj fixtures only
    python3 tools/make_models.py --fixtures DIR  # fixtures to DIR
    python3 tools/make_models.py --fixtures --check  # write fixtures, then validate them

Standard library only. Output is byte-for-byte deterministic.
"""

import argparse
import os
import sys

# The generator lives in tools/models/: vec (vector maths), mesh (primitives), figures (the
# models), objio (OBJ writer, reader and checks), preview (rasteriser) and fixtures.
from models import mesh
from models.figures import build_cube, build_mario, build_quad, build_sonic, build_sphere
from models.fixtures import check_fixtures, write_fixtures
from models.objio import check_models, write_obj
from models.preview import preview_models

REPO_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Tessellation multiplier of --heavy: about the triangle count of the course's mario.obj (145k).
HEAVY_DETAIL = 4.6


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(REPO_ROOT, "assets", "models"),
                    help="output directory for the models (default: assets/models)")
    ap.add_argument("--check", action="store_true", help="re-read the written models and validate them")
    ap.add_argument("--preview", metavar="DIR", help="render PNG previews of the models into DIR")
    ap.add_argument("--preview-size", type=int, default=256, help="tile size of the previews in pixels")
    ap.add_argument("--fixtures", nargs="?", const=os.path.join(REPO_ROOT, "tests", "data", "obj"),
                    metavar="DIR", help="write OBJ loader test fixtures only (default dir: tests/data/obj)")
    ap.add_argument("--heavy", nargs="?", const=os.path.join(REPO_ROOT, "build", "heavy"), metavar="DIR",
                    help="write only mario.obj, tessellated to about the course model's 145k triangles, "
                         "into DIR (default build/heavy) for benchmarks")
    args = ap.parse_args(argv)

    if args.heavy:
        mesh.DETAIL = HEAVY_DETAIL
        os.makedirs(args.heavy, exist_ok=True)
        model, _ = build_mario()
        nv, nt = write_obj(model, os.path.join(args.heavy, "mario.obj"))
        print("heavy mario.obj: vertices %d, triangles %d -> %s" % (nv, nt, args.heavy))
        return 0

    if args.fixtures:
        write_fixtures(args.fixtures)
        return 0 if not args.check or check_fixtures(args.fixtures) else 1

    builders = [
        ("sphere.obj", lambda: (build_sphere(), None)),
        ("quad.obj", lambda: (build_quad(), None)),
        ("cube.obj", lambda: (build_cube(), None)),
        ("mario.obj", build_mario),
        ("sonic.obj", build_sonic),
    ]
    for name, build in builders:
        model, info = build()
        path = os.path.join(args.out, name)
        nv, nt = write_obj(model, path)
        lo, hi = model.bbox()
        print("%-10s vertices %5d  triangles %5d  bbox (%.4f, %.4f, %.4f)..(%.4f, %.4f, %.4f)"
              % (name, nv, nt, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]))
        if info is not None and os.environ.get("MAKE_MODELS_DEBUG"):
            print("   native bbox", info[0], info[1], "scale", info[2])

    ok = True
    if args.check:
        ok = check_models(args.out)
    if args.preview:
        preview_models(args.out, args.preview, args.preview_size)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
