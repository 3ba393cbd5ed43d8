"""PNG writer / reader (8-bit RGB, filter "Up" on every row)."""

import struct
import zlib

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
