// The Web Worker that builds chunks and levels of detail for lod.js, off the page's main thread.
// The building is the C++ the native build runs (core's buildLevels: chunk order and the
// project's simplifier), compiled into a wasm module of its own (lod_module.js, from
// src/platform/web/lod_worker_main.cpp), so the page's levels are native's, triangle for triangle.
// Its heap lives and dies with this worker.
// One message a mesh: { id, positions, vertexFloats, indices, chunks, coarser, settings } ->
// { id, chunks, levels } (or { id, error }); the arrays go back transferred, not copied.
import createLodModule from './lod_module.js';

// The wasm beside this script, wherever the site is served from.
const lodModule = createLodModule({ locateFile: (file) => new URL(file, import.meta.url).href });

// Copies `array` into the module's heap; returns its address (free it with _free).
function toHeap(module, array) {
  const address = module._malloc(Math.max(array.byteLength, 4));
  if (!address) throw new Error('the worker is out of memory');
  new Uint8Array(module.HEAPU8.buffer, address, array.byteLength)
    .set(new Uint8Array(array.buffer, array.byteOffset, array.byteLength));
  return address;
}

// Reads lod_build's block: [levels, then each level's index count, chunk count, indices, chunk
// triangle counts] into [{ indices: Uint32Array (a copy), counts: [triangles a chunk] }].
function readLevels(module, block) {
  const words = new Uint32Array(module.HEAPU8.buffer);  // after the call: the heap may have grown
  let at = block / 4;
  const levels = [];
  for (let level = words[at++]; level > 0; --level) {
    const indexCount = words[at++], chunkCount = words[at++];
    const indices = words.slice(at, at + indexCount);
    at += indexCount;
    levels.push({ indices, counts: Array.from(words.subarray(at, at + chunkCount)) });
    at += chunkCount;
  }
  return levels;
}

// What the worker does with one job: { chunks: { indices, counts } or null, levels: [{ indices,
// counts }] or null }, level 1 simplified from level 0 in chunk order, as natively.
function buildJob(module, { positions, vertexFloats, indices, chunks, coarser, settings }) {
  const vertexCount = positions.length / vertexFloats;
  const vertexAddress = toHeap(module, positions);
  const indexAddress = toHeap(module, indices);
  let block = 0;
  try {
    block = module._lod_build(vertexAddress, vertexCount, vertexFloats, indexAddress, indices.length,
                              chunks ? 1 : 0, coarser ? 1 : 0, settings.maxLevels,
                              settings.triangleRatio, settings.targetError, settings.minTriangles);
    if (!block) throw new Error('the worker could not build the levels (out of memory?)');
    const levels = readLevels(module, block);
    return { chunks: chunks ? levels.shift() : null, levels: coarser ? levels : null };
  } finally {
    module._lod_free(block);
    module._free(indexAddress);
    module._free(vertexAddress);
  }
}

self.onmessage = async ({ data }) => {
  try {
    const result = buildJob(await lodModule, data);
    const transfer = [];
    if (result.chunks) transfer.push(result.chunks.indices.buffer);
    for (const level of result.levels || []) transfer.push(level.indices.buffer);
    self.postMessage({ id: data.id, ...result }, transfer);
  } catch (e) {
    self.postMessage({ id: data.id, error: e.message || String(e) });
  }
};
