// The verdict (stats.viewer, docs/stats-schema.md; defined in docs/physics.md, "Viewer figures" and
// "Verdict"): the light-performance score, the faults found, and each viewer figure beside the GIA
// reference's under the same set-up; and the same for several designs side by side.
import { VIEWER_FIGURES } from './constants.js';
import { h } from './dom.js';
import { decimalsFor, fmtNumber, fmtPctErr, shortId } from './format.js';

// The set-ups in words, from the job's viewer settings.
function setUpText(key, settings) {
  if (key === 'spot') {
    const s = settings.spot || {};
    return `Spot: ${s.lamps} lamps at ${s.elevation_deg}° elevation, seen within ${s.viewing_cone_deg}° of face-up`;
  }
  const o = settings.office || {};
  return `Office: ${o.dome} dome, the viewer's head and shoulders in the way, rocked ±${settings.rock_deg}° at ${settings.azimuths} turns`;
}

function fmtScore(score) {
  if (!score || !Number.isFinite(score.value)) return '—';
  return `${score.value.toFixed(1)} ± ${score.stderr.toFixed(1)}`;
}

// "+2.8 % ± 0.4" against the reference, signed, or "as the reference" when within two standard errors.
function fmtDifference(f) {
  const d = f.difference_pct;
  const se = f.difference_pct_stderr;
  if (!Number.isFinite(d)) return '—';
  const places = Math.max(1, decimalsFor(se));
  const text = `${d >= 0 ? '+' : '−'}${Math.abs(d).toFixed(places)} % ± ${se.toFixed(places)}`;
  return Math.abs(d) <= 2 * se ? `${text} (within noise)` : text;
}

// Better or worse than the reference, beyond two standard errors; the contrast counts by its balance.
function differenceClass(info, f) {
  if (!Number.isFinite(f.difference_pct) || Math.abs(f.difference_pct) <= 2 * f.difference_pct_stderr) return 'same';
  if (info.key === 'contrast') return 'off';
  return (f.difference_pct > 0) !== Boolean(info.lowerIsBetter) ? 'better' : 'worse';
}

// A bar from the reference (the middle) to the figure's difference, ±50 % across.
function differenceBar(f, cls) {
  const d = Math.max(-50, Math.min(50, f.difference_pct || 0));
  const left = 50 + Math.min(0, d);
  return h('span', { class: 'diff-track', 'aria-hidden': 'true' },
    h('span', { class: 'diff-mid' }),
    h('span', { class: `diff-bar ${cls}`, style: `left:${left}%;width:${Math.abs(d)}%` }));
}

function faultList(viewer) {
  const faults = (viewer.faults || []).filter((f) => f.applies);
  return h('ul', { class: 'fault-list' }, faults.map((f) => h('li', { class: `fault ${f.present ? 'found' : 'absent'}`, 'data-fault': f.key, title: f.text },
    h('strong', {}, f.present ? `✕ ${f.name}` : `✓ no ${f.name}`),
    h('span', { class: 'muted' }, ` ${fmtPctErr(f.measure, f.measure_stderr)} (${f.meaning}; a fault above ${fmtNumber(f.threshold * 100, 3)} %)`))));
}

// The result page's first card; none when the job ran without the viewer.
export function verdictCard(stats) {
  const viewer = stats.viewer;
  if (!viewer) return null;
  const found = (viewer.faults || []).filter((f) => f.applies && f.present);
  return h('section', { class: 'card verdict', 'aria-labelledby': 'verdict-title', 'data-section': 'verdict' },
    h('h2', { id: 'verdict-title' }, 'Verdict'),
    h('p', { class: 'verdict-score' },
      h('span', { class: 'score-value' }, fmtScore(viewer.score)),
      h('span', { class: 'score-label' }, ' light performance · the GIA reference: 100'),
      h('span', { class: `verdict-faults ${found.length ? 'found' : 'none'}` },
        found.length ? ` · ${found.map((f) => f.name).join(', ')}` : ' · no faults')),
    h('p', { class: 'hint' }, `Against ${viewer.reference}, seen the same way. The score weighs brightness, fire, scintillation and contrast (docs/physics.md, “Verdict”); it never replaces the figures below.`),
    h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': 'Viewer figures against the GIA reference' },
      h('table', { class: 'data verdict-table' },
        h('thead', {}, h('tr', {},
          h('th', { scope: 'col' }, 'Figure'), h('th', { scope: 'col' }, 'Set-up'),
          h('th', { scope: 'col', class: 'num' }, 'This stone'), h('th', { scope: 'col', class: 'num' }, 'GIA reference'),
          h('th', { scope: 'col', class: 'num' }, 'Difference'), h('th', { scope: 'col' }, h('span', { class: 'visually-hidden' }, 'Difference as a bar')))),
        h('tbody', {}, VIEWER_FIGURES.filter((info) => viewer.figures && viewer.figures[info.key]).map((info) => {
          const f = viewer.figures[info.key];
          const cls = differenceClass(info, f);
          return h('tr', { 'data-figure': info.key, title: info.hint },
            h('th', { scope: 'row' }, info.label, info.lowerIsBetter ? h('span', { class: 'muted' }, ' (less is better)') : null),
            h('td', { class: 'setup' }, setUpText(f.set_up, viewer.settings || {})),
            h('td', { class: 'num' }, fmtPctErr(f.value, f.stderr)),
            h('td', { class: 'num' }, fmtPctErr(f.reference, f.reference_stderr)),
            h('td', { class: `num diff ${cls}` }, fmtDifference(f)),
            h('td', {}, differenceBar(f, cls)));
        })))),
    h('h3', { class: 'small-title' }, 'Faults a gemologist names'),
    faultList(viewer));
}

// The verdicts of several designs side by side, in the comparison's order; none when no job has a viewer.
export function verdictCompare(entries, nameOf) {
  const judged = entries.filter((e) => e.stats.viewer);
  if (!judged.length) return null;
  const row = (label, cell) => h('tr', {}, h('th', { scope: 'row' }, label), judged.map((e) => h('td', { class: 'num' }, cell(e.stats.viewer))));
  return h('section', { class: 'card', 'aria-labelledby': 'verdict-compare-title', 'data-section': 'verdict-compare' },
    h('h2', { id: 'verdict-compare-title' }, 'Verdicts side by side'),
    h('p', { class: 'hint' }, 'Each figure as a share with one standard error and, below it, its difference from the GIA reference seen the same way.'),
    h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-labelledby': 'verdict-compare-title' },
      h('table', { class: 'data verdict-compare-table' },
        h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Figure'),
          judged.map((e) => h('th', { scope: 'col', class: 'num' }, nameOf(e), h('br'), h('span', { class: 'muted' }, `job ${shortId(e.job.id)}`))))),
        h('tbody', {},
          row('Light performance (GIA reference: 100)', (v) => h('strong', {}, fmtScore(v.score))),
          row('Faults', (v) => {
            const found = (v.faults || []).filter((f) => f.applies && f.present);
            return h('span', { class: `verdict-faults ${found.length ? 'found' : 'none'}` }, found.length ? found.map((f) => f.name).join(', ') : 'none');
          }),
          VIEWER_FIGURES.filter((info) => info.key !== 'score').map((info) => row(info.label, (v) => {
            const f = v.figures && v.figures[info.key];
            if (!f) return '—';
            return h('span', {}, fmtPctErr(f.value, f.stderr), h('br'),
              h('span', { class: `diff ${differenceClass(info, f)}` }, fmtDifference(f)));
          }))))));
}
