// Visible, dismissible messages: load failures and missing WebGL2 must not be console-only.
export function showMessage(text, kind = 'error') {
  const box = document.createElement('div');
  box.className = `message ${kind}`;
  box.textContent = text;
  const close = document.createElement('button');
  close.textContent = '×';
  close.setAttribute('aria-label', 'dismiss');
  close.onclick = () => box.remove();
  box.appendChild(close);
  document.getElementById('messages').appendChild(box);
  (kind === 'error' ? console.warn : console.info)(text);
}
