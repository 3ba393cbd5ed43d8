// What leaves the page: the canvas's pixels (read-back, a PNG screenshot) and the link to the
// current view (the address bar, kept in step with every change, and the copy-link action).
import { showMessage } from './messages.js';
import { buildQuery } from './url_state.js';

// The canvas's pixels as drawn by the last frame: { width, height, data: RGBA bottom row first }.
// Call it in the task that drew the frame (the drawing buffer is not preserved).
export function readPixels(canvas) {
  const gl = canvas.getContext('webgl2');
  const readBinding = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
  const packBinding = gl.getParameter(gl.PIXEL_PACK_BUFFER_BINDING);
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
  const width = gl.drawingBufferWidth, height = gl.drawingBufferHeight;
  const data = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, readBinding);
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, packBinding);
  return { width, height, data };
}

// Renders a frame and saves the canvas as a PNG (read in the same task). Resolves to the name.
export function screenshot(session, canvas) {
  const stats = session.frame(0, true);
  const copy = document.createElement('canvas');
  copy.width = canvas.width;
  copy.height = canvas.height;
  copy.getContext('2d').drawImage(canvas, 0, 0);
  const name = `reflect-${session.bridge.scene().name}-t${(stats.time ?? 0).toFixed(2)}.png`;
  return new Promise((resolve, reject) => copy.toBlob((blob) => {
    if (!blob) { reject(new Error('the canvas could not be encoded as PNG')); return; }
    const a = document.createElement('a');
    a.href = URL.createObjectURL(blob);
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 60_000);
    resolve(name);
  }, 'image/png'));
}

// Everything a link carries (url_state.js buildQuery).
function linkState(session) {
  const accuracy = session.bridge.accuracy();
  return {
    scene: session.scene.name, cube: session.cubeSize, faceSize: session.faceSize(),
    planner: session.bridge.plannerState(), paused: session.paused, time: session.bridge.time(),
    camera: session.bridge.camera(), home: session.homeCamera, assets: session.assets,
    acc: session.modes.linkName(accuracy, session.defaultAccuracy), accuracy,
    materials: session.changedMaterials(), view: session.bridge.view(),
    pick: session.pickedPixel || null,
    step: session.shownStep === undefined ? null : session.shownStep + 1,
  };
}

// The address bar follows the session: on every change it shows the link to what is on screen.
// Changes in quick succession (a drag) are written at most every 100 ms, the last one always
// (browsers refuse floods of history changes).
export class AddressBar {
  constructor(session) {
    this.session = session;
    this.last = 0;
    this.timer = null;
    session.onChange(() => this.changed());
    session.onStep(() => this.changed());
  }

  query() { return buildQuery(linkState(this.session), this.session.schema); }

  sync() {
    clearTimeout(this.timer);
    this.timer = null;
    this.last = performance.now();
    const query = this.query();
    if (query !== location.search) history.replaceState(null, '', location.pathname + query);
  }

  changed() {
    const wait = this.last + 100 - performance.now();
    if (wait <= 0) this.sync();
    else if (!this.timer) this.timer = setTimeout(() => this.sync(), wait);
  }

  // Writes the link now and puts it on the clipboard (or, without one, in a message to copy).
  async copyLink() {
    this.sync();
    const link = location.href;
    try {
      if (!navigator.clipboard?.writeText) throw new Error('no clipboard');
      await navigator.clipboard.writeText(link);
      showMessage(`Link copied:\n${link}`, 'info', 5000);
    } catch {
      const box = showMessage('Copy this link (the clipboard is not available here):\n', 'info link');
      const field = document.createElement('input');
      field.value = link;
      field.readOnly = true;
      field.className = 'link-field';
      box.insertBefore(field, box.lastChild);
      field.select();
    }
    return link;
  }
}
