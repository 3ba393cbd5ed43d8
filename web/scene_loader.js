// Loads a scene into the wasm module in stages: the JSON, then every model it names (the
// project's own from models/, then with ?assets=PREFIX the user's files by the same names, then
// models the user dropped on the page), then its skybox images, then commit. Until commit
// succeeds the scene on screen stays, so a bad file never costs the user what they had. A user's
// model that is missing or broken is reported and the built-in one is kept.
import { showMessage } from './messages.js';
import { DEFAULT_SCENE } from './url_state.js';

// Models larger than this are refused before they are read (the wasm heap holds the text, the
// parsed mesh and its levels of detail at once).
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

// Fetches a file with progress. `limit` refuses a larger file (by Content-Length before reading,
// or as soon as more arrives).
export async function fetchBytes(url, { onProgress = null, limit = 0 } = {}) {
  let response;
  try {
    response = await fetch(url);
  } catch (e) {
    throw new Error(`${url}: could not be fetched (${e.message})`);
  }
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status} ${response.statusText}`.trim());
  const total = Number(response.headers.get('Content-Length')) || 0;
  if (limit && total > limit) {
    response.body?.cancel();
    throw new Error(tooLargeMessage(url, total));
  }
  if (!response.body) return new Uint8Array(await response.arrayBuffer());
  return readStream(response.body, total, onProgress, limit, url);
}

// Reads a dropped or picked File with progress (the caller has checked its size).
export function readFileBytes(file, onProgress = null) {
  return readStream(file.stream(), file.size, onProgress, 0, file.name);
}

export function sceneUrl(nameOrUrl) {
  return /[/:]|\.json$/.test(nameOrUrl) ? nameOrUrl : `scenes/${nameOrUrl}.json`;
}

// Loads a scene through the bridge (wasm_bridge.js). `overrides` maps a model file name to
// { bytes, source } the user supplied (dropped files); `progress` is a Progress (or null) that
// shows the bytes still coming. Returns the scene's title. Throws an Error with the message to
// show when the scene cannot be loaded. `beforeCommit` runs right before the new scene replaces
// the old one (to carry over what the user did to the old one while the new one was loading).
// `warn(text)` gets each model's loader warnings (models that loaded with something let pass).
export async function loadScene(bridge, url, {
  userPrefix = null, cubeSize = 0, overrides = null, progress = null, beforeCommit = null, warn = null,
} = {}) {
  const track = (name) => (progress ? progress.track(name) : null);
  const beginError = bridge.beginScene({ source: url, bytes: await fetchBytes(url) });
  if (beginError) throw new Error(beginError);
  const files = bridge.pendingFiles();
  const load = (name, source, bytes) => bridge.loadMesh({ name, source, bytes, pending: true, warn });

  try {
    await Promise.all(files.meshes.map(async (name) => {
      const builtIn = `models/${name}`;
      const error = load(name, builtIn, await fetchBytes(builtIn, { onProgress: track(builtIn), limit: MAX_MODEL_BYTES }));
      if (error) throw new Error(error);
      if (userPrefix) {
        const url2 = userPrefix + name;
        try {
          const userError = load(name, url2, await fetchBytes(url2, { onProgress: track(url2), limit: MAX_MODEL_BYTES }));
          if (userError) showMessage(`${userError}\n(keeping the built-in ${name})`);
        } catch (e) {
          showMessage(`${e.message}\n(keeping the built-in ${name})`);
        }
      }
      const own = overrides?.get(name);
      if (own) {
        const ownError = load(name, own.source, own.bytes);
        if (ownError) showMessage(`${ownError}\n(keeping the built-in ${name})`);
      }
    }));

    await Promise.all(files.skybox.map(async (path, index) => {
      const error = bridge.skyboxImage({ index, source: path, bytes: await fetchBytes(path, { onProgress: track(path) }) });
      if (error) throw new Error(error);
    }));
  } finally {
    progress?.clear();
  }

  beforeCommit?.();
  const result = bridge.commitScene({ cubeSize });
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
