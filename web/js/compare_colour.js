// The comparison's colours: each job's mean colour as a swatch, its CIELAB and its shares side by side, the
// absorbed share where a stone absorbs, and the colour pictures; none when no job has a colour view or absorbs.
import { ABSORBED_FIGURE, LAB_ROWS, absorbs, colourShares, colourSwatch, labCell, meanColourText, spreadCell } from './colour.js';
import { h, zoomable } from './dom.js';
import { fmtNumber, fmtPctErr, shortId } from './format.js';

export function colourCompare(entries, nameOf) {
  const ranked = entries.map((e, i) => ({ ...e, rank: i + 1 }));
  if (!ranked.some((e) => e.stats.colour || absorbs(e.stats))) return null;
  const colourOf = (f) => (s) => s.colour && f(s.colour);
  const rows = [
    ['mean', 'Mean colour', colourOf((c) => [colourSwatch(c.mean_colour.srgb, `The mean colour, ${meanColourText(c)}`), c.mean_colour.srgb])],
    ['size', 'Seen at', colourOf((c) => `${fmtNumber(c.size_mm, 2)} mm under ${c.illuminant}`)],
    ...LAB_ROWS.map(([key, label]) => [key, `${label} mean`, colourOf((c) => labCell(c, key))]),
    ...LAB_ROWS.map(([key, label]) => [`${key}-spread`, `${label} spread`, colourOf((c) => spreadCell(c, key))]),
    ...['windowed', 'extinct', 'saturated'].map((key, i) => [key, null, colourOf((c) => colourShares(c)[i][2])]),
    ['absorbed', ABSORBED_FIGURE.label, (s) => absorbs(s) && fmtPctErr(s.totals.absorbed_share, s.totals.absorbed_share_stderr)],
  ];
  // A share's row is named by its words (their thresholds may differ from job to job: the first job's).
  const first = ranked.find((e) => e.stats.colour);
  const labelOf = (key, label) => label || (first ? colourShares(first.stats.colour).find(([k]) => k === key)[1] : key);
  return h('section', { 'aria-labelledby': 'colour-compare-title', 'data-section': 'colour-compare' },
    h('h2', { id: 'colour-compare-title' }, 'Colour, side by side'),
    h('p', { class: 'hint' }, 'Each stone face-up in true colour (docs/optics.md, "The colour a viewer sees"): CIELAB over its pixels and shares of its face-up area, ± one standard error; absorbed: the share of the photons that hit it taken up inside.'),
    h('div', { class: 'card' }, h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-labelledby': 'colour-compare-title' },
      h('table', { class: 'data colour-compare-table' },
        h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Figure'),
          ranked.map((e) => h('th', { scope: 'col', class: 'num' }, `#${e.rank} ${nameOf(e)}`, h('br'), h('span', { class: 'muted' }, `job ${shortId(e.job.id)}`))))),
        h('tbody', {}, rows.map(([key, label, value]) => h('tr', { 'data-colour-row': key }, h('th', { scope: 'row' }, labelOf(key, label)),
          ranked.map((e) => {
            const v = value(e.stats);
            return h('td', { class: 'num', 'data-id': e.job.id }, v || h('span', { class: 'muted' }, key === 'absorbed' ? 'clear stone' : 'no colour view'));
          }))))))),
    ranked.some((e) => (e.job.links || {}).colour) ? h('div', { class: 'compare-grid' }, ranked.filter((e) => (e.job.links || {}).colour).map((e) => h('article', { class: 'card colour-card', 'data-id': e.job.id },
      h('h3', {}, h('span', { class: 'rank-no small' }, `#${e.rank}`), ' ', h('a', { href: `#/jobs/${e.job.id}` }, nameOf(e))),
      h('figure', { class: 'colour-picture' }, zoomable(e.job.links.colour, `${nameOf(e)} face-up in true colour`))))) : null);
}
