// The tilt series' light return against tilt drawn on the page, on a y range the caller gives: the comparison
// draws every design's on one range, so that the curves read against each other (tilt.png, drawn by the
// server, fits each design's own).
import { svg } from './dom.js';
import { fmtPctErr, fmtNumber } from './format.js';

// Whole 5 % steps around every frame's light return ± one standard error of `tilts`, as tilt.png rounds.
export function tiltRange(tilts) {
  const values = tilts.flatMap((t) => t.frames.flatMap((f) => [100 * (f.light_return - f.light_return_stderr),
    100 * (f.light_return + f.light_return_stderr)]));
  if (!values.length) return null;
  const lo = Math.max(0, 5 * Math.floor(Math.min(...values) / 5 - 1e-9));
  const hi = Math.min(100, Math.max(lo + 5, 5 * Math.ceil(Math.max(...values) / 5 + 1e-9)));
  return [lo, hi];
}

// The chart of `tilt` (stats.tilt_series) with light return in percent from range[0] to range[1] up.
export function tiltChartSvg(tilt, range, name = '') {
  const [lo, hi] = range;
  const frames = tilt.frames;
  const [left, top, width, height] = [60, 12, 440, 230];
  const t0 = frames[0].tilt_deg;
  const t1 = Math.max(frames[frames.length - 1].tilt_deg, t0 + 1);
  const x = (t) => left + ((t - t0) / (t1 - t0)) * width;
  const y = (p) => top + ((hi - p) / (hi - lo)) * height;
  const axis = { stroke: '#333', 'stroke-width': 1 };
  const grid = { stroke: '#d9dee7', 'stroke-width': 1 };
  const marks = [];
  const yStep = hi - lo > 20 ? 10 : (hi - lo > 10 ? 5 : 1);
  for (let v = lo; v <= hi + 1e-9; v += yStep) {
    marks.push(svg('line', { x1: left, y1: y(v), x2: left + width, y2: y(v), ...grid }),
      svg('text', { x: left - 8, y: y(v) + 4, 'text-anchor': 'end', class: 'chart-tick' }, `${v}`));
  }
  const span = t1 - t0;
  const xStep = span > 40 ? 10 : (span > 10 ? 5 : 1);
  for (let t = Math.ceil(t0 / xStep) * xStep; t <= t1 + 1e-9; t += xStep) {
    marks.push(svg('line', { x1: x(t), y1: top + height, x2: x(t), y2: top + height + 5, ...axis }),
      svg('text', { x: x(t), y: top + height + 18, 'text-anchor': 'middle', class: 'chart-tick' }, `${t}`));
  }
  const points = frames.map((f) => [x(f.tilt_deg), y(100 * f.light_return)]);
  return svg('svg', { class: 'tilt-chart', viewBox: `0 0 ${left + width + 12} ${top + height + 48}`, role: 'img',
    'data-range': `${lo} ${hi}`,
    'aria-label': `Light return against tilt${name ? `, ${name}` : ''}: ${lo} to ${hi} % of the face-up area` },
  svg('rect', { x: left, y: top, width, height, fill: '#fff', ...axis }),
  ...marks,
  ...frames.map((f) => svg('line', { x1: x(f.tilt_deg), y1: y(100 * (f.light_return - f.light_return_stderr)),
    x2: x(f.tilt_deg), y2: y(100 * (f.light_return + f.light_return_stderr)), stroke: '#17202c', 'stroke-width': 1.5 })),
  svg('polyline', { points: points.map((p) => p.join(',')).join(' '), fill: 'none', stroke: '#c2261a', 'stroke-width': 2 }),
  ...frames.map((f, i) => svg('circle', { cx: points[i][0], cy: points[i][1], r: 3.5, fill: '#c2261a' },
    svg('title', {}, `${fmtNumber(f.tilt_deg, 1)}°: ${fmtPctErr(f.light_return, f.light_return_stderr)}`))),
  svg('text', { x: left + width / 2, y: top + height + 38, 'text-anchor': 'middle', class: 'chart-label' }, 'tilt (degrees)'),
  svg('text', { x: 14, y: top + height / 2, 'text-anchor': 'middle', class: 'chart-label', transform: `rotate(-90 14 ${top + height / 2})` },
    'light return (% of face-up area)'));
}
