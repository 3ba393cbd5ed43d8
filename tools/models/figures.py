"""The shipped models: the course's icosphere, quad and cube, and the two original figures."""

import math

from .mesh import (Model, Part, capsule, disc_cyl, dome, ellipsoid, ellipsoid_patch,
                   ellipsoid_point, frustum, on_ellipsoid, unit_box)
from .vec import (IDENTITY, frame_along, mvec, rot_x, rot_y, rot_z, vadd, vmul, vnorm, vsub)


def build_sphere():
    """Icosphere: icosahedron subdivided twice (162 vertices, 320 triangles)."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [
        (-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0),
        (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
        (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1),
    ]
    verts = [vnorm(tuple(float(c) for c in v)) for v in verts]
    faces = [
        (0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
        (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
        (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
        (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1),
    ]
    for _ in range(2):
        cache = {}

        def mid(i, j):
            key = (min(i, j), max(i, j))
            if key not in cache:
                verts.append(vnorm(vmul(vadd(verts[i], verts[j]), 0.5)))
                cache[key] = len(verts) - 1
            return cache[key]

        new_faces = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    radius, centre = 2.5456, (0.0, 0.5, 0.0)
    part = Part()
    for n in verts:
        u = 0.5 + math.atan2(n[0], n[2]) / (2.0 * math.pi)
        v = 0.5 + math.asin(max(-1.0, min(1.0, n[1]))) / math.pi
        part.add_vertex(vadd(vmul(n, radius), centre), (u, v), n)
    part.faces = faces
    model = Model()
    model.obj("sphere").parts.append(part)
    return model


def build_quad():
    part = Part()
    n = (0.0, 1.0, 0.0)
    for x, z, uv in ((-1, 1, (0, 0)), (1, 1, (1, 0)), (1, -1, (1, 1)), (-1, -1, (0, 1))):
        part.add_vertex((float(x), 0.0, float(z)), (float(uv[0]), float(uv[1])), n)
    part.faces = [(0, 1, 2), (0, 2, 3)]
    model = Model()
    model.obj("quad").parts.append(part)
    return model


def build_cube():
    part = unit_box()
    part.faces = [t for q in part.faces for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    model = Model()
    model.obj("cube").parts.append(part)
    return model


MARIO_BOX = ((-42.9, -65.3, -29.4), (39.2, 60.5, 28.1))
SONIC_BOX = ((-7.6, -0.1, -10.6), (11.0, 30.7, 7.3))


TORSO_C, TORSO_R = (0.0, 0.35, 0.0), (2.15, 2.05, 1.8)


def build_mario():
    """Plumber stand-in. Built in a local unit (~1/10 of the final size), then fitted."""
    m = Model()

    def add(name, part):
        m.obj(name).parts.append(part)

    for side, sx in (("l", -1.0), ("r", 1.0)):
        # shoes: long rounded boots pointing forward, flat-ish
        add("shoe_" + side, ellipsoid((sx * 1.05, -5.95, 0.55), (0.95, 0.6, 1.45), rot_x(-6), 16, 10))
        # legs (overall trousers)
        add("leg_" + side, capsule((sx * 1.0, -5.5, 0.05), (sx * 0.95, -2.4, 0.0), 0.82, 16, 8))
        # arms: upper arm + forearm (shirt sleeves)
        sh, el, wr = (sx * 2.0, 1.0, 0.0), (sx * 3.05, -0.55, 0.35), (sx * 3.45, -1.95, 0.75)
        add("upper_arm_" + side, capsule(sh, el, 0.62, 14, 8))
        add("forearm_" + side, capsule(el, wr, 0.58, 14, 8))
        # gloves: a cuff, the fist and a thumb
        add("glove_cuff_" + side, frustum((sx * 3.42, -1.85, 0.72), (sx * 3.58, -2.35, 0.85), 0.62, 0.72, 16))
        add("glove_" + side, ellipsoid((sx * 3.62, -2.85, 0.9), (0.72, 0.78, 0.72), rot_z(sx * 10), 14, 8))
        add("thumb_" + side, capsule((sx * 3.25, -2.55, 1.35), (sx * 3.05, -2.2, 1.55), 0.24, 10, 6))
        # overall straps over the shoulders, hugging the torso from the bib to the back
        s_rng = (0.34, 0.5) if sx > 0 else (-0.5, -0.34)
        add("strap_" + side, ellipsoid_patch(TORSO_C, TORSO_R, s_rng, (-128.0, 74.0), 2, 24, 1.045))
        # buttons where the straps meet the bib
        bc = on_ellipsoid(TORSO_C, TORSO_R, sx * 0.42, 76.0, 1.06)
        add("button_" + side, ellipsoid(bc, (0.24, 0.24, 0.12), rot_x(-14), 12, 6))
        # ears, eyes, moustache halves
        add("ear_" + side, ellipsoid((sx * 1.72, 3.75, 0.0), (0.28, 0.48, 0.36), IDENTITY, 10, 6))
        add("eye_" + side, ellipsoid((sx * 0.52, 4.3, 1.6), (0.24, 0.42, 0.16), rot_y(sx * 18), 12, 8))
        add("pupil_" + side, ellipsoid((sx * 0.47, 4.25, 1.72), (0.12, 0.24, 0.07), rot_y(sx * 18), 10, 6))
        add("brow_" + side, capsule((sx * 0.25, 4.85, 1.65), (sx * 0.8, 4.8, 1.5), 0.1, 8, 4))
        add("moustache_" + side, ellipsoid((sx * 0.55, 3.15, 1.72), (0.75, 0.32, 0.38), rot_z(sx * 14), 14, 8))

    # overall shorts/pelvis and torso
    add("overalls", ellipsoid((0.0, -1.75, 0.0), (2.05, 1.55, 1.75), IDENTITY, 20, 12))
    add("torso", ellipsoid(TORSO_C, TORSO_R, IDENTITY, 20, 12))
    add("bib", ellipsoid_patch(TORSO_C, TORSO_R, (-0.5, 0.5), (70.0, 128.0), 8, 8, 1.035))
    add("pocket", ellipsoid_patch(TORSO_C, TORSO_R, (-0.2, 0.2), (88.0, 104.0), 3, 3, 1.045))
    # head
    add("head", ellipsoid((0.0, 3.85, 0.05), (1.72, 1.78, 1.68), IDENTITY, 24, 14))
    add("hair", ellipsoid((0.0, 3.6, -0.55), (1.7, 1.2, 1.3), IDENTITY, 16, 8))
    add("nose", ellipsoid((0.0, 3.7, 1.95), (0.66, 0.55, 0.62), IDENTITY, 14, 8))
    add("chin", ellipsoid((0.0, 2.75, 1.05), (1.0, 0.55, 0.7), IDENTITY, 14, 8))
    # cap: dome, brim disc and a white emblem disc
    cap_c, cap_r, cap_rot = (0.0, 4.55, -0.05), (1.88, 1.55, 1.88), rot_x(-12)
    add("cap", dome(cap_c, cap_r, cap_rot, 24, 8))
    add("cap_brim", disc_cyl((0.0, 4.86, 1.45), (1.42, 1.05), 0.2, rot_x(-10), 24))
    # white emblem disc sitting on the front of the dome, facing along the surface normal
    d = ellipsoid_point(0.0, 66.0)
    e_pos = vadd(cap_c, mvec(cap_rot, tuple(cap_r[k] * d[k] for k in range(3))))
    e_nrm = vnorm(mvec(cap_rot, tuple(d[k] / cap_r[k] for k in range(3))))
    add("cap_emblem", disc_cyl(vadd(e_pos, vmul(e_nrm, 0.03)), (0.5, 0.5), 0.14, frame_along(e_nrm), 20))

    lo, hi = m.bbox()
    scale = m.fit_to_box(*MARIO_BOX)
    return m, (lo, hi, scale)


def build_sonic():
    """Hedgehog stand-in, built directly in roughly the final units, then fitted.

    13 `o` objects, each with a `usemtl` (sonic.mtl is deliberately not shipped).
    """
    m = Model(mtllib="sonic.mtl")
    # objects are written in the order they are created: head, face, then body
    _sonic_head(m)
    _sonic_face(m)
    _sonic_body(m)

    lo, hi = m.bbox()
    scale = m.fit_to_box(*SONIC_BOX)
    return m, (lo, hi, scale)


def _sonic_head(m):
    """Head, the quills behind it and the ears (InnerEars holds their skin-coloured insides)."""
    head_c = (0.0, 20.0, -0.5)
    head_r = 6.3

    head = m.obj("Head", "blue_fur")
    head.parts.append(ellipsoid(head_c, (head_r, head_r * 0.98, head_r * 0.95), IDENTITY, 24, 14))

    # quills: big cones sweeping backwards (-Z) and down from the back of the head
    o = m.obj("Quills", "blue_fur")
    # (elevation deg, azimuth deg (0 = straight back, + = toward +x), base radius, length)
    quills = [
        (58.0, 0.0, 2.5, 8.0),
        (28.0, -30.0, 2.6, 8.5),
        (28.0, 30.0, 2.6, 8.5),
        (12.0, 0.0, 3.0, 10.5),
        (-12.0, -34.0, 2.6, 9.0),
        (-12.0, 34.0, 2.6, 9.0),
        (-22.0, 0.0, 2.8, 10.0),
        (-42.0, -18.0, 2.3, 7.5),
        (-42.0, 18.0, 2.3, 7.5),
    ]
    for elev, azim, r0, length in quills:
        e, a = math.radians(elev), math.radians(azim)
        d = (math.cos(e) * math.sin(a), math.sin(e), -math.cos(e) * math.cos(a))
        base = vadd(head_c, vmul(d, head_r * 0.5))
        # bend every tip backwards and down so the spikes read as swept back
        tip_dir = vnorm(vadd(d, (0.0, -0.45, -0.6)))
        tip = vadd(base, vmul(tip_dir, length))
        o.parts.append(frustum(base, tip, r0, 0.0, 12, caps=True))

    # ears: blue cones (part of the Head object) with skin-coloured inner cones
    o2 = m.obj("InnerEars", "skin")
    for sx in (-1.0, 1.0):
        base = (sx * 3.4, 24.2, -1.3)
        tip = (sx * 4.6, 28.6, -2.3)
        head.parts.append(frustum(base, tip, 1.6, 0.0, 12))
        o2.parts.append(frustum((sx * 3.45, 24.6, -0.5), (sx * 4.45, 27.9, -1.55), 0.95, 0.0, 10))


def _sonic_face(m):
    """Eyes, pupils, muzzle and nose."""
    o = m.obj("Eyes", "eye_white")
    for sx in (-1.0, 1.0):
        o.parts.append(ellipsoid((sx * 1.5, 21.4, 4.6), (1.8, 2.6, 1.9), rot_z(sx * -8), 14, 10))
    o = m.obj("Pupils", "eye_green")
    for sx in (-1.0, 1.0):
        o.parts.append(ellipsoid((sx * 1.15, 21.2, 6.35), (0.65, 1.2, 0.35), rot_y(sx * 14), 10, 6))

    o = m.obj("Muzzle", "skin")
    o.parts.append(ellipsoid((0.0, 17.5, 3.9), (3.3, 2.4, 2.9), IDENTITY, 18, 10))
    o = m.obj("Nose", "black")
    o.parts.append(ellipsoid((0.0, 19.0, 6.75), (0.8, 0.62, 0.6), IDENTITY, 10, 6))


def _sonic_body(m):
    """Body with its legs, belly, arms, gloves and shoes."""
    body = m.obj("Body", "blue_fur")
    body.parts.append(ellipsoid((0.0, 10.0, -0.4), (2.9, 3.6, 2.7), IDENTITY, 18, 10))
    o = m.obj("Belly", "skin")
    o.parts.append(ellipsoid((0.0, 9.7, 0.9), (2.1, 2.8, 1.9), IDENTITY, 18, 10))

    o = m.obj("Arms", "skin")
    g = m.obj("Gloves", "glove_white")
    # left arm hangs down, right arm raised outwards (gives the asymmetric x extents)
    arms = [((-2.6, 12.0, -0.3), (-4.6, 9.9, 0.4), (-5.6, 7.8, 1.0)),
            ((2.6, 12.0, -0.3), (5.4, 13.5, 0.2), (8.2, 15.6, 0.8))]
    for sh, el, wr in arms:
        o.parts.append(capsule(sh, el, 0.55, 12, 6))
        o.parts.append(capsule(el, wr, 0.52, 12, 6))
        d = vnorm(vsub(wr, el))
        hand = vadd(wr, vmul(d, 1.2))
        g.parts.append(frustum(vadd(wr, vmul(d, -0.2)), vadd(wr, vmul(d, 0.5)), 0.95, 1.0, 12))
        g.parts.append(ellipsoid(hand, (1.25, 1.25, 1.15), frame_along(d), 12, 8))

    shoes = m.obj("Shoes", "shoe_red")
    trim = m.obj("ShoeTrim", "shoe_white")
    for sx in (-1.0, 1.0):
        # thin legs belong to the Body object
        body.parts.append(capsule((sx * 1.35, 2.2, -0.3), (sx * 1.2, 7.2, -0.4), 0.62, 12, 6))
        shoes.parts.append(ellipsoid((sx * 2.0, 1.45, 1.0), (1.9, 1.45, 3.4), rot_y(sx * 8), 16, 10))
        # white strap across the shoe, sock cuff at the ankle and a flat sole
        trim.parts.append(ellipsoid((sx * 1.98, 1.75, 1.1), (1.97, 1.32, 0.6), rot_y(sx * 8), 14, 6))
        trim.parts.append(frustum((sx * 1.6, 2.0, -0.6), (sx * 1.5, 3.0, -0.5), 1.0, 0.85, 14))
        trim.parts.append(ellipsoid((sx * 2.0, 0.35, 1.0), (1.75, 0.45, 3.25), rot_y(sx * 8), 16, 6))
