// The comparison's viewer views: each design's ASET picture with its shares, and its tilt series'
// animation, chart and scintillation where the job has one, side by side; and a table of those figures.
import { h } from './dom.js';
import { fmtPctErr, shortId } from './format.js';
import { ASET_CLASSES, viewerFigures } from './result.js';
import { tiltRange } from './tilt.js';

// The frame the stone is face-up in (tilt 0), the middle of the series.
function faceUpFrame(tilt) {
  return tilt.frames.find((f) => f.tilt_deg === 0) || tilt.frames[(tilt.frames.length - 1) >> 1];
}

function viewerTable(entries, nameOf) {
  const rows = [
    ...ASET_CLASSES.map(([k, label]) => [`ASET ${label.toLowerCase()}`, (s) => s.aset && s.aset.shares[k]
      && fmtPctErr(s.aset.shares[k].share, s.aset.shares[k].stderr)]),
    ['Scintillation per frame', (s) => s.tilt_series && fmtPctErr(s.tilt_series.scintillation, s.tilt_series.scintillation_stderr)],
    ['Light return face-up, tilt series', (s) => {
      if (!s.tilt_series) return null;
      const f = faceUpFrame(s.tilt_series);
      return fmtPctErr(f.light_return, f.light_return_stderr);
    }],
  ];
  return h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-labelledby': 'viewer-compare-title' },
    h('table', { class: 'data viewer-compare-table' },
      h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Figure'),
        entries.map((e) => h('th', { scope: 'col', class: 'num' }, `#${e.rank} ${nameOf(e)}`, h('br'), h('span', { class: 'muted' }, `job ${shortId(e.job.id)}`))))),
      h('tbody', {}, rows.map(([label, value]) => h('tr', {}, h('th', { scope: 'row' }, label),
        entries.map((e) => h('td', { class: 'num' }, value(e.stats) || h('span', { class: 'muted' }, 'not asked for'))))))));
}

// `entries` in the comparison's order; none when no job asked for a viewer view.
export function viewerCompare(entries, nameOf) {
  const ranked = entries.map((e, i) => ({ ...e, rank: i + 1 }));
  if (!ranked.some((e) => viewerFigures(e.job, e.stats).length)) return null;
  // Two or more tilt series share one y range, so that their charts read against each other.
  const tilts = ranked.map((e) => e.stats.tilt_series).filter(Boolean);
  const range = tilts.length > 1 ? tiltRange(tilts) : null;
  return h('section', { 'aria-labelledby': 'viewer-compare-title', 'data-section': 'viewer-compare' },
    h('h2', { id: 'viewer-compare-title' }, 'What a viewer sees, side by side'),
    h('p', { class: 'hint' }, 'ASET colours: each view ray traced back through the stone and coloured by where its light comes from (the sky by elevation and the viewer\'s head cone, not the job\'s light model). Shares of the face-up area with one standard error.'),
    h('div', { class: 'card' }, viewerTable(ranked, nameOf)),
    h('div', { class: 'compare-grid' }, ranked.map((e) => {
      const figures = viewerFigures(e.job, e.stats, nameOf(e), range);
      return h('article', { class: 'card viewer-card', 'data-id': e.job.id },
        h('h3', {}, h('span', { class: 'rank-no small' }, `#${e.rank}`), ' ', h('a', { href: `#/jobs/${e.job.id}` }, nameOf(e))),
        figures.length ? figures : h('p', { class: 'empty' }, 'This job asked for no ASET view or tilt series.'));
    })));
}
