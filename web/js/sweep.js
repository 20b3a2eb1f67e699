// Sweeps (docs/sweeps.md): the form that submits one, and its chart, which fills in as the points finish. One
// varied quantity: the figures the user ticks against it, each with a ±1σ band; two: a filled map in viridis
// with the axes, reference designs and palette of the CLI's map; both with the best point marked: the search's
// refined best (best.json) once it has one.
import { api, jobUrl } from './api.js';
import { FIGURES, POLL_ACTIVE_MS, VIEWER_FIGURES } from './constants.js';
import { $, clearFieldError, h, showFieldError, svg } from './dom.js';
import { FIRE_FIGURES, fmtFire } from './fire.js';
import { fmtNumber, humanize, shortId } from './format.js';
import { viridis } from './heatmap.js';
import { jobsView, refreshJobs } from './jobs.js';
import { jobName } from './meshes.js';

// `compared`: the jobs of designs opened from sweeps, for the compare view.
// `best`: the search's best.json once the sweep has finished.
// `points`: the last points answer; `shown`: the figures a one-axis chart draws, the job's figure first;
// `mapped`: the figure a two-axis map colours by (none: the job's).
export const sweepView = { id: '', timer: 0, job: null, shape: '', compared: [], best: null, points: null, shown: [], mapped: '' };

const TOOLTIP_HINT = 'Hover a point to see its figures; click it to trace that design as a job and compare it.';
const W = 680;
const H = 400;
// The right margin holds the legend: room for the longest figure's name ("cosine-weighted return").
const M = { left: 70, right: 210, top: 20, bottom: 56 };

// The colour figures (docs/sweeps.md, "Colour figures"; points of a sweep with the colour view): CIELAB means
// over the face-up area, then shares of it.
const COLOUR_FIGURES = [
  { key: 'colour_lightness', label: 'Colour lightness L*', cielab: true, hint: 'Mean CIELAB L* over the stone face-up' },
  { key: 'colour_a', label: 'Colour a*', cielab: true, hint: 'Mean a*: green (−) to red (+)' },
  { key: 'colour_b', label: 'Colour b*', cielab: true, hint: 'Mean b*: blue (−) to yellow (+)' },
  { key: 'colour_chroma', label: 'Colour chroma C*ab', cielab: true, hint: 'Mean C*ab: the colour’s strength' },
  { key: 'colour_windowed', label: 'Windowed (colour view)', hint: 'Share of the face-up view seen through the pavilion' },
  { key: 'colour_extinct', label: 'Extinct (colour view)', hint: 'Share of the face-up pixels darker than L* 20' },
  { key: 'colour_saturated', label: 'Saturated (colour view)', hint: 'Share of the face-up pixels of chroma above 40' },
];
// The viewer's figures, the statistics' totals, the fire figures (points of a sweep that traces fire), then the
// colour figures.
const SWEEP_FIGURES = [...VIEWER_FIGURES, ...FIGURES, ...FIRE_FIGURES, ...COLOUR_FIGURES];
function figureInfo(key) { return SWEEP_FIGURES.find((f) => f.key === key) || { key, label: humanize(key) }; }
// Where a point keeps a figure and its standard error: its totals, its viewer, colour or fire figures.
function figuresOf(p, key) {
  if (key in p.totals) return p.totals;
  if (p.viewer && key in p.viewer) return p.viewer;
  return p.colour && key in p.colour ? p.colour : p.fire || {};
}
// A figure and its error as text: the score in points, CIELAB to two decimals, the rest as fire.js writes them.
function fmtFigure(f, figures) {
  if (!f.points && !f.cielab) return fmtFire(f, figures);
  const v = figures[f.key];
  const d = f.points ? 1 : 2;
  return Number.isFinite(v) ? `${v.toFixed(d)} ± ${figures[`${f.key}_stderr`].toFixed(d)}` : '—';
}

// The defaults of each axis: a pavilion range, and a crown range for the map.
const AXIS_DEFAULTS = [{ name: 'pavilion', from: 38, to: 43, step: 0.5 }, { name: 'crown', from: 30, to: 38, step: 2 }];

// An axis's fieldset: its quantity and range, each input with its label and the id the server's field errors
// (sweep.axes[i].step) are shown under.
function axisFieldset(i) {
  const path = `sweep.axes[${i}]`;
  const defaults = AXIS_DEFAULTS[i];
  const input = (key, attrs) => h('div', { class: 'field' },
    h('label', { for: `s-${key}-${i}` }, key === 'name' ? 'Quantity' : key[0].toUpperCase() + key.slice(1)),
    h('input', { id: `s-${key}-${i}`, name: `${key}-${i}`, value: defaults[key], 'aria-describedby': `err-${path}.${key}`, ...attrs }));
  const legend = i === 0 ? 'First axis'
    : h('label', {}, h('input', { type: 'checkbox', id: 's-second', name: 'second' }), ' Second axis');
  return h('fieldset', { id: `s-axis-${i}` }, h('legend', {}, legend),
    h('div', { class: 'field-row' }, input('name', { type: 'text', list: 'sweep-quantities' }),
      ...['from', 'to', 'step'].map((key) => input(key, { type: 'number', step: 'any' }))),
    ['', '.name', '.from', '.to', '.step'].map((key) => h('p', { class: 'field-error', id: `err-${path}${key}`, role: 'alert', hidden: true })));
}

export function initSweepForm() {
  const form = $('#sweep-form');
  $('#sweep-axes').replaceChildren(axisFieldset(0), axisFieldset(1));
  $('#s-figure').replaceChildren(
    h('optgroup', { label: 'What a viewer sees' }, VIEWER_FIGURES.map((f) => h('option', { value: f.key, selected: f.key === 'brightness' }, f.label))),
    h('optgroup', { label: 'Light return' }, FIGURES.map((f) => h('option', { value: f.key }, f.label))),
    h('optgroup', { label: 'Fire (traces fire)' }, FIRE_FIGURES.map((f) => h('option', { value: f.key }, f.label))),
    h('optgroup', { label: 'Colour (measures colour)' }, COLOUR_FIGURES.map((f) => h('option', { value: f.key }, f.label))));
  // The job form's materials, the one list of them (web/index.html), less "Your own material", which the sweep
  // form has no fields for.
  $('#s-material').replaceChildren(...[...$('#f-material').children]
    .filter((el) => !el.querySelector('option[value="custom"]')).map((el) => el.cloneNode(true)));
  $('#s-material').value = 'auto';
  // A fire figure needs the fire trace; a colour figure the colour view.
  $('#s-figure').addEventListener('change', (ev) => {
    if (FIRE_FIGURES.some((f) => f.key === ev.target.value)) $('#s-fire').checked = true;
    if (COLOUR_FIGURES.some((f) => f.key === ev.target.value)) $('#s-colour').checked = true;
  });
  const second = $('#s-second');
  const sync = () => { for (const el of $('#s-axis-1').querySelectorAll('.field input')) el.disabled = !second.checked; };
  second.addEventListener('change', sync);
  sync();
  // Constraints bound the search: typed only when there is one.
  const maximize = $('#s-maximize');
  const syncConstraints = () => { $('#s-constraints').disabled = !maximize.checked; };
  maximize.addEventListener('change', syncConstraints);
  syncConstraints();
  form.addEventListener('submit', submitSweep);
  $('#s-shape').addEventListener('change', syncSweepQuantities);
  // The meshes list changes when the user uploads one (web/js/meshes.js).
  document.addEventListener('meshes-loaded', (ev) => setSweepShapes(ev.detail.shipped || [], ev.detail.uploaded || []));
}

// The quantities any stone can be swept over besides its own parameters (sweep_axis.h's trace axes).
const TRACE_QUANTITIES = ['tilt', 'head_shadow', 'n', 'size_mm', 'optic_axis_tilt', 'optic_axis_azimuth', 'optic_axis_rotation'];
// Every mesh the form offers, by its `mesh` name: a library shape's parameters, an upload's tiers.
const sweepMeshes = new Map();

// What the form may sweep: the shapes of the cut library (their parameters), and the user's uploads: a GemCad
// design's tiers (tier:NAME, its slope) or, for a mesh, the trace settings only (docs/gemcad.md).
export function setSweepShapes(shipped, uploaded = []) {
  const shapes = shipped.filter((m) => !m.error && (m.parameters || []).length);
  const designs = uploaded.filter((m) => !m.error);
  if (!shapes.length && !designs.length) return;
  const el = $('#s-shape');
  const previous = el.value;
  sweepMeshes.clear();
  for (const m of [...shapes, ...designs]) sweepMeshes.set(m.mesh, m);
  el.replaceChildren(
    h('optgroup', { label: 'Shapes of the cut library' }, shapes.map((m) => h('option', { value: m.mesh }, humanize(m.mesh)))),
    designs.length ? h('optgroup', { label: 'Your designs and meshes' },
      designs.map((m) => h('option', { value: m.mesh }, `${m.file_name || m.name}${(m.tiers || []).length ? ` (${m.tiers.length} tiers)` : ''}`))) : null);
  el.value = sweepMeshes.has(previous) ? previous : (shapes[0] || designs[0]).mesh;
  syncSweepQuantities();
}

// The quantities the chosen shape offers; choosing a design starts the first axis on its first tier.
function syncSweepQuantities() {
  const m = sweepMeshes.get($('#s-shape').value);
  if (!m) return;
  const tiers = m.tiers || [];
  const own = tiers.length ? tiers.map((t) => t.parameter) : (m.parameters || []).map((p) => p.name);
  $('#sweep-quantities').replaceChildren(...[...own, ...TRACE_QUANTITIES].map((q) => h('option', { value: q })));
  const form = $('#sweep-form');
  const first = form.elements['name-0'];
  const known = new Set([...own, ...TRACE_QUANTITIES]);
  if (tiers.length && !known.has(first.value)) {
    const t = tiers[0];
    first.value = t.parameter;
    form.elements['from-0'].value = Math.max(1, Math.round((t.angle_deg - 1.5) * 4) / 4);
    form.elements['to-0'].value = Math.min(89, Math.round((t.angle_deg + 1.5) * 4) / 4);
    form.elements['step-0'].value = 0.5;
    const second = form.elements['name-1'];
    if (tiers[1] && !known.has(second.value)) {
      second.value = tiers[1].parameter;
      form.elements['from-1'].value = Math.max(1, Math.round((tiers[1].angle_deg - 2) * 4) / 4);
      form.elements['to-1'].value = Math.min(89, Math.round((tiers[1].angle_deg + 2) * 4) / 4);
      form.elements['step-1'].value = 1;
    }
  } else if (!tiers.length && !known.has(first.value)) {
    first.value = own[0] || 'tilt';
  }
}

function axisFromForm(form, i) {
  const num = (name) => (form.elements[`${name}-${i}`].value.trim() === '' ? undefined : Number(form.elements[`${name}-${i}`].value));
  return { name: form.elements[`name-${i}`].value.trim(), from: num('from'), to: num('to'), step: num('step') };
}

// The held parameters typed as "NAME=VALUE, ...": an object for sweep.set; throws naming the entry at fault.
function parseHeld(text) {
  const set = {};
  for (const item of text.split(/[,;]/).map((s) => s.trim()).filter(Boolean)) {
    const m = item.match(/^([A-Za-z_][\w:]*)\s*=\s*(\S+)$/);
    if (!m || !Number.isFinite(Number(m[2]))) throw new Error(`"${item}" is not NAME=VALUE with a number`);
    if (m[1] in set) throw new Error(`${m[1]} is held twice`);
    set[m[1]] = Number(m[2]);
  }
  return set;
}

// The constraints typed as "NAME<=VALUE, ...": the server checks each (sweep.constraints[i]).
function parseConstraints(text) {
  return text.split(/[,;]/).map((s) => s.replace(/\s+/g, '')).filter(Boolean);
}

function clearSweepErrors() {
  for (const err of $('#sweep-form').querySelectorAll('.field-error')) clearFieldError(err.id.slice(4));
  $('#sweep-error').hidden = true;
}

async function submitSweep(ev) {
  ev.preventDefault();
  const form = ev.currentTarget;
  clearSweepErrors();
  const axes = [axisFromForm(form, 0)];
  if (form.elements.second.checked) axes.push(axisFromForm(form, 1));
  const sweep = { axes, figure: form.elements.figure.value };
  try {
    const set = parseHeld(form.elements.set.value);
    if (Object.keys(set).length) sweep.set = set;
  } catch (e) {
    showFieldError('sweep.set', e.message);
    form.elements.set.focus();
    return;
  }
  if (form.elements.maximize.checked) {
    sweep.maximize = form.elements.figure.value;
    const constraints = parseConstraints(form.elements.constraints.value);
    if (constraints.length) sweep.constraints = constraints;
  }
  const job = { mesh: form.elements.shape.value, photons: Number(form.elements.photons.value), sweep };
  if (form.elements.fire.checked) job.fire = { enabled: true };
  if (form.elements.material.value !== 'auto') job.material = form.elements.material.value;
  if (form.elements.size_mm.value.trim() !== '') job.size_mm = Number(form.elements.size_mm.value);
  if (form.elements.colour.checked) job.colour = {};
  const threads = Number($('#f-threads').value);
  if (threads > 0) job.threads = threads;
  const status = $('#sweep-status');
  status.textContent = 'Submitting…';
  try {
    const created = await api('/api/jobs', {
      method: 'POST', headers: { 'Content-Type': 'application/json', Accept: 'application/json' }, body: JSON.stringify(job),
    });
    status.textContent = `Sweep ${shortId(created.id)} queued.`;
    jobsView.submitted.set('#sweep-status', created.id);
    refreshJobs();
    location.hash = `#/sweeps/${created.id}`;
  } catch (e) {
    status.textContent = '';
    // A held parameter's or a constraint's error is shown at its field, its entry named in the message.
    const at = (e.field || '').match(/^sweep\.(set|constraints)\b/);
    const own = { mesh: 'sweep-mesh', photons: 'sweep-photons', material: 'sweep-material', size_mm: 'sweep-size_mm' };
    const field = own[e.field] || (at ? `sweep.${at[1]}` : e.field);
    if (!field || !showFieldError(field, e.message)) {
      const err = $('#sweep-error');
      err.textContent = e.message;
      err.hidden = false;
    }
  }
}

export async function showSweep(id) {
  sweepView.id = id;
  clearTimeout(sweepView.timer);
  $('#sweep-view-title').textContent = 'Sweep';
  $('#sweep-progress').textContent = '';
  $('#sweep-tooltip').textContent = TOOLTIP_HINT;
  $('#sweep-chart').replaceChildren(h('p', { class: 'hint' }, 'Waiting for the first points…'));
  $('#sweep-links').replaceChildren();
  $('#sweep-best').replaceChildren();
  sweepView.best = null;
  sweepView.shown = [];
  sweepView.mapped = '';
  $('#sweep-figures').hidden = true;
  delete $('#sweep-figures').dataset.sweep;
  await pollSweep(id);
}

async function pollSweep(id) {
  if (sweepView.id !== id) return;
  let job;
  let points;
  try {
    [job, points] = await Promise.all([api(jobUrl(id)), api(jobUrl(id, '/points'))]);
  } catch (e) {
    $('#sweep-progress').textContent = e.message;
    return;
  }
  if (sweepView.id !== id) return;
  sweepView.job = job;
  sweepView.shape = points.shape;
  const figure = job.settings.sweep.figure;
  if (!points.points.length) $('#sweep-view-title').textContent = `${jobName(job)}: ${figureInfo(figure).label.toLowerCase()}`;
  document.title = `${jobName(job)} — facetlight`;
  if (job.state === 'succeeded' && job.links.best && !sweepView.best) {
    try {
      sweepView.best = await api(job.links.best);
    } catch (e) {
      $('#sweep-best').replaceChildren(h('p', { class: 'form-error' }, `The best design could not be read: ${e.message}`));
    }
    if (sweepView.id !== id) return;
  }
  $('#sweep-progress').textContent = progressText(job);
  sweepView.points = points;
  if (!sweepView.shown.length) sweepView.shown.push(figure);
  figurePicker(points, figure);
  drawSweep(points, figure, sweepView.best);
  if (sweepView.best) $('#sweep-best').replaceChildren(bestCard(sweepView.best, points.axes));
  if (job.state === 'succeeded') {
    $('#sweep-links').replaceChildren(...Object.entries(job.links)
      .filter(([k]) => ['sweep', 'sweep_csv', 'sweep_picture', 'best', 'best_obj', 'best_asc'].includes(k))
      .map(([k, href]) => h('a', { class: 'button secondary small', href }, k.replace('_', ' '))));
  }
  if (job.state === 'queued' || job.state === 'running') sweepView.timer = setTimeout(() => pollSweep(id), POLL_ACTIVE_MS);
}

// The server's progress in words: the round under way and its points (a search's rounds have their own grids).
function progressText(job) {
  const p = job.progress;
  const points = `${p.points_done} of ${p.points_total} points`;
  const where = p.steps > 1 ? `round ${Math.max(1, p.step)} of ${p.steps}: ${points}` : points;
  return `${job.state} · ${where} · ${Math.round(p.overall * 100)} %${job.error ? ` · ${job.error}` : ''}`;
}

// The search's answer: the refined best design with its 95 % interval, its ties and the command that cuts it.
function bestCard(best, axes) {
  const f = figureInfo(best.figure);
  const d = best.best;
  const fmt = (v) => (f.degrees ? `${fmtNumber(v, 3)}°` : f.points ? fmtNumber(v, 1) : f.cielab ? fmtNumber(v, 2) : `${fmtNumber(v * 100, 2)} %`);
  const where = axes.map((a) => `${humanize(a.name)} ${fmtNumber(d.values[a.name], 4)}${a.unit === 'deg' ? '°' : a.unit === '%' ? ' %' : ''}`).join(', ');
  const ties = best.ties.length;
  return h('section', { class: 'card sweep-best-card', 'aria-labelledby': 'sweep-best-title' },
    h('h2', { id: 'sweep-best-title' }, `★ Best design: ${where}`),
    h('p', { class: 'best-figure' }, `${f.label} ${fmt(d.value)}, 95 % interval ${fmt(d.interval[0])} to ${fmt(d.interval[1])}`,
      ` (${fmtNumber(d.photons, 0)} photons${best.constraints.length ? `; ${best.constraints.join(', ')}` : ''})`),
    h('p', { class: 'hint' }, ties ? `${ties} other design${ties === 1 ? '' : 's'} of the last round cannot be told apart from it at this photon count.`
      : 'No other design of the last round comes within its noise.'),
    // A library shape's best is a facetlight cut line; a design's is its tweaked .asc (docs/gemcad.md).
    d.command ? h('p', {}, 'Cut it: ', h('code', { class: 'best-command' }, `${d.command} --out best.obj`))
      : h('p', {}, 'The design with these tier angles: ', h('a', { href: jobUrl(sweepView.id, '/best.asc'), download: 'best.asc' }, 'best.asc'), ' (GemCad)'),
    h('button', { type: 'button', class: 'button secondary small', 'data-action': 'open-best', onclick: () => openBest(d) },
      'Open as a job'));
}

// Traces the best design as a job of its own, at the search's last photon count, and opens it.
async function openBest(d) {
  const { sweep, name, ...settings } = sweepView.job.settings;
  try {
    const created = await api('/api/jobs', {
      method: 'POST', headers: { 'Content-Type': 'application/json', Accept: 'application/json' },
      body: JSON.stringify({ ...settings, mesh: sweepView.shape, render: false, photons: d.photons, cut: d.cut }),
    });
    refreshJobs();
    location.hash = `#/jobs/${created.id}`;
  } catch (e) {
    $('#sweep-best').append(h('p', { class: 'form-error', role: 'alert' }, e.message));
  }
}

function label(axis) { return axis.unit ? `${humanize(axis.name)} (${axis.unit})` : humanize(axis.name); }
function axisValues(axis) { return axis.values || axis.choices.map((_, i) => i); }
function axisText(axis, i) { return axis.values ? fmtNumber(axis.values[i], 4) : humanize(axis.choices[i]); }
function scale(lo, hi, a, b) { return (v) => (hi === lo ? (a + b) / 2 : a + ((v - lo) / (hi - lo)) * (b - a)); }

function ticks(lo, hi, n = 5) {
  if (hi === lo) return [lo];
  const raw = (hi - lo) / n;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= raw);
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push(Number(v.toPrecision(12)));
  return out;
}

// Axes, ticks and their labels around the plot area.
function frame(x, xs, xAxis, yTicks, y, yLabel) {
  const g = svg('g', { class: 'chart-axes' });
  const bottom = H - M.bottom;
  g.append(svg('line', { x1: M.left, y1: bottom, x2: W - M.right, y2: bottom }), svg('line', { x1: M.left, y1: M.top, x2: M.left, y2: bottom }));
  xs.forEach((v, i) => g.append(svg('text', { x: x(v), y: bottom + 16, 'text-anchor': 'middle' }, xAxis.values ? fmtNumber(v, 3) : axisText(xAxis, i))));
  for (const t of yTicks) {
    g.append(svg('line', { x1: M.left - 4, y1: y(t), x2: M.left, y2: y(t) }),
      svg('text', { x: M.left - 6, y: y(t) + 4, 'text-anchor': 'end' }, yLabel.format(t)));
  }
  g.append(svg('text', { x: (M.left + W - M.right) / 2, y: H - 14, 'text-anchor': 'middle', class: 'axis-title' }, label(xAxis)),
    svg('text', { x: 16, y: (M.top + bottom) / 2, 'text-anchor': 'middle', transform: `rotate(-90 16 ${(M.top + bottom) / 2})`, class: 'axis-title' }, yLabel.title));
  return g;
}

// The point's values in the axes' order, then every figure the sweep reports with its standard error.
function pointText(pt, axes, figures) {
  const values = axes.map((a) => {
    const v = pt.values[a.name];
    return `${humanize(a.name)} ${typeof v === 'number' ? fmtNumber(v, 4) : humanize(v)}`;
  }).join(', ');
  if (pt.error) return `${values}: cannot be made (${pt.error})`;
  const figs = figures.map((key) => `${figureInfo(key).label.toLowerCase()} ${fmtFigure(figureInfo(key), figuresOf(pt, key))}`);
  const depth = pt.proportions && pt.proportions.total_depth_pct;
  return `${values}: ${figs.join(' · ')}${Number.isFinite(depth) ? ` · total depth ${fmtNumber(depth, 1)} %` : ''}`;
}

// The design of a point as a job of its own: the sweep's settings, its shape with the point's parameters; the
// server names it by them (the sweep's name is not the design's).
function designJob(job, shape, point) {
  const { sweep, name, ...settings } = job.settings;
  const design = { ...settings, mesh: shape, render: false, light: { ...settings.light }, cut: { ...sweep.set } };
  for (const [name, value] of Object.entries(point.values)) {
    if (name === 'tilt') design.light.tilt_deg = value;
    else if (name === 'head_shadow') design.light.head_shadow_deg = value;
    else if (name === 'light') design.light.model = value;
    else if (name === 'material') design.material = value;
    else if (name === 'n' || name === 'size_mm') design[name] = value;
    else if (name.startsWith('optic_axis_')) {
      design.optic_axis = { ...settings.optic_axis, [name.replace('optic_axis_', '') + '_deg']: value };
    } else design.cut[name] = value;
  }
  return design;
}

// Traces the point's design as a normal job and, once it has finished, shows it in the compare view.
async function openDesign(point) {
  const tooltip = $('#sweep-tooltip');
  try {
    const created = await api('/api/jobs', {
      method: 'POST', headers: { 'Content-Type': 'application/json', Accept: 'application/json' },
      body: JSON.stringify(designJob(sweepView.job, sweepView.shape, point)),
    });
    tooltip.textContent = `Tracing that design as job ${shortId(created.id)}…`;
    refreshJobs();
    let state = created.state;
    while (state === 'queued' || state === 'running') {
      await new Promise((resolve) => { setTimeout(resolve, POLL_ACTIVE_MS); });
      state = (await api(jobUrl(created.id))).state;
    }
    if (state !== 'succeeded') throw new Error(`the design's job ${shortId(created.id)} ${state}`);
    sweepView.compared.push(created.id);
    location.hash = `#/compare/${sweepView.compared.join(',')}`;
  } catch (e) {
    tooltip.textContent = e.message;
  }
}

function hoverable(el, point, data) {
  const text = pointText(point, data.axes, data.figures);
  el.setAttribute('tabindex', '0');
  el.setAttribute('aria-label', text);
  const show = () => { $('#sweep-tooltip').textContent = text; };
  el.addEventListener('mouseenter', show);
  el.addEventListener('focus', show);
  if (!point.error) {
    el.addEventListener('click', () => openDesign(point));
    el.addEventListener('keydown', (ev) => { if (ev.key === 'Enter') openDesign(point); });
  }
  el.append(svg('title', {}, text));
  return el;
}

// Where value `v` lies among an axis's ascending values, in (fractional) steps from the first.
function stepsAlong(values, v) {
  for (let i = 0; i + 1 < values.length; ++i) {
    if (v <= values[i + 1]) return i + Math.max(0, (v - values[i]) / (values[i + 1] - values[i]));
  }
  return values.length - 1;
}

// Colours for the curves, one a figure: Okabe and Ito's set, told apart with any colour vision (Okabe & Ito 2008,
// "Color Universal Design"); its yellow left out, too faint on white.
const CURVE_COLOURS = ['#0072B2', '#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9', '#000000'];

// Shares in %, the mean separation in degrees, the score in points, L*, a*, b* and C*ab in CIELAB units.
function unitOf(key) {
  const { degrees, points, cielab } = figureInfo(key);
  return degrees ? '°' : points ? 'points' : cielab ? 'CIELAB' : '%';
}
function formatIn(unit) {
  if (unit === 'CIELAB') return (v) => fmtNumber(v, 2);
  return unit === '°' ? (v) => fmtNumber(v, 3) : unit === 'points' ? (v) => fmtNumber(v, 1) : (v) => fmtNumber(v * 100, 2);
}

// A text's width in the chart's font, measured in a hidden chart (a guess by its length before there is a page).
let measurer = null;
function textWidth(text) {
  if (!measurer) {
    measurer = svg('svg', { class: 'sweep-svg', 'aria-hidden': 'true', style: 'position:absolute;left:0;top:0;width:0;height:0;visibility:hidden' }, svg('text', {}));
    document.body.append(measurer);
  }
  measurer.firstChild.textContent = text;
  return measurer.firstChild.getComputedTextLength() || text.length * 7;
}
// `text` broken at spaces into lines no wider than `width` (a word longer than that is a line of its own).
function wrapText(text, width) {
  const lines = [];
  for (const word of text.split(' ')) {
    const longer = lines.length ? `${lines[lines.length - 1]} ${word}` : word;
    if (lines.length && textWidth(longer) <= width) lines[lines.length - 1] = longer;
    else lines.push(word);
  }
  return lines;
}
const LINE = 14;
// Lines of text from (x, y) down.
function textBlock(x, y, lines, attrs = {}) {
  return svg('text', { x, y, ...attrs }, ...lines.map((line, i) => svg('tspan', { x, dy: i ? LINE : 0 }, line)));
}

// The figures a one-axis sweep's chart shows (the job's figure first), as checkboxes of those it measured: each
// curve in its colour; figures in another unit than those ticked wait until those are unticked.
function figurePicker(data, figure) {
  const box = $('#sweep-figures');
  if (data.axes.length !== 1) {
    mapPicker(box, data, figure);
    return;
  }
  if (box.dataset.sweep !== sweepView.id) {
    box.dataset.sweep = sweepView.id;
    const keys = [figure, ...data.figures.filter((k) => k !== figure)];
    box.replaceChildren(h('legend', {}, 'Figures on the chart'), ...keys.map((key) => h('label', { class: 'sweep-figure' },
      h('input', { type: 'checkbox', name: 'sweep-figure', value: key, onchange: (ev) => {
        const { shown } = sweepView;
        if (ev.target.checked) shown.push(key);
        else shown.splice(shown.indexOf(key), 1);
        figurePicker(sweepView.points, figure);
        drawSweep(sweepView.points, figure, sweepView.best);
      } }), ` ${figureInfo(key).label} (${unitOf(key)})`)));
  }
  box.hidden = false;
  const { shown } = sweepView;
  const unit = shown.length ? unitOf(shown[0]) : null;
  for (const input of box.querySelectorAll('input')) {
    const at = shown.indexOf(input.value);
    const other = at < 0 && unitOf(input.value) !== unit;
    input.checked = at >= 0;
    // The last one ticked stays: a chart of nothing says nothing.
    input.disabled = (at >= 0 && shown.length === 1) || other;
    input.parentElement.style.borderColor = at >= 0 ? CURVE_COLOURS[at % CURVE_COLOURS.length] : 'transparent';
    input.parentElement.title = other ? `In ${unitOf(input.value)}: untick the figures in ${unit} to draw it` : '';
  }
}

// The figure a two-axis sweep's map colours by, one of those it measured (the job's first): the map, its
// legend and its star are then the CLI's map_<figure>.png's (sweep_pictures.cpp's sweepMap).
function mapPicker(box, data, figure) {
  if (box.dataset.sweep !== sweepView.id) {
    box.dataset.sweep = sweepView.id;
    const keys = [figure, ...data.figures.filter((k) => k !== figure)];
    const select = h('select', { id: 'sweep-map-figure', onchange: (ev) => {
      sweepView.mapped = ev.target.value;
      drawSweep(sweepView.points, figure, sweepView.best);
    } }, keys.map((key) => h('option', { value: key }, `${figureInfo(key).label} (${unitOf(key)})`)));
    box.replaceChildren(h('legend', {}, 'Figure on the map'),
      h('label', { class: 'sweep-map-figure' }, h('span', { class: 'visually-hidden' }, 'Colour the map by '), select));
  }
  box.hidden = false;
}

function drawSweep(data, figure, best) {
  const chart = $('#sweep-chart');
  if (!data.points.length) return;
  // A map of another figure than the search's: its own highest point starred, as the CLI's.
  const mapped = data.axes.length === 1 ? figure : (sweepView.mapped || figure);
  const root = svg('svg', { viewBox: `0 0 ${W} ${H}`, class: 'sweep-svg', role: 'img',
    'aria-label': `${figureInfo(mapped).label} over ${data.axes.map((a) => humanize(a.name)).join(' and ')}` });
  if (data.axes.length === 1) drawCurves(root, data, sweepView.shown.length ? sweepView.shown : [figure], best);
  else drawMap(root, data, mapped, best && best.figure === mapped ? best : null);
  if (sweepView.job) $('#sweep-view-title').textContent = `${jobName(sweepView.job)}: ${figureInfo(mapped).label.toLowerCase()}`;
  chart.replaceChildren(root);
}

// One varied quantity: each figure against it with its ±1σ band, in its own colour, and the search's best.
function drawCurves(root, data, figures, best) {
  const ok = data.points.filter((p) => !p.error);
  const value = (p, key) => figuresOf(p, key)[key];
  const sigma = (p, key) => figuresOf(p, key)[`${key}_stderr`];
  const axis = data.axes[0];
  const xs = axisValues(axis);
  const x = scale(Math.min(...xs), Math.max(...xs), M.left + 10, W - M.right - 10);
  const series = figures.map((key) => ({ key, points: ok.filter((p) => Number.isFinite(value(p, key))).sort((a, b) => a.at[0] - b.at[0]) }));
  const ends = series.flatMap(({ key, points }) => points.flatMap((p) => [value(p, key) - sigma(p, key), value(p, key) + sigma(p, key)]));
  if (!ends.length) return;
  const lo = Math.min(...ends);
  const hi = Math.max(...ends);
  const y = scale(lo, hi, H - M.bottom - 10, M.top + 10);
  const unit = unitOf(figures[0]);
  const title = figures.length === 1 ? figureInfo(figures[0]).label : { '%': 'Share', '°': 'Degrees', points: 'Score', CIELAB: 'Colour' }[unit];
  root.append(frame(x, xs, axis, ticks(lo, hi), y, { title: `${title} (${unit})`, format: formatIn(unit) }));
  const xOf = (p) => x(xs[p.at[0]]);
  series.forEach(({ key, points }, k) => {
    const colour = CURVE_COLOURS[k % CURVE_COLOURS.length];
    const band = [...points.map((p) => `${xOf(p)},${y(value(p, key) + sigma(p, key))}`),
      ...[...points].reverse().map((p) => `${xOf(p)},${y(value(p, key) - sigma(p, key))}`)].join(' ');
    root.append(svg('polygon', { points: band, class: 'sweep-band', style: `fill:${colour}`, 'data-figure': key }),
      svg('polyline', { points: points.map((p) => `${xOf(p)},${y(value(p, key))}`).join(' '), class: 'sweep-line', style: `stroke:${colour}`, 'data-figure': key }));
    for (const p of points) {
      root.append(hoverable(svg('circle', { cx: xOf(p), cy: y(value(p, key)), r: 5, class: 'sweep-point', style: `fill:${colour}`,
        'data-at': p.at.join(','), 'data-figure': key }), p, data));
    }
  });
  const starred = best && figures.includes(best.figure);
  if (starred) {
    // The refined best at its own place, with its 95 % interval (which may reach beyond the grid's range).
    const bx = x(best.best.values[axis.name]);
    const clampY = (v) => Math.min(H - M.bottom, Math.max(M.top, y(v)));
    root.append(svg('line', { x1: bx, x2: bx, y1: clampY(best.best.interval[0]), y2: clampY(best.best.interval[1]), class: 'sweep-interval' }),
      svg('text', { x: bx, y: clampY(best.best.value) + 7, 'text-anchor': 'middle', class: 'sweep-best' }, '★'));
  }
  // The legend in the right margin: a swatch and the name of each figure (broken into lines that fit), the band.
  const lx = W - M.right + 10;
  const width = W - lx - 24 - 4;
  const legend = svg('g', { class: 'chart-legend' });
  let ly = M.top + 14;
  series.forEach(({ key }, k) => {
    const colour = CURVE_COLOURS[k % CURVE_COLOURS.length];
    const lines = wrapText(figureInfo(key).label.toLowerCase(), width);
    legend.append(svg('line', { x1: lx, y1: ly - 4, x2: lx + 20, y2: ly - 4, class: 'sweep-line', style: `stroke:${colour}` }),
      textBlock(lx + 24, ly, lines, { class: 'legend-figure' }));
    ly += lines.length * LINE + 6;
  });
  legend.append(svg('rect', { x: lx, y: ly - 9, width: 20, height: 10, class: 'sweep-band', style: 'fill:#555' }),
    svg('text', { x: lx + 24, y: ly }, '±1σ'));
  if (starred) legend.append(textBlock(lx, ly + LINE + 6, wrapText('★ best, 95 % interval', W - lx - 4)));
  root.append(legend);
}

// Two varied quantities: the figure as a filled map in viridis, the first axis across and the second up (as the
// CLI's map), the highest point or the search's refined best starred and the reference designs ringed.
function drawMap(root, data, figure, best) {
  const ok = data.points.filter((p) => !p.error);
  const value = (p) => figuresOf(p, figure)[figure];
  const values = ok.map(value);
  const unit = unitOf(figure);
  const pct = formatIn(unit);
  const [ax, ay] = data.axes;
  const xv = axisValues(ax);
  const yv = axisValues(ay);
  const cw = (W - M.left - M.right) / xv.length;
  const ch = (H - M.top - M.bottom) / yv.length;
  const lo = Math.min(...values);
  const hi = Math.max(...values);
  const colour = (v) => viridis(hi === lo ? 0.5 : (v - lo) / (hi - lo));
  // A place along an axis, in (fractional) cells from the first.
  const px = (i) => M.left + (i + 0.5) * cw;
  const py = (j) => H - M.bottom - (j + 0.5) * ch;
  root.append(frame((v) => px(xv.indexOf(v)), xv, ax, [], () => 0, { title: label(ay), format: String }));
  yv.forEach((v, j) => root.append(svg('text', { x: M.left - 6, y: py(j) + 4, 'text-anchor': 'end', class: 'chart-axes' }, axisText(ay, j))));
  for (const p of data.points) {
    const [i, j] = p.at;
    const rect = svg('rect', { x: px(i) - cw / 2, y: py(j) - ch / 2, width: cw, height: ch, class: p.error ? 'sweep-cell failed' : 'sweep-cell',
      fill: p.error ? '#ccc' : colour(value(p)), 'data-at': p.at.join(',') });
    root.append(hoverable(rect, p, data));
  }
  // The reference designs within the grid's span, as the CLI rings them; labels moved down where they would meet.
  const inside = (a, v) => a.values && v >= Math.min(...a.values) && v <= Math.max(...a.values);
  const placed = [];
  let references = 0;
  for (const r of data.references || []) {
    const [vx, vy] = [r.values[ax.name], r.values[ay.name]];
    if (!inside(ax, vx) || !inside(ay, vy)) continue;
    const cx = px(stepsAlong(xv, vx));
    const cy = py(stepsAlong(yv, vy));
    const w = textWidth(r.label);
    const right = cx + 11 + w <= W - M.right - 2;
    let ty = cy + 4;
    while (placed.some((b) => Math.abs(b - ty) < LINE)) ty += LINE;
    placed.push(ty);
    root.append(svg('g', { class: 'sweep-reference', 'data-shape': r.shape },
      svg('circle', { cx, cy, r: 7, class: 'sweep-reference-halo' }), svg('circle', { cx, cy, r: 7, class: 'sweep-reference-ring' }),
      svg('text', { x: right ? cx + 11 : cx - 11, y: ty, 'text-anchor': right ? 'start' : 'end', class: 'sweep-reference-label' }, r.label),
      svg('title', {}, `${r.label}: ${label(ax)} ${fmtNumber(vx, 4)}, ${label(ay)} ${fmtNumber(vy, 4)}`)));
    references += 1;
  }
  // The search's refined best between the grid's cells, else the highest point of the grid.
  const highest = ok.reduce((b, p) => (!b || value(p) > value(b) ? p : b), null);
  const star = best
    ? [stepsAlong(xv, best.best.values[ax.name]), stepsAlong(yv, best.best.values[ay.name])]
    : highest && highest.at;
  if (star) root.append(svg('text', { x: px(star[0]), y: py(star[1]) + 7, 'text-anchor': 'middle', class: 'sweep-best' }, '★'));
  // The legend: the figure's name and unit above the ramp, which is labelled at round values between its ends.
  const lx = W - M.right + 20;
  const legend = svg('g', { class: 'chart-legend' });
  const name = wrapText(`${figureInfo(figure).label} (${unit})`, W - lx - 4);
  legend.append(textBlock(lx, M.top + 4, name, { class: 'legend-title' }));
  const top = M.top + name.length * LINE + 8;
  const bottom = H - M.bottom;
  const steps = 32;
  for (let k = 0; k < steps; ++k) {
    const v = lo + ((hi - lo) * (k + 0.5)) / steps;
    root.append(svg('rect', { x: lx, y: bottom - (k + 1) * ((bottom - top) / steps), width: 16, height: (bottom - top) / steps + 0.5, fill: colour(v), class: 'legend-step' }));
  }
  const ly = scale(lo, hi, bottom, top);
  for (const t of ticks(lo, hi, 4)) {
    legend.append(svg('line', { x1: lx + 16, x2: lx + 20, y1: ly(t), y2: ly(t), class: 'legend-tick' }),
      svg('text', { x: lx + 22, y: ly(t) + 4, class: 'legend-label' }, pct(t)));
  }
  legend.append(svg('text', { x: lx, y: bottom + 20 }, best ? '★ best (refined)' : '★ highest'));
  if (references) legend.append(svg('text', { x: lx, y: bottom + 20 + LINE }, '◯ reference designs'));
  root.append(legend);
}
