// Several jobs side by side: a ranking by crown return and a table of the figures.
import { api, jobUrl } from './api.js';
import { colourCompare } from './compare_colour.js';
import { FIGURES } from './constants.js';
import { $, h } from './dom.js';
import { fireCompare } from './fire.js';
import { decimalsFor, fmtNumber, fmtPctErr, shortId } from './format.js';
import { commonScale, pictures } from './heatmap.js';
import { jobName } from './meshes.js';
import { jobSummary } from './progress.js';
import { crystalCompare } from './compare_crystal.js';
import { viewerCompare } from './compare_viewer.js';
import { regionTable } from './result.js';
import { verdictCompare } from './verdict.js';

const compareView = { ids: [] };

export async function showCompare(ids) {
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
    h('span', {}, h('strong', {}, jobName(j)), ` · ${jobSummary(j.settings)} · job ${shortId(j.id)}`)))
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
  if (ok.length) parts.push(...[verdictCompare(ok, entryName), ranking(ok), compareCards(ok), stonesCompare(ok), viewerCompare(ok, entryName), colourCompare(ok, entryName), compareTable(ok), fireCompare(ok, entryName), crystalCompare(ok, entryName)].filter(Boolean));
  body.replaceChildren(...parts);
}

function entryName(e) { return jobName(e.job); }

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

// The design's size, weight and traced index, with a link to its faceting diagram (the result page's design
// section has the whole sheet).
function designSummary(e) {
  const size = e.stats.size;
  const m = e.stats.material;
  const diagram = (e.job.links || {}).diagram;
  if (!size && !m) return null;
  const parts = [];
  if (size) parts.push(`${fmtNumber(size.length_mm, 2)} × ${fmtNumber(size.width_mm, 2)} × ${fmtNumber(size.depth_mm, 2)} mm`);
  if (size && size.carats != null) parts.push(`${fmtNumber(size.carats, 2)} ct`);
  if (m) parts.push(`n ${fmtNumber(m.n_d, 3)}${m.source === 'design file' ? ' (the design\'s own)' : ''}`);
  return h('p', { class: 'compare-design' }, parts.join(' · '),
    diagram ? [' · ', h('a', { href: diagram, target: '_blank', rel: 'noopener' }, 'faceting diagram')] : null);
}

function compareCards(entries) {
  // One colour scale for every heat-map, so that the same colour means the same share in each design.
  const scale = commonScale(entries.map((e) => e.stats));
  return h('section', { 'aria-labelledby': 'side-title' },
    h('h2', { id: 'side-title' }, 'Side by side'),
    h('p', { class: 'hint' }, `Heat-maps share one colour scale, 0 to ${(scale * 100).toFixed(1)} % of the light leaving a facet: the largest of the scales the pictures have on their own; facets beyond it (mostly the table) are hatched.`),
    h('div', { class: 'compare-grid side-grid' }, entries.map((e, i) => {
      const t = e.stats.totals;
      return h('article', { class: 'card compare-card', 'data-id': e.job.id },
        h('h3', {}, h('span', { class: 'rank-no small' }, `#${i + 1}`), ' ', h('a', { href: `#/jobs/${e.job.id}` }, entryName(e))),
        h('p', { class: 'rank-meta' }, jobSummary(e.job.settings)),
        h('p', { class: 'compare-value' }, fmtPctErr(t.crown_return, t.crown_return_stderr), h('span', { class: 'muted' }, ' crown return')),
        pictures(e.job, entryName(e), e.stats, scale),
        designSummary(e),
        regionTable(e.stats.regions || {}, `Light leaving each region, ${entryName(e)}`, true));
    })));
}

// The designs in 3-D, one view with a menu of them, every one coloured on one scale. stone3d.js (and three.js)
// are loaded only when the section comes near the window: a comparison read for its tables loads neither.
function stonesCompare(entries) {
  const stones = entries.filter((e) => e.job.links && e.job.links.stone).map((e) => ({ job: e.job, stats: e.stats, name: entryName(e) }));
  if (!stones.length) return null;
  const body = h('div', { class: 'stone3d' }, h('p', { class: 'hint' }, 'The 3-D view loads when you scroll to it.'));
  const section = h('section', { class: 'card', 'aria-labelledby': 'compare3d-title', 'data-section': 'compare3d' },
    h('h2', { id: 'compare3d-title' }, 'In 3-D'),
    h('p', { class: 'hint' }, 'Pick a design to turn it; each is coloured on the same scale as the others, so that the same colour is the same value in each.'),
    body);
  const seen = new IntersectionObserver((events) => {
    if (!events.some((e) => e.isIntersecting)) return;
    seen.disconnect();
    body.replaceChildren(h('p', { class: 'hint' }, 'Loading the 3-D view…'));
    import('./stone3d.js').then((m) => m.showStones(body, stones, 'compare3d')).catch((e) => {
      body.replaceChildren(h('p', { class: 'hint stone3d-missing', role: 'status' }, `The 3-D view could not be loaded: ${e.message}`));
    });
  }, { rootMargin: '200px' });
  seen.observe(section);
  return section;
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
