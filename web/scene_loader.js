// Loads a scene into the wasm module in stages: the JSON, then every model it names (the
// project's own from models/, then with ?assets=PREFIX the user's files by the same names), then
// its skybox images, then commit. Until commit succeeds the scene on screen stays, so a bad file
// never costs the user what they had. A user's model that is missing or broken is reported and
// the built-in one is kept.
import { showMessage } from './messages.js';

export async function fetchBytes(url) {
  let response;
  try {
    response = await fetch(url);
  } catch (e) {
    throw new Error(`${url}: could not be fetched (${e.message})`);
  }
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status} ${response.statusText}`.trim());
  return new Uint8Array(await response.arrayBuffer());
}

// Copies bytes into wasm memory for the duration of call(ptr, length).
export function withBytes(Module, bytes, call) {
  const ptr = Module._malloc(Math.max(bytes.length, 1));
  Module.HEAPU8.set(bytes, ptr);
  try { return call(ptr, bytes.length); } finally { Module._free(ptr); }
}

export function sceneUrl(nameOrUrl) {
  return /[/:]|\.json$/.test(nameOrUrl) ? nameOrUrl : `scenes/${nameOrUrl}.json`;
}

// Throws an Error with the message to show when the scene cannot be loaded.
export async function loadScene(Module, api, url, { userPrefix = null, cubeSize = 0 } = {}) {
  const json = await fetchBytes(url);
  const beginError = withBytes(Module, json, (ptr, n) => api.beginScene(ptr, n, url));
  if (beginError) throw new Error(beginError);
  const files = JSON.parse(api.pendingFiles());

  await Promise.all(files.meshes.map(async (name) => {
    const builtIn = `models/${name}`;
    const error = withBytes(Module, await fetchBytes(builtIn), (ptr, n) => api.loadMesh(1, name, ptr, n, builtIn));
    if (error) throw new Error(error);
    if (!userPrefix) return;
    const url2 = userPrefix + name;
    try {
      const userError = withBytes(Module, await fetchBytes(url2), (ptr, n) => api.loadMesh(1, name, ptr, n, url2));
      if (userError) showMessage(`${userError}\n(keeping the built-in ${name})`);
    } catch (e) {
      showMessage(`${e.message}\n(keeping the built-in ${name})`);
    }
  }));

  await Promise.all(files.skybox.map(async (path, index) => {
    const error = withBytes(Module, await fetchBytes(path), (ptr, n) => api.skyboxImage(index, ptr, n, path));
    if (error) throw new Error(error);
  }));

  const result = api.commitScene(cubeSize);
  if (result && !result.startsWith('{')) throw new Error(result);
  if (result) showMessage(JSON.parse(result).notice, 'info');
  return files.title;
}
