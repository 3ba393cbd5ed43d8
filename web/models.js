// Fetches the scene's models: the project's own from models/, then, with ?assets=PREFIX, the
// user's files by the same names (the course folder). A user file that is missing or broken is
// reported and the built-in model stays, so the scene is never lost.
import { showMessage } from './messages.js';

async function fetchBytes(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status} ${response.statusText}`.trim());
  return new Uint8Array(await response.arrayBuffer());
}

// loadText(name, bytes, source) returns '' or an error message.
export async function loadModels(names, userPrefix, loadText) {
  await Promise.all(names.map(async (name) => {
    const url = `models/${name}`;
    const error = loadText(name, await fetchBytes(url), url);
    if (error) throw new Error(error);
  }));
  if (!userPrefix) return;
  await Promise.all(names.map(async (name) => {
    const url = userPrefix + name;
    try {
      const error = loadText(name, await fetchBytes(url), url);
      if (error) showMessage(`${error}\n(keeping the built-in ${name})`);
    } catch (e) {
      showMessage(`${e.message}\n(keeping the built-in ${name})`);
    }
  }));
}
