// The measured accuracy modes: the rows of sweep.csv (`reflect bench --sweep`, measured on the
// native reference machine against the ray-traced reference, shipped as assets/sweep.csv), each a
// named point on the measured speed/accuracy curve. A row's `settings` column holds its accuracy
// settings as JSON by the schema's names (what the page applies), `setting` their description for
// people, and face_size its cube size.

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
// angularError, offPsnr, pareto, accuracy }] (rows whose settings do not parse are left out).
export function parseSweep(text) {
  const lines = text.split(/\r?\n/).filter((l) => l.trim() !== '');
  if (!lines.length) return [];
  const header = csvFields(lines[0]).map((h) => h.trim());
  const rows = [];
  for (const line of lines.slice(1)) {
    const fields = csvFields(line);
    const get = (key) => fields[header.indexOf(key)];
    const num = (key) => Number(get(key));
    let accuracy = null;
    try {
      accuracy = JSON.parse(get('settings'));
    } catch {
      continue;
    }
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

// Whether two settings objects (by the schema's names) hold the same values.
export const sameSettings = (a, b) => Object.keys({ ...a, ...b }).every((k) => a[k] === b[k]);

// The rows and the one the user picked (a row name or null).
export class AccuracyModes {
  constructor(rows) {
    this.rows = rows;
    this.chosen = null;
  }

  find(name) {
    return this.rows.find((r) => r.name === name) || null;
  }

  names() {
    return this.rows.map((r) => r.name).join(', ');
  }

  // The row measuring `settings` at cube size `faceSize`: the picked one when it does, else the
  // first that does; null when that combination was not measured.
  current(settings, faceSize) {
    const hits = this.rows.filter((r) => sameSettings(r.accuracy, settings) && r.faceSize === faceSize);
    return hits.find((r) => r.name === this.chosen) || hits[0] || null;
  }

  // acc= for a link: the picked row while its settings are current, else the first row with
  // them; null for the shipped defaults (not picked) and for settings no row has.
  linkName(settings, defaults) {
    const picked = this.find(this.chosen);
    if (picked && sameSettings(picked.accuracy, settings)) return picked.name;
    if (sameSettings(settings, defaults)) return null;
    return this.rows.find((r) => sameSettings(r.accuracy, settings))?.name || null;
  }

  // The readout under the selector: the expected error of the current setting.
  readout(row, describe, faceSize) {
    if (!this.rows.length) return 'sweep.csv is not available: no measured modes';
    if (!row) return `${describe}, ${faceSize}²: not measured (no sweep row for this combination)`;
    return `${row.name}: reflector PSNR ${row.psnr.toFixed(2)} dB · mean angular error ` +
           `${row.angularError.toFixed(2)}° · ${row.ms.toFixed(1)} ms a frame on the native reference ` +
           `machine · ${row.pareto ? 'on the Pareto front' : 'not on the Pareto front'}`;
  }
}
