"""Grid debug faces: tinted grid, border, big face name and an "up" arrow."""

from .cubemap import FACE_LABEL, N

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
