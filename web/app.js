// The facetlight page: submit a study, watch the jobs, read one result, compare several. Plain ES module, no
// build step, no requests beyond this server's /api. Everything the server sends is put in the page as text
// (never as HTML): uploaded file names are untrusted.

const POLL_ACTIVE_MS = 600;  // while a job is queued or running
const POLL_IDLE_MS = 4000;
const JOBS_PER_PAGE = 10;
const REGIONS = ['table', 'crown', 'girdle', 'pavilion'];
const STATES = {
  queued: { glyph: '◷', label: 'Queued' },
  running: { glyph: '▶', label: 'Running' },
  succeeded: { glyph: '✓', label: 'Finished' },
  failed: { glyph: '✕', label: 'Failed' },
  canceled: { glyph: '⊘', label: 'Canceled' },
};
// The figures of merit of the statistics (docs/stats-schema.md), each with its standard error.
const FIGURES = [
  { key: 'crown_return', label: 'Crown return', hint: 'Leaves through table and crown, upward' },
  { key: 'crown_return_with_reflection', label: 'With surface reflection', hint: 'Crown return plus first-surface glare' },
  { key: 'weighted_return', label: 'Cosine-weighted return', hint: 'Crown return weighted by closeness to vertical' },
  { key: 'cone_return_30', label: 'Within 30° cone', hint: 'Crown return within 30° of vertical, outside the head cone' },
  { key: 'cone_return_45', label: 'Within 45° cone', hint: 'Crown return within 45° of vertical' },
  { key: 'cone_return_60', label: 'Within 60° cone', hint: 'Crown return within 60° of vertical' },
  { key: 'leakage', label: 'Leakage', hint: 'Leaves through pavilion and girdle (lower is better)', lowerIsBetter: true },
];
const FACET_COLUMNS = [
  { key: 'id', label: 'Id', numeric: true },
  { key: 'name', label: 'Name' },
  { key: 'region', label: 'Region' },
  { key: 'area', label: 'Area', numeric: true, format: (v) => fmtNumber(v, 4) },
  { key: 'entering', label: 'Entering', numeric: true, format: fmtInt },
  { key: 'reflected', label: 'Reflected', numeric: true, format: fmtInt },
  { key: 'internal_reflections', label: 'Internal refl.', numeric: true, format: fmtInt },
  { key: 'leaving', label: 'Leaving', numeric: true, format: fmtInt },
  { key: 'leaving_share', label: 'Leaving share', numeric: true },
];

const $ = (selector, root = document) => root.querySelector(selector);

// --- small DOM helper: h('p', {class: 'x'}, 'text', child) --------------------------------------------------
function h(tag, attrs = {}, ...children) {
  const el = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false) continue;
    if (key === 'class') el.className = value;
    else if (key === 'text') el.textContent = value;
    else if (key.startsWith('on')) el.addEventListener(key.slice(2), value);
    else if (key === 'style') el.style.cssText = value;
    else el.setAttribute(key, value === true ? '' : String(value));
  }
  for (const child of children.flat(Infinity)) {
    if (child === undefined || child === null || child === false) continue;
    el.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return el;
}

// --- formatting ---------------------------------------------------------------------------------------------
const intFormat = new Intl.NumberFormat('en-US', { maximumFractionDigits: 0 });
function fmtInt(v) { return Number.isFinite(v) ? intFormat.format(v) : '—'; }
function fmtNumber(v, digits = 3) {
  return Number.isFinite(v) ? v.toLocaleString('en-US', { maximumFractionDigits: digits }) : '—';
}
// Decimals that show the standard error to two significant figures (in percentage points).
function decimalsFor(stderrPct) {
  if (!(stderrPct > 0)) return 2;
  return Math.min(4, Math.max(1, 1 - Math.floor(Math.log10(stderrPct))));
}
function fmtPct(share, stderr) {
  if (!Number.isFinite(share)) return '—';
  const d = decimalsFor(stderr * 100);
  return `${(share * 100).toFixed(d)} %`;
}
function fmtPctErr(share, stderr) {
  if (!Number.isFinite(share)) return '—';
  const d = decimalsFor(stderr * 100);
  return `${(share * 100).toFixed(d)} % ± ${(stderr * 100).toFixed(d)}`;
}
function fmtTime(iso) {
  if (!iso) return '';
  const t = new Date(iso);
  if (Number.isNaN(t.getTime())) return iso;
  const sameDay = t.toDateString() === new Date().toDateString();
  return sameDay ? t.toLocaleTimeString('en-GB') : t.toLocaleString('en-GB', { dateStyle: 'medium', timeStyle: 'short' });
}
function fmtDuration(seconds) {
  if (!Number.isFinite(seconds)) return '—';
  return seconds < 60 ? `${seconds.toFixed(seconds < 10 ? 2 : 1)} s` : `${Math.floor(seconds / 60)} min ${Math.round(seconds % 60)} s`;
}
function humanize(name) { return String(name).replace(/_/g, ' '); }
function shortId(id) { return String(id).slice(0, 8); }

// --- the API ------------------------------------------------------------------------------------------------
class ApiError extends Error {
  constructor(status, detail, field) {
    super(detail);
    this.status = status;
    this.field = field || '';
  }
}

async function api(path, options = {}) {
  let res;
  try {
    res = await fetch(path, { headers: { Accept: 'application/json' }, ...options });
  } catch {
    throw new ApiError(0, 'the service cannot be reached; is facetlight-server running?');
  }
  if (res.status === 204) return null;
  const type = res.headers.get('Content-Type') || '';
  const body = type.includes('json') ? await res.json().catch(() => null) : await res.text();
  if (!res.ok) {
    const detail = body && typeof body === 'object' ? body.detail || body.title : `HTTP ${res.status}`;
    throw new ApiError(res.status, detail, body && typeof body === 'object' ? body.field : '');
  }
  return body;
}

const jobUrl = (id, tail = '') => `/api/jobs/${encodeURIComponent(id)}${tail}`;

// --- progress: one bar across the study's phases ------------------------------------------------------------
function phaseKey(phase) { return String(phase || '').toLowerCase().replace(/[^a-z]/g, ''); }

// Overall fraction and a caption. The server reports the fraction of the current phase; a study with pictures
// has three phases (tracing, photon map, rendering), one without only the first.
function overallProgress(job) {
  const p = job.progress || {};
  if (job.state === 'succeeded') return { fraction: 1, caption: 'Done' };
  if (job.state === 'queued') {
    return { fraction: 0, caption: job.queue_position ? `Waiting, position ${job.queue_position} in the queue` : 'Waiting' };
  }
  if (job.state === 'failed') return { fraction: p.fraction || 0, caption: 'Failed' };
  if (job.state === 'canceled') return { fraction: p.fraction || 0, caption: 'Canceled' };
  const rendered = job.settings && job.settings.render && typeof job.settings.render === 'object';
  const phases = rendered ? ['tracing', 'photonmap', 'rendering'] : ['tracing'];
  const index = phases.indexOf(phaseKey(p.phase));
  const within = Math.min(1, Math.max(0, Number(p.fraction) || 0));
  const fraction = index < 0 ? 0 : (index + within) / phases.length;
  const step = index < 0 ? '' : ` · step ${index + 1} of ${phases.length}`;
  const detail = p.total ? ` ${Math.floor(within * 100)} %` : '';
  const cancel = job.cancel_requested ? ' · canceling' : '';
  return { fraction, caption: `${humanize(p.phase || 'starting')}${detail}${step}${cancel}` };
}

function progressBar(job, label) {
  const { fraction, caption } = overallProgress(job);
  const pct = Math.round(fraction * 100);
  return h('div', { class: 'progress-block' },
    h('div', {
      class: `progress state-${job.state}`, role: 'progressbar', 'aria-valuemin': 0, 'aria-valuemax': 100,
      'aria-valuenow': pct, 'aria-valuetext': `${pct} %, ${caption}`, 'aria-label': label,
    }, h('div', { class: 'progress-fill', style: `width:${pct}%` })),
    h('p', { class: 'progress-text' }, h('span', { class: 'progress-pct' }, `${pct} %`), h('span', {}, caption)));
}

function stateBadge(state) {
  const s = STATES[state] || { glyph: '?', label: state };
  return h('span', { class: `state state-${state}` }, h('span', { 'aria-hidden': 'true', class: 'glyph' }, s.glyph), s.label);
}

function jobSummary(settings) {
  if (!settings) return '';
  const parts = [`${fmtInt(settings.photons)} photons`, humanize(settings.material || '')];
  if (settings.light) {
    let light = settings.light.model;
    if (settings.light.tilt_deg) light += `, tilt ${settings.light.tilt_deg}°`;
    if (settings.light.model === 'hemisphere' && settings.light.sky) light += `, ${settings.light.sky} sky`;
    if (settings.light.model === 'hemisphere' && settings.light.head_shadow_deg) {
      light += `, head shadow ${settings.light.head_shadow_deg}°`;
    }
    parts.push(light);
  }
  if (settings.dispersion === false) parts.push('no dispersion');
  return parts.filter(Boolean).join(' · ');
}

// --- shapes -------------------------------------------------------------------------------------------------
const meshes = new Map();  // mesh name or id -> summary

function meshLabel(m) {
  const name = m.file_name || m.name || m.mesh;
  return m.error ? `${name} (cannot be read)` : `${name} — ${m.facet_count} facets`;
}

function displayMeshName(mesh) {
  const m = meshes.get(mesh);
  return m ? m.file_name || m.name || mesh : mesh;
}

async function loadMeshes(select) {
  const el = $('#f-mesh');
  const previous = select || el.value;
  let list;
  try {
    list = await api('/api/meshes');
  } catch (e) {
    el.replaceChildren(h('option', { value: '' }, 'Shapes unavailable'));
    showFieldError('mesh', e.message);
    return;
  }
  meshes.clear();
  const groups = [];
  for (const [key, title] of [['shipped', 'Shipped shapes'], ['uploaded', 'Your uploads']]) {
    const items = list[key] || [];
    if (!items.length) continue;
    groups.push(h('optgroup', { label: title }, items.map((m) => {
      meshes.set(m.mesh, m);
      return h('option', { value: m.mesh, disabled: Boolean(m.error) }, meshLabel(m));
    })));
  }
  if (!groups.length) groups.push(h('option', { value: '' }, 'No shapes yet: upload a mesh'));
  el.replaceChildren(...groups);
  // The classic round brilliant is the reference design people start from.
  const preferred = [previous, 'round_brilliant'].find((m) => m && meshes.has(m));
  if (preferred) el.value = preferred;
  describeMesh();
}

function describeMesh() {
  const m = meshes.get($('#f-mesh').value);
  const hint = $('#hint-mesh');
  if (!m || m.error) {
    hint.textContent = m ? m.error : 'Shipped shapes and your uploads, with their facet counts.';
    return;
  }
  const p = m.proportions || {};
  const parts = [`${m.facet_count} facets`];
  if (p.table_pct != null) parts.push(`table ${fmtNumber(p.table_pct, 1)} %`);
  if (p.crown_angle_deg != null) parts.push(`crown ${fmtNumber(p.crown_angle_deg, 1)}°`);
  if (p.pavilion_angle_deg != null) parts.push(`pavilion ${fmtNumber(p.pavilion_angle_deg, 1)}°`);
  if (p.lower_half_angle_deg != null) parts.push(`lower halves ${fmtNumber(p.lower_half_angle_deg, 2)}°`);
  if (p.total_depth_pct != null) parts.push(`depth ${fmtNumber(p.total_depth_pct, 1)} %`);
  if (!m.convex) parts.push('non-convex');
  hint.textContent = parts.join(' · ');
}

async function uploadMesh() {
  const input = $('#f-file');
  const status = $('#upload-status');
  clearFieldError('file');
  const file = input.files && input.files[0];
  if (!file) {
    showFieldError('file', 'Choose a mesh file first.');
    return;
  }
  const button = $('#upload-button');
  button.disabled = true;
  status.textContent = `Uploading ${file.name}…`;
  try {
    const m = await api(`/api/meshes?name=${encodeURIComponent(file.name)}`, {
      method: 'POST', headers: { 'Content-Type': 'application/octet-stream', Accept: 'application/json' }, body: file,
    });
    await loadMeshes(m.mesh);
    clearFieldError('mesh');
    status.textContent = `Uploaded ${m.file_name || file.name}: ${m.facet_count} facets. It is now the selected shape.`;
    input.value = '';
  } catch (e) {
    status.textContent = '';
    showFieldError('file', e.message);
  } finally {
    button.disabled = false;
  }
}

// --- the form -----------------------------------------------------------------------------------------------
function fieldError(field) { return document.getElementById(`err-${field}`); }

function showFieldError(field, message) {
  const err = fieldError(field);
  if (!err) return false;
  err.textContent = message;
  err.hidden = false;
  const wrapper = err.closest('.field');
  if (wrapper) wrapper.classList.add('invalid');
  const input = wrapper && wrapper.querySelector('input, select');
  if (input) input.setAttribute('aria-invalid', 'true');
  const details = err.closest('details');
  if (details) details.open = true;
  return true;
}

function clearFieldError(field) {
  const err = fieldError(field);
  if (!err) return;
  err.hidden = true;
  err.textContent = '';
  const wrapper = err.closest('.field');
  if (wrapper) {
    wrapper.classList.remove('invalid');
    const input = wrapper.querySelector('input, select');
    if (input) input.removeAttribute('aria-invalid');
  }
}

function clearFormErrors() {
  for (const err of document.querySelectorAll('#job-form .field-error')) clearFieldError(err.id.slice(4));
  const formError = $('#form-error');
  formError.hidden = true;
  formError.textContent = '';
}

// A number input read for the job; empty or unreadable input is reported here, range checks are the server's.
function readNumber(form, name, errors, { required = true } = {}) {
  const input = form.elements[name];
  if (input.validity.badInput) {
    errors.push([name, `${name} must be a number`]);
    return undefined;
  }
  if (input.value.trim() === '') {
    if (required) errors.push([name, `${name} is required`]);
    return undefined;
  }
  return Number(input.value);
}

function buildJob(form) {
  const errors = [];
  const job = { mesh: form.elements.mesh.value };
  if (!job.mesh) errors.push(['mesh', 'Choose a shape, or upload a mesh']);
  job.photons = readNumber(form, 'photons', errors);
  const threads = readNumber(form, 'threads', errors, { required: false });
  if (threads !== undefined) job.threads = threads;
  const seed = readNumber(form, 'seed', errors, { required: false });
  if (seed !== undefined) job.seed = seed;
  job.light = {
    model: form.elements['light.model'].value,
    tilt_deg: readNumber(form, 'light.tilt_deg', errors),
  };
  if (job.light.model === 'hemisphere') {
    job.light.head_shadow_deg = readNumber(form, 'light.head_shadow_deg', errors);
    job.light.sky = form.elements['light.sky'].value;
  }
  job.material = form.elements.material.value;
  job.dispersion = form.elements.dispersion.checked;
  job.max_bounces = readNumber(form, 'max_bounces', errors);
  if (form.elements.render.checked) {
    job.render = {
      width: readNumber(form, 'render.width', errors),
      height: readNumber(form, 'render.height', errors),
      samples: readNumber(form, 'render.samples', errors),
      map_photons: readNumber(form, 'render.map_photons', errors),
      camera: { elevation_deg: readNumber(form, 'render.camera.elevation_deg', errors) },
    };
  } else {
    job.render = false;
  }
  return { job, errors };
}

function reportError(e) {
  if (e.field && showFieldError(e.field, e.message)) {
    const input = fieldError(e.field).closest('.field').querySelector('input, select');
    if (input) input.focus();
    return;
  }
  const formError = $('#form-error');
  formError.textContent = e.field ? `${e.field}: ${e.message}` : e.message;
  formError.hidden = false;
}

async function submitJob(event) {
  event.preventDefault();
  const form = event.currentTarget;
  clearFormErrors();
  const status = $('#submit-status');
  const { job, errors } = buildJob(form);
  if (errors.length) {
    for (const [field, message] of errors) showFieldError(field, message);
    const first = fieldError(errors[0][0]).closest('.field').querySelector('input, select');
    if (first) first.focus();
    status.textContent = '';
    return;
  }
  const button = $('#submit-button');
  button.disabled = true;
  status.textContent = 'Submitting…';
  try {
    const created = await api('/api/jobs', {
      method: 'POST', headers: { 'Content-Type': 'application/json', Accept: 'application/json' }, body: JSON.stringify(job),
    });
    status.textContent = `Job ${shortId(created.id)} queued: ${displayMeshName(created.mesh)}.`;
    jobsView.offset = 0;
    await refreshJobs();
  } catch (e) {
    status.textContent = '';
    reportError(e);
  } finally {
    button.disabled = false;
  }
}

function syncFormControls() {
  const form = $('#job-form');
  const hemisphere = form.elements['light.model'].value === 'hemisphere';
  form.elements['light.head_shadow_deg'].disabled = !hemisphere;
  form.elements['light.sky'].disabled = !hemisphere;
  const render = form.elements.render.checked;
  for (const input of $('#render-options').querySelectorAll('input')) input.disabled = !render;
  $('#render-options').classList.toggle('disabled', !render);
}

// --- the jobs list ------------------------------------------------------------------------------------------
const jobsView = { offset: 0, total: 0, jobs: [], selected: new Set(), timer: 0, pendingDelete: new Map() };

function anyActive(jobs) { return jobs.some((j) => j.state === 'queued' || j.state === 'running'); }

async function refreshJobs() {
  clearTimeout(jobsView.timer);
  let active = false;
  try {
    const page = await api(`/api/jobs?limit=${JOBS_PER_PAGE}&offset=${jobsView.offset}`);
    jobsView.jobs = page.jobs || [];
    jobsView.total = page.total || 0;
    renderJobs();
    active = anyActive(jobsView.jobs);
    setServerStatus(true);
  } catch (e) {
    setServerStatus(false, e.message);
  }
  jobsView.timer = setTimeout(refreshJobs, active ? POLL_ACTIVE_MS : POLL_IDLE_MS);
}

function jobItem(job) {
  const name = displayMeshName(job.mesh);
  const finished = job.state === 'succeeded';
  const title = finished
    ? h('a', { href: `#/jobs/${job.id}`, class: 'job-name' }, name)
    : h('span', { class: 'job-name' }, name);
  const actions = h('div', { class: 'job-actions' });
  if (finished) actions.append(h('a', { class: 'button secondary small', href: `#/jobs/${job.id}`, 'data-action': 'open' }, 'Open result'));
  if (job.state === 'queued' || job.state === 'running') {
    actions.append(h('button', {
      type: 'button', class: 'button secondary small', 'data-action': 'cancel',
      'aria-label': `Cancel job ${shortId(job.id)} (${name})`, disabled: Boolean(job.cancel_requested),
      onclick: () => cancelJob(job.id),
    }, job.cancel_requested ? 'Canceling…' : 'Cancel'));
  } else {
    const confirming = jobsView.pendingDelete.has(job.id);
    actions.append(h('button', {
      type: 'button', class: `button ${confirming ? 'danger' : 'secondary'} small`, 'data-action': 'delete',
      'aria-label': confirming ? `Confirm: delete job ${shortId(job.id)} (${name})` : `Delete job ${shortId(job.id)} (${name})`,
      onclick: () => deleteJob(job.id),
    }, confirming ? 'Delete? Click again' : 'Delete'));
  }
  const select = finished
    ? h('input', {
      type: 'checkbox', class: 'compare-box', 'data-id': job.id, 'data-action': 'select', checked: jobsView.selected.has(job.id),
      'aria-label': `Compare job ${shortId(job.id)} (${name})`,
      onchange: (ev) => {
        if (ev.target.checked) jobsView.selected.add(job.id);
        else jobsView.selected.delete(job.id);
        updateCompareButton();
      },
    })
    : h('span', { class: 'compare-box-placeholder', 'aria-hidden': 'true' });
  const meta = [jobSummary(job.settings), `job ${shortId(job.id)}`, `created ${fmtTime(job.created_at)}`];
  if (job.threads && job.threads.note) meta.push(`${job.threads.used} threads (${job.threads.note})`);
  return h('li', { class: `job state-${job.state}`, 'data-id': job.id, 'data-state': job.state },
    h('div', { class: 'job-top' }, select, h('div', { class: 'job-title' }, title), stateBadge(job.state)),
    h('p', { class: 'job-meta' }, meta.join(' · ')),
    progressBar(job, `Progress of job ${shortId(job.id)} (${name})`),
    job.state === 'failed' && job.error ? h('p', { class: 'job-error' }, h('strong', {}, 'Error: '), job.error) : null,
    actions);
}

// Redraws only what changed, so a click or hover on a job is not lost to a poll: an item is rebuilt when its
// state or actions change, and only its progress bar is swapped while it runs.
function jobSignature(job) {
  return JSON.stringify([job.state, job.cancel_requested, job.error, job.mesh, displayMeshName(job.mesh),
    jobsView.selected.has(job.id), jobsView.pendingDelete.has(job.id), job.threads && job.threads.note]);
}

function renderJobs() {
  const list = $('#job-list');
  const old = new Map([...list.children].map((li) => [li.dataset.id, li]));
  const items = jobsView.jobs.map((job) => {
    const name = displayMeshName(job.mesh);
    const signature = jobSignature(job);
    const existing = old.get(job.id);
    if (existing && existing.dataset.signature === signature) {
      const bar = existing.querySelector('.progress-block');
      const fresh = progressBar(job, `Progress of job ${shortId(job.id)} (${name})`);
      if (bar.querySelector('.progress').getAttribute('aria-valuetext') !== fresh.querySelector('.progress').getAttribute('aria-valuetext')) {
        bar.replaceWith(fresh);
      }
      return existing;
    }
    const li = jobItem(job);
    li.dataset.signature = signature;
    return li;
  });
  const focused = document.activeElement && list.contains(document.activeElement) && !items.includes(document.activeElement.closest('li'))
    ? { id: document.activeElement.closest('li').dataset.id, action: document.activeElement.dataset.action }
    : null;
  items.forEach((li, i) => {
    if (list.children[i] !== li) list.insertBefore(li, list.children[i] || null);
  });
  while (list.children.length > items.length) list.lastElementChild.remove();
  if (focused) {
    const li = list.querySelector(`li[data-id="${CSS.escape(focused.id)}"]`);
    const target = li && (li.querySelector(`[data-action="${focused.action}"]`) || li.querySelector('a, button, input'));
    if (target) target.focus();
  }
  $('#jobs-empty').hidden = jobsView.jobs.length > 0;
  const from = jobsView.total ? jobsView.offset + 1 : 0;
  const to = jobsView.offset + jobsView.jobs.length;
  $('#jobs-page').textContent = jobsView.total > JOBS_PER_PAGE ? `${from}–${to} of ${jobsView.total}` : '';
  $('#jobs-prev').disabled = jobsView.offset === 0;
  $('#jobs-next').disabled = to >= jobsView.total;
  $('#jobs-prev').closest('.pager').hidden = jobsView.total <= JOBS_PER_PAGE;
  updateCompareButton();
}

function updateCompareButton() {
  const n = jobsView.selected.size;
  const button = $('#compare-selected');
  button.disabled = n < 2;
  button.textContent = n ? `Compare selected (${n})` : 'Compare selected';
}

async function cancelJob(id) {
  try {
    await api(jobUrl(id, '/cancel'), { method: 'POST' });
  } catch (e) {
    alertStatus(`Cannot cancel: ${e.message}`);
  }
  refreshJobs();
}

async function deleteJob(id) {
  if (!jobsView.pendingDelete.has(id)) {
    // Two clicks delete: a result costs minutes to make again.
    jobsView.pendingDelete.set(id, setTimeout(() => { jobsView.pendingDelete.delete(id); renderJobs(); }, 5000));
    renderJobs();
    return;
  }
  clearTimeout(jobsView.pendingDelete.get(id));
  jobsView.pendingDelete.delete(id);
  try {
    await api(jobUrl(id), { method: 'DELETE' });
    jobsView.selected.delete(id);
  } catch (e) {
    alertStatus(`Cannot delete: ${e.message}`);
  }
  refreshJobs();
}

function alertStatus(message) {
  const el = $('#submit-status');
  el.textContent = message;
}

let lastHealth = '';
async function refreshHealth() {
  try {
    const health = await api('/healthz');
    lastHealth = `Service ready · ${health.cores} cores`;
    setServerStatus(true);
    return health;
  } catch (e) {
    setServerStatus(false, e.message);
    return null;
  }
}

function setServerStatus(ok, message) {
  const el = $('#server-status');
  el.classList.toggle('down', !ok);
  el.textContent = ok ? lastHealth || 'Service ready' : `Service unreachable: ${message}`;
}

// --- one result ---------------------------------------------------------------------------------------------
const resultView = { id: '', timer: 0, stats: null, sort: { key: 'leaving_share', dir: -1 } };

async function showResult(id) {
  clearTimeout(resultView.timer);
  resultView.id = id;
  const body = $('#result-body');
  let job;
  try {
    job = await api(jobUrl(id));
  } catch (e) {
    if (resultView.id !== id) return;
    body.replaceChildren(h('h1', { id: 'result-title' }, 'Job not found'), h('p', { class: 'form-error', role: 'alert' }, e.message));
    return;
  }
  if (resultView.id !== id) return;
  if (job.state !== 'succeeded') {
    body.replaceChildren(
      h('h1', { id: 'result-title' }, `${displayMeshName(job.mesh)} `, stateBadge(job.state)),
      h('p', { class: 'lede' }, jobSummary(job.settings)),
      h('div', { class: 'card' }, progressBar(job, `Progress of job ${shortId(job.id)}`),
        job.error ? h('p', { class: 'job-error' }, h('strong', {}, 'Error: '), job.error) : null));
    if (job.state === 'queued' || job.state === 'running') {
      resultView.timer = setTimeout(() => showResult(id), POLL_ACTIVE_MS);
    }
    return;
  }
  let stats;
  try {
    stats = await api(jobUrl(id, '/stats'));
  } catch (e) {
    body.replaceChildren(h('h1', { id: 'result-title' }, 'Statistics unavailable'), h('p', { class: 'form-error', role: 'alert' }, e.message));
    return;
  }
  if (resultView.id !== id) return;
  resultView.stats = stats;
  body.replaceChildren(resultPage(job, stats));
  $('#result-title').focus();
}

function figureCard(f, totals, emphasis = false) {
  const value = totals[f.key];
  const stderr = totals[`${f.key}_stderr`];
  return h('div', { class: `figure${emphasis ? ' emphasis' : ''}`, 'data-figure': f.key },
    h('dt', {}, f.label),
    h('dd', {},
      h('span', { class: 'figure-value' }, fmtPct(value, stderr)),
      h('span', { class: 'figure-err' }, Number.isFinite(stderr) ? `± ${(stderr * 100).toFixed(decimalsFor(stderr * 100))} pts` : ''),
      h('span', { class: 'figure-hint' }, f.hint)));
}

// --- heat-map overlay ----------------------------------------------------------------------------------------
// The heat-map's facets as shapes laid over its picture (heatmap.json): pointing at a facet names it and
// lights up its row of the facet table; pointing at a row lights up the facet.
const SVG_NS = 'http://www.w3.org/2000/svg';
function svg(tag, attrs = {}, ...children) {
  const el = document.createElementNS(SVG_NS, tag);
  for (const [key, value] of Object.entries(attrs)) el.setAttribute(key, String(value));
  el.append(...children);
  return el;
}

// Lights up facet `id` (null: none) within `root`: its shapes on the heat-map and its table row.
function linkFacet(root, id) {
  for (const el of root.querySelectorAll('.linked')) el.classList.remove('linked');
  if (id === null) return;
  for (const el of root.querySelectorAll(`[data-facet="${id}"]`)) el.classList.add('linked');
}

// Matplotlib's viridis (van der Walt & Smith, 2015) as core/colormap.h draws it: Matt Zucker's degree-6
// polynomial fit (shadertoy WlfXRN, CC0), so the page's colours match the pictures'.
const VIRIDIS_FIT = [[0.2777273272234177, 0.005407344544966578, 0.3340998053353061],
  [0.1050930431085774, 1.404613529898575, 1.384590162594685], [-0.3308618287255563, 0.214847559468213, 0.09509516302823659],
  [-4.634230498983486, -5.799100973351585, -19.33244095627987], [6.228269936347081, 14.17993336680509, 56.69055260068105],
  [4.776384997670288, -13.74514537774601, -65.35303263337234], [-5.435455855934631, 4.645852612178535, 26.3124352495832]];
function viridis(t) {
  const x = Math.min(1, Math.max(0, t));
  const rgb = [0, 1, 2].map((k) => {
    let v = VIRIDIS_FIT[6][k];
    for (let i = 5; i >= 0; i--) v = v * x + VIRIDIS_FIT[i][k];
    return Math.round(255 * Math.min(1, Math.max(0, v)));
  });
  return `rgb(${rgb.join(', ')})`;
}

// The end of a colour scale: the first of 1, 2 or 5 times a power of ten, in fifths, at or above `max`.
function scaleEnd(max) {
  if (!(max > 0)) return 1;
  const raw = max / 5;
  const p = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * p).find((v) => v >= raw);
  return Math.ceil(max / step - 1e-9) * step;
}

// Fetches the heat-map's layout and either lays its facets over the picture (overlay) or, with a common
// colour scale (the comparison), draws them in its place filled on that scale; both name the facet pointed at.
async function heatmapShapes(figure, href, stats, commonScale) {
  const anchor = figure.querySelector('a');
  let layout = null;
  try {
    layout = await api(href);
  } catch {
    // below: the picture as it is
  }
  if (!anchor || !anchor.isConnected) return;
  const drawing = commonScale > 0;
  if (!layout) {
    if (drawing) anchor.replaceChildren(h('img', { src: anchor.href, alt: 'Facet heat-map', decoding: 'async' }));
    return;
  }
  const facets = new Map(((stats && stats.facets) || []).map((f) => [f.id, f]));
  const hit = stats && stats.totals ? stats.totals.hit : 0;
  const describe = (f) => {
    const s = facets.get(f.id);
    return s ? `${humanize(f.name)} (${f.side}): ${fmtPctErr(s.leaving_share, shareStderr(s.leaving_share, hit))} of the light leaving`
      : humanize(f.name);
  };
  const polygons = layout.facets.map((f) => {
    const share = facets.has(f.id) ? facets.get(f.id).leaving_share : 0;
    const fill = drawing ? { fill: viridis(share / commonScale), stroke: '#1a1a1a', 'stroke-width': 1.2 } : {};
    return svg('polygon', { points: f.points.map((p) => p.join(',')).join(' '), 'data-facet': f.id, ...fill },
      svg('title', {}, describe(f)));
  });
  let shapes;
  if (drawing) {
    const xs = layout.facets.flatMap((f) => f.points.map((p) => p[0]));
    const ys = layout.facets.flatMap((f) => f.points.map((p) => p[1]));
    const [x0, y0] = [Math.min(...xs) - 8, Math.min(...ys) - 40];
    const [w, hgt] = [Math.max(...xs) + 8 - x0, Math.max(...ys) + 8 - y0];
    const titles = [['crown', 'Crown, from above'], ['pavilion', 'Pavilion, from below']].map(([side, title]) => {
      const sx = layout.facets.filter((f) => f.side === side).flatMap((f) => f.points.map((p) => p[0]));
      return sx.length ? svg('text', { x: (Math.min(...sx) + Math.max(...sx)) / 2, y: y0 + 24, 'text-anchor': 'middle', class: 'heat-side' }, title) : null;
    }).filter(Boolean);
    shapes = svg('svg', { class: 'heatmap-drawing', viewBox: `${x0} ${y0} ${w} ${hgt}`, role: 'img',
      'aria-label': `Facet heat-map: crown from above, pavilion from below, on the comparison's common scale (0 to ${(commonScale * 100).toFixed(1)} %)` },
    ...titles, ...polygons);
    anchor.replaceChildren(shapes);
    figure.insertBefore(h('div', { class: 'heat-legend' },
      h('span', {}, '0 %'),
      h('span', { class: 'heat-ramp', 'aria-hidden': 'true', style: `background: linear-gradient(to right, ${[0, 0.25, 0.5, 0.75, 1].map(viridis).join(', ')})` }),
      h('span', { class: 'heat-max' }, `${(commonScale * 100).toFixed(1)} %`)), figure.querySelector('figcaption'));
  } else {
    shapes = svg('svg', { class: 'heatmap-overlay', viewBox: `0 0 ${layout.width} ${layout.height}`, 'aria-hidden': 'true' }, ...polygons);
    anchor.append(shapes);
  }
  const readout = h('p', { class: 'heatmap-readout', 'aria-live': 'polite' }, 'Point at a facet to name it.');
  const root = figure.closest('.result, .compare-card') || figure;
  const byId = new Map(layout.facets.map((f) => [String(f.id), f]));
  shapes.addEventListener('mouseover', (e) => {
    const id = e.target.getAttribute && e.target.getAttribute('data-facet');
    if (id === null || !byId.has(id)) return;
    linkFacet(root, id);
    readout.textContent = describe(byId.get(id));
  });
  shapes.addEventListener('mouseleave', () => linkFacet(root, null));
  figure.append(readout);
}

// `commonScale` (the comparison): the heat-map is drawn on the page, its colours running from 0 to this share
// for every design compared, instead of each picture's own scale.
function pictures(job, name, stats, commonScale = 0) {
  const links = job.links || {};
  const render = job.settings && job.settings.render;
  if (!links.render) {
    return h('p', { class: 'empty' }, 'No pictures: this job ran without rendering (statistics only).');
  }
  const size = render ? { width: render.width, height: render.height } : {};
  const items = [
    { href: links.render, cls: 'pic-render', title: 'Render', alt: `Render of ${name} as the camera sees it` },
    { href: links.heatmap, cls: 'pic-heatmap', title: 'Facet heat-map', alt: `Heat-map of ${name}: facets shaded by the share of light leaving them` },
    { href: links.angular, cls: 'pic-angular', title: 'Exit angles', alt: `Chart of ${name}: where the light leaves, by angle from vertical` },
  ];
  const drawHeatmap = commonScale > 0 && links.heatmap_layout;
  const figures = items.map((p) => h('figure', { class: `picture ${p.cls}` },
    h('a', { href: p.href, target: '_blank', rel: 'noopener' },
      drawHeatmap && p.cls === 'pic-heatmap' ? h('div', { class: 'heatmap-pending' })
        : h('img', { src: p.href, alt: p.alt, ...(p.cls === 'pic-angular' ? {} : size), decoding: 'async' })),
    h('figcaption', {}, p.title)));
  if (links.heatmap_layout) heatmapShapes(figures[1], links.heatmap_layout, stats, drawHeatmap ? commonScale : 0);
  return h('div', { class: 'pictures' }, figures);
}

// Standard error of a share of the photons that hit the stone (binomial), as the statistics compute it.
function shareStderr(share, hit) { return hit > 0 ? Math.sqrt(Math.max(0, share * (1 - share)) / hit) : 0; }

// `compact` (the comparison's narrow cards) leaves the bars out.
function regionTable(regions, caption, hit, compact = false) {
  const max = Math.max(1e-12, ...REGIONS.map((r) => (regions[r] ? regions[r].share : 0)));
  return h('div', { class: 'table-scroll' }, h('table', { class: `data regions${compact ? ' compact' : ''}` },
    h('caption', {}, caption),
    h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Region'), h('th', { scope: 'col', class: 'num' }, 'Photons leaving'),
      h('th', { scope: 'col', class: 'num' }, 'Share ± s.e.'), h('th', { scope: 'col' }, h('span', { class: 'visually-hidden' }, 'Bar')))),
    h('tbody', {}, REGIONS.filter((r) => regions[r]).map((r) => h('tr', { 'data-region': r },
      h('th', { scope: 'row' }, h('span', { class: `swatch region-${r}`, 'aria-hidden': 'true' }), humanize(r)),
      h('td', { class: 'num' }, fmtInt(regions[r].leaving)),
      h('td', { class: 'num' }, fmtPctErr(regions[r].share, shareStderr(regions[r].share, hit))),
      h('td', { class: 'bar-cell' }, h('span', { class: `bar region-${r}`, style: `width:${(regions[r].share / max) * 100}%` })))))));
}

function facetTable(facets, hit) {
  const wrap = h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-labelledby': 'facet-caption' });
  const draw = () => {
    const { key, dir } = resultView.sort;
    const col = FACET_COLUMNS.find((c) => c.key === key);
    const sorted = [...facets].sort((a, b) => {
      const x = a[key];
      const y = b[key];
      const c = col.numeric ? x - y : String(x).localeCompare(String(y), 'en', { numeric: true });
      return c * dir || a.id - b.id;
    });
    const maxShare = Math.max(1e-12, ...facets.map((f) => f.leaving_share));
    const head = h('tr', {}, FACET_COLUMNS.map((c) => {
      const active = c.key === key;
      const sortState = active ? (dir > 0 ? 'ascending' : 'descending') : 'none';
      return h('th', { scope: 'col', class: c.numeric ? 'num' : '', 'aria-sort': sortState },
        h('button', {
          type: 'button', class: 'sort', 'data-sort': c.key,
          onclick: () => {
            resultView.sort = { key: c.key, dir: active ? -dir : (c.numeric ? -1 : 1) };
            draw();
            wrap.querySelector(`button[data-sort="${c.key}"]`).focus();
          },
        }, c.label, h('span', { class: 'sort-mark', 'aria-hidden': 'true' }, active ? (dir > 0 ? ' ▲' : ' ▼') : ' ↕')));
    }));
    const rows = sorted.map((f) => h('tr', {
      'data-facet': f.id, 'data-region': f.region,
      onmouseenter: (e) => linkFacet(e.currentTarget.closest('.result') || document, f.id),
      onmouseleave: (e) => linkFacet(e.currentTarget.closest('.result') || document, null),
    }, FACET_COLUMNS.map((c) => {
      if (c.key === 'leaving_share') {
        return h('td', { class: 'num share-cell' },
          h('span', { class: 'mini-track', 'aria-hidden': 'true' },
            h('span', { class: `bar mini region-${f.region}`, style: `width:${(f.leaving_share / maxShare) * 100}%` })),
          h('span', { class: 'share-text' }, fmtPct(f.leaving_share, shareStderr(f.leaving_share, hit))));
      }
      if (c.key === 'region') {
        return h('td', {}, h('span', { class: `swatch region-${f.region}`, 'aria-hidden': 'true' }), humanize(f.region));
      }
      const v = f[c.key];
      return h('td', { class: c.numeric ? 'num' : '' }, c.format ? c.format(v) : String(v ?? ''));
    })));
    wrap.replaceChildren(h('table', { class: 'data facets' },
      h('caption', { id: 'facet-caption' }, `Facets (${facets.length}) — sorted by ${FACET_COLUMNS.find((c) => c.key === key).label.toLowerCase()}, ${dir > 0 ? 'ascending' : 'descending'}`),
      h('thead', {}, head), h('tbody', {}, rows)));
  };
  draw();
  return wrap;
}

function proportionList(mesh) {
  const p = (mesh && mesh.proportions) || {};
  const rows = [
    ['Facets', mesh && mesh.facets], ['Table', p.table_pct, '%'], ['Crown height', p.crown_height_pct, '%'],
    ['Pavilion depth', p.pavilion_depth_pct, '%'], ['Girdle, thinnest', p.girdle_pct, '%'],
    ['Girdle, thickest', p.girdle_thickest_pct, '%'], ['Total depth', p.total_depth_pct, '%'],
    ['Crown angle', p.crown_angle_deg, '°'], ['Pavilion angle', p.pavilion_angle_deg, '°'],
    ['Star angle', p.star_angle_deg, '°'], ['Upper half angle', p.upper_half_angle_deg, '°'],
    ['Lower half angle', p.lower_half_angle_deg, '°'], ['Star length', p.star_pct, '%'],
    ['Lower half length', p.lower_half_pct, '%'],
  ].filter(([, v]) => v !== undefined && v !== null);
  return h('dl', { class: 'kv' }, rows.map(([k, v, unit]) => [h('dt', {}, k), h('dd', {}, unit ? `${fmtNumber(v, 2)}${unit === '%' ? ' %' : unit}` : String(v))]));
}

function resultPage(job, stats) {
  const name = displayMeshName(job.mesh);
  const totals = stats.totals || {};
  const timing = stats.timing || {};
  const base = jobUrl(job.id);
  return h('article', { class: 'result' },
    h('header', { class: 'result-head' },
      h('h1', { id: 'result-title', tabindex: -1 }, name, ' ', stateBadge(job.state)),
      h('p', { class: 'lede' }, `${jobSummary(job.settings)} · job ${shortId(job.id)} · finished ${fmtTime(job.finished_at)}`),
      h('p', { class: 'downloads' }, 'Download: ',
        h('a', { href: `${base}/stats`, download: `facetlight-${shortId(job.id)}.json` }, 'Statistics (JSON)'), ' · ',
        h('a', { href: `${base}/stats.csv`, download: `facetlight-${shortId(job.id)}.csv` }, 'Facet table (CSV)'))),
    h('section', { class: 'card', 'aria-labelledby': 'merit-title' },
      h('h2', { id: 'merit-title' }, 'Figures of merit'),
      h('p', { class: 'hint' }, 'Shares of the photons that hit the stone, with one standard error.'),
      h('dl', { class: 'figures' }, FIGURES.map((f, i) => figureCard(f, totals, i === 0)))),
    h('section', { class: 'card', 'aria-labelledby': 'pictures-title' },
      h('h2', { id: 'pictures-title' }, 'Pictures'), pictures(job, name, stats)),
    h('div', { class: 'result-grid' },
      h('section', { class: 'card', 'aria-labelledby': 'regions-title' },
        h('h2', { id: 'regions-title' }, 'Where the light leaves'), regionTable(stats.regions || {}, 'Light leaving each region', totals.hit)),
      h('section', { class: 'card', 'aria-labelledby': 'run-title' },
        h('h2', { id: 'run-title' }, 'The run'),
        h('dl', { class: 'kv' },
          h('dt', {}, 'Photons'), h('dd', {}, fmtInt(totals.photons)),
          h('dt', {}, 'Hit the stone'), h('dd', {}, fmtInt(totals.hit)),
          h('dt', {}, 'Reflected at entry'), h('dd', {}, fmtInt(totals.reflected_at_entry)),
          h('dt', {}, 'Entered'), h('dd', {}, fmtInt(totals.entered)),
          h('dt', {}, 'Exited'), h('dd', {}, fmtInt(totals.exited)),
          h('dt', {}, 'Trapped'), h('dd', {}, totals.trapped_share == null ? fmtInt(totals.trapped)
            : `${fmtInt(totals.trapped)} (${fmtNumber(100 * totals.trapped_share, 4)} % ± ${fmtNumber(100 * totals.trapped_share_stderr, 4)})`),
          h('dt', {}, 'Time'), h('dd', {}, `${fmtDuration(timing.seconds)} on ${timing.threads} thread${timing.threads === 1 ? '' : 's'}`),
          h('dt', {}, 'Speed'), h('dd', {}, `${fmtInt(timing.photons_per_second)} photons/s`))),
      h('section', { class: 'card', 'aria-labelledby': 'stone-title' },
        h('h2', { id: 'stone-title' }, 'The stone'), proportionList(stats.mesh))),
    h('section', { class: 'card', 'aria-labelledby': 'facet-caption' }, facetTable(stats.facets || [], totals.hit)));
}

// --- compare ------------------------------------------------------------------------------------------------
const compareView = { ids: [] };

async function showCompare(ids) {
  compareView.ids = ids;
  const choices = $('#compare-choices');
  const body = $('#compare-body');
  let finished = [];
  try {
    const page = await api('/api/jobs?limit=100');
    finished = (page.jobs || []).filter((j) => j.state === 'succeeded');
  } catch (e) {
    body.replaceChildren(h('p', { class: 'form-error', role: 'alert' }, e.message));
    return;
  }
  choices.replaceChildren(...(finished.length ? finished.map((j) => h('label', { class: 'choice' },
    h('input', { type: 'checkbox', name: 'job', value: j.id, checked: ids.includes(j.id) }),
    h('span', {}, h('strong', {}, displayMeshName(j.mesh)), ` · ${jobSummary(j.settings)} · job ${shortId(j.id)}`)))
    : [h('p', { class: 'empty' }, 'No finished jobs yet.')]));
  if (ids.length < 2) {
    body.replaceChildren(h('p', { class: 'empty' }, 'Choose two or more finished jobs above to see them side by side.'));
    return;
  }
  body.replaceChildren(h('p', { class: 'hint', role: 'status' }, 'Loading statistics…'));
  const entries = await Promise.all(ids.map(async (id) => {
    try {
      const [job, stats] = await Promise.all([api(jobUrl(id)), api(jobUrl(id, '/stats'))]);
      return { job, stats };
    } catch (e) {
      return { id, error: e.message };
    }
  }));
  if (compareView.ids !== ids) return;
  const ok = entries.filter((e) => !e.error);
  ok.sort((a, b) => (b.stats.totals.crown_return - a.stats.totals.crown_return) || a.job.created_at.localeCompare(b.job.created_at));
  const failed = entries.filter((e) => e.error);
  const parts = [];
  if (failed.length) {
    parts.push(h('p', { class: 'form-error', role: 'alert' }, failed.map((f) => `Job ${shortId(f.id)}: ${f.error}`).join('; ')));
  }
  if (ok.length) parts.push(ranking(ok), compareCards(ok), compareTable(ok));
  body.replaceChildren(...parts);
}

function entryName(e) { return displayMeshName(e.job.mesh); }

// Differences within two combined standard errors are called "within noise", not a win.
function verdict(best, other) {
  const a = best.stats.totals;
  const b = other.stats.totals;
  const diff = a.crown_return - b.crown_return;
  const se = Math.hypot(a.crown_return_stderr || 0, b.crown_return_stderr || 0);
  const d = decimalsFor(se * 100);
  const text = `${(diff * 100).toFixed(d)} pts below #1`;
  return se > 0 && diff < 2 * se ? `${text} — within noise (±${(2 * se * 100).toFixed(d)})` : text;
}

function ranking(entries) {
  const best = entries[0].stats.totals.crown_return || 1e-12;
  return h('section', { class: 'card ranking', 'aria-labelledby': 'ranking-title' },
    h('h2', { id: 'ranking-title' }, 'Crown return, ranked'),
    h('ol', { class: 'rank-list' }, entries.map((e, i) => {
      const t = e.stats.totals;
      return h('li', { class: `rank rank-${i + 1}`, 'data-id': e.job.id },
        h('span', { class: 'rank-no' }, `#${i + 1}`),
        h('div', { class: 'rank-body' },
          h('p', { class: 'rank-name' }, h('a', { href: `#/jobs/${e.job.id}` }, entryName(e)),
            i === 0 ? h('span', { class: 'best-tag' }, '★ Most light out of the top') : null),
          h('p', { class: 'rank-meta' }, `${jobSummary(e.job.settings)} · job ${shortId(e.job.id)}`),
          h('div', { class: 'rank-bar-track' },
            h('span', { class: `rank-bar${i === 0 ? ' best' : ''}`, style: `width:${(t.crown_return / best) * 100}%` })),
          h('p', { class: 'rank-value' }, h('strong', {}, fmtPctErr(t.crown_return, t.crown_return_stderr)),
            i === 0 ? '' : ` · ${verdict(entries[0], e)}`)));
    })));
}

function compareCards(entries) {
  // One colour scale for every heat-map, so that the same colour means the same share in each design.
  const commonScale = scaleEnd(Math.max(0, ...entries.flatMap((e) => (e.stats.facets || []).map((f) => f.leaving_share))));
  return h('section', { 'aria-labelledby': 'side-title' },
    h('h2', { id: 'side-title' }, 'Side by side'),
    h('p', { class: 'hint' }, `Heat-maps share one colour scale, 0 to ${(commonScale * 100).toFixed(1)} % of the light leaving a facet.`),
    h('div', { class: 'compare-grid' }, entries.map((e, i) => {
      const t = e.stats.totals;
      return h('article', { class: 'card compare-card', 'data-id': e.job.id },
        h('h3', {}, h('span', { class: 'rank-no small' }, `#${i + 1}`), ' ', h('a', { href: `#/jobs/${e.job.id}` }, entryName(e))),
        h('p', { class: 'rank-meta' }, jobSummary(e.job.settings)),
        h('p', { class: 'compare-value' }, fmtPctErr(t.crown_return, t.crown_return_stderr), h('span', { class: 'muted' }, ' crown return')),
        pictures(e.job, entryName(e), e.stats, commonScale),
        regionTable(e.stats.regions || {}, `Light leaving each region, ${entryName(e)}`, t.hit, true));
    })));
}

function compareTable(entries) {
  return h('section', { class: 'card', 'aria-labelledby': 'figures-compare-title' },
    h('h2', { id: 'figures-compare-title' }, 'All figures'),
    h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-labelledby': 'figures-compare-title' },
      h('table', { class: 'data compare-table' },
        h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Figure'),
          entries.map((e, i) => h('th', { scope: 'col', class: 'num' }, `#${i + 1} ${entryName(e)}`, h('br'), h('span', { class: 'muted' }, `job ${shortId(e.job.id)}`))))),
        h('tbody', {}, FIGURES.map((f) => {
          const values = entries.map((e) => e.stats.totals[f.key]);
          const best = f.lowerIsBetter ? Math.min(...values) : Math.max(...values);
          return h('tr', {}, h('th', { scope: 'row' }, f.label, f.lowerIsBetter ? h('span', { class: 'muted' }, ' (lower is better)') : null),
            entries.map((e) => {
              const v = e.stats.totals[f.key];
              const isBest = v === best;
              return h('td', { class: `num${isBest ? ' best-cell' : ''}` }, fmtPctErr(v, e.stats.totals[`${f.key}_stderr`]),
                isBest ? h('span', { class: 'best-mark' }, ' ▲ best') : null);
            }));
        })))));
}

// --- routing ------------------------------------------------------------------------------------------------
function route() {
  const hash = location.hash.replace(/^#/, '') || '/';
  const parts = hash.split('/').filter(Boolean);
  let view = 'home';
  if (parts[0] === 'jobs' && parts[1]) view = 'result';
  else if (parts[0] === 'compare') view = 'compare';
  for (const v of ['home', 'result', 'compare']) $(`#view-${v}`).hidden = v !== view;
  for (const a of document.querySelectorAll('[data-nav]')) {
    if (a.dataset.nav === (view === 'compare' ? 'compare' : 'home')) a.setAttribute('aria-current', 'page');
    else a.removeAttribute('aria-current');
  }
  clearTimeout(resultView.timer);
  resultView.id = '';
  if (view === 'result') {
    document.title = 'Result — facetlight';
    $('#result-body').replaceChildren(h('p', { class: 'hint', id: 'result-title' }, 'Loading…'));
    showResult(decodeURIComponent(parts[1]));
  } else if (view === 'compare') {
    document.title = 'Compare — facetlight';
    const ids = (parts[1] || '').split(',').filter(Boolean).map(decodeURIComponent);
    showCompare(ids);
  } else {
    document.title = 'facetlight — light through cut stones';
  }
  window.scrollTo(0, 0);
}

async function start() {
  const form = $('#job-form');
  form.addEventListener('submit', submitJob);
  form.addEventListener('input', (ev) => {
    const field = ev.target.closest('.field');
    if (field && field.dataset.field) clearFieldError(field.dataset.field);
  });
  form.elements['light.model'].addEventListener('change', syncFormControls);
  form.elements.render.addEventListener('change', syncFormControls);
  $('#f-mesh').addEventListener('change', describeMesh);
  $('#upload-button').addEventListener('click', uploadMesh);
  $('#compare-selected').addEventListener('click', () => {
    location.hash = `#/compare/${[...jobsView.selected].join(',')}`;
  });
  $('#jobs-prev').addEventListener('click', () => { jobsView.offset = Math.max(0, jobsView.offset - JOBS_PER_PAGE); refreshJobs(); });
  $('#jobs-next').addEventListener('click', () => { jobsView.offset += JOBS_PER_PAGE; refreshJobs(); });
  $('#compare-pick').addEventListener('submit', (ev) => {
    ev.preventDefault();
    const ids = [...ev.currentTarget.querySelectorAll('input[name="job"]:checked')].map((i) => i.value);
    location.hash = `#/compare/${ids.join(',')}`;
  });
  window.addEventListener('hashchange', route);
  syncFormControls();
  route();
  const health = await refreshHealth();
  if (health && health.cores) {
    const threads = $('#f-threads');
    threads.value = String(health.cores);
    threads.max = String(health.cores);
  }
  await loadMeshes();
  refreshJobs();
}

start();
