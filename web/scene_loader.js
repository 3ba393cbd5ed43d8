// Loads a scene into the wasm module in stages: the JSON, then every model it names (a model the
// user dropped on the page, else with ?assets=PREFIX the user's file by the same name, else the
// project's own from models/: the first that loads; one that is missing or broken is reported and
// the next one taken), then its skybox images, then commit. Until commit succeeds the scene on
// screen stays, so a bad file never costs the user what they had.
//
// Models are parsed as they stream in: each piece of a download (or of a dropped file) goes to the
// C++ parser as it arrives (bridge.streamMesh), so the text is never whole in memory, on either
// side of the bridge.
import { showMessage } from './messages.js';
import { DEFAULT_SCENE } from './url_state.js';

// Models larger than this are refused before they are read (or as soon as more arrives).
export const MAX_MODEL_BYTES = 64 * 1024 * 1024;

export const megabytes = (bytes) => (bytes / (1024 * 1024)).toFixed(1);

export function tooLargeMessage(name, bytes) {
  return `${name}: ${megabytes(bytes)} MB is over the ${MAX_MODEL_BYTES / (1024 * 1024)} MB limit ` +
         'for a model; not loaded';
}

// Reads a stream to its end, reporting (loaded, total) after each chunk. total may be 0 (unknown).
async function readStream(stream, total, onProgress, limit, name) {
  const reader = stream.getReader();
  const chunks = [];
  let loaded = 0;
  onProgress?.(0, total);
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    chunks.push(value);
    loaded += value.length;
    if (limit && loaded > limit) {
      await reader.cancel();
      throw new Error(tooLargeMessage(name, loaded));
    }
    onProgress?.(loaded, total);
  }
  const bytes = new Uint8Array(loaded);
  let offset = 0;
  for (const chunk of chunks) {
    bytes.set(chunk, offset);
    offset += chunk.length;
  }
  return bytes;
}

// Load to first frame: index.html starts downloading the first scene's JSON and the built-in
// models it names before any module runs (window.reflectPrefetch, URL -> fetch promise), so they
// arrive while the wasm module compiles rather than after it. Only a head start: the C++ still
// reads the scene and decides its files, and a download that is not taken, or fails, costs
// nothing but itself (openResponse fetches again). This takes the response for `url` (once), or
// null when there is none or it failed.
async function takePrefetched(url) {
  const prefetched = window.reflectPrefetch;
  const pending = prefetched?.get(url);
  if (!pending) return null;
  prefetched.delete(url);
  return pending.catch(() => null);
}

// Starts fetching `url`: the response and its announced size (0 when unknown). Rejects with a
// message naming the URL when it cannot be fetched, answers with an HTTP error, or announces more
// than `limit` bytes (when a limit is set).
async function openResponse(url, limit) {
  let response;
  try {
    response = (await takePrefetched(url)) || await fetch(url);
  } catch (e) {
    throw new Error(`${url}: could not be fetched (${e.message})`);
  }
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status} ${response.statusText}`.trim());
  const total = Number(response.headers.get('Content-Length')) || 0;
  if (limit && total > limit) {
    response.body?.cancel();
    throw new Error(tooLargeMessage(url, total));
  }
  return { response, total };
}

// Fetches a file with progress. `limit` refuses a larger file (by Content-Length before reading,
// or as soon as more arrives).
export async function fetchBytes(url, { onProgress = null, limit = 0 } = {}) {
  const { response, total } = await openResponse(url, limit);
  if (!response.body) return new Uint8Array(await response.arrayBuffer());
  return readStream(response.body, total, onProgress, limit, url);
}

// Reads a dropped or picked File with progress (the caller has checked its size).
export function readFileBytes(file, onProgress = null) {
  return readStream(file.stream(), file.size, onProgress, 0, file.name);
}

// Models are parsed one at a time, in the order their streams are read (the downloads still start
// together; one waiting for its turn is held back by the browser, not read). Parsed side by side,
// two models' arrays would lie interleaved in wasm memory, and what one parse frees would be too
// scattered to hold the other's final arrays (core/block_array.h): their peaks would add up, and
// wasm memory never shrinks.
let parseTurn = Promise.resolve();
function inParseTurn(task) {
  const run = parseTurn.then(task);
  parseTurn = run.catch(() => {});
  return run;
}

// Streams `stream` (total bytes, 0 if unknown) into mesh `target.name` (target: { name, source,
// pending, warn }: bridge.streamMesh's), piece by piece as it arrives. Resolves to "" or the parser's error (the mesh it had
// stays); rejects when the stream fails or passes `limit`.
function streamInto(bridge, target, stream, total, options = {}) {
  return inParseTurn(() => streamIntoNow(bridge, target, stream, total, options));
}

async function streamIntoNow(bridge, target, stream, total, { onProgress = null, limit = 0 } = {}) {
  const parser = bridge.streamMesh(target);
  if (parser.error) return parser.error;
  const reader = stream.getReader();
  let loaded = 0;
  onProgress?.(0, total);
  try {
    for (;;) {
      const { done, value } = await reader.read();
      if (done) break;
      loaded += value.length;
      if (limit && loaded > limit) throw new Error(tooLargeMessage(target.source, loaded));
      const error = parser.feed(value);
      if (error) {  // the file is broken: no need to read the rest
        reader.cancel().catch(() => {});
        return error;
      }
      onProgress?.(loaded, total);
    }
  } catch (e) {
    parser.cancel();
    reader.cancel().catch(() => {});
    throw e;
  }
  return parser.end();
}

// Fetches the model at `url` into mesh `target.name`, parsing it as it arrives. Resolves to "" or
// the parser's error; rejects with a message when it cannot be fetched or is too large.
export async function fetchMesh(bridge, target, url, { onProgress = null, limit = 0 } = {}) {
  const { response, total } = await openResponse(url, limit);
  const body = response.body || new Blob([await response.arrayBuffer()]).stream();
  return streamInto(bridge, target, body, total, { onProgress, limit });
}

// A dropped or picked File (or any Blob) into mesh `target.name`, parsed as it is read.
export function readFileMesh(bridge, target, file, onProgress = null) {
  return streamInto(bridge, target, file.stream(), file.size, { onProgress });
}

export function sceneUrl(nameOrUrl) {
  return /[/:]|\.json$/.test(nameOrUrl) ? nameOrUrl : `scenes/${nameOrUrl}.json`;
}

// Loads a scene through the bridge (wasm_bridge.js). `overrides` maps a model file name to
// { file, source } the user supplied (dropped files, kept as File objects); `progress` is a
// Progress (or null) that shows the bytes still coming. Returns the scene's title. Throws an Error
// with the message to show when the scene cannot be loaded. `beforeCommit` runs right before the
// new scene replaces the old one (to carry over what the user did to the old one while the new one
// was loading).
// `warn(text)` gets each model's loader warnings (models that loaded with something let pass).
export async function loadScene(bridge, url, {
  userPrefix = null, cubeSize = 0, overrides = null, progress = null, beforeCommit = null, warn = null,
} = {}) {
  const track = (name) => (progress ? progress.track(name) : null);
  const beginError = bridge.beginScene({ source: url, bytes: await fetchBytes(url) });
  if (beginError) throw new Error(beginError);
  const files = bridge.pendingFiles();

  try {
    await Promise.all(files.meshes.map(async (name) => {
      const builtIn = `models/${name}`;
      // The user's model if there is one that loads; each that does not is named, and the next
      // in line taken (the built-in model last).
      const own = overrides?.get(name);
      const user = userPrefix ? userPrefix + name : null;
      const fallback = (next) => (next === builtIn ? `(keeping the built-in ${name})` : `(using ${next} instead)`);
      if (own) {
        const error = await readFileMesh(bridge, { name, source: own.source, pending: true, warn }, own.file, track(own.source))
          .catch((e) => e.message);
        if (!error) return;
        showMessage(`${error}\n${fallback(user || builtIn)}`);
      }
      if (user) {
        const error = await fetchMesh(bridge, { name, source: user, pending: true, warn }, user,
                                      { onProgress: track(user), limit: MAX_MODEL_BYTES })
          .catch((e) => e.message);
        if (!error) return;
        showMessage(`${error}\n${fallback(builtIn)}`);
      }
      const error = await fetchMesh(bridge, { name, source: builtIn, pending: true, warn }, builtIn,
                                    { onProgress: track(builtIn), limit: MAX_MODEL_BYTES });
      if (error) throw new Error(error);
    }));

    await Promise.all(files.skybox.map(async (path, index) => {
      const error = bridge.skyboxImage({ index, source: path, bytes: await fetchBytes(path, { onProgress: track(path) }) });
      if (error) throw new Error(error);
    }));
  } finally {
    progress?.clear();
  }

  beforeCommit?.();
  // Load to first frame in parts (tools/peer_bench.mjs --load reads them): models in, scene made.
  performance.mark('reflect:models-in');
  const result = bridge.commitScene({ cubeSize });
  performance.mark('reflect:scene-committed', { detail: { bvhMs: result.bvhMs ?? 0 } });
  if (result.error) throw new Error(result.error);
  if (result.notice) showMessage(result.notice, 'info');
  return files.title;
}

// The shipped scenes, in the picker's order: scenes/index.json, which the build writes from
// assets/scenes/*.json (cmake/SceneIndex.cmake). Without it the picker offers the default alone.
export async function sceneTitles() {
  try {
    const response = await fetch('scenes/index.json');
    if (!response.ok) throw new Error(`${response.status}`);
    const list = await response.json();
    return list.map(({ name, title, description }) => ({ name, title: title || name, description: description || '' }));
  } catch {
    return [{ name: DEFAULT_SCENE, title: DEFAULT_SCENE, description: '' }];
  }
}
