// A job's state badge, settings summary and progress bar (the server sends the overall progress).
import { STATES } from './constants.js';
import { h } from './dom.js';
import { fmtInt, humanize } from './format.js';

// Overall fraction and a caption, from the server's progress (overall, step of steps, current phase).
function overallProgress(job) {
  const p = job.progress || {};
  if (job.state === 'succeeded') return { fraction: 1, caption: 'Done' };
  if (job.state === 'queued') {
    return { fraction: 0, caption: job.queue_position ? `Waiting, position ${job.queue_position} in the queue` : 'Waiting' };
  }
  if (job.state === 'failed') return { fraction: p.fraction || 0, caption: 'Failed' };
  if (job.state === 'canceled') return { fraction: p.fraction || 0, caption: 'Canceled' };
  const within = Math.min(1, Math.max(0, Number(p.fraction) || 0));
  const fraction = Math.min(1, Math.max(0, Number(p.overall) || 0));
  const step = p.step > 0 ? ` · step ${p.step} of ${p.steps}` : '';
  const detail = p.total ? ` ${Math.floor(within * 100)} %` : '';
  const cancel = job.cancel_requested ? ' · canceling' : '';
  return { fraction, caption: `${humanize(p.phase || 'starting')}${detail}${step}${cancel}` };
}

export function progressBar(job, label) {
  const { fraction, caption } = overallProgress(job);
  const pct = Math.round(fraction * 100);
  return h('div', { class: 'progress-block' },
    h('div', {
      class: `progress state-${job.state}`, role: 'progressbar', 'aria-valuemin': 0, 'aria-valuemax': 100,
      'aria-valuenow': pct, 'aria-valuetext': `${pct} %, ${caption}`, 'aria-label': label,
    }, h('div', { class: 'progress-fill', style: `width:${pct}%` })),
    h('p', { class: 'progress-text' }, h('span', { class: 'progress-pct' }, `${pct} %`), h('span', {}, caption)));
}

export function stateBadge(state) {
  const s = STATES[state] || { glyph: '?', label: state };
  return h('span', { class: `state state-${state}` }, h('span', { 'aria-hidden': 'true', class: 'glyph' }, s.glyph), s.label);
}

// The job's light in words: "hemisphere, uniform sky, head shadow 15°".
export function lightText(settings) {
  if (!settings || !settings.light) return '';
  let light = settings.light.model;
  if (settings.light.tilt_deg) light += `, tilt ${settings.light.tilt_deg}°`;
  if (settings.light.model === 'hemisphere' && settings.light.sky) light += `, ${settings.light.sky} sky`;
  if (settings.light.model === 'hemisphere' && settings.light.head_shadow_deg) {
    light += `, head shadow ${settings.light.head_shadow_deg}°`;
  }
  return light;
}

// The material a job traces, in the server's order of precedence (scene/scene.h, namedMaterial).
function materialText(settings) {
  if (settings.n != null) return `n ${settings.n}`;
  if (settings.custom_material) return `${settings.custom_material.name || 'own material'} (its own material)`;
  return settings.material === 'auto' ? 'its design\'s index or diamond' : humanize(settings.material || '');
}

export function jobSummary(settings) {
  if (!settings) return '';
  const parts = [`${fmtInt(settings.photons)} photons`, materialText(settings), lightText(settings)];
  if (settings.dispersion === false) parts.push('no dispersion');
  // Polarised is the default: a summary names the exceptions.
  if (settings.polarization === 'off') parts.push('unpolarised');
  else if (settings.light && settings.light.polarizer_deg != null) parts.push(`polariser at ${settings.light.polarizer_deg}°`);
  return parts.filter(Boolean).join(' · ');
}
