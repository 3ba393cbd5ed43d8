// A link's settings applied to a new session, in the order they depend on each other.
import { showMessage } from './messages.js';
import { DEFAULT_SCENE } from './url_state.js';

// The link's settings: the first scene (at the link's cube size, or its accuracy mode's), then
// the accuracy mode and settings, materials, planner settings, camera, time and pause. A value
// that cannot be used is named in a message and the rest still applies.
export async function applyLink(session, link) {
  const { bridge, modes, schema } = session;
  const row = link.acc ? modes.find(link.acc) : null;
  if (link.acc && !row) {
    showMessage(`acc=${link.acc}: not a measured accuracy mode ` +
                (modes.rows.length ? `(sweep.csv has ${modes.names()})` : '(sweep.csv is not available)') +
                `; settings go as keys of their own (${schema.accuracy.map((i) => i.name).join(', ')}); ignored`);
  }
  session.cubeSize = link.cube || row?.faceSize || 0;
  session.paused = link.paused;
  await openScene(session, link.scene);
  // All at once (one GL rebuild for accuracy settings); when that fails, one by one.
  const each = (changes, set) => {
    if (!Object.keys(changes).length || !set(changes)) return;
    for (const [key, value] of Object.entries(changes)) {
      const error = set({ [key]: value });
      if (error) showMessage(`${error} (from the link; ignored)`);
    }
  };
  if (row) {
    modes.chosen = row.name;
    const error = bridge.setAccuracy(row.accuracy);
    if (error) showMessage(`acc=${row.name}: ${error}`);
  }
  each(link.accuracy, (c) => bridge.setAccuracy(c));
  for (const { index, changes, entry } of link.materials) {
    const error = bridge.setMaterial({ index, changes });
    if (error) showMessage(`mat=${entry}: ${error}; ignored`);
  }
  each(link.planner, (c) => bridge.setPlanner(c));
  session.startLevels();  // levels the link's LOD settings want
  each(link.view, (c) => bridge.setView(c));
  if (link.cam) bridge.setCamera({ eye: link.cam.slice(0, 3), yaw: link.cam[3], pitch: link.cam[4] });
  if (link.t !== null) bridge.setTime(link.t);
  session.changed('settings');
}

// The link's scene, or the default one when it cannot be loaded (a name no scene has, a broken
// file): the message naming the file stays on the page, and the page runs rather than leave a
// black canvas. A default scene that fails too is the page's failure.
async function openScene(session, name) {
  try {
    await session.switchScene(name);
  } catch (e) {
    if (name === DEFAULT_SCENE) throw e;
    showMessage(`scene=${name} could not be loaded; showing the default scene (${DEFAULT_SCENE}) instead`, 'info');
    await session.switchScene(DEFAULT_SCENE);
  }
}
