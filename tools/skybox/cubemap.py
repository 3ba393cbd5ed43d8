"""Cube-map face layout and the GL convention's mapping between texels and directions.

The orientation is described in tools/make_skybox.py's docstring.
"""

import math

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


def self_test_mapping():
    """Round-trip every face mapping through the GL spec selection formula."""
    for face in FACES:
        for s, t in ((-0.9, -0.3), (0.2, 0.7), (0.5, -0.5), (0.0, 0.0)):
            f2, s2, t2 = dir_to_face_st(face_dir(face, s, t))
            if f2 != face or abs(s2 - s) > 1e-12 or abs(t2 - t) > 1e-12:
                return False
    return True



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
