// The user's own models: .obj files (or whole folders) dropped on the page or picked with the
// file and folder pickers. This module only gathers the files; app.js decides what each one does.

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
