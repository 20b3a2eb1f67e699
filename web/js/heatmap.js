// The heat-map's facets as shapes laid over its picture (heatmap.json): pointing at a facet names it and
// lights up its row of the facet table; pointing at a row lights up the facet.
import { api } from './api.js';
import { h, svg } from './dom.js';
import { fmtNumber, fmtPctErr, humanize } from './format.js';

// Lights up facet `id` (null: none) within `root`: its shapes on the heat-map and its table row.
export function linkFacet(root, id) {
  for (const el of root.querySelectorAll('.linked')) el.classList.remove('linked');
  if (id === null) return;
  for (const el of root.querySelectorAll(`[data-facet="${id}"], [data-facets~="${id}"]`)) el.classList.add('linked');
}

// Matplotlib's viridis (van der Walt & Smith, 2015) as core/colormap.h draws it: Matt Zucker's degree-6
// polynomial fit (shadertoy WlfXRN, CC0), so the page's colours match the pictures'.
const VIRIDIS_FIT = [[0.2777273272234177, 0.005407344544966578, 0.3340998053353061],
  [0.1050930431085774, 1.404613529898575, 1.384590162594685], [-0.3308618287255563, 0.214847559468213, 0.09509516302823659],
  [-4.634230498983486, -5.799100973351585, -19.33244095627987], [6.228269936347081, 14.17993336680509, 56.69055260068105],
  [4.776384997670288, -13.74514537774601, -65.35303263337234], [-5.435455855934631, 4.645852612178535, 26.3124352495832]];
export function viridis(t) {
  const x = Math.min(1, Math.max(0, t));
  const rgb = [0, 1, 2].map((k) => {
    let v = VIRIDIS_FIT[6][k];
    for (let i = 5; i >= 0; i--) v = v * x + VIRIDIS_FIT[i][k];
    return Math.round(255 * Math.min(1, Math.max(0, v)));
  });
  return `rgb(${rgb.join(', ')})`;
}

// The end of a colour scale: the first of 1, 2 or 5 times a power of ten, in fifths, at or above `max`.
export function scaleEnd(max) {
  if (!(max > 0)) return 1;
  const raw = max / 5;
  const p = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * p).find((v) => v >= raw);
  return Math.ceil(max / step - 1e-9) * step;
}

// What a heat-map shades each facet by: the share of the light leaving it (heatmap.png), or of the fire
// (heatmap_fire.png, the statistics' fire.facets).
const LIGHT = { facets: (s) => s.facets || [], share: (f) => f.leaving_share, stderr: (f) => f.leaving_share_stderr, of: 'of the light leaving' };
export const FIRE = { facets: (s) => (s.fire && s.fire.facets) || [], share: (f) => f.share, stderr: (f) => f.share_stderr, of: 'of the fire leaving' };

// The end of one colour scale for the heat-maps of `statsList`: the largest of the scales their pictures have
// on their own (core/pictures/heatmap.cpp, scaleTop: the 95th percentile of the facets other than the table,
// the table's large share would leave every other facet the same dark colour), so that no design's map
// saturates more than its own picture does. Facets beyond it are drawn hatched and named under the legend.
export function commonScale(statsList, measure = LIGHT) {
  return Math.max(...statsList.map((s) => {
    const region = new Map((s.facets || []).map((f) => [f.id, f.region]));
    const shares = measure.facets(s);
    const others = shares.filter((f) => region.get(f.id) !== 'table').map(measure.share).sort((a, b) => a - b);
    const p95 = others.length ? others[Math.ceil(0.95 * others.length) - 1] : 0;
    return scaleEnd(p95 > 0 ? p95 : Math.max(0, ...shares.map(measure.share)));
  }));
}

let hatches = 0;  // each drawing's hatch pattern has an id of its own

// Fetches the heat-map's layout and either lays its facets over the picture (overlay) or, with a common
// colour scale (the comparison), draws them in its place filled on that scale; both name the facet pointed at.
async function heatmapShapes(figure, href, stats, commonScale, measure = LIGHT) {
  const anchor = figure.querySelector('a');
  let layout = null;
  try {
    layout = await api(href);
  } catch {
    // below: the picture as it is
  }
  if (!anchor || !anchor.isConnected) return;
  const drawing = commonScale > 0;
  if (!layout) {
    if (drawing) anchor.replaceChildren(h('img', { src: anchor.href, alt: 'Facet heat-map', decoding: 'async' }));
    return;
  }
  const facets = new Map((stats ? measure.facets(stats) : []).map((f) => [f.id, f]));
  const describe = (f) => {
    const s = facets.get(f.id);
    return s ? `${humanize(f.name)} (${f.side}): ${fmtPctErr(measure.share(s), measure.stderr(s))} ${measure.of}`
      : humanize(f.name);
  };
  const shareOf = (f) => (facets.has(f.id) ? measure.share(facets.get(f.id)) : 0);
  const beyond = drawing ? layout.facets.filter((f) => shareOf(f) > commonScale * (1 + 1e-9)) : [];
  const hatch = `heat-hatch-${++hatches}`;
  const polygons = layout.facets.map((f) => {
    const points = f.points.map((p) => p.join(',')).join(' ');
    const fill = drawing ? { fill: viridis(shareOf(f) / commonScale), stroke: '#1a1a1a', 'stroke-width': 1.2 } : {};
    const shape = svg('polygon', { points, 'data-facet': f.id, ...fill }, svg('title', {}, describe(f)));
    // Beyond the scale: its top colour, hatched, as the server's picture marks it.
    return beyond.includes(f) ? [shape, svg('polygon', { points, fill: `url(#${hatch})`, class: 'heat-beyond', 'pointer-events': 'none' })] : [shape];
  }).flat();
  let shapes;
  if (drawing) {
    const xs = layout.facets.flatMap((f) => f.points.map((p) => p[0]));
    const ys = layout.facets.flatMap((f) => f.points.map((p) => p[1]));
    const [x0, y0] = [Math.min(...xs) - 8, Math.min(...ys) - 40];
    const [w, hgt] = [Math.max(...xs) + 8 - x0, Math.max(...ys) + 8 - y0];
    const titles = [['crown', 'Crown, from above'], ['pavilion', 'Pavilion, from below']].map(([side, title]) => {
      const sx = layout.facets.filter((f) => f.side === side).flatMap((f) => f.points.map((p) => p[0]));
      return sx.length ? svg('text', { x: (Math.min(...sx) + Math.max(...sx)) / 2, y: y0 + 24, 'text-anchor': 'middle', class: 'heat-side' }, title) : null;
    }).filter(Boolean);
    shapes = svg('svg', { class: 'heatmap-drawing', viewBox: `${x0} ${y0} ${w} ${hgt}`, role: 'img',
      'aria-label': `Facet heat-map: crown from above, pavilion from below, on the comparison's common scale (0 to ${(commonScale * 100).toFixed(1)} % ${measure.of} a facet)` },
    svg('defs', {}, svg('pattern', { id: hatch, width: 14, height: 14, patternUnits: 'userSpaceOnUse', patternTransform: 'rotate(45)' },
      svg('line', { x1: 0, y1: 0, x2: 0, y2: 14, stroke: '#1a1a1a', 'stroke-width': 4 }))),
    ...titles, ...polygons);
    anchor.replaceChildren(shapes);
    const caption = figure.querySelector('figcaption');
    figure.insertBefore(h('div', { class: 'heat-legend' },
      h('span', {}, '0 %'),
      h('span', { class: 'heat-ramp', 'aria-hidden': 'true', style: `background: linear-gradient(to right, ${[0, 0.25, 0.5, 0.75, 1].map(viridis).join(', ')})` }),
      h('span', { class: 'heat-max' }, `${(commonScale * 100).toFixed(1)} %`)), caption);
    if (beyond.length) {
      figure.insertBefore(h('p', { class: 'heat-beyond-list' }, 'Hatched, beyond the scale: ',
        beyond.map((f) => `${humanize(f.name)} ${fmtPctErr(shareOf(f), measure.stderr(facets.get(f.id)))}`).join(', ')), caption);
    }
  } else {
    shapes = svg('svg', { class: 'heatmap-overlay', viewBox: `0 0 ${layout.width} ${layout.height}`, 'aria-hidden': 'true' }, ...polygons);
    anchor.append(shapes);
  }
  const readout = h('p', { class: 'heatmap-readout', 'aria-live': 'polite' }, 'Point at a facet to name it.');
  const root = figure.closest('.result, .compare-card') || figure;
  const byId = new Map(layout.facets.map((f) => [String(f.id), f]));
  shapes.addEventListener('mouseover', (e) => {
    const id = e.target.getAttribute && e.target.getAttribute('data-facet');
    if (id === null || !byId.has(id)) return;
    linkFacet(root, id);
    readout.textContent = describe(byId.get(id));
  });
  shapes.addEventListener('mouseleave', () => linkFacet(root, null));
  figure.append(readout);
}

// The fire heat-map of a compared job drawn on the page on the comparison's common scale (heatmap_fire.png's
// facets, from its layout and the statistics' fire.facets); the picture itself where there is no layout.
export function fireHeatmapDrawn(job, name, stats, commonScale) {
  const links = job.links || {};
  const figure = h('figure', { class: 'picture pic-heatmap-fire' },
    h('a', { href: links.heatmap_fire, target: '_blank', rel: 'noopener', class: 'zoom', title: 'Open the picture at full size' },
      links.heatmap_layout ? h('div', { class: 'heatmap-pending' }) : h('img', { src: links.heatmap_fire, alt: `Fire heat-map of ${name}`, loading: 'lazy' })),
    h('figcaption', {}, 'Fire heat-map', h('span', { class: 'muted picture-light' }, ` · ${name}`)));
  if (links.heatmap_layout) heatmapShapes(figure, links.heatmap_layout, stats, commonScale, FIRE);
  return figure;
}

// `commonScale` (the comparison, from commonScale()): the heat-map is drawn on the page, its colours running
// from 0 to this share for every design compared, instead of each picture's own scale.
export function pictures(job, name, stats, commonScale = 0) {
  const links = job.links || {};
  const render = job.settings && job.settings.render;
  // A job without rendering still has its heat-map, which the statistics alone draw.
  if (!links.render && !links.heatmap) {
    return h('p', { class: 'empty' }, 'No pictures: this job ran without rendering (statistics only).');
  }
  const size = render ? { width: render.width, height: render.height } : {};
  // Which light each picture uses (docs/physics.md, "Which light each picture uses").
  const model = (job.settings && job.settings.light && job.settings.light.model) || 'the job\'s';
  const fire = job.settings && job.settings.fire_picture;
  const items = [
    links.render ? { href: links.render, cls: 'pic-render', title: 'Render', light: 'studio light, the viewer\'s head shadow', alt: `Render of ${name} as the camera sees it` } : null,
    // Beside the render: the same camera under one small light, where dispersion shows as colour.
    links.fire_picture ? {
      href: links.fire_picture, cls: 'pic-fire', title: 'Fire, spectral colour',
      light: fire ? `one small light ${fmtNumber(fire.light_tilt_deg, 1)}° from vertical, ${fmtNumber(fire.light_radius_deg, 2)}° radius, in a dim room`
        : 'one small light in a dim room',
      alt: `Fire picture of ${name}: the flashes of colour under a small bright light`,
    } : null,
    { href: links.heatmap, cls: 'pic-heatmap', title: 'Facet heat-map', light: `${model} light`, alt: `Heat-map of ${name}: facets shaded by the share of light leaving them` },
    links.angular ? { href: links.angular, cls: 'pic-angular', title: 'Exit angles', light: `${model} light`, alt: `Chart of ${name}: where the light leaves, by angle from vertical` } : null,
  ].filter(Boolean);
  const drawHeatmap = commonScale > 0 && links.heatmap_layout;
  const figures = items.map((p) => h('figure', { class: `picture ${p.cls}` },
    h('a', { href: p.href, target: '_blank', rel: 'noopener', class: 'zoom', title: 'Open the picture at full size' },
      drawHeatmap && p.cls === 'pic-heatmap' ? h('div', { class: 'heatmap-pending' })
        : h('img', { src: p.href, alt: p.alt, ...(p.cls === 'pic-angular' ? {} : size), decoding: 'async' })),
    h('figcaption', {}, p.title, h('span', { class: 'muted picture-light' }, ` · ${p.light}`))));
  const heatmap = figures[items.findIndex((p) => p.cls === 'pic-heatmap')];
  if (links.heatmap_layout) heatmapShapes(heatmap, links.heatmap_layout, stats, drawHeatmap ? commonScale : 0);
  return h('div', { class: 'pictures' }, figures,
    links.render ? null : h('p', { class: 'hint' }, 'No render or exit-angle chart: this job ran without rendering; the heat-map comes from its statistics.'));
}
