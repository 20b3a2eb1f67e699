// The design a job traced, as a faceter reads it (docs/gemcad.md): the faceting diagram, the cutting sheet
// (each tier's angle as designed and as measured on the cut stone, indices, distance, meets), the stone's
// size and weight, the material traced and where its index came from, and what was done to the file's frame.
import { h } from './dom.js';
import { fmtNumber, humanize } from './format.js';

const SOURCE_TEXT = {
  'design file': "the design file's own index (its I line)",
  material: 'the material the job names',
  n: "the job's constant index n",
  default: 'diamond, the default',
};

function indexText(indices) {
  return indices.map((i) => (Number.isInteger(i) ? String(i).padStart(2, '0') : fmtNumber(i, 4))).join('-');
}

function sheetTable(sheet) {
  return h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': 'Cutting sheet' }, h('table', { class: 'data cutting-sheet' },
    h('caption', {}, `Cutting sheet (${sheet.source}): ${Math.abs(sheet.gear)}-tooth gear, ${sheet.symmetry}-fold${sheet.mirror ? ' mirror' : ''} symmetry${sheet.refractive_index ? `, index ${fmtNumber(sheet.refractive_index, 3)}` : ''}`),
    h('thead', {}, h('tr', {}, ['Tier', 'Side', 'Angle', 'Measured', 'Distance', 'Facets cut', 'Indices', 'Meets']
      .map((c) => h('th', { scope: 'col' }, c)))),
    h('tbody', {}, sheet.tiers.map((t) => h('tr', {},
      h('th', { scope: 'row' }, t.name),
      h('td', {}, t.side),
      h('td', { class: 'num' }, `${fmtNumber(Math.abs(t.angle_deg), 2)}°`),
      h('td', { class: 'num' }, t.measured_angle_deg == null ? '—' : `${fmtNumber(Math.abs(t.measured_angle_deg), 2)}°`),
      h('td', { class: 'num' }, fmtNumber(t.distance, 6)),
      h('td', { class: 'num' }, `${t.facets_cut} of ${t.facets}`),
      h('td', { class: 'indices' }, indexText(t.indices)),
      h('td', {}, t.meets.join(', ')))))));
}

// How light was traced (stats.settings.polarization, docs/optics.md "Polarisation"), where the job says.
const POLARIZATION_TEXT = {
  off: 'off: each facet reflects the unpolarised Fresnel average',
  on: 'on: each photon carries its polarisation through every facet',
};

// How a doubly refracting stone was traced: the statistics' own sentence (material.double_refraction) and, when
// its rays were split, where its optic axis lay. Statistics from before polarised tracing traced n_o or beta.
function doubleRefractionText(material, settings) {
  const head = `${material.optic}, birefringence ${fmtNumber(material.birefringence, 3)}; `;
  if (!material.double_refraction) return `${head}traced at ${material.optic === 'uniaxial' ? 'the ordinary ray\'s index' : 'β'}`;
  const axis = settings.optic_axis;
  const split = material.optic !== 'isotropic' && settings.polarization === 'on' && axis;
  const where = material.optic === 'biaxial'
    ? `Z axis ${fmtNumber(axis?.tilt_deg, 4)}° from the table's normal, toward ${fmtNumber(axis?.azimuth_deg, 4)}° from x, X turned ${fmtNumber(axis?.rotation_deg ?? 0, 4)}°`
    : `optic axis ${fmtNumber(axis?.tilt_deg, 4)}° from the table's normal, toward ${fmtNumber(axis?.azimuth_deg, 4)}° from x`;
  return `${head}${material.double_refraction}${split ? ` (${where})` : ''}`;
}

function absorptionText(absorption) {
  const c = absorption.corundum_ppma;
  if (!c) return 'the job\'s own absorption spectrum';
  const parts = [];
  if (c.cr > 0) parts.push(`Cr³⁺ ${fmtNumber(c.cr, 4)} ppma`);
  if (c.fe_ti > 0) parts.push(`Fe²⁺–Ti⁴⁺ pairs ${fmtNumber(c.fe_ti, 4)} ppma`);
  return `${parts.join(', ') || 'no chromophores'} (GIA's absorption cross sections)`;
}

function sizeList(size, material, settings = {}) {
  const rows = [];
  if (size) {
    rows.push(['Size', `${fmtNumber(size.length_mm, 2)} × ${fmtNumber(size.width_mm, 2)} × ${fmtNumber(size.depth_mm, 2)} mm`],
      ['Volume', `${fmtNumber(size.volume_mm3, 1)} mm³`],
      ['Weight', size.carats == null ? 'no density: the traced index names no material' : `${fmtNumber(size.carats, 3)} ct at ${fmtNumber(size.density_g_cm3, 2)} g/cm³`],
      ['Keeps of its block', `${fmtNumber(100 * size.block_retention, 1)} %`]);
  }
  if (material) {
    const what = material.source === 'design file' ? '' : `${humanize(material.name)}, `;
    rows.push(['Traced as', `${what}n ${fmtNumber(material.n_d, 4)}: ${SOURCE_TEXT[material.source] || material.source}`]);
    if (material.optic && material.optic !== 'isotropic') rows.push(['Double refraction', doubleRefractionText(material, settings)]);
  }
  // A job's own spectrum replaces the material's colour (docs/optics.md, "Absorption"): say by what.
  if (settings.absorption) rows.push(['Coloured by', absorptionText(settings.absorption)]);
  if (POLARIZATION_TEXT[settings.polarization]) rows.push(['Polarisation', POLARIZATION_TEXT[settings.polarization]]);
  return h('dl', { class: 'kv' }, rows.map(([k, v]) => [h('dt', {}, k), h('dd', {}, v)]));
}

function frameNote(frame) {
  if (!frame || frame.file_orientation) return null;
  const parts = [];
  if (frame.table_facet) parts.push(`facet ${frame.table_facet} was turned ${fmtNumber(frame.turned_deg, 2)}° to face up as the table`);
  if (frame.long_axis_turned) parts.push('its long axis was laid along x');
  return h('p', { class: 'hint frame-note' }, `The mesh was re-oriented: ${parts.join('; ')}.`);
}

// The section, or none for a job whose statistics predate it.
export function designSection(job, stats) {
  const links = job.links || {};
  const sheet = stats.cutting_sheet;
  if (!sheet && !stats.size && !links.diagram) return null;
  const name = job.name || humanize(job.mesh);
  return h('section', { class: 'card', 'aria-labelledby': 'design-title', 'data-section': 'design' },
    h('h2', { id: 'design-title' }, 'The design'),
    links.diagram ? h('figure', { class: 'diagram' },
      h('a', { href: links.diagram, target: '_blank', rel: 'noopener' },
        h('img', { src: links.diagram, alt: `Faceting diagram of ${name}: crown, profile and pavilion with each facet's tier`, loading: 'lazy' }))) : null,
    frameNote(stats.mesh && stats.mesh.frame),
    sizeList(stats.size, stats.material, stats.settings),
    sheet ? sheetTable(sheet) : null);
}
