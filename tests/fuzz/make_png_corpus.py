#!/usr/bin/env python3
"""Writes the fuzz_png seed corpus (corpus/png/): tiny PNGs of each colour type and bit depth,
an interlaced one, a palette one with transparency, and a truncated one. Standard library only:
zlib for IDAT, struct for chunks. Run once; the files are committed."""
import os
import struct
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "png")


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]


def adam7(rows, width, height, bytes_per_pixel):
    """8-bit rows (filter 0) reordered into the seven reduced images of Adam7 interlacing."""
    raw = b""
    for x0, y0, dx, dy in ADAM7:
        xs, ys = range(x0, width, dx), range(y0, height, dy)
        if not xs or not ys:
            continue  # an empty pass has no rows at all
        for y in ys:
            raw += b"\x00" + b"".join(rows[y][x * bytes_per_pixel:(x + 1) * bytes_per_pixel] for x in xs)
    return raw


def png(width, height, depth, colour_type, rows, interlace=0, extra=b""):
    ihdr = struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, interlace)
    if interlace:
        raw = adam7(rows, width, height, {0: 1, 2: 3, 4: 2, 6: 4}[colour_type])
    else:
        raw = b"".join(b"\x00" + row for row in rows)  # filter 0 on every row
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + extra +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def write(name, data):
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)


def main():
    os.makedirs(OUT, exist_ok=True)
    write("rgba_1x1.png", png(1, 1, 8, 6, [bytes([255, 0, 0, 255])]))
    write("rgb_2x2.png", png(2, 2, 8, 2, [bytes([0, 255, 0, 0, 0, 255]), bytes([9, 9, 9, 200, 100, 50])]))
    write("grey_3x2.png", png(3, 2, 8, 0, [bytes([0, 128, 255]), bytes([1, 2, 3])]))
    write("grey_alpha_2x1.png", png(2, 1, 8, 4, [bytes([10, 255, 20, 0])]))
    write("grey_1bit_9x1.png", png(9, 1, 1, 0, [bytes([0b10101010, 0b10000000])]))
    palette = chunk(b"PLTE", bytes([255, 0, 0, 0, 255, 0, 0, 0, 255])) + chunk(b"tRNS", bytes([255, 128]))
    write("palette_4x2.png", png(4, 2, 2, 3, [bytes([0b00011000]), bytes([0b10010010])], extra=palette))
    write("rgba16_1x2.png", png(1, 2, 16, 6, [bytes(range(8)), bytes(range(8, 16))]))
    rows = [bytes((x * 40 + y * 20) % 256 for x in range(5 * 3)) for y in range(5)]
    write("rgb_interlaced_5x5.png", png(5, 5, 8, 2, rows, interlace=1))
    whole = png(4, 4, 8, 6, [bytes(range(16 * y, 16 * y + 16)) for y in range(4)])
    write("truncated_4x4.png", whole[: len(whole) - 20])  # IDAT cut short, no IEND


if __name__ == "__main__":
    main()
