// A tiny PNG decoder for the screenshots Playwright takes (8-bit greyscale/RGB/RGBA, with or
// without a palette, non-interlaced). No dependencies beyond node:zlib.
import { inflateSync } from 'node:zlib';

const SIGNATURE = [137, 80, 78, 71, 13, 10, 26, 10];

// The chunks a decode needs: the header's fields, the palette and its alphas, the image data.
function readChunks(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const png = { width: 0, height: 0, bitDepth: 0, colourType: 0, interlace: 0,
                palette: null, transparency: null, idat: [] };
  for (let pos = 8; pos + 8 <= bytes.length;) {
    const length = view.getUint32(pos);
    const type = String.fromCharCode(...bytes.subarray(pos + 4, pos + 8));
    const body = bytes.subarray(pos + 8, pos + 8 + length);
    if (type === 'IHDR') {
      png.width = view.getUint32(pos + 8);
      png.height = view.getUint32(pos + 12);
      png.bitDepth = body[8];
      png.colourType = body[9];
      png.interlace = body[12];
    } else if (type === 'PLTE') {
      png.palette = body;
    } else if (type === 'tRNS') {
      png.transparency = body;
    } else if (type === 'IDAT') {
      png.idat.push(body);
    } else if (type === 'IEND') {
      break;
    }
    pos += 12 + length;
  }
  return png;
}

// The scanlines with their filters undone: `channels` bytes a pixel, rows top first.
function unfilter(raw, width, height, channels) {
  const stride = width * channels;
  const pixels = new Uint8Array(height * stride);
  let previous = new Uint8Array(stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const out = pixels.subarray(y * stride, (y + 1) * stride);
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? out[x - channels] : 0;
      const b = previous[x];
      const c = x >= channels ? previous[x - channels] : 0;
      let value = line[x];
      switch (filter) {
        case 0: break;
        case 1: value += a; break;
        case 2: value += b; break;
        case 3: value += (a + b) >> 1; break;
        case 4: {
          const p = a + b - c;
          const pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
          value += pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
          break;
        }
        default: throw new Error(`bad PNG filter ${filter}`);
      }
      out[x] = value & 255;
    }
    previous = out;
  }
  return pixels;
}

// Returns { width, height, data } with data an RGBA Uint8Array (width * height * 4).
export function decodePng(buffer) {
  const bytes = new Uint8Array(buffer.buffer, buffer.byteOffset, buffer.byteLength);
  for (let i = 0; i < 8; ++i) {
    if (bytes[i] !== SIGNATURE[i]) throw new Error('not a PNG file');
  }
  const { width, height, bitDepth, colourType, interlace, palette, transparency, idat } =
    readChunks(bytes);
  if (bitDepth !== 8) throw new Error(`unsupported PNG bit depth ${bitDepth}`);
  if (interlace !== 0) throw new Error('interlaced PNG is not supported');
  const channels = { 0: 1, 2: 3, 3: 1, 4: 2, 6: 4 }[colourType];
  if (!channels) throw new Error(`unsupported PNG colour type ${colourType}`);

  const raw = inflateSync(Buffer.concat(idat.map((c) => Buffer.from(c))));
  const pixels = unfilter(raw, width, height, channels);
  const data = new Uint8Array(width * height * 4);
  for (let i = 0; i < width * height; ++i) {
    const s = i * channels, d = i * 4;
    if (colourType === 0) {
      data[d] = data[d + 1] = data[d + 2] = pixels[s]; data[d + 3] = 255;
    } else if (colourType === 4) {
      data[d] = data[d + 1] = data[d + 2] = pixels[s]; data[d + 3] = pixels[s + 1];
    } else if (colourType === 2) {
      data[d] = pixels[s]; data[d + 1] = pixels[s + 1]; data[d + 2] = pixels[s + 2]; data[d + 3] = 255;
    } else if (colourType === 6) {
      data.set(pixels.subarray(s, s + 4), d);
    } else {
      const index = pixels[s];
      data[d] = palette[index * 3]; data[d + 1] = palette[index * 3 + 1]; data[d + 2] = palette[index * 3 + 2];
      data[d + 3] = transparency && index < transparency.length ? transparency[index] : 255;
    }
  }
  return { width, height, data };
}
