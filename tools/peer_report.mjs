// tools/peer_bench.mjs's tables: per page the medians over the rounds of each round's figures,
// the frame and the load split into their parts, the floor (the scene with its mirror as a Phong
// object), and each project page against the peers.
import { summary } from './bench_lib.mjs';

export const fmt = (x, width = 9) => (Number.isFinite(x) ? x.toFixed(1) : 'n/a').padStart(width);
const median = (values) => summary(values.filter(Number.isFinite)).median;
const medianOr = (values) => (values.some(Number.isFinite) ? median(values) : NaN);

// A page's load in spans (ms): code (the project: the wasm module fetched, compiled, instantiated
// and its runtime up, at the wasm-ready mark; the peers: three.js and the page's modules fetched
// and run, at peer:script-start), models (fetched and parsed, from there), BVH (the project: the
// commit's trees; the peers: the rendition made, three-mesh-bvh's trees on the bvh page), the
// rest of the scene's setup (the project's commit without its trees), first draw (from there to
// the first draw call into the canvas), and shaders (the main thread's time inside compile and
// link calls before the first draw, wherever in the load they fell). wasm: the module's
// instantiateStreaming, from its call to its end (its fetch and compile, which overlap).
export function loadSpans(l, peer) {
  if (peer) {
    return { total: l.firstDraw, code: l.scriptStart, models: l.peerModelsIn - l.scriptStart,
             bvh: l.renditionMade - l.peerModelsIn, setup: 0, first: l.firstDraw - l.renditionMade,
             shaders: l.shaderMs, wasm: NaN };
  }
  return { total: l.firstDraw, code: l.wasmReady, models: l.modelsIn - l.wasmReady, bvh: l.bvhMs,
           setup: l.committed - l.modelsIn - l.bvhMs, first: l.firstDraw - l.committed, shaders: l.shaderMs,
           wasm: l.wasmEnd - l.wasmStart };
}

// One row a page: medians over the rounds of each round's median (frame and its parts) and load.
export function pageRows(pages, samples) {
  return pages.map((spec) => {
    const s = samples.get(spec.key);
    const split = (key) => medianOr(s.map((r) => r.split[key]));
    const spans = s.map((r) => loadSpans(r.load, spec.peer));
    const load = Object.fromEntries(Object.keys(spans[0]).map((k) => [k, medianOr(spans.map((x) => x[k]))]));
    return { spec, frame: median(s.map((r) => r.frame.median)), p10: median(s.map((r) => r.frame.p10)),
             p90: median(s.map((r) => r.frame.p90)), capture: split('capture'), main: split('main'),
             cpu: split('cpu'), traced: split('traced'), gpu: split('gpu'), load };
  });
}

// The floor a page is measured against: the project's plain page for the project's pages, the
// three.js plain page for the peers.
const floorOf = (row, rows) => rows.find((r) => r.spec.plain && !!r.spec.peer === !!row.spec.peer);

export function printTables(rows, o, title = '') {
  const heading = title ? `${title}: ` : '';
  console.log('');
  console.log(`${heading}medians over ${o.rounds} round(s) of each round's median; frame ms (one read-back at`);
  console.log('  its end on every page), then its parts (from frames with a read-back after each pass):');
  console.log('  capture: from the frame\'s start to its captures\' end, the GPU waited for (the project\'s');
  console.log('    captureMs, which includes its plan; the CubeCamera\'s update() and a read-back, in frames');
  console.log('    drawn apart with frameSplit); main: the rest, the main pass (a traced mirror\'s trace runs');
  console.log('    inside it), the GPU waited for; trace: main less the floor\'s main pass, on pages that');
  console.log('    trace; CPU: the frame less its time inside finish/readPixels (the page\'s own thread:');
  console.log('    JS, wasm, GL calls handed to the GPU process; SwiftShader rasterises there, beside it)');
  console.log(`${'page'.padEnd(28)}${'frame'.padStart(8)}${'p10'.padStart(8)}${'p90'.padStart(8)}` +
              `${'capture'.padStart(9)}${'main'.padStart(8)}${'trace'.padStart(8)}${'CPU'.padStart(8)}` +
              `${'x floor'.padStart(9)}`);
  for (const r of rows) {
    const floor = floorOf(r, rows);
    const traces = r.spec.peer ? r.spec.key === 'bvh' : r.traced > 0;
    const trace = traces && floor ? r.main - floor.main : NaN;
    console.log(`${r.spec.label.padEnd(28)}${fmt(r.frame, 8)}${fmt(r.p10, 8)}${fmt(r.p90, 8)}${fmt(r.capture, 9)}` +
                `${fmt(r.main, 8)}${fmt(trace, 8)}${fmt(r.cpu, 8)}` +
                `${(floor && !r.spec.plain ? `${(r.frame / floor.frame).toFixed(2)}x` : '').padStart(9)}`);
  }
  const gpuTimed = rows.filter((r) => r.gpu > 0);
  if (!gpuTimed.length) console.log('  (no GPU timer queries here: EXT_disjoint_timer_query_webgl2 is absent, gpuFrameMs -1)');
  console.log('');
  console.log(`${heading}load to first frame, ms (spans; code: the wasm ready / three.js run, from navigation start):`);
  console.log(`${'page'.padEnd(28)}${'load'.padStart(8)}${'code'.padStart(8)}${'(wasm)'.padStart(8)}${'models'.padStart(8)}` +
              `${'BVH'.padStart(8)}${'setup'.padStart(8)}${'1st draw'.padStart(9)}${'shaders'.padStart(9)}`);
  for (const r of rows) {
    const l = r.load;
    console.log(`${r.spec.label.padEnd(28)}${fmt(l.total, 8)}${fmt(l.code, 8)}${fmt(l.wasm, 8)}${fmt(l.models, 8)}` +
                `${fmt(l.bvh, 8)}${fmt(l.setup, 8)}${fmt(l.first, 9)}${fmt(l.shaders, 9)}`);
  }
  const floors = rows.filter((r) => r.spec.plain);
  if (floors.length) {
    console.log('');
    console.log(`${heading}the floor, the main pass alone (the scene with its mirror a Phong object: no capture, no`);
    console.log('trace), which every method pays, whatever it does for the reflection: ' +
                floors.map((r) => `${r.spec.label} ${r.frame.toFixed(1)} ms`).join('; '));
  }
  const peers = rows.filter((r) => r.spec.peer && !r.spec.plain);
  const projects = rows.filter((r) => !r.spec.peer && !r.spec.plain);
  if (peers.length && projects.length) {
    console.log('');
    console.log(`${heading}project pages against the peers (x the peer's: frame, load to first frame):`);
    for (const r of projects) {
      console.log(`${r.spec.label.padEnd(28)}` + peers.map((p) => `vs ${p.spec.key}: ` +
        `frame ${(r.frame / p.frame).toFixed(2)}x, load ${(r.load.total / p.load.total).toFixed(2)}x`).join('; '));
    }
  }
}

// --both: the two scenes' rows together, each against its own CubeCamera page.
export function printBoth(light, heavy) {
  console.log('both scenes (frame ms, its capture and main parts; load ms; x the CubeCamera page\'s):');
  for (const [name, rows] of [['shipped', light], ['heavy', heavy]]) {
    const peer = rows.find((r) => r.spec.key === 'cubecamera');
    for (const r of rows) {
      console.log(`${name.padEnd(8)}${r.spec.label.padEnd(28)}${fmt(r.frame, 8)}${fmt(r.capture, 8)}${fmt(r.main, 8)}` +
                  `${fmt(r.load.total, 8)}` + (peer && r !== peer
        ? `   frame ${(r.frame / peer.frame).toFixed(2)}x, load ${(r.load.total / peer.load.total).toFixed(2)}x` : ''));
    }
  }
}
