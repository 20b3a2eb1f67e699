// Fire (stats.fire, docs/stats-schema.md; defined in docs/physics.md, "Fire"): the fire trace's figures with
// their standard errors, the histogram of red-blue separation against exit angle as a chart, the fire view of
// the heat-map, and the same side by side for several designs.
import { h, svg } from './dom.js';
import { decimalsFor, fmtInt, fmtNumber, fmtPctErr, shortId } from './format.js';
import { FIRE, commonScale, fireHeatmapDrawn } from './heatmap.js';

export const FIRE_FIGURES = [
  { key: 'mean_separation_deg', label: 'Mean red–blue separation', degrees: true,
    hint: 'Angle between the C-line (656 nm) and F-line (486 nm) exits, over crown exits toward the viewer' },
  { key: 'coloured_share', label: 'Seen as colour',
    hint: 'Share of hits whose red and blue part by more than the pupil spans' },
  { key: 'coloured_return_weighted', label: 'Coloured return, cosine-weighted',
    hint: 'Coloured exits weighted by cos(angle to vertical), outside the head cone (after GIA’s DCLR)' },
  { key: 'pair_share', label: 'Red and blue together',
    hint: 'Share of hits whose red and blue both leave the crown upward along one facet path' },
  { key: 'split_share', label: 'Red and blue parted',
    hint: 'Share of hits where only one of red and blue leaves the crown upward along that path (not in the separation)' },
];

export function fmtFire(f, fire) {
  const v = fire[f.key];
  const se = fire[`${f.key}_stderr`];
  if (!f.degrees) return fmtPctErr(v, se);
  if (!Number.isFinite(v)) return '—';
  const d = Math.max(2, decimalsFor(se));
  return `${v.toFixed(d)}° ± ${se.toFixed(d)}`;
}

// The histogram as a grid: separation across (0.1° bins, the last holding everything wider), exit angle from
// the vertical down (5° bins), darker cells holding more pairs (square-root scale), the pupil's angle dashed.
export function fireHistogramChart(fire) {
  const hist = fire.histogram;
  const rows = hist.counts;
  const sepBin = hist.separation_bin_degrees;
  const exitBin = hist.exit_bin_degrees;
  const cols = rows[0].length;
  const max = Math.max(1, ...rows.flat());
  const [left, top, width, height] = [64, 16, 540, 270];
  const cw = width / cols;
  const rh = height / rows.length;
  const cells = [];
  rows.forEach((row, r) => row.forEach((count, c) => {
    if (!count) return;
    cells.push(svg('rect', { x: left + c * cw, y: top + r * rh, width: cw + 0.3, height: rh + 0.3,
      fill: '#c2410c', 'fill-opacity': Math.sqrt(count / max).toFixed(3) },
    svg('title', {}, `${fmtNumber(c * sepBin, 1)}–${c + 1 === cols ? '' : fmtNumber((c + 1) * sepBin, 1)}° apart, ${r * exitBin}–${(r + 1) * exitBin}° from vertical: ${fmtInt(count)} pairs`)));
  }));
  const axis = { stroke: '#333', 'stroke-width': 1 };
  const ticks = [];
  for (let deg = 0; deg <= cols * sepBin + 1e-9; deg += 1) {
    const x = left + (deg / sepBin) * cw;
    ticks.push(svg('line', { x1: x, y1: top + height, x2: x, y2: top + height + 5, ...axis }),
      svg('text', { x, y: top + height + 18, 'text-anchor': 'middle', class: 'chart-tick' }, `${deg}`));
  }
  for (let deg = 0; deg <= rows.length * exitBin; deg += 15) {
    const y = top + (deg / exitBin) * rh;
    ticks.push(svg('line', { x1: left - 5, y1: y, x2: left, y2: y, ...axis }),
      svg('text', { x: left - 8, y: y + 4, 'text-anchor': 'end', class: 'chart-tick' }, `${deg}`));
  }
  const px = left + Math.min(cols, fire.pupil_deg / sepBin) * cw;
  return svg('svg', { class: 'fire-histogram-chart', viewBox: `0 0 ${left + width + 16} ${top + height + 52}`, role: 'img',
    'aria-label': `Histogram of ${fmtInt(fire.pairs)} red–blue pairs: separation in degrees against exit angle from vertical; the pupil spans ${fmtNumber(fire.pupil_deg, 2)}°` },
  svg('rect', { x: left, y: top, width, height, fill: '#fff', ...axis }),
  ...cells, ...ticks,
  svg('line', { x1: px, y1: top, x2: px, y2: top + height, stroke: '#1d4ed8', 'stroke-width': 1.5, 'stroke-dasharray': '5 4' }),
  svg('text', { x: px + 4, y: top + 14, class: 'chart-note' }, `pupil ${fmtNumber(fire.pupil_deg, 2)}°`),
  svg('text', { x: left + width / 2, y: top + height + 40, 'text-anchor': 'middle', class: 'chart-label' }, 'red–blue separation (degrees)'),
  svg('text', { x: 14, y: top + height / 2, 'text-anchor': 'middle', class: 'chart-label', transform: `rotate(-90 14 ${top + height / 2})` }, 'exit angle from vertical (degrees)'));
}

function figureList(fire) {
  return h('dl', { class: 'figures' }, FIRE_FIGURES.map((f) => h('div', { class: 'figure', 'data-figure': `fire.${f.key}` },
    h('dt', {}, f.label),
    h('dd', {}, h('span', { class: 'figure-value' }, fmtFire(f, fire)), h('span', { class: 'figure-hint' }, f.hint)))));
}

// The result page's fire card; null when the job traced no fire.
export function fireSection(job, stats) {
  const fire = stats.fire;
  if (!fire) return null;
  const links = job.links || {};
  return h('section', { class: 'card', 'aria-labelledby': 'fire-title', 'data-section': 'fire' },
    h('h2', { id: 'fire-title' }, 'Fire'),
    h('p', { class: 'hint' }, `Each photon also traced at ${fire.wavelengths_nm.join(', ')} nm with the same random choices: `
      + `${fmtInt(fire.pairs)} red–blue pairs out of the crown among ${fmtInt(fire.hit)} hits. A ${fmtNumber(fire.pupil_deg, 2)}° pupil `
      + 'sees the pairs further apart than that as colour. Values ± one standard error.'),
    figureList(fire),
    h('div', { class: 'result-grid' },
      h('figure', { class: 'fire-histogram' }, fireHistogramChart(fire),
        h('figcaption', {}, 'Separation against exit angle: darker cells hold more pairs (square-root scale).')),
      links.heatmap_fire ? h('figure', { class: 'picture pic-heatmap-fire' },
        h('a', { href: links.heatmap_fire, target: '_blank', rel: 'noopener' },
          h('img', { src: links.heatmap_fire, alt: 'Fire heat-map: facets shaded by their share of the fire', decoding: 'async' })),
        h('figcaption', {}, 'Fire heat-map: each facet’s share of the fire')) : null));
}

// The comparison's fire table and fire heat-maps; null when none of the jobs traced fire.
export function fireCompare(entries, nameOf) {
  const withFire = entries.filter((e) => e.stats.fire);
  if (!withFire.length) return null;
  // One colour scale for every fire heat-map, so that the same colour is the same share in each.
  const scale = commonScale(withFire.map((e) => e.stats), FIRE);
  return h('section', { class: 'card', 'aria-labelledby': 'fire-compare-title', 'data-section': 'fire-compare' },
    h('h2', { id: 'fire-compare-title' }, 'Fire, side by side'),
    h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-labelledby': 'fire-compare-title' },
      h('table', { class: 'data compare-table fire-compare' },
        h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Figure'),
          withFire.map((e) => h('th', { scope: 'col', class: 'num' }, nameOf(e), h('br'), h('span', { class: 'muted' }, `job ${shortId(e.job.id)}`))))),
        h('tbody', {}, FIRE_FIGURES.map((f) => {
          const best = Math.max(...withFire.map((e) => e.stats.fire[f.key]));
          return h('tr', {}, h('th', { scope: 'row' }, f.label), withFire.map((e) => {
            const isBest = e.stats.fire[f.key] === best && withFire.length > 1;
            return h('td', { class: `num${isBest ? ' best-cell' : ''}` }, fmtFire(f, e.stats.fire), isBest ? h('span', { class: 'best-mark' }, ' ▲ most') : null);
          }));
        })))),
    h('p', { class: 'hint' }, `Fire heat-maps share one colour scale, 0 to ${(scale * 100).toFixed(1)} % of the fire leaving a facet; facets beyond it hatched.`),
    h('div', { class: 'compare-grid fire-compare-grid' }, withFire.map((e) => h('figure', { class: 'fire-compare-card', 'data-id': e.job.id },
      fireHistogramChart(e.stats.fire),
      e.job.links && e.job.links.heatmap_fire ? fireHeatmapDrawn(e.job, nameOf(e), e.stats, scale) : null,
      h('figcaption', {}, nameOf(e))))));
}
