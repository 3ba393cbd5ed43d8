// New figures from the user's .obj files (names that are not models of the scene): each becomes
// an orbiting figure scaled to fit, on a ring around the scene's centre, as a scene-file object
// entry (bridge.addObject).

export const FIGURE_SIZE = 1.5;      // world units: the largest extent of the bounding box
export const RING_RADIUS = 3;        // world units from the origin
export const FEET_Y = -1.8;          // where the box's bottom goes (the course's mario stands there)
export const ORBIT_DEG_PER_S = 27;   // as the course's figures
// Side places first (visible next to the reflector from the scene's camera), then the back,
// the front last (it would stand between the camera and the reflector).
const ANGLES = [0, 180, 45, 135, 315, 225, 270, 90];
const MIN_GAP_DEG = 40;
export const FIGURE_COLOURS = [
  [0.95, 0.55, 0.15], [0.65, 0.45, 0.95], [0.2, 0.8, 0.85], [0.95, 0.45, 0.75],
  [0.9, 0.9, 0.9], [0.55, 0.85, 0.25],
];

const angleOf = (x, z) => ((Math.atan2(z, x) * 180) / Math.PI + 360) % 360;
const gap = (a, b) => {
  const d = Math.abs(a - b) % 360;
  return Math.min(d, 360 - d);
};

// The ring angle (degrees, atan2(z, x)) for the next figure, away from the `taken` angles.
export function freeAngle(taken) {
  for (const a of ANGLES) {
    if (taken.every((t) => gap(a, t) >= MIN_GAP_DEG)) return a;
  }
  // All crowded: the place farthest from every figure, in 15° steps.
  let best = 0, bestGap = -1;
  for (let a = 0; a < 360; a += 15) {
    const g = Math.min(...taken.map((t) => gap(a, t)));
    if (g > bestGap) { best = a; bestGap = g; }
  }
  return best;
}

// Angles of the scene's orbiting objects (bridge.objects(): { orbits, translate }), the figures
// added before among them.
export function takenAngles(objects) {
  const out = [];
  for (const o of objects || []) {
    if (!o.orbits || !Array.isArray(o.translate)) continue;
    const [x, , z] = o.translate;
    if (Math.hypot(x, z) > 0.1) out.push(angleOf(x, z));
  }
  return out;
}

// The scene-file object for mesh `name` with object-space `bounds` ({min, max}).
export function figureObject(name, bounds, angleDeg, colourIndex) {
  const extent = bounds.max.map((v, i) => v - bounds.min[i]);
  const largest = Math.max(...extent);
  const scale = largest > 0 && Number.isFinite(largest) ? FIGURE_SIZE / largest : 1;
  const centre = bounds.max.map((v, i) => (v + bounds.min[i]) / 2);
  const a = (angleDeg * Math.PI) / 180;
  const round = (v) => Math.round(v * 1e4) / 1e4;
  return {
    mesh: name,
    translate: [RING_RADIUS * Math.cos(a) - centre[0] * scale, FEET_Y - bounds.min[1] * scale,
                RING_RADIUS * Math.sin(a) - centre[2] * scale].map(round),
    scale: Number(scale.toPrecision(6)),
    colour: FIGURE_COLOURS[colourIndex % FIGURE_COLOURS.length],
    animation: { type: 'orbit', degreesPerSecond: ORBIT_DEG_PER_S, axis: [0, 1, 0] },
  };
}
