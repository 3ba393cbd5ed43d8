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

import math
import os
import struct
import sys
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT_DIR = os.path.join(ROOT, "assets", "skybox")
N = 256  # face size in texels

FACES = ["px", "nx", "py", "ny", "pz", "nz"]
FACE_LABEL = {"px": "+X", "nx": "-X", "py": "+Y", "ny": "-Y", "pz": "+Z", "nz": "-Z"}

# Horizontal cross: (row, col) of each face in 256x256 cells, 4 cols x 3 rows.
CROSS_CELL = {
    "py": (0, 1),
    "nx": (1, 0),
    "pz": (1, 1),
    "px": (1, 2),
    "nz": (1, 3),
    "ny": (2, 1),
}


# --------------------------------------------------------------------------
# Cube-map mapping (GL convention)
# --------------------------------------------------------------------------

def face_dir(face, s, t):
    """Unnormalised world direction of face coords s (right), t (down) in [-1, 1]."""
    if face == "px":
        return (1.0, -t, -s)
    if face == "nx":
        return (-1.0, -t, s)
    if face == "py":
        return (s, 1.0, t)
    if face == "ny":
        return (s, -1.0, -t)
    if face == "pz":
        return (s, -t, 1.0)
    if face == "nz":
        return (-s, -t, -1.0)
    raise ValueError(face)


def dir_to_face_st(d, face=None):
    """GL spec cube-map selection: direction -> (face, s, t) with s, t in [-1, 1].

    If `face` is given, project onto that face instead of the major axis (used
    for points exactly on an edge, which belong to two faces)."""
    x, y, z = d
    if face is None:
        ax, ay, az = abs(x), abs(y), abs(z)
        if ax >= ay and ax >= az:
            face = "px" if x > 0 else "nx"
        elif ay >= az:
            face = "py" if y > 0 else "ny"
        else:
            face = "pz" if z > 0 else "nz"
    if face == "px":
        sc, tc, ma = -z, -y, x
    elif face == "nx":
        sc, tc, ma = z, -y, -x
    elif face == "py":
        sc, tc, ma = x, z, y
    elif face == "ny":
        sc, tc, ma = x, -z, -y
    elif face == "pz":
        sc, tc, ma = x, -y, z
    else:  # nz
        sc, tc, ma = -x, -y, -z
    return face, sc / ma, tc / ma


def texel_st(i, n=N):
    return 2.0 * (i + 0.5) / n - 1.0


# --------------------------------------------------------------------------
# PNG writer / reader (8-bit RGB, filter "Up" on every row)
# --------------------------------------------------------------------------

PNG_SIG = b"\x89PNG\r\n\x1a\n"


def encode_png(width, height, rows):
    """rows: list of `height` bytes-like objects of length width*3."""
    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data
                + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    raw = bytearray()
    prev = bytes(width * 3)
    for row in rows:
        row = bytes(row)
        assert len(row) == width * 3
        raw.append(2)  # filter type 2 (Up): great for smooth vertical gradients
        raw.extend(bytes((a - b) & 0xFF for a, b in zip(row, prev)))
        prev = row
    return (PNG_SIG
            + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(bytes(raw), 9))
            + chunk(b"IEND", b""))


def write_png(path, width, height, rows):
    data = encode_png(width, height, rows)
    with open(path, "wb") as fh:
        fh.write(data)
    return data


def read_png(path):
    """Minimal reader for 8-bit RGB, non-interlaced PNGs with filters 0/1/2.

    Returns (width, height, rows) with rows as bytes."""
    with open(path, "rb") as fh:
        data = fh.read()
    if data[:8] != PNG_SIG:
        raise ValueError("%s: not a PNG" % path)
    pos = 8
    idat = bytearray()
    width = height = None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        tag = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        if zlib.crc32(tag + body) & 0xFFFFFFFF != crc:
            raise ValueError("%s: bad CRC in %r" % (path, tag))
        pos += 12 + length
        if tag == b"IHDR":
            width, height, depth, ctype, comp, filt, interlace = struct.unpack(">IIBBBBB", body)
            if (depth, ctype, comp, filt, interlace) != (8, 2, 0, 0, 0):
                raise ValueError("%s: unsupported PNG format" % path)
        elif tag == b"IDAT":
            idat.extend(body)
        elif tag == b"IEND":
            break
    raw = zlib.decompress(bytes(idat))
    stride = width * 3
    if len(raw) != height * (stride + 1):
        raise ValueError("%s: bad image data size" % path)
    rows = []
    prev = bytes(stride)
    for y in range(height):
        off = y * (stride + 1)
        ftype = raw[off]
        line = bytearray(raw[off + 1:off + 1 + stride])
        if ftype == 0:
            pass
        elif ftype == 1:  # Sub
            for i in range(3, stride):
                line[i] = (line[i] + line[i - 3]) & 0xFF
        elif ftype == 2:  # Up
            for i in range(stride):
                line[i] = (line[i] + prev[i]) & 0xFF
        else:
            raise ValueError("%s: unsupported filter type %d" % (path, ftype))
        prev = bytes(line)
        rows.append(prev)
    return width, height, rows


# --------------------------------------------------------------------------
# Grid debug faces
# --------------------------------------------------------------------------

# 5x7 dot-matrix glyphs, '#' = lit.
FONT = {
    "+": [".....",
          "..#..",
          "..#..",
          "#####",
          "..#..",
          "..#..",
          "....."],
    "-": [".....",
          ".....",
          ".....",
          "#####",
          ".....",
          ".....",
          "....."],
    "X": ["#...#",
          "#...#",
          ".#.#.",
          "..#..",
          ".#.#.",
          "#...#",
          "#...#"],
    "Y": ["#...#",
          "#...#",
          ".#.#.",
          "..#..",
          "..#..",
          "..#..",
          "..#.."],
    "Z": ["#####",
          "....#",
          "...#.",
          "..#..",
          ".#...",
          "#....",
          "#####"],
    "U": ["#...#",
          "#...#",
          "#...#",
          "#...#",
          "#...#",
          "#...#",
          ".###."],
    "P": ["####.",
          "#...#",
          "#...#",
          "####.",
          "#....",
          "#....",
          "#...."],
}

GRID_BASE = {
    "px": (250, 180, 180),  # light red
    "nx": (160, 80, 85),    # dark red
    "py": (180, 240, 180),  # light green
    "ny": (70, 140, 80),    # dark green
    "pz": (180, 205, 250),  # light blue
    "nz": (70, 90, 170),    # dark blue
}


class Canvas:
    def __init__(self, w, h, color):
        self.w, self.h = w, h
        self.px = [[color] * w for _ in range(h)]

    def rect(self, x0, y0, x1, y1, color):
        """Fill [x0, x1) x [y0, y1)."""
        x0, y0 = max(0, x0), max(0, y0)
        x1, y1 = min(self.w, x1), min(self.h, y1)
        for y in range(y0, y1):
            row = self.px[y]
            for x in range(x0, x1):
                row[x] = color

    def text(self, s, cx, cy, scale, color):
        """Draw string centred at (cx, cy); glyphs 5x7 cells, 1-cell spacing."""
        w = (len(s) * 6 - 1) * scale
        h = 7 * scale
        x0 = cx - w // 2
        y0 = cy - h // 2
        for k, ch in enumerate(s):
            glyph = FONT[ch]
            gx = x0 + k * 6 * scale
            for gy, line in enumerate(glyph):
                for gxx, c in enumerate(line):
                    if c == "#":
                        self.rect(gx + gxx * scale, y0 + gy * scale,
                                  gx + (gxx + 1) * scale, y0 + (gy + 1) * scale, color)

    def rows(self):
        return [bytes(c for p in row for c in p) for row in self.px]


def shade(color, f):
    return tuple(max(0, min(255, int(round(c * f)))) for c in color)


def make_grid_face(face):
    base = GRID_BASE[face]
    lum = 0.299 * base[0] + 0.587 * base[1] + 0.114 * base[2]
    dark_bg = lum < 140
    ink = (255, 255, 255) if dark_bg else (20, 20, 30)
    line = shade(base, 1.35) if dark_bg else shade(base, 0.72)
    border = (255, 255, 255) if dark_bg else (30, 30, 40)

    cv = Canvas(N, N, base)
    # thin grid lines every 32 px (1 px wide)
    for k in range(0, N, 32):
        cv.rect(k, 0, k + 1, N, line)
        cv.rect(0, k, N, k + 1, line)
    cv.rect(N - 1, 0, N, N, line)
    cv.rect(0, N - 1, N, N, line)
    # thick border (4 px)
    b = 4
    cv.rect(0, 0, N, b, border)
    cv.rect(0, N - b, N, N, border)
    cv.rect(0, 0, b, N, border)
    cv.rect(N - b, 0, N, N, border)
    # big label: 5x7 glyphs scaled x9 -> 63 px tall
    cv.text(FACE_LABEL[face], N // 2, N // 2 + 4, 9, ink)
    # "up" mark near the top edge: a filled triangle arrow + shaft + small "UP"
    ax, atop = N // 2, 12
    for r in range(14):  # triangle rows, widening downward
        cv.rect(ax - r, atop + r, ax + r + 1, atop + r + 1, ink)
    cv.rect(ax - 3, atop + 14, ax + 4, atop + 30, ink)
    cv.text("UP", ax + 40, atop + 14, 2, ink)
    return cv.rows()


# --------------------------------------------------------------------------
# Procedural sky
# --------------------------------------------------------------------------

def normalize(v):
    l = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    return (v[0] / l, v[1] / l, v[2] / l)


SUN_DIR = normalize((0.5, 0.35, -0.8))
SUN_COS_DISC = math.cos(math.radians(2.2))   # sun disc angular radius
SUN_COS_EDGE = math.cos(math.radians(3.0))   # disc soft edge


def lerp3(a, b, f):
    return (a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f)


def smoothstep(e0, e1, x):
    if e0 == e1:
        return 0.0 if x < e0 else 1.0
    f = min(1.0, max(0.0, (x - e0) / (e1 - e0)))
    return f * f * (3.0 - 2.0 * f)


SKY_HORIZON = (196, 222, 242)
SKY_ZENITH = (34, 86, 178)
GROUND_NEAR = (118, 118, 74)
GROUND_FAR = (48, 56, 30)
HAZE = (226, 228, 220)
SUN_CORE = (255, 252, 235)
SUN_GLOW = (255, 226, 160)


def sky_color(d):
    x, y, z = d
    if y >= 0.0:
        sky = lerp3(SKY_HORIZON, SKY_ZENITH, math.sqrt(y) ** 1.2)
    else:
        sky = lerp3(SKY_HORIZON, SKY_ZENITH, 0.0)
    ground = lerp3(GROUND_NEAR, GROUND_FAR, math.sqrt(max(0.0, -y)))
    # soft blend between sky and ground across the horizon
    g = smoothstep(-0.03, 0.015, y)
    c = lerp3(ground, sky, g)
    # soft bright haze band at the horizon
    band = math.exp(-(y / 0.05) ** 2)
    c = lerp3(c, HAZE, 0.55 * band)
    # sun glow (only where it is above / near the horizon) and disc
    cosang = x * SUN_DIR[0] + y * SUN_DIR[1] + z * SUN_DIR[2]
    above = smoothstep(-0.04, 0.02, y)
    glow = 0.55 * max(0.0, cosang) ** 64 + 0.35 * max(0.0, cosang) ** 8
    c = lerp3(c, SUN_GLOW, min(1.0, glow) * above)
    disc = smoothstep(SUN_COS_EDGE, SUN_COS_DISC, cosang)
    c = lerp3(c, SUN_CORE, disc)
    return tuple(max(0, min(255, int(c[i] + 0.5))) for i in range(3))


def make_sky_face(face):
    rows = []
    for yy in range(N):
        t = texel_st(yy)
        row = bytearray()
        for xx in range(N):
            s = texel_st(xx)
            row.extend(sky_color(normalize(face_dir(face, s, t))))
        rows.append(bytes(row))
    return rows


def make_cross(sky_faces):
    W, H = 4 * N, 3 * N
    rows = [bytearray(W * 3) for _ in range(H)]  # black
    for face, (r, c) in CROSS_CELL.items():
        for y in range(N):
            rows[r * N + y][c * N * 3:(c + 1) * N * 3] = sky_faces[face][y]
    return W, H, [bytes(r) for r in rows]


# --------------------------------------------------------------------------
# Build everything in memory
# --------------------------------------------------------------------------

def build():
    """Returns {filename: (width, height, rows)} for every output image."""
    out = {}
    for face in FACES:
        out["grid_%s.png" % face] = (N, N, make_grid_face(face))
    sky = {}
    for face in FACES:
        sky[face] = make_sky_face(face)
        out["sky_%s.png" % face] = (N, N, sky[face])
    out["sky_cross.png"] = make_cross(sky)
    return out


def self_test_mapping():
    """Round-trip every face mapping through the GL spec selection formula."""
    for face in FACES:
        for s, t in ((-0.9, -0.3), (0.2, 0.7), (0.5, -0.5), (0.0, 0.0)):
            f2, s2, t2 = dir_to_face_st(face_dir(face, s, t))
            if f2 != face or abs(s2 - s) > 1e-12 or abs(t2 - t) > 1e-12:
                return False
    return True


# --------------------------------------------------------------------------
# Check
# --------------------------------------------------------------------------

def edge_pairs():
    """Yield (faceA, xA, yA, faceB, xB, yB) for every border texel of every
    face and the texel on the neighbouring face directly across the edge."""
    for fa in FACES:
        for edge in ("left", "right", "top", "bottom"):
            for i in range(N):
                if edge == "left":
                    xa, ya, s, t = 0, i, -1.0, texel_st(i)
                elif edge == "right":
                    xa, ya, s, t = N - 1, i, 1.0, texel_st(i)
                elif edge == "top":
                    xa, ya, s, t = i, 0, texel_st(i), -1.0
                else:
                    xa, ya, s, t = i, N - 1, texel_st(i), 1.0
                d = face_dir(fa, s, t)  # point exactly on the edge
                # neighbour = the other axis with |component| == 1
                cands = []
                for axis, (pos, neg) in enumerate((("px", "nx"), ("py", "ny"), ("pz", "nz"))):
                    if abs(abs(d[axis]) - 1.0) < 1e-12:
                        f = pos if d[axis] > 0 else neg
                        if f != fa:
                            cands.append(f)
                if len(cands) != 1:
                    raise AssertionError("edge mapping broken for %s %s" % (fa, edge))
                fb = cands[0]
                _, sb, tb = dir_to_face_st(d, fb)
                xb = min(N - 1, max(0, int(math.floor((sb + 1.0) * 0.5 * N))))
                yb = min(N - 1, max(0, int(math.floor((tb + 1.0) * 0.5 * N))))
                yield fa, xa, ya, fb, xb, yb


def check():
    ok = True

    def report(cond, msg):
        nonlocal ok
        print(("OK   " if cond else "FAIL ") + msg)
        if not cond:
            ok = False

    report(self_test_mapping(), "face_dir() round-trips through GL spec cube-map selection")

    imgs = {}
    expected_sizes = {"sky_cross.png": (4 * N, 3 * N)}
    names = (["grid_%s.png" % f for f in FACES] + ["sky_%s.png" % f for f in FACES]
             + ["sky_cross.png"])
    for name in names:
        path = os.path.join(OUT_DIR, name)
        try:
            w, h, rows = read_png(path)
        except (OSError, ValueError) as e:
            report(False, "%s: %s" % (name, e))
            continue
        imgs[name] = (w, h, rows)
        ew, eh = expected_sizes.get(name, (N, N))
        report((w, h) == (ew, eh), "%s is %dx%d (expected %dx%d, %d bytes)"
               % (name, w, h, ew, eh, os.path.getsize(path)))
    if not ok:
        return False

    # deterministic: regenerating gives byte-identical files
    regenerated = build()
    same = all(encode_png(*regenerated[n]) == open(os.path.join(OUT_DIR, n), "rb").read()
               for n in names)
    report(same, "files are byte-identical to a fresh in-memory regeneration")

    # grid faces are distinct from each other
    grid_rows = [b"".join(imgs["grid_%s.png" % f][2]) for f in FACES]
    report(len(set(grid_rows)) == 6, "six grid faces are all distinct")

    # cross cells == separate sky faces, unused cells black
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

    # continuity across the 12 cube edges (both directions, every border texel)
    tol = 10
    worst = {}
    sky = {f: imgs["sky_%s.png" % f][2] for f in FACES}
    for fa, xa, ya, fb, xb, yb in edge_pairs():
        pa = sky[fa][ya][xa * 3:xa * 3 + 3]
        pb = sky[fb][yb][xb * 3:xb * 3 + 3]
        diff = max(abs(a - b) for a, b in zip(pa, pb))
        key = tuple(sorted((fa, fb)))
        worst[key] = max(worst.get(key, 0), diff)
    report(len(worst) == 12, "found all 12 cube edges (got %d)" % len(worst))
    for key in sorted(worst):
        report(worst[key] <= tol, "edge %s|%s continuous: max channel diff %d (tol %d)"
               % (key[0], key[1], worst[key], tol))

    # explicit spot-check from the brief: right column of +Z vs left column of +X
    pz, px = sky["pz"], sky["px"]
    d = max(abs(pz[y][(N - 1) * 3 + k] - px[y][k]) for y in range(N) for k in range(3))
    report(d <= tol, "+Z right column vs +X left column: max diff %d" % d)

    # sanity on content: sun is on -Z face (upper left), sky above ground
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

    print("OK" if ok else "FAIL")
    return ok


def main(argv):
    if "--check" in argv[1:]:
        return 0 if check() else 1
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
