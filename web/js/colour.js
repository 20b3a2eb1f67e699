// Absorption and colour (docs/optics.md, "Absorption" and "The colour a viewer sees"): the job form's absorption
// table, read and checked, with the colour it transmits beside it; the result's colour section and absorbed
// figure. The swatches sum the colour view's own CIE tables (GET /api/colour/cie), not a copy of them.
import { api } from './api.js';
import { $, clearFieldError, h, showFieldError, zoomable } from './dom.js';
import { fmtInt, fmtNumber, fmtPctErr } from './format.js';

// The absorbed share, among the figures of merit when the stone's material absorbs.
export const ABSORBED_FIGURE = {
  key: 'absorbed_share', label: 'Absorbed', hint: 'Taken up inside the stone (Beer-Lambert at its size)', lowerIsBetter: true,
};

// Whether the job traced an absorbing material (its settings name a spectrum).
export function absorbs(stats) {
  return Boolean(stats && stats.settings && stats.settings.absorption);
}

// The indices typed for "Your own material", as numbers (NaN where one does not read).
export function customIndices(form) {
  const text = form.elements['custom_material.indices'].value.trim();
  return text ? text.split(/[\s,;]+/).map(Number) : [];
}

// The optic class of the material chosen: a menu entry's, or for your own material the number of indices typed.
export function chosenOptic(form) {
  const material = form.elements.material;
  if (material.value === 'custom') return ['isotropic', 'isotropic', 'uniaxial', 'biaxial'][customIndices(form).length] || 'isotropic';
  return material.selectedOptions[0]?.dataset.optic || 'isotropic';
}

// The columns of coefficients a row may have beside its wavelength: one, or for a uniaxial material one or
// two (o, e), or for a biaxial one one or three (its X, Y and Z rays).
function allowedColumns(form) {
  return { uniaxial: [1, 2], biaxial: [1, 3] }[chosenOptic(form)] || [1];
}

// The absorption textarea as a job's `absorption`: one row a line, "wavelength_nm alpha_o", or for a uniaxial
// material "wavelength_nm alpha_o alpha_e", or for a biaxial one "wavelength_nm alpha_X alpha_Y alpha_Z" (per
// mm; spaces, tabs or commas between; # starts a comment). Empty: a clear stone (undefined). What is wrong goes
// to `errors` as [field, message] naming the line; the ranges are the server's to check.
export function readAbsorption(form, errors) {
  const text = form.elements.absorption.value;
  const rows = [];
  const lines = text.split('\n');
  for (let i = 0; i < lines.length; ++i) {
    const line = lines[i].replace(/#.*/, '').trim();
    if (!line) continue;
    const cells = line.split(/[\s,;]+/);
    const values = cells.map(Number);
    const bad = cells.findIndex((c, k) => c === '' || !Number.isFinite(values[k]));
    if (bad >= 0) {
      errors.push(['absorption', `Line ${i + 1}: "${cells[bad]}" is not a number`]);
      return undefined;
    }
    if (values.length < 2 || values.length > 4) {
      const counts = allowedColumns(form).map((n) => ['', 'one', 'two', 'three'][n]).join(' or ');
      errors.push(['absorption', `Line ${i + 1}: write a wavelength in nm and ${counts} coefficient${counts === 'one' ? '' : 's'} per mm`]);
      return undefined;
    }
    rows.push({ line: i + 1, values });
  }
  if (!rows.length) return undefined;
  if (rows.length < 2) {
    errors.push(['absorption', 'Give at least two rows (wavelengths), or leave the table empty for a clear stone']);
    return undefined;
  }
  const columns = rows[0].values.length;
  const ragged = rows.find((r) => r.values.length !== columns);
  if (ragged) {
    errors.push(['absorption', `Line ${ragged.line}: ${ragged.values.length} numbers where line ${rows[0].line} has ${columns}`]);
    return undefined;
  }
  if (!allowedColumns(form).includes(columns - 1)) {
    errors.push(['absorption', columns === 3
      ? 'A third (extraordinary) column needs a uniaxial material: choose one, or drop the column'
      : 'Three coefficients (the X, Y and Z rays) need a biaxial material: choose one, or keep one column']);
    return undefined;
  }
  for (let k = 1; k < rows.length; ++k) {
    if (!(rows[k].values[0] > rows[k - 1].values[0])) {
      errors.push(['absorption', `Line ${rows[k].line}: wavelengths must increase (${rows[k].values[0]} after ${rows[k - 1].values[0]})`]);
      return undefined;
    }
  }
  const column = (k) => rows.map((r) => r.values[k]);
  if (columns === 4) return { wavelength_nm: column(0), x_per_mm: column(1), y_per_mm: column(2), z_per_mm: column(3) };
  const spectrum = { wavelength_nm: column(0), ordinary_per_mm: column(1) };
  if (columns === 3) spectrum.extraordinary_per_mm = column(2);
  return spectrum;
}

let cieTables = null;  // the server's tables, asked for once
function cie() {
  cieTables ??= api('/api/colour/cie').catch((e) => { cieTables = null; throw e; });
  return cieTables;
}

// alpha at `nm`: linear between the rows, constant beyond the ends (as the tracer reads a spectrum).
function alphaAt(wavelengths, alphas, nm) {
  if (nm <= wavelengths[0]) return alphas[0];
  const last = wavelengths.length - 1;
  if (nm >= wavelengths[last]) return alphas[last];
  let k = 1;
  while (wavelengths[k] < nm) ++k;
  const t = (nm - wavelengths[k - 1]) / (wavelengths[k] - wavelengths[k - 1]);
  return alphas[k - 1] + t * (alphas[k] - alphas[k - 1]);
}

// The colour D65 light has after `mm` of the material: X = sum S T x-bar / sum S y-bar over the tables' rows
// with T = exp(-alpha mm) (Beer-Lambert alone, no surface losses), its CIELAB against D65's white and its sRGB.
export function transmittedColour(tables, wavelengths, alphas, mm) {
  const power = tables.illuminants.D65;
  const xyz = [0, 0, 0];
  let norm = 0;
  tables.wavelength_nm.forEach((nm, i) => {
    const s = power[i];
    const bar = tables.xyz_bar[i];
    const t = Math.exp(-alphaAt(wavelengths, alphas, nm) * mm);
    for (let c = 0; c < 3; ++c) xyz[c] += s * t * bar[c];
    norm += s * bar[1];
  });
  for (let c = 0; c < 3; ++c) xyz[c] /= norm;
  const white = tables.white_xyz.D65;
  // CIELAB, CIE 015:2018 8.2.1.
  const d = 6 / 29;
  const f = (v) => (v > d * d * d ? Math.cbrt(v) : v / (3 * d * d) + 4 / 29);
  const [fx, fy, fz] = xyz.map((v, c) => f(v / white[c]));
  const lab = { L: 116 * fy - 16, a: 500 * (fx - fy), b: 200 * (fy - fz) };
  // sRGB's transfer curve, IEC 61966-2-1.
  const encode = (v) => {
    const x = Math.min(1, Math.max(0, v));
    return x <= 0.0031308 ? 12.92 * x : 1.055 * x ** (1 / 2.4) - 0.055;
  };
  const hex = tables.xyz_to_linear_srgb.map((row) => {
    const v = Math.round(255 * encode(row[0] * xyz[0] + row[1] * xyz[1] + row[2] * xyz[2]));
    return v.toString(16).padStart(2, '0');
  }).join('');
  return { ...lab, srgb: `#${hex}` };
}

function labText(c) {
  return `L* ${c.L.toFixed(1)}, a* ${c.a.toFixed(1)}, b* ${c.b.toFixed(1)}`;
}

// A colour patch with its words for those who cannot see it.
export function colourSwatch(srgb, label, extraClass = '') {
  return h('span', { class: `colour-swatch${extraClass}`, style: `background:${srgb}`, role: 'img', 'aria-label': label, title: label });
}

// The swatches beside the absorption table: what 1 mm and the stone's size transmit, for each wave of a
// pleochroic stone. `asked` drops the answer to an older table.
let swatchesAsked = 0;
export async function updateAbsorptionSwatches() {
  const form = $('#job-form');
  const box = $('#absorption-swatches');
  const asked = ++swatchesAsked;
  const errors = [];
  const spectrum = readAbsorption(form, errors);
  const size = Number(form.elements.size_mm.value);
  const byChromophores = !$('#corundum-fields').hidden
    && ['cr', 'fe_ti'].some((k) => form.elements[`absorption.corundum_ppma.${k}`].value.trim() !== '');
  if (!spectrum && byChromophores) {
    box.replaceChildren(h('span', { class: 'muted' }, 'By its chromophores: the server makes the spectrum (GIA\'s cross sections).'));
    return;
  }
  if (!spectrum || errors.length) {
    box.replaceChildren(h('span', { class: 'muted' }, errors.length ? 'No colour until the table reads.' : 'Clear: no table, no colour.'));
    return;
  }
  let tables;
  try {
    tables = await cie();
  } catch (e) {
    if (asked === swatchesAsked) box.replaceChildren(h('span', { class: 'muted' }, `No colour: ${e.message}`));
    return;
  }
  if (asked !== swatchesAsked) return;
  const waves = spectrum.x_per_mm
    ? [['X', 'X ray', spectrum.x_per_mm], ['Y', 'Y ray', spectrum.y_per_mm], ['Z', 'Z ray', spectrum.z_per_mm]]
    : spectrum.extraordinary_per_mm
      ? [['o', 'ordinary wave', spectrum.ordinary_per_mm], ['e', 'extraordinary wave', spectrum.extraordinary_per_mm]]
      : [['', '', spectrum.ordinary_per_mm]];
  const lengths = [1, ...(size > 0 && size !== 1 ? [size] : [])];
  box.replaceChildren(h('span', { class: 'muted' }, 'Transmits under D65:'), ...lengths.flatMap((mm) => waves.map(([key, name, alphas]) => {
    const c = transmittedColour(tables, spectrum.wavelength_nm, alphas, mm);
    const what = `${fmtNumber(mm, 2)} mm${name ? `, ${name}` : ''}`;
    return h('span', { class: 'swatch-item', 'data-mm': mm, 'data-wave': key || 'both', 'data-srgb': c.srgb },
      colourSwatch(c.srgb, `${what}: ${c.srgb}, ${labText(c)}`), `${fmtNumber(mm, 2)} mm${key ? ` (${key})` : ''}`);
  })));
}

// The table's label and hint follow the material: the extraordinary column only for a uniaxial one; an error
// the table has is shown beside it once it is left (or the material changes), while the swatches follow typing.
export function syncAbsorptionField() {
  const form = $('#job-form');
  const optic = chosenOptic(form);
  $('#absorption-columns').textContent = {
    uniaxial: 'wavelength (nm), α ordinary (1/mm), α extraordinary (1/mm, optional)',
    biaxial: 'wavelength (nm), α (1/mm), or α of the X, Y and Z rays (1/mm)',
  }[optic] || 'wavelength (nm), α (1/mm)';
  form.elements.absorption.placeholder = {
    uniaxial: '400 0.30 0.10\n550 0.05 0.02\n700 0.15 0.40',
    biaxial: '400 0.30 0.10 0.05\n550 0.05 0.02 0.20\n700 0.15 0.40 0.10',
  }[optic] || '400 0.30\n550 0.05\n700 0.15';
  checkAbsorptionField();
  updateAbsorptionSwatches();
}

function checkAbsorptionField() {
  const errors = [];
  readAbsorption($('#job-form'), errors);
  if (errors.length) showFieldError('absorption', errors[0][1]);
  else clearFieldError('absorption');
}

export function syncColourControls() {
  const form = $('#job-form');
  const on = form.elements.colour.checked;
  for (const input of $('#colour-options').querySelectorAll('input, select')) input.disabled = !on;
  $('#colour-options').classList.toggle('disabled', !on);
}

// Fills the absorption table from the colour 1 mm transmits: the server's spectrum for it, one row per 10 nm.
export async function fillAbsorptionFromColour() {
  const form = $('#job-form');
  const colour = form.querySelector('#f-transmitted-colour').value;
  try {
    const table = await api(`/api/colour/by-transmission?transmitted_colour=${encodeURIComponent(colour)}`);
    form.elements.absorption.value = table.wavelength_nm
      .map((nm, i) => `${nm} ${Number(table.ordinary_per_mm[i].toPrecision(4))}`).join('\n');
    syncAbsorptionField();
  } catch (e) {
    showFieldError('absorption', e.message);
  }
}

export function initColourFields() {
  const form = $('#job-form');
  $('#fill-from-colour').addEventListener('click', fillAbsorptionFromColour);
  form.elements.absorption.addEventListener('input', updateAbsorptionSwatches);
  form.elements.absorption.addEventListener('change', checkAbsorptionField);
  form.elements.size_mm.addEventListener('input', updateAbsorptionSwatches);
  for (const key of ['cr', 'fe_ti']) form.elements[`absorption.corundum_ppma.${key}`].addEventListener('input', updateAbsorptionSwatches);
  form.elements.material.addEventListener('change', syncAbsorptionField);
  form.elements.colour.addEventListener('change', syncColourControls);
  syncAbsorptionField();
  syncColourControls();
}

// "12.3 ± 0.45": a value with its standard error, to the error's second significant figure.
function fmtErr(v, se) {
  if (!Number.isFinite(v)) return '—';
  const d = se > 0 ? Math.max(0, 1 - Math.floor(Math.log10(se))) : 2;
  return `${v.toFixed(Math.min(d, 4))} ± ${Number.isFinite(se) ? se.toFixed(Math.min(d, 4)) : '—'}`;
}

export const LAB_ROWS = [['L', 'L*'], ['a', 'a*'], ['b', 'b*'], ['chroma', 'C*ab']];

// The shares of the face-up area with their words (docs/stats-schema.md, `colour`).
export function colourShares(c) {
  return [
    ['windowed', 'Windowed (seen through)', `${fmtPctErr(c.windowed.share, c.windowed.stderr)}`],
    ['extinct', `Extinct (L* below ${fmtNumber(c.extinct_below_l, 1)})`, fmtPctErr(c.extinct.share, c.extinct.stderr)],
    ['saturated', `Saturated (C*ab above ${fmtNumber(c.saturated_above_c, 1)})`, fmtPctErr(c.saturated.share, c.saturated.stderr)],
  ];
}

export function labCell(c, key) {
  return fmtErr(c[key].mean, c[key].mean_stderr);
}

export function spreadCell(c, key) {
  return fmtErr(c[key].spread, c[key].spread_stderr);
}

export function meanColourText(c) {
  const m = c.mean_colour;
  return `${m.srgb}: L* ${m.L.toFixed(1)}, a* ${m.a.toFixed(1)}, b* ${m.b.toFixed(1)}, hue ${m.hue_deg.toFixed(0)}°`;
}

function colourFigures(c) {
  return h('div', { class: 'colour-figures' },
    h('p', { class: 'colour-mean' }, colourSwatch(c.mean_colour.srgb, `The face-up area's light averaged, ${meanColourText(c)}`, ' large'),
      h('span', {}, h('strong', {}, 'Colour seen from afar '), meanColourText(c),
        h('br'), h('span', { class: 'muted' }, 'the face-up area\'s light averaged; the table averages its pixels\' CIELAB'))),
    h('table', { class: 'data colour-lab' },
      h('caption', {}, `CIELAB over the stone's ${fmtInt(c.pixels)} pixels, ± one standard error`),
      h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, ''), h('th', { scope: 'col', class: 'num' }, 'Mean'),
        h('th', { scope: 'col', class: 'num' }, 'Spread (s.d.)'))),
      h('tbody', {}, LAB_ROWS.map(([key, label]) => h('tr', { 'data-lab': key },
        h('th', { scope: 'row' }, label), h('td', { class: 'num' }, labCell(c, key)), h('td', { class: 'num' }, spreadCell(c, key)))))),
    h('table', { class: 'data colour-shares' },
      h('caption', {}, `Shares of the face-up area (${fmtInt(c.rays)} view rays)`),
      h('tbody', {}, colourShares(c).map(([key, label, value]) => h('tr', { 'data-share': key },
        h('th', { scope: 'row' }, label), h('td', { class: 'num' }, value))))));
}

export function colourHint(c) {
  return `The stone face-up at ${fmtNumber(c.size_mm, 2)} mm under a dome of CIE illuminant ${c.illuminant} less a `
    + `${fmtNumber(c.head_cone_deg, 1)}° head cone, over a ground of reflectance ${fmtNumber(c.ground, 2)}`
    + `${c.absorbs ? ', absorbing along every path inside' : '; its material does not absorb'} (docs/optics.md, "The colour a viewer sees").`;
}

// The result's colour section: colour.png, the mean colour, CIELAB and the shares; none without a colour view.
export function colourSection(job, stats) {
  const c = stats.colour;
  const link = (job.links || {}).colour;
  if (!c && !link) return null;
  return h('section', { class: 'card', 'aria-labelledby': 'colour-title', 'data-section': 'colour' },
    h('h2', { id: 'colour-title' }, 'Colour'),
    c ? h('p', { class: 'hint' }, colourHint(c)) : null,
    h('div', { class: 'colour-grid' },
      link ? h('figure', { class: 'colour-picture' }, zoomable(link, 'The stone face-up in true colour')) : null,
      c ? colourFigures(c) : null));
}
