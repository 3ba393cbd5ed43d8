// The Web Worker that builds chunks and levels of detail for lod.js, off the page's main thread,
// with npm meshoptimizer (its wasm heap lives and dies with this worker). One message a mesh:
// { id, positions, vertexFloats, indices, chunks, coarser, settings } -> { id, chunks, levels }
// (or { id, error }); the arrays go back transferred, not copied.
import { buildJob } from './lod.js';

const simplifier = import('./vendor/meshopt_simplifier.js').then(async ({ MeshoptSimplifier }) => {
  await MeshoptSimplifier.ready;
  return MeshoptSimplifier;
});

self.onmessage = async ({ data }) => {
  try {
    const result = buildJob(await simplifier, data);
    const transfer = [];
    if (result.chunks) transfer.push(result.chunks.indices.buffer);
    for (const level of result.levels || []) transfer.push(level.indices.buffer);
    self.postMessage({ id: data.id, ...result }, transfer);
  } catch (e) {
    self.postMessage({ id: data.id, error: e.message || String(e) });
  }
};
