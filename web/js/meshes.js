// The shapes a job may use: shipped and uploaded meshes, their descriptions, uploads and their deletion.
// loadMeshes returns the shipped ones.
import { api } from './api.js';
import { showCutFields } from './cut_fields.js';
import { $, clearFieldError, h, showFieldError } from './dom.js';
import { fmtNumber } from './format.js';

const meshes = new Map();  // mesh name or id -> summary

function meshLabel(m) {
  const name = m.file_name || m.name || m.mesh;
  return m.error ? `${name} (cannot be read)` : `${name} — ${m.facet_count} facets`;
}

function displayMeshName(mesh) {
  const m = meshes.get(mesh);
  return m ? m.file_name || m.name || mesh : mesh;
}

// A job's name as the server gives it ("round brilliant P 43.5"); jobs stored before names were given show
// their mesh's name instead of its id.
export function jobName(job) {
  return job.name && job.name !== job.mesh ? job.name : displayMeshName(job.mesh);
}

export async function loadMeshes(select) {
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
  renderUploads(list.uploaded || []);
  // The classic round brilliant is the reference design people start from.
  const preferred = [previous, 'round_brilliant'].find((m) => m && meshes.has(m));
  if (preferred) el.value = preferred;
  describeMesh();
  document.dispatchEvent(new CustomEvent('meshes-loaded', { detail: list }));
  return list.shipped || [];
}

// Each upload with a Delete button. The server refuses to delete one a queued or running job uses (409): its
// reason is shown under the upload.
function renderUploads(uploaded) {
  const list = $('#upload-list');
  list.replaceChildren(...uploaded.map((m) => {
    const name = m.file_name || m.mesh;
    const error = h('p', { class: 'field-error', role: 'alert', hidden: true });
    const button = h('button', {
      type: 'button', class: 'button secondary small', 'data-action': 'delete-mesh', 'aria-label': `Delete ${name}`,
      onclick: () => deleteMesh(m, button, error),
    }, 'Delete');
    return h('li', { 'data-mesh': m.mesh }, h('span', { class: 'upload-name' }, meshLabel(m)), button, error);
  }));
  list.hidden = uploaded.length === 0;
}

async function deleteMesh(m, button, error) {
  const name = m.file_name || m.mesh;
  button.disabled = true;
  error.hidden = true;
  try {
    await api(`/api/meshes/${encodeURIComponent(m.mesh)}`, { method: 'DELETE' });
    $('#upload-status').textContent = `Deleted ${name}.`;
    await loadMeshes();
  } catch (e) {
    error.textContent = `Cannot delete ${name}: ${e.message}`;
    error.hidden = false;
    button.disabled = false;
  }
}

export function describeMesh() {
  const m = meshes.get($('#f-mesh').value);
  showCutFields(m);
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
  if ((m.tiers || []).length) parts.push(`GemCad design: ${m.tiers.length} tiers to sweep`);
  hint.textContent = parts.join(' · ');
}

export async function uploadMesh() {
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
