// Pointer, wheel and keyboard input to camera actions. Pointer events cover mouse, pen and touch;
// the canvas has touch-action: none so a one-finger drag turns the view instead of scrolling, two
// fingers pinch to move along the view, and two fingers dragged together slide the eye sideways
// and up or down (the scene follows the fingers, as a map does).
//
// actions: drag(dx, dy) in CSS pixels, move(steps) along the view, strafe(steps) to the right,
// rise(steps) up, pan(rightSteps, upSteps) both at once, reset(), togglePause(), toggleHelp(),
// closeHelp(), togglePick(), click(x, y) (CSS pixels from the canvas's top-left corner). The steps' length and directions are the C++ camera's (LookCamera: move, strafe,
// rise); this module only turns events into steps.

// Typing in a control moves nothing; Space and Enter on a focused button press the button.
function isTextField(target) {
  return target instanceof HTMLInputElement || target instanceof HTMLSelectElement ||
         target instanceof HTMLTextAreaElement || (target instanceof HTMLElement && target.isContentEditable);
}

// Wheel distance to move steps (one step is 0.1 scene units): a mouse notch is 100 px.
export function wheelSteps(e) {
  const scale = e.deltaMode === 1 ? 1 / 3 : e.deltaMode === 2 ? 1 : 1 / 100;
  // Trackpad pinches arrive as wheel events with ctrlKey and small deltas.
  return -e.deltaY * scale * (e.ctrlKey ? 4 : 1);
}

export const PINCH_PIXELS_PER_STEP = 20;
// Two fingers moved together this far (CSS px) slide the eye one step (0.1) the other way.
export const PAN_PIXELS_PER_STEP = 10;

// A press that stays within CLICK_PIXELS of where it began is a click (actions.click: pick a
// pixel), besides the drag it also is.
const CLICK_PIXELS = 4;

export function attachInput(canvas, actions) {
  const pointers = new Map();  // pointerId -> { x, y }
  let press = null;  // the one pointer down: { id, x, y } where it began, or null
  let pinch = null;  // with two pointers down: { distance, x, y } (the midpoint) when last seen
  const twoFingers = () => {
    const [a, b] = [...pointers.values()];
    return { distance: Math.hypot(a.x - b.x, a.y - b.y), x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
  };

  canvas.addEventListener('pointerdown', (e) => {
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    canvas.setPointerCapture(e.pointerId);
    canvas.focus();
    pinch = pointers.size === 2 ? twoFingers() : null;
    press = pointers.size === 1 ? { id: e.pointerId, x: e.clientX, y: e.clientY } : null;
  });
  canvas.addEventListener('pointermove', (e) => {
    const p = pointers.get(e.pointerId);
    if (!p) return;
    const dx = e.clientX - p.x, dy = e.clientY - p.y;
    p.x = e.clientX;
    p.y = e.clientY;
    if (pointers.size === 1) {
      actions.drag(dx, dy);
    } else if (pointers.size === 2 && pinch !== null) {
      const now = twoFingers();
      const forward = (now.distance - pinch.distance) / PINCH_PIXELS_PER_STEP;  // spreading moves in
      // The midpoint's move: the scene follows the fingers, so the eye goes the other way
      // (fingers to the right: the eye to the left; fingers up: the eye down).
      const right = -(now.x - pinch.x) / PAN_PIXELS_PER_STEP;
      const up = (now.y - pinch.y) / PAN_PIXELS_PER_STEP;
      if (forward) actions.move(forward);
      if (right || up) actions.pan(right, up);
      pinch = now;
    }
  });
  const end = (e) => {
    if (!pointers.delete(e.pointerId)) return;
    if (e.type === 'pointerup' && press?.id === e.pointerId &&
        Math.hypot(e.clientX - press.x, e.clientY - press.y) < CLICK_PIXELS) {
      const box = canvas.getBoundingClientRect();
      actions.click?.(e.clientX - box.left, e.clientY - box.top);
    }
    press = null;
    pinch = pointers.size === 2 ? twoFingers() : null;
  };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);

  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();  // neither scroll nor zoom the page
    const steps = wheelSteps(e);
    if (steps) actions.move(steps);
  }, { passive: false });

  window.addEventListener('keydown', (e) => {
    if (isTextField(e.target)) return;
    if (e.ctrlKey || e.metaKey || e.altKey) return;  // browser shortcuts (Ctrl+R, Ctrl+S) stay the browser's
    const key = e.key.toLowerCase();
    if ((key === ' ' || key === 'enter') && e.target instanceof HTMLButtonElement) return;
    if (key === 'w' || key === 'arrowup') actions.move(1);
    else if (key === 's' || key === 'arrowdown') actions.move(-1);
    else if (key === 'a' || key === 'arrowleft') actions.strafe(-1);
    else if (key === 'd' || key === 'arrowright') actions.strafe(1);
    else if (key === 'q') actions.rise(-1);
    else if (key === 'e') actions.rise(1);
    else if (key === 'r') actions.reset();
    else if (key === 'f') actions.toggleFaces();
    else if (key === 'u') actions.toggleFaceUse();
    else if (key === 'p') actions.togglePick();
    else if (key === '.') actions.stepFrame();
    else if (key === ' ') actions.togglePause();
    else if (key === '?' || key === 'h') actions.toggleHelp();
    else if (key === 'escape') { if (!actions.closeHelp()) return; }
    else return;
    e.preventDefault();
  });
}

// The help overlay that lists the keys: toggle(show = it is hidden) and close() (false when it
// was not open); its × button closes it.
export function helpOverlay() {
  const help = document.getElementById('help-overlay');
  const toggle = (show = help.hidden) => { help.hidden = !show; };
  document.getElementById('help-close').onclick = () => toggle(false);
  return {
    toggle,
    close: () => {
      if (help.hidden) return false;
      toggle(false);
      return true;
    },
  };
}
