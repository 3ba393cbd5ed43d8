// Pointer and keyboard input to camera actions. Pointer events cover mouse, pen and touch; the
// canvas has touch-action: none so a one-finger drag turns the view instead of scrolling.
export function attachInput(canvas, actions) {
  let last = null;
  canvas.addEventListener('pointerdown', (e) => {
    last = { x: e.clientX, y: e.clientY, id: e.pointerId };
    canvas.setPointerCapture(e.pointerId);
    canvas.focus();
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!last || e.pointerId !== last.id) return;
    actions.drag(e.clientX - last.x, e.clientY - last.y);
    last = { x: e.clientX, y: e.clientY, id: e.pointerId };
  });
  const end = (e) => { if (last && e.pointerId === last.id) last = null; };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);

  window.addEventListener('keydown', (e) => {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement ||
        e.target instanceof HTMLTextAreaElement) return;  // typing in a control moves nothing
    if (e.ctrlKey || e.metaKey || e.altKey) return;  // browser shortcuts (Ctrl+R, Ctrl+S) stay the browser's
    const key = e.key.toLowerCase();
    if (key === 'w' || key === 'arrowup') actions.move(1);
    else if (key === 's' || key === 'arrowdown') actions.move(-1);
    else if (key === 'r') actions.reset();
    else if (key === ' ') actions.togglePause();
    else return;
    e.preventDefault();
  });
}
