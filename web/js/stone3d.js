// The stone in 3-D (stone.json): its facets as a mesh to turn and zoom, each coloured by a figure of the
// statistics' facets on the viridis scale with its legend; clicking a facet names it and shows its numbers with
// their standard errors. The comparison shows its designs in one such view, one at a time, picked from a menu,
// every one on the same colour scale. three.js comes from Debian's libjs-three, which our server serves at /vendor/three/;
// this module loads it only when a result is shown (result.js imports this module lazily), and says so when the
// server has none.
import { api } from './api.js';
import { h } from './dom.js';
import { fmtInt, fmtNumber, fmtPctErr, humanize } from './format.js';
import { linkFacet, scaleEnd, viridis } from './heatmap.js';

const THREE_URL = '/vendor/three/build/three.module.js';
const CONTROLS_URL = '/vendor/three/examples/jsm/controls/OrbitControls.js';
const BACKGROUND = 0xf4f5f7;
const EDGE = 0x1a1a1a;
const HIGHLIGHT = 0xd6246e;  // the picked facet's outline, as the heat-map's: apart from every viridis colour
const VIEW_FROM_VERTICAL_DEG = 35;  // the first view: from above at an angle, the table facing the viewer
const TURN_STEP = Math.PI / 24;  // a key press turns the stone 7.5 degrees
const ZOOM_STEP = 1.15;

// The figures a facet can be coloured by: those of the statistics' facets (and the fire's) that the job has.
// `share`: a share of the photons, shown in % with its standard error; otherwise a count or an area.
const FIGURES = [
  { key: 'leaving_share', label: 'Light leaving (share of the photons that hit the stone)', short: 'Light leaving', share: true },
  { key: 'fire_share', label: 'Share of the fire (coloured light)', short: 'Share of the fire', share: true },
  { key: 'leaving', label: 'Photons leaving', count: true },
  { key: 'entering', label: 'Photons entering', count: true },
  { key: 'reflected', label: 'First-surface reflections', count: true },
  { key: 'internal_reflections', label: 'Internal reflections', count: true },
  { key: 'area', label: 'Area (mesh units²)' },
];

let active = null;  // the view on the page now: disposed when another takes its place

// Each facet's numbers by id: the statistics' facets with the fire's share (as fire_share) where traced.
function facetNumbers(stats) {
  const byId = new Map((stats.facets || []).map((f) => [f.id, { ...f }]));
  for (const f of (stats.fire && stats.fire.facets) || []) {
    const n = byId.get(f.id);
    if (n) Object.assign(n, { fire_share: f.share, fire_share_stderr: f.share_stderr });
  }
  return byId;
}

function formatValue(fig, value, stderr) {
  if (fig.share) return Number.isFinite(stderr) ? fmtPctErr(value, stderr) : `${fmtNumber(100 * value, 2)} %`;
  if (fig.count) return fmtInt(value);
  return fmtNumber(value, 4);
}

function tickText(fig, value) {
  if (fig.share) return `${fmtNumber(100 * value, 2)} %`;
  return fig.count ? fmtInt(value) : fmtNumber(value, 3);
}

// The colour scale's top: as the heat-map picture's, near the largest value of the facets other than the table
// (95th percentile), so that the table's large share does not leave every other facet the same dark colour;
// values beyond are drawn in the top colour and named under the legend. Several designs: the largest of their
// own scales, one for all.
function scaleTop(numbersList, key) {
  return Math.max(...numbersList.map((numbers) => {
    const all = [...numbers.values()];
    const others = all.filter((f) => f.region !== 'table').map((f) => f[key]).sort((a, b) => a - b);
    const p95 = others.length ? others[Math.ceil(0.95 * others.length) - 1] : 0;
    return scaleEnd(p95 > 0 ? p95 : Math.max(0, ...all.map((f) => f[key])));
  }));
}

// Triangles of a planar polygon (corners in 3-D) as indices into it, turned to face along `normal`.
function triangulate(THREE, corners, normal) {
  const n = new THREE.Vector3(...normal);
  const u = new THREE.Vector3(Math.abs(n.z) < 0.9 ? 0 : 1, 0, Math.abs(n.z) < 0.9 ? 1 : 0).cross(n).normalize();
  const v = n.clone().cross(u);
  const flat = corners.map((c) => new THREE.Vector2(u.dot(c), v.dot(c)));
  return THREE.ShapeUtils.triangulateShape(flat, []).map(([a, b, c]) => {
    const ab = corners[b].clone().sub(corners[a]);
    const ac = corners[c].clone().sub(corners[a]);
    return ab.cross(ac).dot(n) >= 0 ? [a, b, c] : [a, c, b];
  });
}

function dispose(view) {
  if (!view) return;
  view.resize.disconnect();
  view.controls.dispose();
  view.scene.traverse((o) => {
    if (o.geometry) o.geometry.dispose();
    if (o.material) o.material.dispose();
  });
  view.renderer.dispose();
  view.renderer.forceContextLoss();
}

// Fills `root` (the card's body) with the view of `job`'s stone, or with why there is none.
export function showStone3d(root, job, stats) {
  return showStones(root, [{ job, stats }]);
}

// Fills `root` with one view of `stones` ([{job, stats, name}], the first shown; a menu picks another), every
// one coloured on one scale; `prefix` names its controls' ids (one view per page section).
export async function showStones(root, stones, prefix = 'stone3d') {
  dispose(active);
  active = null;
  const say = (text) => root.replaceChildren(h('p', { class: 'hint stone3d-missing', role: 'status' }, text));
  let THREE;
  let OrbitControls;
  try {
    [THREE, { OrbitControls }] = await Promise.all([import(THREE_URL), import(CONTROLS_URL)]);
  } catch {
    say('The 3-D view needs three.js from Debian\'s libjs-three, which this server does not serve: install '
      + 'libjs-three (or start facetlight-server with --three-js pointing at three.js) and reload.');
    return;
  }
  let geometry;
  try {
    geometry = await loadShape(stones[0]);
  } catch (e) {
    say(e.message);
    return;
  }
  if (!root.isConnected) return;
  let renderer;
  try {
    // The drawing kept after it is shown: "Save image as" and the browser tests read it back.
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch {
    say('The 3-D view needs WebGL, which this browser does not offer.');
    return;
  }
  dispose(active);  // one shown meanwhile, by a quicker call
  active = buildView(THREE, OrbitControls, renderer, root, stones, geometry, prefix);
}

// A stone's shape (stone.json), once; an Error that says why there is none.
async function loadShape(stone) {
  if (!stone.shape) {
    stone.shape = api(stone.job.links.stone).catch((e) => {
      throw new Error(`The stone's shape (stone.json) could not be loaded: ${e.message}. Jobs finished before the 3-D view existed have none.`);
    }).then((geometry) => {
      const ids = new Set((stone.stats.facets || []).map((f) => f.id));
      if (!geometry.facets.some((f) => ids.has(f.id))) throw new Error('The stone\'s shape (stone.json) names none of the statistics\' facets.');
      return geometry;
    });
  }
  return stone.shape;
}

// One triangle list for the whole stone, each triangle knowing its facet (an index into `facets`); edges as
// line segments; each facet's outline and triangles by id for the picked facet's highlight.
function tessellate(THREE, facets) {
  const positions = [];
  const triangleFacet = [];
  const edges = [];
  const outlines = new Map();
  const surfaces = new Map();  // facet id -> its triangles' corners
  let extent = 0;
  for (const [index, f] of facets.entries()) {
    const corners = f.vertices.map((p) => new THREE.Vector3(...p));
    for (const c of corners) extent = Math.max(extent, c.length());
    const surface = [];
    for (const tri of triangulate(THREE, corners, f.normal)) {
      for (const k of tri) surface.push(corners[k].x, corners[k].y, corners[k].z);
      triangleFacet.push(index);
    }
    positions.push(...surface);
    surfaces.set(f.id, surface);
    const loop = [];
    corners.forEach((c, k) => {
      const d = corners[(k + 1) % corners.length];
      loop.push(c.x, c.y, c.z, d.x, d.y, d.z);
    });
    edges.push(...loop);
    outlines.set(f.id, loop);
  }
  return { positions, triangleFacet, edges, outlines, surfaces, extent };
}

function buildView(THREE, OrbitControls, renderer, root, stones, firstGeometry, prefix) {
  const numbersOf = stones.map((s) => facetNumbers(s.stats));
  // The figures every stone has.
  const figures = FIGURES.filter((f) => numbersOf.every((numbers) => {
    const sample = numbers.values().next().value || {};
    return Number.isFinite(sample[f.key]);
  }));
  // The stone shown: its index into `stones`, its facets and their triangles.
  let shown = 0;
  let geometry = firstGeometry;
  let numbers = numbersOf[0];
  let facets = [];
  let shape = null;
  let colours = null;
  let extent = 1;

  const mesh = new THREE.Mesh(new THREE.BufferGeometry(), new THREE.MeshBasicMaterial({
    vertexColors: THREE.VertexColors, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
  }));
  const edgeLines = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: EDGE }));
  // The picked facet: outlined, and veiled so that it stands out whatever its colour (drawn on the facet's own
  // depth: the stone's surface is pushed back by its polygon offset).
  const highlight = new THREE.LineSegments(new THREE.BufferGeometry(),
    new THREE.LineBasicMaterial({ color: HIGHLIGHT }));
  const veil = new THREE.Mesh(new THREE.BufferGeometry(), new THREE.MeshBasicMaterial({
    color: HIGHLIGHT, transparent: true, opacity: 0.4,
  }));
  highlight.renderOrder = 2;
  veil.renderOrder = 1;
  highlight.visible = false;
  veil.visible = false;
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(BACKGROUND);
  scene.add(mesh, edgeLines, veil, highlight);

  const camera = new THREE.PerspectiveCamera(30, 4 / 3, 0.01, 100);
  camera.up.set(0, 0, 1);  // the stone's frame: table up along +z
  const home = () => {
    const r = extent * 4.2;
    const a = (VIEW_FROM_VERTICAL_DEG * Math.PI) / 180;
    camera.position.set(0, -r * Math.sin(a), r * Math.cos(a));
    camera.lookAt(0, 0, 0);
  };
  home();  // away from the target before the controls measure their distance; again once the stone is known
  const canvas = renderer.domElement;
  const controls = new OrbitControls(camera, canvas);
  controls.enableKeys = false;  // its keys pan; ours (below) turn and zoom, and pick facets
  controls.enablePan = false;

  // The card: the canvas with its text alternative, and beside it the stone (several), the figure, the legend
  // and the facet picked.
  const nameOf = (k) => stones[k].name || (k === shown && geometry.name) || stones[k].job.mesh || 'the stone';
  const summaryId = `${prefix}-summary`;
  canvas.setAttribute('tabindex', '0');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-describedby', `${summaryId} ${prefix}-keys`);
  canvas.classList.add('stone3d-canvas');
  const select = h('select', { id: `${prefix}-figure` },
    figures.map((f) => h('option', { value: f.key }, f.short || f.label)));
  const stoneSelect = stones.length > 1 ? h('select', { id: `${prefix}-stone` },
    stones.map((s, k) => h('option', { value: String(k) }, nameOf(k)))) : null;
  const status = h('p', { class: 'hint stone3d-status', role: 'status' });
  const legend = h('div', { class: 'stone3d-legend' });
  const readout = h('div', { class: 'stone3d-readout', 'aria-live': 'polite' },
    h('p', { class: 'hint' }, 'Click a facet to see its numbers.'));
  const summary = h('p', { id: summaryId, class: 'stone3d-summary' });
  root.replaceChildren(h('div', { class: 'stone3d-layout' },
    h('div', { class: 'stone3d-stage' }, canvas),
    h('div', { class: 'stone3d-side' },
      stoneSelect ? h('div', { class: 'field' }, h('label', { for: `${prefix}-stone` }, 'Design'), stoneSelect, status) : null,
      h('div', { class: 'field' }, h('label', { for: `${prefix}-figure` }, 'Colour facets by'), select),
      legend, readout,
      h('p', { class: 'hint', id: `${prefix}-keys` },
        'Drag to turn, scroll to zoom, click a facet for its numbers. With the view focused: arrow keys turn it, '
        + '+ and − zoom, N and P pick the next and previous facet, Home goes back to the first view.'))),
  summary);

  let sized = false;  // drawn only once the canvas has its box's size
  const render = () => {
    if (!sized) return;
    renderer.render(scene, camera);
    root.dataset.triangles = String(renderer.info.render.triangles);
  };
  let picked = null;

  // Colours every facet by the chosen figure, draws the legend and writes the text alternative.
  const colour = () => {
    const fig = figures.find((f) => f.key === select.value) || figures[0];
    const top = scaleTop(numbersOf, fig.key);
    const c = new THREE.Color();
    shape.triangleFacet.forEach((index, t) => {
      const value = numbers.get(facets[index].id)[fig.key];
      c.setStyle(viridis(top > 0 ? value / top : 0));
      for (let k = 0; k < 3; ++k) colours.set([c.r, c.g, c.b], 9 * t + 3 * k);
    });
    mesh.geometry.attributes.color.needsUpdate = true;
    const beyond = facets.filter((f) => numbers.get(f.id)[fig.key] > top * (1 + 1e-9));
    const ticks = [0, 0.25, 0.5, 0.75, 1].map((t) => h('span', {}, tickText(fig, t * top)));
    legend.replaceChildren(...[
      h('p', { class: 'stone3d-legend-title' }, fig.label),
      stones.length > 1 ? h('p', { class: 'hint stone3d-shared' }, `One scale for the ${stones.length} designs compared`) : null,
      h('div', { class: 'stone3d-ramp', 'aria-hidden': 'true',
        style: `background: linear-gradient(to right, ${Array.from({ length: 11 }, (_, i) => viridis(i / 10)).join(', ')})` }),
      h('div', { class: 'stone3d-ticks' }, ticks),
      beyond.length ? h('p', { class: 'hint stone3d-beyond' }, 'Beyond the scale, in its top colour: ',
        beyond.map((f) => `${humanize(f.name)} ${tickText(fig, numbers.get(f.id)[fig.key])}`).join(', ')) : null,
    ].filter(Boolean));
    const ranked = [...facets].sort((a, b) => numbers.get(b.id)[fig.key] - numbers.get(a.id)[fig.key]);
    const hi = ranked[0];
    const lo = ranked[ranked.length - 1];
    const name = nameOf(shown);
    const text = `${humanize(name)} in 3-D: ${facets.length} facets coloured by ${fig.label.toLowerCase()}, on a scale from `
      + `${tickText(fig, 0)} to ${tickText(fig, top)}; highest ${humanize(hi.name)} (${humanize(hi.region)}) `
      + `${formatValue(fig, numbers.get(hi.id)[fig.key], numbers.get(hi.id)[`${fig.key}_stderr`])}, lowest `
      + `${humanize(lo.name)} (${humanize(lo.region)}) ${formatValue(fig, numbers.get(lo.id)[fig.key], numbers.get(lo.id)[`${fig.key}_stderr`])}. `
      + 'The facet table below lists every facet\'s numbers.';
    summary.textContent = text;
    canvas.setAttribute('aria-label', `${humanize(name)} in 3-D, coloured by ${fig.label.toLowerCase()}`);
    root.dataset.figure = fig.key;
    root.dataset.top = String(top);
    render();
  };

  // Shows stone `k` (its shape loaded): its triangles in the mesh, the camera at its size, coloured.
  const showShape = (k, shapeJson) => {
    shown = k;
    geometry = shapeJson;
    numbers = numbersOf[k];
    facets = geometry.facets.filter((f) => numbers.has(f.id));
    shape = tessellate(THREE, facets);
    extent = shape.extent;
    for (const [object, array] of [[mesh, shape.positions], [edgeLines, shape.edges]]) {
      object.geometry.dispose();
      object.geometry = new THREE.BufferGeometry();
      object.geometry.setAttribute('position', new THREE.Float32BufferAttribute(array, 3));
    }
    colours = new Float32Array(shape.positions.length);
    mesh.geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    camera.near = extent / 100;
    camera.far = extent * 100;
    camera.updateProjectionMatrix();
    controls.minDistance = extent * 1.5;
    controls.maxDistance = extent * 20;
    root.dataset.stone = stones[k].job.id;
    picked = null;
    colour();
    pick(null);
  };

  // Shows facet `index` (into `facets`; null: none) beside the view and outlines it; its row of the facet table
  // and its shape on the heat-map light up.
  const pick = (index) => {
    picked = index;
    linkFacet(root.closest('.result') || root, index === null ? null : facets[index].id);
    if (index === null) {
      highlight.visible = false;
      veil.visible = false;
      delete root.dataset.picked;
      render();
      return;
    }
    const f = facets[index];
    const n = numbers.get(f.id);
    highlight.geometry.setAttribute('position', new THREE.Float32BufferAttribute(shape.outlines.get(f.id), 3));
    veil.geometry.setAttribute('position', new THREE.Float32BufferAttribute(shape.surfaces.get(f.id), 3));
    highlight.visible = true;
    veil.visible = true;
    root.dataset.picked = String(f.id);
    readout.replaceChildren(
      h('h3', {}, humanize(f.name)),
      h('p', { class: 'hint' }, `Facet ${f.id}, ${humanize(f.region)}`),
      h('dl', { class: 'kv stone3d-numbers', 'data-facet': f.id },
        figures.map((fig) => [h('dt', {}, fig.short || fig.label),
          h('dd', { 'data-figure': fig.key }, formatValue(fig, n[fig.key], n[`${fig.key}_stderr`]))])));
    render();
  };

  const pointer = new THREE.Vector2();
  const raycaster = new THREE.Raycaster();
  let down = null;
  canvas.addEventListener('pointerdown', (e) => { down = [e.clientX, e.clientY]; });
  canvas.addEventListener('pointerup', (e) => {
    // A click, not the end of a drag that turned the stone.
    if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
    const box = canvas.getBoundingClientRect();
    pointer.set(((e.clientX - box.left) / box.width) * 2 - 1, -((e.clientY - box.top) / box.height) * 2 + 1);
    raycaster.setFromCamera(pointer, camera);
    const hit = raycaster.intersectObject(mesh)[0];
    pick(hit ? shape.triangleFacet[hit.faceIndex] : null);
  });
  const turn = (dAzimuth, dPolar) => {
    const offset = camera.position.clone().sub(controls.target);
    const r = offset.length();
    const azimuth = Math.atan2(offset.y, offset.x) + dAzimuth;
    const polar = Math.min(Math.PI - 0.01, Math.max(0.01, Math.acos(offset.z / r) + dPolar));
    offset.set(r * Math.sin(polar) * Math.cos(azimuth), r * Math.sin(polar) * Math.sin(azimuth), r * Math.cos(polar));
    camera.position.copy(controls.target).add(offset);
    controls.update();
  };
  const zoom = (factor) => {
    const offset = camera.position.clone().sub(controls.target);
    const r = Math.min(controls.maxDistance, Math.max(controls.minDistance, offset.length() * factor));
    camera.position.copy(controls.target).add(offset.setLength(r));
    controls.update();
  };
  canvas.addEventListener('keydown', (e) => {
    const keys = {
      ArrowLeft: () => turn(-TURN_STEP, 0), ArrowRight: () => turn(TURN_STEP, 0),
      ArrowUp: () => turn(0, -TURN_STEP), ArrowDown: () => turn(0, TURN_STEP),
      '+': () => zoom(1 / ZOOM_STEP), '=': () => zoom(1 / ZOOM_STEP), '-': () => zoom(ZOOM_STEP),
      n: () => pick(picked === null ? 0 : (picked + 1) % facets.length),
      p: () => pick(picked === null ? facets.length - 1 : (picked + facets.length - 1) % facets.length),
      Home: () => { home(); controls.target.set(0, 0, 0); controls.update(); },
      Escape: () => pick(null),
    };
    const action = keys[e.key.length === 1 ? e.key.toLowerCase() : e.key];
    if (!action || e.altKey || e.ctrlKey || e.metaKey) return;
    e.preventDefault();
    action();
  });
  controls.addEventListener('change', render);
  select.addEventListener('change', () => {
    colour();
    if (picked !== null) pick(picked);
  });
  if (stoneSelect) {
    stoneSelect.addEventListener('change', async () => {
      const k = Number(stoneSelect.value);
      status.textContent = 'Loading…';
      try {
        const next = await loadShape(stones[k]);
        if (Number(stoneSelect.value) !== k) return;  // another picked meanwhile
        status.textContent = '';
        showShape(k, next);
        home();
        controls.target.set(0, 0, 0);
        controls.update();
      } catch (e) {
        status.textContent = e.message;
      }
    });
  }

  // The canvas fills its box at the screen's pixel density.
  const stage = canvas.parentElement;
  const resize = new ResizeObserver(() => {
    const width = stage.clientWidth;
    if (!width) return;
    const height = Math.round(width * 0.75);
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(width, height, false);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    sized = true;
    render();
  });
  resize.observe(stage);
  showShape(0, firstGeometry);
  home();
  controls.update();
  return { renderer, controls, scene, resize };
}
