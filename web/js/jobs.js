// The jobs list (polled while jobs are active), cancel and delete, and the server's health.
import { api, jobUrl } from './api.js';
import { JOBS_PER_PAGE, POLL_ACTIVE_MS, POLL_IDLE_MS, STATES } from './constants.js';
import { $, h } from './dom.js';
import { fmtTime, shortId } from './format.js';
import { jobName } from './meshes.js';
import { jobSummary, progressBar, stateBadge } from './progress.js';

// `submitted`: the job last sent from each form, by the status beside the form's button, which follows its state.
export const jobsView = { offset: 0, total: 0, jobs: [], selected: new Set(), timer: 0, pendingDelete: new Map(), submitted: new Map() };

function anyActive(jobs) { return jobs.some((j) => j.state === 'queued' || j.state === 'running'); }

export async function refreshJobs() {
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
  const name = jobName(job);
  const finished = job.state === 'succeeded';
  // A sweep's chart fills in while it runs.
  const sweep = Boolean(job.settings && job.settings.sweep);
  const href = sweep ? `#/sweeps/${job.id}` : `#/jobs/${job.id}`;
  const openable = finished || (sweep && job.state === 'running');
  const title = openable
    ? h('a', { href, class: 'job-name' }, name)
    : h('span', { class: 'job-name' }, name);
  const actions = h('div', { class: 'job-actions' });
  if (openable) actions.append(h('a', { class: 'button secondary small', href, 'data-action': 'open' }, sweep ? 'Open sweep' : 'Open result'));
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
  return JSON.stringify([job.state, job.cancel_requested, job.error, job.mesh, jobName(job),
    jobsView.selected.has(job.id), jobsView.pendingDelete.has(job.id), job.threads && job.threads.note]);
}

function renderJobs() {
  const list = $('#job-list');
  const old = new Map([...list.children].map((li) => [li.dataset.id, li]));
  const items = jobsView.jobs.map((job) => {
    const name = jobName(job);
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
  updateSubmitStatus();
  const from = jobsView.total ? jobsView.offset + 1 : 0;
  const to = jobsView.offset + jobsView.jobs.length;
  $('#jobs-page').textContent = jobsView.total > JOBS_PER_PAGE ? `${from}–${to} of ${jobsView.total}` : '';
  $('#jobs-prev').disabled = jobsView.offset === 0;
  $('#jobs-next').disabled = to >= jobsView.total;
  $('#jobs-prev').closest('.pager').hidden = jobsView.total <= JOBS_PER_PAGE;
  updateCompareButton();
}

// The status beside a form's button follows the job it sent, so it never says "queued" once the job ran.
function updateSubmitStatus() {
  for (const [status, id] of jobsView.submitted) {
    const job = jobsView.jobs.find((j) => j.id === id);
    if (!job) continue;
    const state = (STATES[job.state] || { label: job.state }).label.toLowerCase();
    $(status).textContent = `Job ${shortId(job.id)} ${state}: ${jobName(job)}.`;
  }
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

let degraded = false;  // /healthz answered 503: shown until it answers 200
let lastHealth = '';
export async function refreshHealth() {
  try {
    const health = await api('/healthz');
    lastHealth = `Service ready · ${health.cores} cores`;
    degraded = false;
    setServerStatus(true);
    return health;
  } catch (e) {
    // 503: the server answers, but its disk takes nothing more (storage.detail says why).
    const storage = e.body && e.body.storage;
    if (!storage) {
      setServerStatus(false, e.message);
      return null;
    }
    lastHealth = `Service degraded: ${storage.detail}`;
    degraded = true;
    setServerStatus(true);
    return e.body;
  }
}

function setServerStatus(ok, message) {
  const el = $('#server-status');
  el.classList.toggle('down', !ok || degraded);
  el.textContent = ok ? lastHealth || 'Service ready' : `Service unreachable: ${message}`;
}
