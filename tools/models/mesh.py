"""Mesh containers and the primitives the figures are assembled from.

Unit shapes are generated in local space, then placed with an affine map; DETAIL scales every
tessellation count (see tools/make_models.py --heavy).
"""

import math

from .vec import (IDENTITY, diag, frame_along, mdet, minverse, mmul, mtranspose, mvec, vadd,
                  vlen, vnorm, vsub)


class Part:
    """A primitive: vertices (pos, uv, normal) and faces (tuples of 3 or 4 local indices)."""

    def __init__(self):
        self.pos = []
        self.uv = []
        self.nrm = []
        self.faces = []

    def add_vertex(self, p, uv, n):
        self.pos.append(p)
        self.uv.append(uv)
        self.nrm.append(n)
        return len(self.pos) - 1

    def transformed(self, m, t):
        """Affine transform p -> M p + t, normals by the inverse transpose (det(M) must be > 0)."""
        if mdet(m) <= 0.0:
            raise ValueError("transform must preserve orientation")
        nm = mtranspose(minverse(m))
        out = Part()
        out.pos = [vadd(mvec(m, p), t) for p in self.pos]
        out.uv = list(self.uv)
        out.nrm = [vnorm(mvec(nm, n)) for n in self.nrm]
        out.faces = list(self.faces)
        return out


class Obj:
    """A named OBJ object (`o name` + optional `usemtl`) made of one or more parts."""

    def __init__(self, name, material=None):
        self.name = name
        self.material = material
        self.parts = []


class Model:
    def __init__(self, mtllib=None):
        self.objects = []
        self.mtllib = mtllib

    def obj(self, name, material=None):
        o = Obj(name, material)
        self.objects.append(o)
        return o

    def all_parts(self):
        for o in self.objects:
            for p in o.parts:
                yield p

    def bbox(self):
        lo = [math.inf] * 3
        hi = [-math.inf] * 3
        for p in self.all_parts():
            for q in p.pos:
                for k in range(3):
                    lo[k] = min(lo[k], q[k])
                    hi[k] = max(hi[k], q[k])
        return lo, hi

    def fit_to_box(self, lo_t, hi_t):
        """Per-axis affine map of the whole model onto the exact target box."""
        lo, hi = self.bbox()
        scale = [(hi_t[k] - lo_t[k]) / (hi[k] - lo[k]) for k in range(3)]
        m = diag(*scale)
        t = tuple(lo_t[k] - scale[k] * lo[k] for k in range(3))
        for o in self.objects:
            o.parts = [p.transformed(m, t) for p in o.parts]
        return scale


# --------------------------------------------------------------------------------------
# primitive generators (local unit shapes)
# --------------------------------------------------------------------------------------


def _rows_surface(part, rows, segs):
    """Surface of revolution around +Y from a list of rows (theta, y_offset).

    theta is the polar angle from +Y (0 = top pole, pi = bottom pole); every row is a
    ring of the unit sphere, shifted by y_offset along Y (lets capsules share the code).
    Rows at a pole collapse to a point; faces touching a pole are emitted as triangles,
    all others as quads. Winding is counter-clockwise seen from outside.
    """
    grid = []
    nrows = len(rows)
    for i, (theta, yoff) in enumerate(rows):
        st, ct = math.sin(theta), math.cos(theta)
        pole = st < 1e-9
        row = []
        for j in range(segs + 1):
            # at poles put one vertex per segment (centred in the segment) for nicer uvs
            phi = 2.0 * math.pi * ((j + 0.5) if pole else j) / segs
            if pole:
                st_ = 0.0
                n = (0.0, 1.0 if ct > 0 else -1.0, 0.0)
                p = (0.0, n[1] + yoff, 0.0)
            else:
                st_ = st
                n = (st_ * math.cos(phi), ct, -st_ * math.sin(phi))
                p = (n[0], n[1] + yoff, n[2])
            u = ((j + 0.5) if pole else j) / segs
            v = 1.0 - i / (nrows - 1)
            row.append(part.add_vertex(p, (u, v), n))
        grid.append((row, pole))
    for i in range(nrows - 1):
        top, top_pole = grid[i]
        bot, bot_pole = grid[i + 1]
        for j in range(segs):
            a, b, c, d = top[j], bot[j], bot[j + 1], top[j + 1]
            if top_pole and bot_pole:
                continue
            if top_pole:
                part.faces.append((a, b, c))
            elif bot_pole:
                part.faces.append((a, b, d))
            else:
                part.faces.append((a, b, c, d))


def _disc(part, y, radius, segs, up):
    """Flat disc at height y facing +Y (up=True) or -Y."""
    n = (0.0, 1.0 if up else -1.0, 0.0)
    centre = part.add_vertex((0.0, y, 0.0), (0.5, 0.5), n)
    ring = []
    for j in range(segs):
        phi = 2.0 * math.pi * j / segs
        x, z = radius * math.cos(phi), -radius * math.sin(phi)
        ring.append(part.add_vertex((x, y, z), (0.5 + 0.5 * math.cos(phi), 0.5 + 0.5 * math.sin(phi)), n))
    for j in range(segs):
        a, b = ring[j], ring[(j + 1) % segs]
        part.faces.append((centre, a, b) if up else (centre, b, a))


# Tessellation multiplier: 1 for the shipped models; --heavy raises it to write a figure with the
# triangle count of the course's mario.obj (about 145k) for benchmarks.
DETAIL = 1.0


def _fine(n, minimum=3):
    return max(minimum, int(round(n * DETAIL)))


def unit_sphere(segs, rings):
    segs, rings = _fine(segs), _fine(rings, 2)
    part = Part()
    _rows_surface(part, [(math.pi * i / rings, 0.0) for i in range(rings + 1)], segs)
    return part


def unit_dome(segs, rings):
    """Upper hemisphere (y >= 0) closed by a flat disc at y = 0."""
    segs, rings = _fine(segs), _fine(rings, 1)
    part = Part()
    _rows_surface(part, [(0.5 * math.pi * i / rings, 0.0) for i in range(rings + 1)], segs)
    _disc(part, 0.0, 1.0, segs, up=False)
    return part


def unit_capsule(half_len, segs, rings):
    """Radius-1 capsule along Y with hemisphere centres at y = 0 and y = 2*half_len."""
    segs, rings = _fine(segs), _fine(rings, 2)
    half = rings // 2
    rows = [(0.5 * math.pi * i / half, 2.0 * half_len) for i in range(half + 1)]
    rows += [(0.5 * math.pi + 0.5 * math.pi * i / half, 0.0) for i in range(half + 1)]
    part = Part()
    _rows_surface(part, rows, segs)
    return part


def unit_frustum(r0, r1, segs, caps=True):
    """Cylinder / cone frustum along Y from y=0 (radius r0) to y=1 (radius r1)."""
    segs = _fine(segs)
    part = Part()
    slope = r0 - r1
    rows = []
    for y, r in ((0.0, r0), (1.0, r1)):
        row = []
        for j in range(segs + 1):
            if r == 0.0:
                phi = 2.0 * math.pi * (j + 0.5) / segs
            else:
                phi = 2.0 * math.pi * j / segs
            n = vnorm((math.cos(phi), slope, -math.sin(phi)))
            p = (r * math.cos(phi), y, -r * math.sin(phi))
            row.append(part.add_vertex(p, (j / segs, y), n))
        rows.append(row)
    bot, top = rows
    for j in range(segs):
        a, b, c, d = bot[j], bot[j + 1], top[j + 1], top[j]
        if r1 == 0.0:
            part.faces.append((a, b, d))
        elif r0 == 0.0:
            part.faces.append((a, c, d))
        else:
            part.faces.append((a, b, c, d))
    if caps:
        if r0 > 0.0:
            _disc(part, 0.0, r0, segs, up=False)
        if r1 > 0.0:
            _disc(part, 1.0, r1, segs, up=True)
    return part


def unit_box():
    """Cube -1..1 with flat normals, 6 quads."""
    part = Part()
    # (normal, u axis, v axis): u x v = normal so the quad is CCW from outside
    faces = [
        ((1, 0, 0), (0, 0, -1), (0, 1, 0)),
        ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 1, 0), (1, 0, 0), (0, 0, -1)),
        ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
        ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
    ]
    for n, u, v in faces:
        idx = []
        for su, sv, uv in ((-1, -1, (0, 0)), (1, -1, (1, 0)), (1, 1, (1, 1)), (-1, 1, (0, 1))):
            p = tuple(float(n[k] + su * u[k] + sv * v[k]) for k in range(3))
            idx.append(part.add_vertex(p, (float(uv[0]), float(uv[1])), tuple(float(c) for c in n)))
        part.faces.append(tuple(idx))
    return part


# --------------------------------------------------------------------------------------
# placed primitives (world space)
# --------------------------------------------------------------------------------------


def ellipsoid(centre, radii, rot=IDENTITY, segs=20, rings=12):
    return unit_sphere(segs, rings).transformed(mmul(rot, diag(*radii)), centre)


def dome(centre, radii, rot=IDENTITY, segs=24, rings=8):
    return unit_dome(segs, rings).transformed(mmul(rot, diag(*radii)), centre)


def capsule(a, b, radius, segs=16, rings=8):
    """Capsule between points a and b."""
    axis = vsub(b, a)
    length = vlen(axis)
    part = unit_capsule(0.5 * length / radius, segs, rings)
    m = mmul(frame_along(axis), diag(radius, radius, radius))
    return part.transformed(m, a)


def frustum(a, b, r0, r1, segs=16, caps=True):
    """Cylinder/cone from point a (radius r0) to point b (radius r1)."""
    axis = vsub(b, a)
    length = vlen(axis)
    part = unit_frustum(r0, r1, segs, caps)
    m = mmul(frame_along(axis), diag(1.0, length, 1.0))
    return part.transformed(m, a)


def disc_cyl(centre, radii, thickness, rot=IDENTITY, segs=28):
    """Thin elliptical disc (closed cylinder) of given x/z radii centred at `centre`."""
    part = unit_frustum(1.0, 1.0, segs, caps=True)
    m = mmul(rot, diag(radii[0], thickness, radii[1]))
    t = vadd(centre, mvec(rot, (0.0, -0.5 * thickness, 0.0)))
    return part.transformed(m, t)


def ellipsoid_point(s, alpha_deg):
    """Unit-sphere point parametrised around the X axis: x = s, alpha = angle from +Y toward +Z."""
    a = math.radians(alpha_deg)
    c = math.sqrt(max(0.0, 1.0 - s * s))
    return (s, c * math.cos(a), c * math.sin(a))


def on_ellipsoid(centre, radii, s, alpha_deg, inflate=1.0):
    p = ellipsoid_point(s, alpha_deg)
    return tuple(centre[k] + radii[k] * inflate * p[k] for k in range(3))


def ellipsoid_patch(centre, radii, s_range, a_range, ns, na, inflate=1.03):
    """Open surface patch hugging an ellipsoid (used for the overall bib and straps)."""
    ns, na = _fine(ns, 1), _fine(na, 1)
    part = Part()
    grid = []
    for i in range(ns + 1):
        sv = s_range[0] + (s_range[1] - s_range[0]) * i / ns
        row = []
        for j in range(na + 1):
            av = a_range[0] + (a_range[1] - a_range[0]) * j / na
            n = ellipsoid_point(sv, av)
            row.append(part.add_vertex(n, (i / ns, j / na), n))
        grid.append(row)
    for i in range(ns):
        for j in range(na):
            part.faces.append((grid[i][j], grid[i][j + 1], grid[i + 1][j + 1], grid[i + 1][j]))
    return part.transformed(diag(*(r * inflate for r in radii)), centre)
