// The accuracy modes the page offers: the rows of sweep.csv (`reflect bench --sweep`, measured on
// the native reference machine against the ray-traced reference), each a point on the measured
// speed/accuracy curve. A row's `setting` is rf_accuracy_json's `describe` string, e.g.
// "centre, distance x2, depth 24, linear, RGBA8, highp", and its face_size the cube size.

// Splits one CSV line (quoted fields may hold commas; "" is a quote).
function csvFields(line) {
  const out = [];
  let field = '', quoted = false;
  for (let i = 0; i < line.length; ++i) {
    const c = line[i];
    if (quoted) {
      if (c === '"' && line[i + 1] === '"') { field += '"'; ++i; }
      else if (c === '"') quoted = false;
      else field += c;
    } else if (c === '"') {
      quoted = true;
    } else if (c === ',') {
      out.push(field);
      field = '';
    } else {
      field += c;
    }
  }
  out.push(field);
  return out;
}

// sweep.csv text -> [{ name, setting, faceSize, ms, msP10, msP90, psnr, rmse, p95, max,
// angularError, offPsnr, pareto, accuracy }] (rows whose setting cannot be parsed are left out).
export function parseSweep(text) {
  const lines = text.split(/\r?\n/).filter((l) => l.trim() !== '');
  if (!lines.length) return [];
  const header = csvFields(lines[0]).map((h) => h.trim());
  const rows = [];
  for (const line of lines.slice(1)) {
    const fields = csvFields(line);
    const get = (key) => fields[header.indexOf(key)];
    const num = (key) => Number(get(key));
    const accuracy = parseSetting(get('setting') || '');
    if (!get('name') || !accuracy) continue;
    rows.push({
      name: get('name'), setting: get('setting'), faceSize: num('face_size'), ms: num('ms'),
      msP10: num('ms_p10'), msP90: num('ms_p90'), psnr: num('psnr_db'), rmse: num('rmse'),
      p95: num('p95'), max: num('max'), angularError: num('mean_angular_error_deg'),
      offPsnr: num('off_reflector_psnr_db'), pareto: get('pareto') === '1', accuracy,
    });
  }
  return rows;
}

// "centre|origin, plain|distance xK, depth N, linear|mipmapped, RGBA8|RGBA16F, highp|mediump"
// -> { distance, origin, depth, mipmaps, halfFloat, mediump } (rf_accuracy_json's keys), or null.
export function parseSetting(text) {
  const parts = text.split(',').map((p) => p.trim());
  if (parts.length !== 6) return null;
  const [where, lookup, depth, filter, format, precision] = parts;
  const distance = lookup === 'plain' ? 0 : Number((/^distance x(\d+)$/.exec(lookup) || [])[1]);
  const depthBits = Number((/^depth (\d+)$/.exec(depth) || [])[1]);
  if (!['centre', 'origin'].includes(where) || !Number.isInteger(distance) || !depthBits ||
      !['linear', 'mipmapped'].includes(filter) || !['RGBA8', 'RGBA16F'].includes(format) ||
      !['highp', 'mediump'].includes(precision)) return null;
  return {
    distance, origin: where === 'origin', depth: depthBits, mipmaps: filter === 'mipmapped',
    halfFloat: format === 'RGBA16F', mediump: precision === 'mediump',
  };
}

// rf_accuracy_json's description of an accuracy object (the same words as the C side).
export function describeAccuracy(a) {
  return [a.origin ? 'origin' : 'centre', a.distance > 0 ? `distance x${a.distance}` : 'plain',
          `depth ${a.depth}`, a.mipmaps ? 'mipmapped' : 'linear', a.halfFloat ? 'RGBA16F' : 'RGBA8',
          a.mediump ? 'mediump' : 'highp'].join(', ');
}

// A combination no sweep row measured, in a URL: the describe words without spaces,
// "centre,distance-x2,depth-24,mipmapped,RGBA8,highp". Both ways; fromUrlSetting gives the
// accuracy object or null.
export function toUrlSetting(describe) {
  return describe.split(',').map((p) => p.trim().replace(/ /g, '-')).join(',');
}
export function fromUrlSetting(text) {
  return parseSetting(text.split(',').map((p) => p.replace(/-/g, ' ')).join(', '));
}

// The sweep row measuring `describe` at cube size `faceSize`: `preferred` (a row name) when it
// matches, else the first that does; null when that combination was not measured.
export function matchingRow(rows, describe, faceSize, preferred = null) {
  const hits = rows.filter((r) => r.setting === describe && r.faceSize === faceSize);
  return hits.find((r) => r.name === preferred) || hits[0] || null;
}

// The readout under the selector: the expected error of the current setting.
export function readout(row, describe, faceSize) {
  if (!row) return `${describe}, ${faceSize}²: not measured (no sweep row for this combination)`;
  return `${row.name}: reflector PSNR ${row.psnr.toFixed(2)} dB · mean angular error ` +
         `${row.angularError.toFixed(2)}° · ${row.ms.toFixed(1)} ms a frame on the native reference ` +
         `machine · ${row.pareto ? 'on the Pareto front' : 'not on the Pareto front'}`;
}
