// The user's own models: .obj files (or whole folders) dropped on the page or picked with the
// file and folder pickers. Each is read (size limit, progress) and either replaces the scene's
// model of the same name or joins as an orbiting figure (figures.js places it); the session keeps
// them. File names go through as they are (any length, any characters).
import { figureObject, freeAngle, takenAngles } from './figures.js';
import { showMessage } from './messages.js';
import { MAX_MODEL_BYTES, tooLargeMessage } from './scene_loader.js';

// Every file in a FileSystemDirectoryEntry, recursively, as { file, path }.
async function readDirectory(entry) {
  const reader = entry.createReader();
  const out = [];
  for (;;) {
    // readEntries answers in batches (100 in Chrome) until it returns none.
    const batch = await new Promise((resolve, reject) => reader.readEntries(resolve, reject));
    if (!batch.length) break;
    for (const child of batch) out.push(...await readEntry(child));
  }
  return out;
}

async function readEntry(entry) {
  if (entry.isFile) {
    const file = await new Promise((resolve, reject) => entry.file(resolve, reject));
    return [{ file, path: entry.fullPath.replace(/^\//, '') || file.name }];
  }
  if (entry.isDirectory) return readDirectory(entry);
  return [];
}

// The files of a drop: folders are walked (webkitGetAsEntry); items without an entry (a
// DataTransfer made by script, some browsers) fall back to getAsFile / dataTransfer.files.
export async function filesFromDrop(dataTransfer) {
  const items = [...(dataTransfer.items || [])].filter((item) => item.kind === 'file');
  if (!items.length) return filesFromList(dataTransfer.files);
  // Entries and files must be taken synchronously, before the first await: the DataTransfer
  // is emptied when the event handler returns.
  const taken = items.map((item) => ({ entry: item.webkitGetAsEntry?.() || null, file: item.getAsFile() }));
  const out = [];
  for (const { entry, file } of taken) {
    if (entry) {
      try {
        out.push(...await readEntry(entry));
        continue;
      } catch (e) {
        console.warn(`reading dropped ${entry.fullPath}: ${e.message}`);
      }
    }
    if (file) out.push({ file, path: file.name });
  }
  return out;
}

// The files of an <input type=file> (with webkitdirectory they carry their folder path).
export function filesFromList(list) {
  return [...(list || [])].map((file) => ({ file, path: file.webkitRelativePath || file.name }));
}

// Splits gathered files into the scene's models to replace, other .obj files, and the rest.
// `meshNames` are the current scene's model file names; matching ignores case and folders.
export function sortFiles(files, meshNames) {
  const byLower = new Map(meshNames.map((n) => [n.toLowerCase(), n]));
  const replace = [], extra = [], ignored = [];
  for (const f of files) {
    const base = f.path.split('/').pop();
    const lower = base.toLowerCase();
    if (!lower.endsWith('.obj')) ignored.push(f);
    else if (byLower.has(lower)) replace.push({ ...f, mesh: byLower.get(lower) });
    else extra.push(f);
  }
  return { replace, extra, ignored };
}

// Whether a dropped or picked file may be read (the size limit, checked before any byte is read).
function readable(f) {
  if (f.file.size <= MAX_MODEL_BYTES) return true;
  showMessage(tooLargeMessage(f.path, f.file.size));
  return false;
}

// The message for a model that could not be used (the C++ message names the file when it can).
const failed = (f, error, outcome) => `${error.includes(f.path) ? error : `${f.path}: ${error}`}\n(${outcome})`;

// The user's .obj files: those named like a model of the scene replace it; the others are added
// as orbiting figures. Each is parsed as it is read (scene_loader.js readFileMesh), with progress.
// Resolves to { replaced, added, extra, ignored } (mesh names and paths).
export function handleFiles(session, files) {
  return session.serial(async () => {
    const { bridge, progress } = session;
    const { replace, extra, ignored } = sortFiles(files, bridge.scene().meshes || []);
    const list = (fs) => fs.map((f) => f.path).join(', ');
    if (ignored.length) showMessage(`${list(ignored)}: not .obj files; ignored`, 'info', 8000);
    const replaced = [], added = [];
    const tracked = async (f, read) => {
      try {
        return await read(progress?.track(f.path));
      } finally {
        progress?.clear();
      }
    };
    const replaceWith = async (f, mesh) => {
      const error = await tracked(f, (onProgress) => session.replaceModel(f, mesh, onProgress));
      if (error) showMessage(failed(f, error, `keeping the ${mesh} it had`));
      else replaced.push({ ...f, mesh });
    };
    for (const f of replace) {
      if (readable(f)) await replaceWith(f, f.mesh);
    }
    const objects = () => bridge.objects();
    for (const f of extra) {
      if (!readable(f)) continue;
      const base = f.path.split('/').pop();
      // A second file of the same name (another folder) replaces the figure added before.
      const known = (bridge.scene().meshes || []).find((m) => m.toLowerCase() === base.toLowerCase());
      if (known) {
        await replaceWith(f, known);
        continue;
      }
      const place = (bounds, figures) =>
        figureObject(base, bounds, freeAngle(takenAngles(objects())), figures.length);
      const error = await tracked(f, (onProgress) => session.addFigure(f, base, place, onProgress));
      if (error) showMessage(failed(f, error, 'not added'));
      else added.push({ ...f, mesh: base });
    }
    if (replaced.length || added.length) {
      showMessage([...replaced.map((f) => `${f.mesh} replaced by ${f.path}`),
                   ...added.map((f) => `added ${f.path} as an orbiting figure`)].join('\n'), 'info', 5000);
      session.modelsChanged();  // their chunks and levels are built in the background
    }
    return { replaced: replaced.map((f) => f.mesh), added: added.map((f) => f.mesh),
             extra: added.map((f) => f.path), ignored: ignored.map((f) => f.path) };
  });
}

// Files dropped anywhere on the page, and the two pickers (#file-input, #folder-input).
export function attachDrop(session) {
  for (const id of ['file-input', 'folder-input']) {
    const input = document.getElementById(id);
    input.addEventListener('change', () => {
      const files = filesFromList(input.files);
      input.value = '';
      handleFiles(session, files);
    });
  }
  const hint = document.getElementById('drop-hint');
  let depth = 0;
  window.addEventListener('dragenter', (e) => {
    if (![...(e.dataTransfer?.types || [])].includes('Files')) return;
    ++depth;
    hint.hidden = false;
  });
  window.addEventListener('dragleave', () => {
    depth = Math.max(0, depth - 1);
    if (!depth) hint.hidden = true;
  });
  window.addEventListener('dragover', (e) => { e.preventDefault(); });
  window.addEventListener('drop', (e) => {
    e.preventDefault();
    depth = 0;
    hint.hidden = true;
    filesFromDrop(e.dataTransfer).then((files) => handleFiles(session, files));
  });
}
