"""Procedural sky faces (gradient, ground, horizon haze, sun) and the horizontal cross."""

import math

from .cubemap import CROSS_CELL, FACES, N, face_dir, texel_st
from .grid import make_grid_face

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
