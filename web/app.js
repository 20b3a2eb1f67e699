// The facetlight page: submit a study, watch the jobs, read one result, compare several. Plain ES modules (web/js/), no
// build step, no requests beyond this server's /api. Everything the server sends is put in the page as text
// (never as HTML): uploaded file names are untrusted.
// This module routes between the views and starts the page.
import { followApiLinksWithToken } from './js/api.js';
import { initColourFields } from './js/colour.js';
import { showCompare } from './js/compare.js';
import { JOBS_PER_PAGE } from './js/constants.js';
import { $, clearFieldError, h } from './js/dom.js';
import { loadFormDefaults, scheduleEstimate, submitJob, syncFormControls } from './js/form.js';
import { jobsView, refreshHealth, refreshJobs } from './js/jobs.js';
import { describeMesh, loadMeshes, uploadMesh } from './js/meshes.js';
import { resultView, showResult } from './js/result.js';
import { initSweepForm, showSweep, sweepView } from './js/sweep.js';

function route() {
  const hash = location.hash.replace(/^#/, '') || '/';
  const parts = hash.split('/').filter(Boolean);
  let view = 'home';
  if (parts[0] === 'jobs' && parts[1]) view = 'result';
  else if (parts[0] === 'sweeps' && parts[1]) view = 'sweep';
  else if (parts[0] === 'compare') view = 'compare';
  for (const v of ['home', 'result', 'sweep', 'compare']) $(`#view-${v}`).hidden = v !== view;
  for (const a of document.querySelectorAll('[data-nav]')) {
    if (a.dataset.nav === (view === 'compare' ? 'compare' : 'home')) a.setAttribute('aria-current', 'page');
    else a.removeAttribute('aria-current');
  }
  clearTimeout(resultView.timer);
  resultView.id = '';
  clearTimeout(sweepView.timer);
  sweepView.id = '';
  if (view === 'result') {
    document.title = 'Result — facetlight';
    $('#result-body').replaceChildren(h('p', { class: 'hint', id: 'result-title' }, 'Loading…'));
    showResult(decodeURIComponent(parts[1]));
  } else if (view === 'sweep') {
    document.title = 'Sweep — facetlight';
    showSweep(decodeURIComponent(parts[1]));
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
  followApiLinksWithToken();
  const form = $('#job-form');
  form.addEventListener('submit', submitJob);
  form.addEventListener('input', (ev) => {
    const field = ev.target.closest('.field');
    if (field && field.dataset.field) clearFieldError(field.dataset.field);
    scheduleEstimate();
  });
  form.addEventListener('change', scheduleEstimate);
  document.addEventListener('meshes-loaded', scheduleEstimate);
  form.elements['light.model'].addEventListener('change', syncFormControls);
  form.elements.render.addEventListener('change', syncFormControls);
  form.elements.tilt_series.addEventListener('change', syncFormControls);
  form.elements.material.addEventListener('change', syncFormControls);
  form.elements['custom_material.indices'].addEventListener('input', syncFormControls);
  form.elements.polarization.addEventListener('change', syncFormControls);
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
  initColourFields();
  initSweepForm();
  route();
  const [health] = await Promise.all([refreshHealth(), loadFormDefaults()]);
  if (health && health.cores) $('#f-threads').max = String(health.cores);
  await loadMeshes();  // fills the sweep form's shapes too ('meshes-loaded')
  refreshJobs();
}

start();
