"""Preview rasteriser (orthographic, z-buffer, smooth N.L shading) and its PNG writer."""

import math
import os
import struct
import zlib

from .objio import EXPECT, bbox_of, read_obj
from .vec import IDENTITY, mmul, mvec, rot_x, rot_y, vadd, vdot, vlen, vmul, vnorm, vsub

PALETTE = {
    # mario parts (object names with the _l/_r suffix stripped)
    "shoe": (110, 60, 25), "leg": (40, 70, 200), "overalls": (40, 70, 200), "bib": (40, 70, 200),
    "strap": (40, 70, 200), "pocket": (30, 55, 170), "button": (250, 210, 40),
    "upper_arm": (215, 30, 30), "forearm": (215, 30, 30), "torso": (215, 30, 30),
    "glove_cuff": (245, 245, 245), "glove": (245, 245, 245), "thumb": (245, 245, 245),
    "ear": (250, 195, 150), "head": (250, 195, 150), "nose": (250, 180, 140), "chin": (250, 195, 150),
    "eye": (250, 250, 250), "pupil": (30, 60, 160), "brow": (60, 35, 20), "moustache": (50, 30, 15),
    "hair": (80, 45, 20), "cap": (215, 30, 30), "cap_brim": (200, 25, 25), "cap_emblem": (250, 250, 250),
    # sonic objects
    "Head": (30, 80, 220), "Quills": (30, 80, 220), "Ears": (30, 80, 220), "InnerEars": (240, 190, 140),
    "Eyes": (250, 250, 250), "Pupils": (40, 160, 60), "Muzzle": (240, 190, 140), "Nose": (20, 20, 20),
    "Body": (30, 80, 220), "Belly": (240, 190, 140), "Arms": (240, 190, 140), "Gloves": (250, 250, 250),
    "Shoes": (220, 30, 30), "ShoeTrim": (240, 240, 240),
}


def _color_for(name):
    if name in PALETTE:
        return PALETTE[name]
    base = name.rsplit("_", 1)[0]
    return PALETTE.get(base, (200, 200, 200))


def write_png(path, width, height, rgb_rows):
    def chunk(tag, data):
        c = struct.pack(">I", len(data)) + tag + data
        return c + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + bytes(row) for row in rgb_rows)
    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9))
    png += chunk(b"IEND", b"")
    with open(path, "wb") as fh:
        fh.write(png)


def render_views(path, views, size=256, bg=(235, 235, 235)):
    """views: list of (rotation matrix, tris) where tris = [(color, [(p, n)]*3)] in model space."""
    width = size * len(views)
    img = [[c for _ in range(width) for c in bg] for _ in range(size)]
    light = vnorm((-0.4, 0.6, 1.0))
    for vi, (rot, tris, lo, hi) in enumerate(views):
        # fit the model's bounding sphere in the tile so every view has the same scale
        centre = vmul(vadd(lo, hi), 0.5)
        radius = 0.5 * vlen(vsub(hi, lo))
        scale = (size * 0.48) / radius
        ox = vi * size
        zbuf = [[-math.inf] * size for _ in range(size)]
        for color, corners in tris:
            sp, sn = [], []
            for p, n in corners:
                q = mvec(rot, vsub(p, centre))
                sp.append((size * 0.5 + q[0] * scale, size * 0.5 - q[1] * scale, q[2]))
                sn.append(mvec(rot, n))
            (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = sp
            area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
            if area >= 0.0:  # back-facing (screen y points down, so CCW has area < 0)
                continue
            minx = max(0, int(math.floor(min(x0, x1, x2))))
            maxx = min(size - 1, int(math.ceil(max(x0, x1, x2))))
            miny = max(0, int(math.floor(min(y0, y1, y2))))
            maxy = min(size - 1, int(math.ceil(max(y0, y1, y2))))
            inv = 1.0 / area
            for py in range(miny, maxy + 1):
                cy = py + 0.5
                row = img[py]
                zrow = zbuf[py]
                for px in range(minx, maxx + 1):
                    cx = px + 0.5
                    w0 = ((x1 - cx) * (y2 - cy) - (x2 - cx) * (y1 - cy)) * inv
                    w1 = ((x2 - cx) * (y0 - cy) - (x0 - cx) * (y2 - cy)) * inv
                    w2 = 1.0 - w0 - w1
                    if w0 < 0.0 or w1 < 0.0 or w2 < 0.0:
                        continue
                    z = w0 * z0 + w1 * z1 + w2 * z2
                    if z <= zrow[px]:
                        continue
                    zrow[px] = z
                    n = (
                        w0 * sn[0][0] + w1 * sn[1][0] + w2 * sn[2][0],
                        w0 * sn[0][1] + w1 * sn[1][1] + w2 * sn[2][1],
                        w0 * sn[0][2] + w1 * sn[1][2] + w2 * sn[2][2],
                    )
                    ln = vlen(n) or 1.0
                    shade = 0.28 + 0.72 * max(0.0, vdot(n, light) / ln)
                    k = (ox + px) * 3
                    row[k] = min(255, int(color[0] * shade))
                    row[k + 1] = min(255, int(color[1] * shade))
                    row[k + 2] = min(255, int(color[2] * shade))
    write_png(path, width, size, img)


PREVIEW_VIEWS = [
    ("front", IDENTITY),
    ("side(+x)", rot_y(-90)),
    ("back", rot_y(180)),
    ("3/4", mmul(rot_x(15), rot_y(-35))),
    ("top", rot_x(90)),
]


def preview_models(model_dir, out_dir, size=256):
    os.makedirs(out_dir, exist_ok=True)
    for name in EXPECT:
        pos, nrm, tris = read_obj(os.path.join(model_dir, name))
        lo, hi = bbox_of(pos)
        ctris = [(_color_for(o), [(pos[vi], nrm[ni]) for vi, ni in tri]) for o, tri in tris]
        views = [(rot, ctris, lo, hi) for _, rot in PREVIEW_VIEWS]
        out = os.path.join(out_dir, name.replace(".obj", ".png"))
        render_views(out, views, size)
        print("preview %s (views: %s)" % (out, ", ".join(v for v, _ in PREVIEW_VIEWS)))
