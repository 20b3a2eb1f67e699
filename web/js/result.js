// One job's result: the figures, the pictures, the region and facet tables.
import { api, jobUrl } from './api.js';
import { ABSORBED_FIGURE, absorbs, colourSection } from './colour.js';
import { FACET_COLUMNS, FIGURES, POLL_ACTIVE_MS, REGIONS } from './constants.js';
import { designSection } from './design.js';
import { $, h, zoomable } from './dom.js';
import { decimalsFor, fmtDuration, fmtInt, fmtNumber, fmtPct, fmtPctErr, fmtTime, humanize, shortId } from './format.js';
import { fireSection } from './fire.js';
import { linkFacet, pictures } from './heatmap.js';
import { jobName } from './meshes.js';
import { jobSummary, lightText, progressBar, stateBadge } from './progress.js';
import { tiltChartSvg } from './tilt.js';
import { verdictCard } from './verdict.js';

// The facet table's order, whether it groups facets by tier, and the tiers opened (all closed at first).
export const resultView = { id: '', timer: 0, stats: null, sort: { key: 'leaving_share', dir: -1 }, grouped: true, open: new Set() };

export async function showResult(id) {
  clearTimeout(resultView.timer);
  resultView.id = id;
  const body = $('#result-body');
  let job;
  try {
    job = await api(jobUrl(id));
  } catch (e) {
    if (resultView.id !== id) return;
    body.replaceChildren(h('h1', { id: 'result-title' }, 'Job not found'), h('p', { class: 'form-error', role: 'alert' }, e.message));
    return;
  }
  if (resultView.id !== id) return;
  document.title = `${jobName(job)} — facetlight`;
  if (job.state !== 'succeeded') {
    body.replaceChildren(
      h('h1', { id: 'result-title' }, `${jobName(job)} `, stateBadge(job.state)),
      h('p', { class: 'lede' }, jobSummary(job.settings)),
      h('div', { class: 'card' }, progressBar(job, `Progress of job ${shortId(job.id)}`),
        job.error ? h('p', { class: 'job-error' }, h('strong', {}, 'Error: '), job.error) : null));
    if (job.state === 'queued' || job.state === 'running') {
      resultView.timer = setTimeout(() => showResult(id), POLL_ACTIVE_MS);
    }
    return;
  }
  let stats;
  try {
    stats = await api(jobUrl(id, '/stats'));
  } catch (e) {
    body.replaceChildren(h('h1', { id: 'result-title' }, 'Statistics unavailable'), h('p', { class: 'form-error', role: 'alert' }, e.message));
    return;
  }
  if (resultView.id !== id) return;
  resultView.stats = stats;
  body.replaceChildren(resultPage(job, stats));
  $('#result-title').focus();
}

function figureCard(f, totals, emphasis = false) {
  const value = totals[f.key];
  const stderr = totals[`${f.key}_stderr`];
  return h('div', { class: `figure${emphasis ? ' emphasis' : ''}`, 'data-figure': f.key },
    h('dt', {}, f.label),
    h('dd', {},
      h('span', { class: 'figure-value' }, fmtPct(value, stderr)),
      h('span', { class: 'figure-err' }, Number.isFinite(stderr) ? `± ${(stderr * 100).toFixed(decimalsFor(stderr * 100))} pts` : ''),
      h('span', { class: 'figure-hint' }, f.hint)));
}

// `compact` (the comparison's narrow cards) leaves the bars out.
export function regionTable(regions, caption, compact = false) {
  const max = Math.max(1e-12, ...REGIONS.map((r) => (regions[r] ? regions[r].share : 0)));
  return h('div', { class: 'table-scroll' }, h('table', { class: `data regions${compact ? ' compact' : ''}` },
    h('caption', {}, caption),
    h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Region'), h('th', { scope: 'col', class: 'num' }, 'Photons leaving'),
      h('th', { scope: 'col', class: 'num' }, 'Share ± s.e.'), h('th', { scope: 'col' }, h('span', { class: 'visually-hidden' }, 'Bar')))),
    h('tbody', {}, REGIONS.filter((r) => regions[r]).map((r) => h('tr', { 'data-region': r },
      h('th', { scope: 'row' }, h('span', { class: `swatch region-${r}`, 'aria-hidden': 'true' }), humanize(r)),
      h('td', { class: 'num' }, fmtInt(regions[r].leaving)),
      h('td', { class: 'num' }, fmtPctErr(regions[r].share, regions[r].share_stderr)),
      h('td', { class: 'bar-cell' }, h('span', { class: `bar region-${r}`, style: `width:${(regions[r].share / max) * 100}%` })))))));
}

// A facet's tier: its name without its number (star_3 -> star, GemCad's P1_2 -> P1); the table is its own.
function tierOf(name) {
  return String(name).replace(/_\d+$/, '');
}

// The facets of each tier summed, in the order of their first facet: the counts and shares add up, and the
// share's standard error is the binomial one of the summed share over the `hit` photons it is a share of.
function tiers(facets, hit) {
  const byName = new Map();
  for (const f of facets) {
    const name = tierOf(f.name);
    if (!byName.has(name)) byName.set(name, { name, facets: [] });
    byName.get(name).facets.push(f);
  }
  return [...byName.values()].map((t) => {
    const sum = (k) => t.facets.reduce((s, f) => s + (f[k] || 0), 0);
    const share = sum('leaving_share');
    const regions = new Set(t.facets.map((f) => f.region));
    return {
      ...t, id: Math.min(...t.facets.map((f) => f.id)), region: regions.size === 1 ? t.facets[0].region : 'mixed',
      area: sum('area'), entering: sum('entering'), reflected: sum('reflected'), internal_reflections: sum('internal_reflections'),
      leaving: sum('leaving'), leaving_share: share,
      leaving_share_stderr: hit > 0 ? Math.sqrt(Math.max(0, share * (1 - share)) / hit) : undefined,
    };
  });
}

function compareBy(col, dir) {
  return (a, b) => {
    const x = a[col.key];
    const y = b[col.key];
    const c = col.numeric ? x - y : String(x).localeCompare(String(y), 'en', { numeric: true });
    return c * dir || a.id - b.id;
  };
}

// `hit`: the photons the shares are of (totals.hit), for the tiers' standard errors.
function facetTable(facets, hit) {
  const wrap = h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-labelledby': 'facet-caption' });
  const maxShare = Math.max(1e-12, ...facets.map((f) => f.leaving_share));
  const cells = (f, isTier) => FACET_COLUMNS.map((c) => {
    if (c.key === 'leaving_share') {
      return h('td', { class: 'num share-cell' },
        isTier ? null : h('span', { class: 'mini-track', 'aria-hidden': 'true' },
          h('span', { class: `bar mini region-${f.region}`, style: `width:${(f.leaving_share / maxShare) * 100}%` })),
        h('span', { class: 'share-text' }, Number.isFinite(f.leaving_share_stderr) ? fmtPctErr(f.leaving_share, f.leaving_share_stderr) : fmtPct(f.leaving_share)));
    }
    if (c.key === 'region') {
      return h('td', {}, f.region === 'mixed' ? 'mixed' : [h('span', { class: `swatch region-${f.region}`, 'aria-hidden': 'true' }), humanize(f.region)]);
    }
    if (isTier && c.key === 'id') return h('td', { class: 'num muted' }, `${f.facets.length}×`);
    if (isTier && c.key === 'name') {
      const open = resultView.open.has(f.name);
      return h('td', {}, h('button', {
        type: 'button', class: 'tier-toggle', 'aria-expanded': String(open), 'data-tier': f.name,
        onclick: () => {
          if (open) resultView.open.delete(f.name);
          else resultView.open.add(f.name);
          draw();
          wrap.querySelector(`button.tier-toggle[data-tier="${CSS.escape(f.name)}"]`).focus();
        },
      }, h('span', { 'aria-hidden': 'true' }, open ? '▾ ' : '▸ '), humanize(f.name)));
    }
    const v = f[c.key];
    return h('td', { class: c.numeric ? 'num' : '' }, c.format ? c.format(v) : String(v ?? ''));
  });
  const facetRow = (f) => h('tr', {
    'data-facet': f.id, 'data-region': f.region,
    onmouseenter: (e) => linkFacet(e.currentTarget.closest('.result') || document, f.id),
    onmouseleave: (e) => linkFacet(e.currentTarget.closest('.result') || document, null),
  }, cells(f, false));
  function draw() {
    const { key, dir } = resultView.sort;
    const col = FACET_COLUMNS.find((c) => c.key === key);
    const head = h('tr', {}, FACET_COLUMNS.map((c) => {
      const active = c.key === key;
      const sortState = active ? (dir > 0 ? 'ascending' : 'descending') : 'none';
      return h('th', { scope: 'col', class: c.numeric ? 'num' : '', 'aria-sort': sortState },
        h('button', {
          type: 'button', class: 'sort', 'data-sort': c.key,
          onclick: () => {
            resultView.sort = { key: c.key, dir: active ? -dir : (c.numeric ? -1 : 1) };
            draw();
            wrap.querySelector(`button[data-sort="${c.key}"]`).focus();
          },
        }, c.label, h('span', { class: 'sort-mark', 'aria-hidden': 'true' }, active ? (dir > 0 ? ' ▲' : ' ▼') : ' ↕')));
    }));
    const order = compareBy(col, dir);
    // Grouped, each tier is a body of its own: its sums, then (when opened) its facets, tiers and facets alike in
    // the table's order; a tier row lights when a facet of it is pointed at on the heat-map.
    const bodies = resultView.grouped
      ? tiers(facets, hit).sort(order).map((t) => h('tbody', { class: 'tier', 'data-tier': t.name },
        h('tr', { class: 'tier-row', 'data-facets': t.facets.map((f) => f.id).join(' '), 'data-region': t.region }, cells(t, true)),
        resultView.open.has(t.name) ? [...t.facets].sort(order).map(facetRow) : null))
      : [h('tbody', {}, [...facets].sort(order).map(facetRow))];
    const grouping = h('label', { class: 'facet-grouping' }, h('input', {
      type: 'checkbox', checked: resultView.grouped,
      onchange: (e) => { resultView.grouped = e.target.checked; draw(); wrap.querySelector('.facet-grouping input').focus(); },
    }), ' Group by tier');
    wrap.replaceChildren(grouping, h('table', { class: `data facets${resultView.grouped ? ' grouped' : ''}` },
      h('caption', { id: 'facet-caption' }, `Facets (${facets.length}${resultView.grouped ? ` in ${tiers(facets, hit).length} tiers` : ''}) — sorted by ${col.label.toLowerCase()}, ${dir > 0 ? 'ascending' : 'descending'}; shares ± one standard error`),
      h('thead', {}, head), bodies));
  }
  draw();
  return wrap;
}

function proportionList(mesh) {
  const p = (mesh && mesh.proportions) || {};
  const rows = [
    ['Facets', mesh && mesh.facets], ['Table', p.table_pct, '%'], ['Crown height', p.crown_height_pct, '%'],
    ['Pavilion depth', p.pavilion_depth_pct, '%'], ['Girdle, thinnest', p.girdle_pct, '%'],
    ['Girdle, thickest', p.girdle_thickest_pct, '%'], ['Total depth', p.total_depth_pct, '%'],
    ['Crown angle', p.crown_angle_deg, '°'], ['Pavilion angle', p.pavilion_angle_deg, '°'],
    ['Star angle', p.star_angle_deg, '°'], ['Upper half angle', p.upper_half_angle_deg, '°'],
    ['Lower half angle', p.lower_half_angle_deg, '°'], ['Star length', p.star_pct, '%'],
    ['Lower half length', p.lower_half_pct, '%'],
  ].filter(([, v]) => v !== undefined && v !== null);
  return h('dl', { class: 'kv' }, rows.map(([k, v, unit]) => [h('dt', {}, k), h('dd', {}, unit ? `${fmtNumber(v, 2)}${unit === '%' ? ' %' : unit}` : String(v))]));
}

// The cut library parameters the job changed from its shape's (the design's own proportions follow).
function cutList(job) {
  const cut = Object.entries((job.settings && job.settings.cut) || {});
  if (!cut.length) return null;
  return h('p', { class: 'cut-values' }, `${humanize(job.mesh)} cut with `,
    cut.map(([k, v]) => `${humanize(k)} ${fmtNumber(v, 4)}`).join(', '));
}

// The ASET classes in the order of aset.png's legend (docs/physics.md, "ASET view").
export const ASET_CLASSES = [
  ['head', 'Head cone (blue)'], ['bright', 'Bright light (red)'], ['low', 'Low light (green)'],
  ['leakage', 'Leakage'], ['trapped', 'Trapped'],
];

// The axis a tilt series rocks about, by its azimuth (docs/physics.md, "Tilt series and sparkle").
function tiltAxisName(deg) {
  const a = ((deg % 180) + 180) % 180;
  if (a === 0) return 'the left–right (x) axis';
  if (a === 90) return 'the front–back (y) axis';
  return `the horizontal axis at ${fmtNumber(deg, 1)}° azimuth`;
}

// The tilt series' scintillation in words.
export function scintillationText(tilt) {
  const { max_deg: max, axis_deg: axis } = tilt.settings;
  return `Rocked ±${fmtNumber(max, 1)}° about ${tiltAxisName(axis)}: scintillation ${fmtPctErr(tilt.scintillation, tilt.scintillation_stderr)} of the face-up area per frame, over ${tilt.frames.length} frames`;
}

// The polariscope's verdict: where the stone goes dark as it turns, or that it stays dark or light.
export function polariscopeText(p) {
  if (p.reaction === 'stays_dark') return 'Polariscope: stays dark as it turns (singly refracting, or seen along an optic axis)';
  if (p.reaction === 'stays_light') {
    return 'Polariscope: stays light as it turns (the facets\' reflections turn the polarisation and hide single or double refraction)';
  }
  return `Polariscope: dark at ${p.dark_angles_deg.map((a) => `${a}°`).join(', ')} of a turn: doubly refracting`;
}

// The doubling measured through the table, or why the stone shows one image.
export function doublingText(d) {
  if (!d.doubly_refracting) return `Doubling: none, ${d.traced_as}`;
  const t = d.table;
  return `Doubling: through the table ${t.median_mm.toFixed(3)} mm (quartiles ${t.quartiles_mm.map((q) => q.toFixed(3)).join('–')} mm), `
    + `${(100 * t.median_share_of_diameter).toFixed(2)} % of the girdle, ${t.median_arcmin.toFixed(1)}′ through a ${d.loupe}× loupe; `
    + `through the whole crown ${d.crown.median_mm.toFixed(3)} mm; seen ${d.view_to_axis_deg.toFixed(0)}° from the ${d.alpha ? 'nearer optic axis' : 'optic axis'}`;
}

// A job's viewer figures: the ASET picture with its shares, the tilt series' animation with its
// scintillation and its chart, the polariscope's animation and chart, the doubling's face-up view; none when
// the job asked for none. With `tiltRange` ([lo, hi] in percent, the comparison's common range) the chart is
// drawn on the page on that range instead of tilt.png's own.
export function viewerFigures(job, stats, name = '', tiltRange = null) {
  const links = job.links || {};
  const aset = stats.aset;
  const tilt = stats.tilt_series;
  const of = name ? ` of ${name}` : ' of the stone';
  return [
    links.aset ? h('figure', { class: 'viewer-aset' },
      zoomable(links.aset, `ASET view${of} face-up`),
      aset ? h('table', { class: 'data aset-shares' },
        h('caption', {}, `Shares of the face-up area (${fmtInt(aset.rays)} view rays)`),
        h('tbody', {}, ASET_CLASSES.filter(([k]) => aset.shares[k]).map(([k, label]) => h('tr', { 'data-aset': k },
          h('th', { scope: 'row' }, label),
          h('td', { class: 'num' }, fmtPctErr(aset.shares[k].share, aset.shares[k].stderr)))))) : null) : null,
    links.tilt_animation ? h('figure', { class: 'viewer-tilt' },
      zoomable(links.tilt_animation, `The stone${name ? ` (${name})` : ''} rocking through the tilt series (animation)`),
      tilt ? h('figcaption', {}, scintillationText(tilt)) : null) : null,
    links.tilt_chart ? h('figure', { class: 'viewer-tilt-chart' },
      tiltRange && tilt ? [
        h('a', { href: links.tilt_chart, target: '_blank', rel: 'noopener', class: 'zoom', title: 'Open tilt.png, on this design\'s own range' },
          tiltChartSvg(tilt, tiltRange, name)),
        h('figcaption', {}, `Light return against tilt, on the comparison's common range (${tiltRange[0]} to ${tiltRange[1]} %)`)]
        : zoomable(links.tilt_chart, `Light return against tilt${name ? `, ${name}` : ''}`)) : null,
    links.polariscope_animation ? h('figure', { class: 'viewer-polariscope' },
      zoomable(links.polariscope_animation, `The stone${name ? ` (${name})` : ''} turning between crossed polarisers (animation)`),
      stats.polariscope ? h('figcaption', {}, polariscopeText(stats.polariscope)) : null) : null,
    links.polariscope_chart ? h('figure', { class: 'viewer-polariscope-chart' },
      zoomable(links.polariscope_chart, `Light through crossed polarisers against the turntable's angle${name ? `, ${name}` : ''}`)) : null,
    links.doubling ? h('figure', { class: 'viewer-doubling' },
      zoomable(links.doubling, `The stone${name ? ` (${name})` : ''} face-up with its pavilion's edges through each wave`),
      stats.doubling ? h('figcaption', {}, doublingText(stats.doubling)) : null) : null,
  ].filter(Boolean);
}

// What a viewer sees: the ASET picture with its shares, the tilt series' animation and chart.
function viewerSection(job, stats) {
  const figures = viewerFigures(job, stats);
  if (!figures.length) return null;
  return h('section', { class: 'card', 'aria-labelledby': 'viewer-title', 'data-section': 'viewer' },
    h('h2', { id: 'viewer-title' }, 'What a viewer sees'),
    h('p', { class: 'hint' }, 'Each view ray traced back through the stone and coloured by where its light comes from (AGS ASET colours: the sky by elevation and the viewer\'s head cone, not the job\'s light model).'),
    h('div', { class: 'viewer-grid' }, figures));
}

// The stone in 3-D: stone3d.js (and three.js with it) is loaded only here, so the page works without either.
function stone3dSection(job, stats) {
  if (!job.links || !job.links.stone) return null;
  const body = h('div', { class: 'stone3d' }, h('p', { class: 'hint' }, 'Loading the 3-D view…'));
  import('./stone3d.js').then((m) => m.showStone3d(body, job, stats)).catch((e) => {
    body.replaceChildren(h('p', { class: 'hint stone3d-missing', role: 'status' }, `The 3-D view could not be loaded: ${e.message}`));
  });
  return h('section', { class: 'card', 'aria-labelledby': 'stone3d-title', 'data-section': 'stone3d' },
    h('h2', { id: 'stone3d-title' }, '3-D view'), body);
}

function resultPage(job, stats) {
  const name = jobName(job);
  const totals = stats.totals || {};
  const timing = stats.timing || {};
  const base = jobUrl(job.id);
  return h('article', { class: 'result' },
    h('header', { class: 'result-head' },
      h('h1', { id: 'result-title', tabindex: -1 }, name, ' ', stateBadge(job.state)),
      h('p', { class: 'lede' }, `${jobSummary(job.settings)} · job ${shortId(job.id)} · finished ${fmtTime(job.finished_at)}`),
      h('p', { class: 'downloads' }, 'Download: ',
        h('a', { href: `${base}/stats`, download: `facetlight-${shortId(job.id)}.json` }, 'Statistics (JSON)'), ' · ',
        h('a', { href: `${base}/stats.csv`, download: `facetlight-${shortId(job.id)}.csv` }, 'Facet table (CSV)'))),
    verdictCard(stats),
    h('section', { class: 'card', 'aria-labelledby': 'merit-title' },
      h('h2', { id: 'merit-title' }, 'Figures of merit'),
      h('p', { class: 'hint' }, `Shares of the photons that hit the stone, with one standard error, under the job's light (${lightText(job.settings)}).`),
      h('dl', { class: 'figures' }, FIGURES.map((f, i) => figureCard(f, totals, i === 0)),
        absorbs(stats) ? figureCard(ABSORBED_FIGURE, totals) : null)),
    h('section', { class: 'card', 'aria-labelledby': 'pictures-title' },
      h('h2', { id: 'pictures-title' }, 'Pictures'), pictures(job, name, stats)),
    stone3dSection(job, stats),
    viewerSection(job, stats),
    colourSection(job, stats),
    fireSection(job, stats),
    designSection(job, stats),
    h('div', { class: 'result-grid' },
      h('section', { class: 'card', 'aria-labelledby': 'regions-title' },
        h('h2', { id: 'regions-title' }, 'Where the light leaves'), regionTable(stats.regions || {}, 'Light leaving each region')),
      h('section', { class: 'card', 'aria-labelledby': 'run-title' },
        h('h2', { id: 'run-title' }, 'The run'),
        h('dl', { class: 'kv' },
          h('dt', {}, 'Photons'), h('dd', {}, fmtInt(totals.photons)),
          h('dt', {}, 'Hit the stone'), h('dd', {}, fmtInt(totals.hit)),
          h('dt', {}, 'Reflected at entry'), h('dd', {}, fmtInt(totals.reflected_at_entry)),
          h('dt', {}, 'Entered'), h('dd', {}, fmtInt(totals.entered)),
          h('dt', {}, 'Exited'), h('dd', {}, fmtInt(totals.exited)),
          h('dt', {}, 'Trapped'), h('dd', {}, totals.trapped_share == null ? fmtInt(totals.trapped)
            : `${fmtInt(totals.trapped)} (${fmtNumber(100 * totals.trapped_share, 4)} % ± ${fmtNumber(100 * totals.trapped_share_stderr, 4)})`),
          h('dt', {}, 'Time'), h('dd', {}, `${fmtDuration(timing.seconds)} on ${timing.threads} thread${timing.threads === 1 ? '' : 's'}`),
          h('dt', {}, 'Speed'), h('dd', {}, `${fmtInt(timing.photons_per_second)} photons/s`))),
      h('section', { class: 'card', 'aria-labelledby': 'stone-title' },
        h('h2', { id: 'stone-title' }, 'The stone'), cutList(job), proportionList(stats.mesh))),
    h('section', { class: 'card', 'aria-labelledby': 'facet-caption' }, facetTable(stats.facets || [], stats.totals ? stats.totals.hit : 0)));
}
