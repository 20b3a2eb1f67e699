// What the page shows and how often it asks: polling intervals, regions, job states, the figures of merit
// (docs/stats-schema.md) and the facet table's columns.
import { fmtInt, fmtNumber } from './format.js';

export const POLL_ACTIVE_MS = 600;  // while a job is queued or running
export const POLL_IDLE_MS = 4000;
export const JOBS_PER_PAGE = 10;
export const ESTIMATE_DELAY_MS = 400;  // the job form's estimate is asked for once typing pauses this long
export const REGIONS = ['table', 'crown', 'girdle', 'pavilion'];
export const STATES = {
  queued: { glyph: '◷', label: 'Queued' },
  running: { glyph: '▶', label: 'Running' },
  succeeded: { glyph: '✓', label: 'Finished' },
  failed: { glyph: '✕', label: 'Failed' },
  canceled: { glyph: '⊘', label: 'Canceled' },
};
// The figures of merit of the statistics (docs/stats-schema.md), each with its standard error.
export const FIGURES = [
  { key: 'crown_return', label: 'Crown return', hint: 'Leaves through table and crown, upward' },
  { key: 'crown_return_with_reflection', label: 'With surface reflection', hint: 'Crown return plus first-surface glare' },
  { key: 'weighted_return', label: 'Cosine-weighted return', hint: 'Crown return weighted by closeness to vertical' },
  { key: 'cone_return_30', label: 'Within 30° cone', hint: 'Crown return within 30° of vertical, outside the head cone' },
  { key: 'cone_return_45', label: 'Within 45° cone', hint: 'Crown return within 45° of vertical' },
  { key: 'cone_return_60', label: 'Within 60° cone', hint: 'Crown return within 60° of vertical' },
  { key: 'leakage', label: 'Leakage', hint: 'Leaves through pavilion and girdle (lower is better)', lowerIsBetter: true },
];
// What a viewer sees (stats.viewer, docs/physics.md "Viewer figures"): shares, and the light-performance score
// in points (100: the GIA reference round brilliant).
export const VIEWER_FIGURES = [
  { key: 'brightness', label: 'Brightness', hint: 'Mean radiance the viewer sees face-up under the office dome, head and shoulders in the way, over the rocking' },
  { key: 'fire', label: 'Fire', hint: 'Share of the spot lamps\u2019 light that reaches the eye as colour' },
  { key: 'scintillation', label: 'Scintillation', hint: 'Share of looks a small rock apart between which a point turns from lit to dark or back' },
  { key: 'contrast', label: 'Contrast', hint: 'Share of the face-up area that shows the viewer: the dark pattern' },
  { key: 'windowing', label: 'Windowing', hint: 'Share of the face-up area that shows the tray through the stone (lower is better)', lowerIsBetter: true },
  { key: 'extinction', label: 'Extinction', hint: 'Share of the face-up area dark throughout a rock (lower is better)', lowerIsBetter: true },
  { key: 'score', label: 'Light-performance score', points: true, hint: 'The figures weighed together; 100 for the GIA reference' },
];
export const FACET_COLUMNS = [
  { key: 'id', label: 'Id', numeric: true },
  { key: 'name', label: 'Name' },
  { key: 'region', label: 'Region' },
  { key: 'area', label: 'Area', numeric: true, format: (v) => fmtNumber(v, 4) },
  { key: 'entering', label: 'Entering', numeric: true, format: fmtInt },
  { key: 'reflected', label: 'Reflected', numeric: true, format: fmtInt },
  { key: 'internal_reflections', label: 'Internal refl.', numeric: true, format: fmtInt },
  { key: 'leaving', label: 'Leaving', numeric: true, format: fmtInt },
  { key: 'leaving_share', label: 'Leaving share', numeric: true },
];
