// The comparison's crystal optics: how each design was traced (polarised or not, its double refraction), the
// polariscope's and the doubling's verdicts (their pictures are with the viewer's views); and, for one stone traced with polarisation on
// and off, what the polarisation changes in each figure, with its error (docs/physics.md, "Polarised or
// unpolarised").
import { FIGURES } from './constants.js';
import { h } from './dom.js';
import { decimalsFor, fmtNumber, humanize, shortId } from './format.js';
import { doublingText, polariscopeText } from './result.js';

// Differences beyond this many combined standard errors are called real (the rule issue 28 chose the
// default by).
const SIGNIFICANT_Z = 2;

// Jobs of one stone: the same mesh, cut, material (named, a constant n or its own, with its absorption and
// optic axis), size and light, so that only how they were traced differs.
function stoneKey(job) {
  const s = job.settings || {};
  return JSON.stringify([job.mesh, s.cut || null, s.material, s.n ?? null, s.custom_material ?? null, s.absorption ?? null,
    s.optic_axis ?? null, s.size_mm ?? null, s.dispersion, s.light]);
}

// The first polarised and unpolarised job of each stone that has both.
function polarizationPairs(entries) {
  const byStone = new Map();
  for (const e of entries) {
    const key = stoneKey(e.job);
    if (!byStone.has(key)) byStone.set(key, {});
    const pair = byStone.get(key);
    const mode = e.job.settings.polarization;
    if ((mode === 'on' || mode === 'off') && !pair[mode]) pair[mode] = e;
  }
  return [...byStone.values()].filter((p) => p.on && p.off);
}

// on - off of one figure in percentage points, with one combined standard error and the difference in them.
function difference(on, off, key) {
  const a = on.stats.totals, b = off.stats.totals;
  const diff = a[key] - b[key];
  const se = Math.hypot(a[`${key}_stderr`] || 0, b[`${key}_stderr`] || 0);
  return { diff, se, z: se > 0 ? diff / se : 0 };
}

function pairTable({ on, off }, nameOf) {
  const title = `${nameOf(on)} (job ${shortId(on.job.id)}) against ${nameOf(off)} (job ${shortId(off.job.id)})`;
  return h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': `Polarised minus unpolarised, ${title}` },
    h('table', { class: 'data polarization-effect', 'data-on': on.job.id, 'data-off': off.job.id },
      h('caption', {}, `Polarised minus unpolarised: ${title}`),
      h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Figure'), h('th', { scope: 'col', class: 'num' }, 'on − off'),
        h('th', { scope: 'col', class: 'num' }, 'in standard errors'))),
      h('tbody', {}, FIGURES.map((f) => {
        const { diff, se, z } = difference(on, off, f.key);
        const d = decimalsFor(se * 100);
        const real = Math.abs(z) > SIGNIFICANT_Z;
        return h('tr', { class: real ? 'significant' : '' }, h('th', { scope: 'row' }, f.label),
          h('td', { class: 'num' }, `${diff >= 0 ? '+' : '−'}${Math.abs(diff * 100).toFixed(d)} pts ± ${(se * 100).toFixed(d)}`),
          h('td', { class: 'num' }, `${fmtNumber(z, 1)}`, real ? h('span', { class: 'best-mark' }, ' real') : h('span', { class: 'muted' }, ' within noise')));
      }))));
}

function tracedAs(e) {
  const s = e.job.settings;
  const m = e.stats.material;
  const parts = [s.polarization === 'off' ? 'unpolarised' : 'polarised'];
  if (m) parts.push(`${m.source === 'design file' ? 'its design\'s index' : humanize(m.name)}, n ${fmtNumber(m.n_d, 3)}`);
  if (m && m.optic && m.optic !== 'isotropic') parts.push(m.double_refraction || `${m.optic}, traced at one index`);
  return parts.join(' · ');
}

function crystalCard(e, nameOf) {
  const s = e.stats;
  return h('article', { class: 'card crystal-card', 'data-id': e.job.id },
    h('h3', {}, h('span', { class: 'rank-no small' }, `#${e.rank}`), ' ', h('a', { href: `#/jobs/${e.job.id}` }, nameOf(e))),
    h('p', { class: 'rank-meta traced-as' }, tracedAs(e)),
    s.polariscope ? h('p', { class: 'polariscope-text' }, polariscopeText(s.polariscope)) : null,
    s.doubling ? h('p', { class: 'doubling-text' }, doublingText(s.doubling)) : null,
    s.polariscope || s.doubling ? null : h('p', { class: 'muted' }, 'No polariscope or doubling asked for.'));
}

// `entries` in the comparison's order; none when every job was traced alike and none asked for a polariscope or
// the doubling.
export function crystalCompare(entries, nameOf) {
  const ranked = entries.map((e, i) => ({ ...e, rank: i + 1 }));
  const pairs = polarizationPairs(ranked);
  if (!pairs.length && !ranked.some((e) => e.stats.polariscope || e.stats.doubling)) return null;
  return h('section', { 'aria-labelledby': 'crystal-compare-title', 'data-section': 'crystal-compare' },
    h('h2', { id: 'crystal-compare-title' }, 'Polarisation and double refraction, side by side'),
    pairs.length ? h('div', { class: 'card' },
      h('p', { class: 'hint' }, `One stone traced with polarisation on and off: each figure's difference with one combined standard error; beyond ${SIGNIFICANT_Z} standard errors it is real, not noise.`),
      pairs.map((p) => pairTable(p, nameOf))) : null,
    h('div', { class: 'compare-grid' }, ranked.map((e) => crystalCard(e, nameOf))));
}
