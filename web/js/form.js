// The job form: its defaults from the server, reading it into a job, its estimate as it is edited, showing the
// server's field errors, submitting.
import { api } from './api.js';
import { chosenOptic, customIndices, readAbsorption, syncAbsorptionField, syncColourControls } from './colour.js';
import { ESTIMATE_DELAY_MS } from './constants.js';
import { readCut } from './cut_fields.js';
import { $, clearFieldError, fieldError, showFieldError } from './dom.js';
import { fmtDuration, shortId } from './format.js';
import { jobsView, refreshJobs } from './jobs.js';
import { jobName } from './meshes.js';

function showFormError(message) {
  const formError = $('#form-error');
  formError.textContent = message;
  formError.hidden = false;
}

// The form starts from the server's defaults (GET /api/defaults: what a job that leaves a setting out gets,
// from the same tables that read a job), each field found by its name, the setting's dotted path. The parts
// a job may add (render, aset, ...) are objects there: their boxes are the page's choice.
export async function loadFormDefaults() {
  let defaults;
  try {
    defaults = await api('/api/defaults');
  } catch (e) {
    showFormError(`The server's defaults could not be read: ${e.message}`);
    return;
  }
  for (const input of $('#job-form').elements) {
    if (!input.name) continue;
    const value = input.name.split('.').reduce((v, key) => (v == null ? undefined : v[key]), defaults);
    if (value == null || typeof value === 'object') continue;
    if (input.type === 'checkbox') input.checked = Boolean(value);
    else input.value = String(value);
  }
  syncFormControls();
  syncColourControls();
  syncAbsorptionField();
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

// The corundum_ppma the corundum fields give (docs/optics.md, "Corundum by its chromophores"): the
// concentrations typed, or undefined when the fields are hidden or both empty.
function readCorundum(form, errors) {
  if ($('#corundum-fields').hidden) return undefined;
  const ppma = {};
  for (const key of ['cr', 'fe_ti']) {
    const value = readNumber(form, `absorption.corundum_ppma.${key}`, errors, { required: false });
    if (value !== undefined) ppma[key] = value;
  }
  return Object.keys(ppma).length ? ppma : undefined;
}

// "Your own material" as a job's custom_material (docs/optics.md, "A job's own material"); the ranges are the
// server's to check.
function readCustomMaterial(form, errors) {
  const indices = customIndices(form);
  const keys = [null, ['n'], ['n_o', 'n_e'], ['alpha', 'beta', 'gamma']][indices.length];
  const material = {};
  if (!keys || indices.some(Number.isNaN)) {
    errors.push(['custom_material', 'Type one index, two (n_o n_e) or three (α β γ), e.g. 1.644 1.624']);
  } else {
    keys.forEach((key, i) => { material[key] = indices[i]; });
  }
  const name = form.elements['custom_material.name'].value.trim();
  if (name) material.name = name;
  material.dispersion = readNumber(form, 'custom_material.dispersion', errors);
  const density = readNumber(form, 'custom_material.density_g_cm3', errors, { required: false });
  if (density !== undefined) material.density_g_cm3 = density;
  return material;
}

function buildJob(form) {
  const errors = [];
  const job = { mesh: form.elements.mesh.value };
  if (!job.mesh) errors.push(['mesh', 'Choose a shape, or upload a mesh']);
  const cut = readCut(form, errors);
  if (cut) job.cut = cut;
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
  if (form.elements.material.value === 'custom') job.custom_material = readCustomMaterial(form, errors);
  else job.material = form.elements.material.value;
  job.dispersion = form.elements.dispersion.checked;
  job.polarization = form.elements.polarization.value;
  job.size_mm = readNumber(form, 'size_mm', errors);
  const absorption = readAbsorption(form, errors);
  // A corundum's chromophores go beside a table as given: the server refuses the pair, naming the table.
  const corundum = readCorundum(form, errors);
  if (absorption || corundum) job.absorption = { ...absorption, ...(corundum && { corundum_ppma: corundum }) };
  if (!$('#optic-axis-fields').hidden) {
    job.optic_axis = {
      tilt_deg: readNumber(form, 'optic_axis.tilt_deg', errors),
      azimuth_deg: readNumber(form, 'optic_axis.azimuth_deg', errors),
    };
    if (!$('#axis-rotation-field').hidden) job.optic_axis.rotation_deg = readNumber(form, 'optic_axis.rotation_deg', errors);
  }
  if (form.elements['fire.enabled'].checked) job.fire = { enabled: true };
  if (form.elements.polariscope.checked) {
    job.polariscope = form.elements.polariscope_lamp.value === 'collimated' ? {} : { lamp: form.elements.polariscope_lamp.value };
  }
  if (form.elements.doubling.checked) job.doubling = {};
  if (form.elements.colour.checked) {
    job.colour = { illuminant: form.elements['colour.illuminant'].value };
    for (const key of ['picture_size', 'samples', 'wavelengths', 'head_cone_deg', 'ground', 'extinct_below_l', 'saturated_above_c']) {
      job.colour[key] = readNumber(form, `colour.${key}`, errors);
    }
  }
  job.max_bounces = readNumber(form, 'max_bounces', errors);
  if (form.elements.render.checked) {
    job.render = {
      width: readNumber(form, 'render.width', errors),
      height: readNumber(form, 'render.height', errors),
      samples: readNumber(form, 'render.samples', errors),
      map_photons: readNumber(form, 'render.map_photons', errors),
      camera: { elevation_deg: readNumber(form, 'render.camera.elevation_deg', errors) },
    };
    if (form.elements.aset.checked) job.aset = {};
    if (form.elements.fire_picture.checked) job.fire_picture = {};
    if (form.elements.tilt_series.checked) {
      job.tilt_series = {
        max_deg: readNumber(form, 'tilt_series.max_deg', errors),
        axis_deg: Number(form.elements['tilt_series.axis_deg'].value),
      };
    }
  } else {
    job.render = false;
  }
  return { job, errors };
}

// The form's field a server's field stands under: itself, else the nearest part of its path that has one
// (absorption.wavelength_nm[2] under the absorption table).
function shownField(field) {
  for (let f = field; f; f = f.replace(/(\[\d+\]|\.[^.[]*)$/, '')) {
    if (fieldError(f)) return f;
    if (!/[.[]/.test(f)) break;
  }
  return field;
}

function reportError(e) {
  const field = e.field && shownField(e.field);
  if (field && showFieldError(field, e.message)) {
    // An error about the cut as a whole (`cut`) stands under the shape's fields, which it names.
    const input = fieldError(field).closest('.field, .cut-fields').querySelector('input, select, textarea');
    if (input) input.focus();
    return;
  }
  showFormError(e.field ? `${e.field}: ${e.message}` : e.message);
}

// The job's cost as the server estimates it (POST /api/jobs/estimate), asked for once the form has been still for
// ESTIMATE_DELAY_MS; `asked` numbers the requests so that a late answer to an older form is dropped. A job over
// the server's --max-job-seconds is shown in red with the server's reason, and cannot be submitted.
const estimateView = { timer: 0, asked: 0, refused: false };

function showEstimate(text, refused) {
  const el = $('#job-estimate');
  el.textContent = text;
  el.classList.toggle('over', refused);
  estimateView.refused = refused;
  $('#submit-button').disabled = refused;
}

export function scheduleEstimate() {
  clearTimeout(estimateView.timer);
  estimateView.timer = setTimeout(estimateJob, ESTIMATE_DELAY_MS);
}

async function estimateJob() {
  const asked = ++estimateView.asked;
  const { job, errors } = buildJob($('#job-form'));
  if (errors.length) {
    showEstimate('', false);  // the fields say what is missing when the job is submitted
    return;
  }
  let estimate;
  try {
    estimate = await api('/api/jobs/estimate', {
      method: 'POST', headers: { 'Content-Type': 'application/json', Accept: 'application/json' }, body: JSON.stringify(job),
    });
  } catch (e) {
    // A field the server refuses: submitting shows it beside its field.
    if (asked === estimateView.asked) showEstimate(`No estimate: ${e.field ? `${e.field}: ` : ''}${e.message}`, false);
    return;
  }
  if (asked !== estimateView.asked) return;
  if (estimate.refused) {
    showEstimate(`Too long for this server: ${estimate.reason}`, true);
    return;
  }
  const largest = estimate.largest;
  const limit = estimate.max_job_seconds > 0
    ? `this server takes jobs of up to ${fmtDuration(estimate.max_job_seconds)}` : 'this server sets no limit';
  showEstimate(`Estimated time here: about ${fmtDuration(estimate.estimate_s)} with ${estimate.threads} `
    + `${estimate.threads === 1 ? 'thread' : 'threads'}, most of it the ${largest.part} (${largest.size}); ${limit}.`, false);
}

export async function submitJob(event) {
  event.preventDefault();
  const form = event.currentTarget;
  clearFormErrors();
  if (estimateView.refused) {
    showFormError('This job would take longer than this server allows: lower the setting the estimate names.');
    return;
  }
  const status = $('#submit-status');
  const { job, errors } = buildJob(form);
  if (errors.length) {
    for (const [field, message] of errors) showFieldError(field, message);
    const first = fieldError(errors[0][0]).closest('.field').querySelector('input, select, textarea');
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
    status.textContent = `Job ${shortId(created.id)} queued: ${jobName(created)}.`;
    jobsView.offset = 0;
    jobsView.submitted.set('#submit-status', created.id);
    await refreshJobs();
    // The job's own view shows its progress live, then its result.
    location.hash = `#/jobs/${created.id}`;
  } catch (e) {
    status.textContent = '';
    reportError(e);
  } finally {
    button.disabled = estimateView.refused;
  }
}

export function syncFormControls() {
  const form = $('#job-form');
  const hemisphere = form.elements['light.model'].value === 'hemisphere';
  form.elements['light.head_shadow_deg'].disabled = !hemisphere;
  form.elements['light.sky'].disabled = !hemisphere;
  const render = form.elements.render.checked;
  for (const input of $('#render-options').querySelectorAll('input, select')) input.disabled = !render;
  $('#render-options').classList.toggle('disabled', !render);
  const tilt = render && form.elements.tilt_series.checked;
  form.elements['tilt_series.max_deg'].disabled = !tilt;
  form.elements['tilt_series.axis_deg'].disabled = !tilt;
  // A doubly refracting stone splits each ray in two only with polarisation on: its axes matter then, and the
  // menu suggests turning it on otherwise (docs/optics.md, Birefringent stones, Biaxial crystals).
  const material = form.elements.material;
  const custom = material.value === 'custom';
  $('#custom-material-fields').hidden = !custom;
  for (const input of $('#custom-material-fields').querySelectorAll('input')) input.disabled = !custom;
  const optic = chosenOptic(form);
  const doubly = optic === 'uniaxial' || optic === 'biaxial';
  const polarized = form.elements.polarization.value === 'on';
  $('#optic-axis-fields').hidden = !(doubly && polarized);
  $('#axis-rotation-field').hidden = optic !== 'biaxial';
  for (const input of $('#optic-axis-fields').querySelectorAll('input')) {
    input.disabled = !(doubly && polarized) || (input.name === 'optic_axis.rotation_deg' && optic !== 'biaxial');
  }
  $('#hint-material-split').hidden = !(doubly && !polarized);
  // Corundum may be coloured by its chromophores.
  const corundum = material.selectedOptions[0]?.dataset.corundum === 'true';
  $('#corundum-fields').hidden = !corundum;
  for (const input of $('#corundum-fields').querySelectorAll('input')) input.disabled = !corundum;
  // A coloured material's swatch (index.html: what 6.5 mm passes of D65).
  const swatch = material.selectedOptions[0]?.dataset.swatch;
  $('#material-swatch').hidden = !swatch;
  $('#material-swatch').style.background = swatch || '';
  $('#hint-material-colour').hidden = !swatch;
}
