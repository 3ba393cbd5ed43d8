// Visible, dismissible messages: load failures and missing WebGL2 must not be console-only.
// `timeoutMs` (optional) removes the message by itself after that long (used for confirmations).
// Every message is also kept in a history (demo.messages()), which outlives the boxes.
const history = [];

export function showMessage(text, kind = 'error', timeoutMs = 0) {
  const box = document.createElement('div');
  box.className = `message ${kind}`;
  box.textContent = text;
  const close = document.createElement('button');
  close.textContent = '×';
  close.setAttribute('aria-label', 'dismiss');
  close.onclick = () => box.remove();
  box.appendChild(close);
  document.getElementById('messages').appendChild(box);
  if (timeoutMs > 0) setTimeout(() => box.remove(), timeoutMs);
  history.push({ text, kind });
  if (history.length > 500) history.splice(0, 250);
  (kind === 'error' ? console.warn : console.info)(text);
  return box;
}

// [{ text, kind }] of every message shown, oldest first.
export const messageHistory = () => history.map((m) => ({ ...m }));
