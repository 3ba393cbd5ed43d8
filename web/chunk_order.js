// Chunks: a mesh's triangles reordered into pieces of nearby triangles, by recursive median splits
// of triangle centres along the longest axis, exactly as src/core/mesh_chunks.cpp makes them
// (float centres, ties broken by triangle number, the mesh's order within a chunk), so that the
// levels simplified from the result are native's. Used by lod.js in the page's worker.

// Rearranges order[begin..end) so that order[middle] has the triangle it would have sorted,
// smaller before it and larger after (std::nth_element), by key and then triangle number: a total
// order, so the split is mesh_chunks.cpp's whatever the implementation.
function nthElement(order, keys, begin, end, middle) {
  const less = (s, t) => keys[s] < keys[t] || (keys[s] === keys[t] && s < t);
  let lo = begin, hi = end - 1;
  while (hi > lo) {
    // Median of three as the pivot.
    const a = order[lo], b = order[(lo + hi) >> 1], c = order[hi];
    const pivot = less(a, b) ? (less(b, c) ? b : (less(a, c) ? c : a)) : (less(a, c) ? a : (less(b, c) ? c : b));
    let i = lo, j = hi;
    while (i <= j) {
      while (less(order[i], pivot)) ++i;
      while (less(pivot, order[j])) --j;
      if (i <= j) {
        const t = order[i];
        order[i] = order[j];
        order[j] = t;
        ++i;
        --j;
      }
    }
    if (middle <= j) hi = j;
    else if (middle >= i) lo = i;
    else return;
  }
}

// `indices` (triangles over `positions`, `stride` floats a vertex) reordered into chunks of at
// most `maxTriangles` nearby triangles: { indices: Uint32Array, counts: [triangles a chunk] }.
export function chunkOrder(positions, stride, indices, maxTriangles) {
  const triangles = indices.length / 3;
  const centres = [new Float32Array(triangles), new Float32Array(triangles), new Float32Array(triangles)];
  for (let t = 0; t < triangles; ++t) {
    for (let axis = 0; axis < 3; ++axis) {
      // In float steps, as (a + b + c) / 3.0f in C++: the same keys, the same split.
      const f = Math.fround;
      centres[axis][t] = f(f(f(positions[indices[t * 3] * stride + axis] + positions[indices[t * 3 + 1] * stride + axis]) +
                             positions[indices[t * 3 + 2] * stride + axis]) / 3);
    }
  }
  const order = new Uint32Array(triangles);
  for (let t = 0; t < triangles; ++t) order[t] = t;
  const counts = [];
  const split = (begin, end) => {
    if (end - begin <= maxTriangles) {
      order.subarray(begin, end).sort();  // the mesh's order within a chunk, as natively
      if (end > begin) counts.push(end - begin);
      return;
    }
    const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
    for (let i = begin; i < end; ++i) {
      for (let axis = 0; axis < 3; ++axis) {
        const v = centres[axis][order[i]];
        if (v < min[axis]) min[axis] = v;
        if (v > max[axis]) max[axis] = v;
      }
    }
    const extent = [0, 1, 2].map((k) => Math.fround(max[k] - min[k]));  // float, as natively
    const axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : (extent[1] >= extent[2] ? 1 : 2);
    const middle = begin + Math.floor((end - begin) / 2);
    nthElement(order, centres[axis], begin, end, middle);
    split(begin, middle);
    split(middle, end);
  };
  split(0, triangles);
  const reordered = new Uint32Array(indices.length);
  for (let t = 0; t < triangles; ++t) {
    const from = order[t] * 3;
    reordered[t * 3] = indices[from];
    reordered[t * 3 + 1] = indices[from + 1];
    reordered[t * 3 + 2] = indices[from + 2];
  }
  return { indices: reordered, counts };
}
