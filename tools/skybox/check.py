"""make_skybox.py --check: re-read the written images and verify them."""

import os

from .cubemap import CROSS_CELL, FACES, N, dir_to_face_st, edge_pairs, self_test_mapping
from .png import encode_png, read_png
from .sky import SUN_DIR, build

NAMES = (["grid_%s.png" % f for f in FACES] + ["sky_%s.png" % f for f in FACES]
         + ["sky_cross.png"])
EDGE_TOL = 10  # max channel difference across a cube edge


class Report:
    """Prints one OK/FAIL line per condition; `ok` stays true until one fails."""

    def __init__(self):
        self.ok = True

    def __call__(self, cond, msg):
        print(("OK   " if cond else "FAIL ") + msg)
        if not cond:
            self.ok = False


def check(out_dir):
    report = Report()
    report(self_test_mapping(), "face_dir() round-trips through GL spec cube-map selection")

    imgs = read_images(out_dir, report)
    if not report.ok:
        return False

    # deterministic: regenerating gives byte-identical files
    regenerated = build()
    same = all(encode_png(*regenerated[n]) == open(os.path.join(out_dir, n), "rb").read()
               for n in NAMES)
    report(same, "files are byte-identical to a fresh in-memory regeneration")

    # grid faces are distinct from each other
    grid_rows = [b"".join(imgs["grid_%s.png" % f][2]) for f in FACES]
    report(len(set(grid_rows)) == 6, "six grid faces are all distinct")

    check_cross(imgs, report)
    sky = {f: imgs["sky_%s.png" % f][2] for f in FACES}
    check_edges(sky, report)
    check_content(sky, report)

    print("OK" if report.ok else "FAIL")
    return report.ok


def read_images(out_dir, report):
    """Reads every image, reporting its size; returns {name: (w, h, rows)} of those readable."""
    imgs = {}
    expected_sizes = {"sky_cross.png": (4 * N, 3 * N)}
    for name in NAMES:
        path = os.path.join(out_dir, name)
        try:
            w, h, rows = read_png(path)
        except (OSError, ValueError) as e:
            report(False, "%s: %s" % (name, e))
            continue
        imgs[name] = (w, h, rows)
        ew, eh = expected_sizes.get(name, (N, N))
        report((w, h) == (ew, eh), "%s is %dx%d (expected %dx%d, %d bytes)"
               % (name, w, h, ew, eh, os.path.getsize(path)))
    return imgs


def check_cross(imgs, report):
    """Cross cells == separate sky faces, unused cells black."""
    cw, ch, crows = imgs["sky_cross.png"]
    used = set(CROSS_CELL.values())
    for face, (r, c) in CROSS_CELL.items():
        frows = imgs["sky_%s.png" % face][2]
        cell = [crows[r * N + y][c * N * 3:(c + 1) * N * 3] for y in range(N)]
        report(cell == frows, "cross cell (row %d, col %d) == sky_%s.png byte for byte"
               % (r, c, face))
    black = bytes(N * 3)
    all_black = True
    for r in range(3):
        for c in range(4):
            if (r, c) in used:
                continue
            if any(crows[r * N + y][c * N * 3:(c + 1) * N * 3] != black for y in range(N)):
                all_black = False
    report(all_black, "unused cross cells are black")


def check_edges(sky, report):
    """Continuity across the 12 cube edges (both directions, every border texel)."""
    worst = {}
    for fa, xa, ya, fb, xb, yb in edge_pairs():
        pa = sky[fa][ya][xa * 3:xa * 3 + 3]
        pb = sky[fb][yb][xb * 3:xb * 3 + 3]
        diff = max(abs(a - b) for a, b in zip(pa, pb))
        key = tuple(sorted((fa, fb)))
        worst[key] = max(worst.get(key, 0), diff)
    report(len(worst) == 12, "found all 12 cube edges (got %d)" % len(worst))
    for key in sorted(worst):
        report(worst[key] <= EDGE_TOL, "edge %s|%s continuous: max channel diff %d (tol %d)"
               % (key[0], key[1], worst[key], EDGE_TOL))

    # explicit spot-check from the brief: right column of +Z vs left column of +X
    pz, px = sky["pz"], sky["px"]
    d = max(abs(pz[y][(N - 1) * 3 + k] - px[y][k]) for y in range(N) for k in range(3))
    report(d <= EDGE_TOL, "+Z right column vs +X left column: max diff %d" % d)


def check_content(sky, report):
    """Sanity on content: sun is on -Z face (upper left), sky above ground."""
    _, ss, st = dir_to_face_st(SUN_DIR)
    fsun = dir_to_face_st(SUN_DIR)[0]
    sx = int((ss + 1) * 0.5 * N)
    sy = int((st + 1) * 0.5 * N)
    sun_px = sky[fsun][sy][sx * 3:sx * 3 + 3]
    report(fsun == "nz" and min(sun_px) >= 230,
           "sun disc at %s texel (%d, %d) is bright %s" % (fsun, sx, sy, tuple(sun_px)))
    top = sky["py"][N // 2][(N // 2) * 3:(N // 2) * 3 + 3]
    bot = sky["ny"][N // 2][(N // 2) * 3:(N // 2) * 3 + 3]
    report(top[2] > top[0] and bot[2] < bot[0],
           "zenith is blue %s, nadir is ground-coloured %s" % (tuple(top), tuple(bot)))
