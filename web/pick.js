// Pick a pixel (the P key): while pick mode is on, a click on the canvas explains that pixel with
// the C++ explanation (rf_explain_pixel: the same code and the same lines `reflect explain`
// prints) in a readout box, and the frames show its rays as 3D lines (the view ray white, glass's
// path inside yellow, the reflected or leaving ray to its exact hit blue, the course's lookup red
// and the search's green from the probe centre). Turning the mode off hides both; with it off
// nothing here runs and the frame is untouched.
export class PickMode {
  // changed(): the picture must be drawn again (the frame loop's). picked(pixel): the pixel
  // explained now ([x, y], or null: none), for the link.
  constructor(bridge, canvas, changed, picked = () => {}) {
    this.bridge = bridge;
    this.canvas = canvas;
    this.changed = changed;
    this.picked = picked;
    this.on = false;
    this.last = null;  // the last explanation (rf_explain_pixel's reply), or null
    this.box = document.getElementById('pick-box');
    this.text = document.getElementById('pick');
    document.getElementById('pick-close').onclick = () => this.toggle(false);
  }

  toggle(on = !this.on) {
    this.on = on;
    this.last = null;
    if (!on) this.bridge.explainPixel({ clear: true });
    this.picked(null);
    this.box.hidden = !on;
    this.text.textContent = on ? 'pick a pixel: click a mirror or glass pixel (P again: off)' : '';
    this.changed();
  }

  // A click at (cssX, cssY) from the canvas's top-left corner, in CSS pixels: the drawing
  // buffer's pixel under it is explained. Returns the explanation, or null when the mode is off.
  click(cssX, cssY) {
    if (!this.on) return null;
    const x = Math.floor((cssX * this.canvas.width) / Math.max(this.canvas.clientWidth, 1));
    const y = Math.floor((cssY * this.canvas.height) / Math.max(this.canvas.clientHeight, 1));
    return this.explain(x, y);
  }

  // Explains drawing-buffer pixel (x, y) of the frame on the canvas and shows it.
  explain(x, y) {
    if (!this.on) this.toggle(true);
    const reply = this.bridge.explainPixel({ x, y });
    this.last = reply;
    this.picked(reply.error ? null : [x, y]);
    this.text.textContent = reply.error ? reply.error : reply.lines.join('\n');
    this.changed();
    return reply;
  }

  // A link's pick=X,Y: explained once the first frame is drawn (the explanation reads that frame).
  explainOnceDrawn(x, y, framesDrawn) {
    const attempt = () => (framesDrawn() > 0 ? this.explain(x, y) : requestAnimationFrame(attempt));
    attempt();
  }

  // What the readout shows now.
  readout() {
    return this.box.hidden ? '' : this.text.textContent;
  }
}
