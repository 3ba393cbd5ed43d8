// The page on the device it is on: whether the panel starts open, the page's layout class for an
// open panel (style.css docks it beside or below the canvas), and which hints the page gives
// (touch gestures, keys, or both).

// The panel starts open in a window at least this wide (CSS px), collapsed below: under that, the
// open panel would take too much of the scene (style.css then docks it as a column from 640 px,
// as a sheet below the canvas under 640 px).
export const PANEL_OPEN_MIN_WIDTH = 1000;

// What the device has to steer with: { touch, keys }.
//   touch: some pointer is coarse (a finger) or the screen takes touches (maxTouchPoints);
//   keys:  the primary pointer is fine (mouse, trackpad, pen) or can hover: a keyboard is likely
//          there too. A phone or tablet (primary pointer coarse, no hover) has touch alone; a
//          laptop with a touch screen has both. A device that says neither gets the keys.
export function inputKinds(win = window) {
  const matches = (query) => Boolean(win.matchMedia?.(query).matches);
  const touch = matches('(any-pointer: coarse)') || (win.navigator?.maxTouchPoints || 0) > 0;
  const keys = matches('(pointer: fine)') || matches('(hover: hover)') || !touch;
  return { touch, keys };
}

export const HINTS = {
  keys: 'drag: look · W/A/S/D, Q/E, wheel: move · R: reset · Space: pause · P: pick a pixel · ?: help · ' +
        'drop .obj files to replace models or add figures',
  touch: 'touch: drag to look · pinch to move · two-finger drag to slide · Controls: more',
};

// The hint line, the canvas's label and the help overlay's rows for `kinds`: the keys' hints
// where a keyboard is likely, the touch gestures where it is not; the overlay lists the rows of
// every kind the device has.
export function showHints(kinds, doc = document) {
  doc.getElementById('help').textContent = kinds.keys ? HINTS.keys : HINTS.touch;
  doc.getElementById('canvas').setAttribute('aria-label', kinds.keys
    ? '3D view: drag to look around, W/A/S/D to move, ? for help'
    : '3D view: drag to look around, pinch to move, two fingers to slide');
  const shown = { keys: kinds.keys, touch: kinds.touch, 'touch-only': kinds.touch && !kinds.keys };
  for (const row of doc.querySelectorAll('#help-overlay [data-input]')) {
    row.hidden = !shown[row.dataset.input];
  }
  doc.getElementById('help-title').textContent =
    kinds.keys && kinds.touch ? 'Keys, mouse and touch' : kinds.keys ? 'Keys and mouse' : 'Touch';
}

// Whether the panel starts open: in a window at least PANEL_OPEN_MIN_WIDTH wide.
export const panelStartsOpen = (win = window) => win.innerWidth >= PANEL_OPEN_MIN_WIDTH;

// Makes room for the panel before it is built (it loads after the scene), so the canvas has its
// size from the first frame on instead of shrinking once the panel appears.
export function reservePanel(win = window) {
  win.document.body.classList.toggle('panel-open', panelStartsOpen(win));
}

// The panel (a lil-gui root) starts open in a wide window; body.panel-open follows it, so the
// layout makes room for it, and `resized()` is called right after (the canvas takes its new size
// at once rather than at the next resize observation). gui null: there is no panel.
export function dockPanel(gui, resized = () => {}, win = window) {
  if (!gui) {
    win.document.body.classList.remove('panel-open');
    resized();
    return;
  }
  if (!panelStartsOpen(win)) gui.close();
  const follow = () => {
    win.document.body.classList.toggle('panel-open', !gui._closed);
    resized();
  };
  gui.onOpenClose((changed) => { if (changed === gui) follow(); });
  follow();
}
