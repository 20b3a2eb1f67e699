// The chosen shape's parameters in the study form (issue 30): a shape of the cut library lists them in
// GET /api/meshes with their defaults and ranges; the form edits them and sends the changed ones as the job's
// `cut` object, each field under the id the server's field errors (cut.pavilion) are shown by.
import { $, h } from './dom.js';
import { fmtNumber, humanize } from './format.js';

const UNITS = { deg: '°', '%': '%' };

function parameterField(p) {
  const id = `f-cut-${p.name}`;
  const unit = UNITS[p.unit] || p.unit;
  const described = `hint-cut-${p.name} err-cut.${p.name}`;
  const control = p.choices
    ? h('select', { id, name: `cut.${p.name}`, 'data-default': p.default, 'aria-describedby': described },
      p.choices.map((c, i) => h('option', { value: i, selected: i === p.default }, humanize(c))))
    : h('input', {
      id, name: `cut.${p.name}`, type: 'number', inputmode: 'decimal', min: p.min, max: p.max,
      step: p.integer ? 1 : 'any', value: p.default, 'data-default': p.default, 'aria-describedby': described,
    });
  const range = p.choices ? p.help : `${fmtNumber(p.min, 4)}–${fmtNumber(p.max, 4)}${unit ? ` ${unit}` : ''}: ${p.help}`;
  return h('div', { class: 'field', 'data-field': `cut.${p.name}` },
    h('label', { for: id }, humanize(p.name), unit ? h('span', { class: 'muted' }, ` (${unit})`) : null),
    control,
    h('p', { class: 'hint', id: `hint-cut-${p.name}` }, range),
    h('p', { class: 'field-error', id: `err-cut.${p.name}`, role: 'alert', hidden: true }));
}

// Shows the fields of `mesh` (an entry of GET /api/meshes), at their defaults when the shape changed; none
// for a mesh without parameters (an upload).
export function showCutFields(mesh) {
  const box = $('#cut-fields');
  const shape = mesh && mesh.parameters ? mesh.mesh : '';
  if (box.dataset.shape === shape) return;
  box.dataset.shape = shape;
  box.hidden = !shape;
  $('#cut-params').replaceChildren(...(shape ? mesh.parameters.map(parameterField) : []));
}

// The parameters changed from their defaults, or undefined when none is; an unreadable number is reported
// in `errors`, ranges are the server's to check.
export function readCut(form, errors) {
  const cut = {};
  for (const input of $('#cut-params').querySelectorAll('input, select')) {
    const key = input.name.slice('cut.'.length);
    if (input.validity.badInput || input.value.trim() === '') {
      errors.push([input.name, `${humanize(key)} must be a number`]);
      continue;
    }
    const value = Number(input.value);
    if (value !== Number(input.dataset.default)) cut[key] = value;
  }
  return Object.keys(cut).length ? cut : undefined;
}
