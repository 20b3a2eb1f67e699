// Browser tests of the web page (issue 7): Debian's headless Chromium, driven by playwright-core, against the
// real facetlight-server on a free loopback port with a fresh data folder. Screenshots of each step go to
// FACETLIGHT_SCREENSHOT_DIR (build/screenshots) for people to look at.
//
//   FACETLIGHT_SERVER=build/bin/facetlight-server node --test tests/browser/web.test.mjs
//
// FACETLIGHT_BASE_URL points the tests at a server that is already running instead.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
const sourceDir = process.env.FACETLIGHT_SOURCE_DIR || path.resolve(here, '../..');
const serverBinary = process.env.FACETLIGHT_SERVER || path.join(sourceDir, 'build/bin/facetlight-server');
const screenshotDir = process.env.FACETLIGHT_SCREENSHOT_DIR || path.join(sourceDir, 'build/screenshots');
const chromiumPath = process.env.FACETLIGHT_CHROMIUM || '/usr/bin/chromium';
const JOB_TIMEOUT_MS = 240_000;
// No GPU here: WebGL (the 3-D view) runs on SwiftShader. Chromium is withdrawing that automatic fallback unless
// asked with --enable-unsafe-swiftshader ("unsafe" for pages from the web, not for our own page); Debian's
// Chromium 156 headless draws with or without it.
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--disable-quic',
  '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'];
const DESKTOP = { width: 1366, height: 900 };
const PHONE = { width: 390, height: 844 };

// Small jobs: enough photons for every facet of the test stone, pictures small enough to render in seconds.
const SMALL_JOB = { photons: '20000', width: '96', height: '96', samples: '1', mapPhotons: '5000' };

let server;        // { process, log, dataDir } when we started one
let baseUrl;
let browser;       // a persistent context in a fresh user-data folder
let userDataDir;
let page;
const foreignRequests = [];
const pageErrors = [];
const jobIds = {};  // name -> job id

async function freePort() {
  return new Promise((resolve, reject) => {
    const probe = net.createServer();
    probe.unref();
    probe.on('error', reject);
    probe.listen(0, '127.0.0.1', () => {
      const { port } = probe.address();
      probe.close(() => resolve(port));
    });
  });
}

async function waitForHealth(url, child, deadlineMs) {
  const until = Date.now() + deadlineMs;
  while (Date.now() < until) {
    if (child.exitCode !== null) return false;
    try {
      const res = await fetch(`${url}/healthz`);
      if (res.ok) return true;
    } catch {
      // not listening yet
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  return false;
}

// Starts the server on a free port; another process may take the port between the probe and the bind, so a
// failed start is tried again on a fresh port.
async function startServer(extraArgs = []) {
  assert.ok(fs.existsSync(serverBinary), `no server binary at ${serverBinary} (build facetlight-server first)`);
  const dataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'facetlight-web-data-'));
  for (let attempt = 0; attempt < 5; ++attempt) {
    const port = await freePort();
    const log = [];
    const child = spawn(serverBinary, [
      '--host', '127.0.0.1', '--port', String(port), '--data', dataDir,
      '--meshes', path.join(sourceDir, 'meshes'), '--web', path.join(sourceDir, 'web'), ...extraArgs,
    ], { stdio: ['ignore', 'pipe', 'pipe'] });
    child.stdout.on('data', (d) => log.push(String(d)));
    child.stderr.on('data', (d) => log.push(String(d)));
    const url = `http://127.0.0.1:${port}`;
    if (await waitForHealth(url, child, 20_000)) return { process: child, log, dataDir, url };
    child.kill('SIGKILL');
    if (attempt === 4) throw new Error(`facetlight-server did not start:\n${log.join('')}`);
  }
  throw new Error('unreachable');
}

// The page's modules as a graph: module -> the modules it imports.
function webImports() {
  const dir = path.join(sourceDir, 'web/js');
  const graph = new Map();
  for (const file of fs.readdirSync(dir).filter((f) => f.endsWith('.js'))) {
    const text = fs.readFileSync(path.join(dir, file), 'utf8');
    graph.set(file, [...text.matchAll(/from '\.\/([\w-]+\.js)'/g)].map((m) => m[1]));
  }
  return graph;
}

async function shot(name) {
  fs.mkdirSync(screenshotDir, { recursive: true });
  await page.screenshot({ path: path.join(screenshotDir, `${name}.png`), fullPage: true });
}

// Uploads a mesh through the page and returns the id the shape select now holds.
async function uploadThroughPage(file) {
  await page.setInputFiles('#f-file', path.join(sourceDir, file));
  await page.click('#upload-button');
  await page.waitForFunction((name) => document.querySelector('#upload-status').textContent.startsWith(`Uploaded ${name}`)
    || !document.querySelector('#err-file').hidden, path.basename(file), { timeout: 30_000 });
  assert.equal(await page.isHidden('#err-file'), true, `upload of ${file} refused: ${await page.textContent('#err-file')}`);
  return page.$eval('#f-mesh', (el) => el.value);
}

async function fillSmallJob(overrides = {}, on = page) {
  const job = { ...SMALL_JOB, ...overrides };
  const page = on;
  await page.fill('#f-photons', job.photons);
  await page.fill('#f-threads', '2');
  await page.setChecked('#f-render', true);
  await page.fill('#f-width', job.width);
  await page.fill('#f-height', job.height);
  await page.fill('#f-samples', job.samples);
  await page.$eval('details.advanced', (d) => { d.open = true; });
  await page.fill('#f-map-photons', job.mapPhotons);
  if (job.material) await page.selectOption('#f-material', job.material);
  if (job.light) await page.selectOption('#f-light-model', job.light);
}

// Submits the form and returns the new job's id: the page goes to the job's own view (issue 30), whose id is
// in its address; unless `stay`, the test goes back to the home page, where the job is listed.
async function submitAndGetId({ stay = false } = {}) {
  const before = await page.evaluate(() => location.hash);
  await page.click('#submit-button');
  await page.waitForFunction((old) => location.hash !== old && /^#\/jobs\/[0-9a-f]{32}$/.test(location.hash), before,
    { timeout: 15_000 });
  const id = await page.evaluate(() => location.hash.split('/')[2]);
  if (!stay) {
    await page.evaluate(() => { location.hash = '#/'; });
    await page.waitForSelector(`#job-list li[data-id="${id}"]`);
  }
  return id;
}

async function waitForFinished(id) {
  const bar = `#job-list li[data-id="${id}"] [role="progressbar"]`;
  await page.waitForFunction((sel) => {
    const el = document.querySelector(sel);
    return el && ['100'].includes(el.getAttribute('aria-valuenow'))
      && el.closest('li').dataset.state === 'succeeded';
  }, bar, { timeout: JOB_TIMEOUT_MS, polling: 100 });
}

// An axis of the sweep form: its quantity, from, to and step.
async function fillSweepAxis(i, values) {
  for (const [k, key] of ['name', 'from', 'to', 'step'].entries()) await page.fill(`#s-${key}-${i}`, values[k]);
}

async function picturesLoaded(scope, on = page) {
  await on.waitForFunction((sel) => {
    const imgs = [...document.querySelectorAll(`${sel} img`)];
    return imgs.length > 0 && imgs.every((img) => img.complete);
  }, scope, { timeout: 30_000 });
  return on.$$eval(`${scope} img`, (imgs) => imgs.map((img) => ({ src: img.getAttribute('src'), width: img.naturalWidth })));
}

// The sweep chart's texts that reach past its edges (a legend cut off).
async function chartTextsCutOff() {
  return page.$$eval('#sweep-chart svg text', (texts) => {
    const chart = texts[0].ownerSVGElement.getBoundingClientRect();
    return texts.filter((t) => {
      const b = t.getBoundingClientRect();
      return b.left < chart.left - 0.5 || b.right > chart.right + 0.5;
    }).map((t) => t.textContent);
  });
}

// The 3-D view's canvas (within `scope`), sampled every 5th pixel: how many differ from the background, and the samples.
async function stoneCanvasPixels(scope = '') {
  return page.$eval(`${scope} canvas.stone3d-canvas`, (c) => {
    const copy = document.createElement('canvas');
    copy.width = c.width;
    copy.height = c.height;
    const g = copy.getContext('2d');
    g.drawImage(c, 0, 0);
    const px = g.getImageData(0, 0, c.width, c.height).data;
    const samples = [];
    for (let i = 0; i < px.length; i += 4 * 5) samples.push((px[i] << 16) | (px[i + 1] << 8) | px[i + 2]);
    return { samples, drawn: samples.filter((v) => v !== 0xf4f5f7).length };
  });
}

// The comparison's heat-maps of `ids` in `cards` (a card selector with data-id) drawn on the page on one colour
// scale: the same legend in each, the largest of the scales each picture has on its own (the 95th percentile of
// the facets other than the table, rounded up); every facet filled with the page's viridis of its share over
// that scale, those beyond it hatched and named under the legend. `shares(stats)`: [{id, share, stderr}].
async function assertCommonHeatScale(cards, ids, shares) {
  await page.waitForFunction(([sel, n]) => document.querySelectorAll(`${sel} .heatmap-drawing`).length === n, [cards, ids.length]);
  const legends = await page.$$eval(`${cards} .heat-max`, (els) => els.map((e) => e.textContent));
  assert.equal(legends.length, ids.length);
  for (const l of legends) assert.equal(l, legends[0], 'one scale');
  const scale = parseFloat(legends[0]) / 100;
  const own = [];
  let hatched = 0;
  for (const id of ids) {
    const stats = await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json();
    const region = new Map(stats.facets.map((f) => [f.id, f.region]));
    const all = shares(stats);
    const others = all.filter((f) => region.get(f.id) !== 'table').map((f) => f.share).sort((x, y) => x - y);
    own.push(others[Math.ceil(0.95 * others.length) - 1]);
    const byId = new Map(all.map((f) => [String(f.id), f]));
    const drawn = await page.$$eval(`${cards}[data-id="${id}"] .heatmap-drawing polygon[data-facet]`,
      (ps) => ps.map((p) => ({ id: p.dataset.facet, fill: p.getAttribute('fill'), points: p.getAttribute('points') })));
    const overlays = await page.$$eval(`${cards}[data-id="${id}"] .heatmap-drawing polygon.heat-beyond`, (ps) => ps.map((p) => p.getAttribute('points')));
    const expected = await page.evaluate(async ([list, top]) => {
      const { viridis } = await import('/js/heatmap.js');
      return list.map((s) => viridis(s / top));
    }, [drawn.map((d) => (byId.get(d.id) || { share: 0 }).share), scale]);
    drawn.forEach((d, k) => {
      assert.equal(d.fill, expected[k], `facet ${d.id} of ${id}`);
      const beyond = (byId.get(d.id) || { share: 0 }).share > scale * (1 + 1e-9);
      assert.equal(overlays.includes(d.points), beyond, `facet ${d.id} of ${id} hatched when beyond the scale`);
      if (beyond) hatched += 1;
    });
    if (overlays.length) assert.match(await page.textContent(`${cards}[data-id="${id}"] .heat-beyond-list`), /^Hatched, beyond the scale: \S/);
  }
  const largest = Math.max(...own);
  assert.ok(scale >= largest - 1e-12 && scale <= 1.5 * largest + 1e-12, `scale ${scale} against the pictures' own ${own}`);
  return { scale, hatched };
}

// The texts shown within `scope` smaller than 11 px on the screen: HTML at its computed size, SVG at its size
// times the drawing's scale (a chart's viewBox shrunk into its box shrinks its text).
async function smallTexts(scope) {
  return page.$$eval(`${scope} *`, (els) => els.filter((el) => [...el.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim()))
    .filter((el) => el.getClientRects().length && !el.closest('[hidden], .visually-hidden, title, option, select'))
    .map((el) => {
      const size = parseFloat(getComputedStyle(el).fontSize);
      const m = el instanceof SVGElement && el.getScreenCTM();
      return { text: el.textContent.trim().slice(0, 40), px: Math.round(10 * size * (m ? Math.hypot(m.a, m.b) : 1)) / 10, where: el.closest('[class]') && el.closest('[class]').className.baseVal !== undefined ? el.closest('[class]').className.baseVal : (el.closest('[class]') || {}).className };
    })
    .filter((t) => t.px < 11));
}

// Scrolls through the page, so that every lazy picture and section loads.
async function scrollThrough() {
  const height = await page.evaluate(() => document.documentElement.scrollHeight);
  for (let y = 0; y < height; y += 600) {
    await page.evaluate((to) => window.scrollTo(0, to), y);
    await page.waitForTimeout(80);
  }
  await page.evaluate(() => window.scrollTo(0, 0));
}

async function noHorizontalOverflow() {
  return page.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth + 1);
}

// The pictures within `scope` as the page shows them: the width drawn and the link around each.
async function shownPictures(scope) {
  return page.$$eval(`${scope} img`, (imgs) => imgs.map((img) => ({
    src: img.getAttribute('src'), width: img.getBoundingClientRect().width,
    link: img.closest('a') && img.closest('a').getAttribute('href'),
  })));
}

// Every picture within `scope` at least 480 px wide on the desktop page (its text legible) and a link to
// itself, which opens it at full size.
async function assertLegiblePictures(scope) {
  const shown = await shownPictures(scope);
  assert.ok(shown.length > 0, scope);
  for (const p of shown) {
    assert.ok(p.width >= 480, `${p.src} shown ${Math.round(p.width)} px wide`);
    assert.equal(p.link, p.src, `${p.src} opens at full size`);
  }
  return shown;
}

test('the page\'s modules import no circle', () => {
  const graph = webImports();
  const done = new Set();
  const visit = (file, trail) => {
    assert.ok(!trail.includes(file), `import circle: ${[...trail, file].join(' -> ')}`);
    if (done.has(file)) return;
    for (const next of graph.get(file) || []) visit(next, [...trail, file]);
    done.add(file);
  };
  for (const file of graph.keys()) visit(file, []);
});

describe('facetlight web page', { timeout: 900_000 }, () => {
  before(async () => {
    if (process.env.FACETLIGHT_BASE_URL) {
      baseUrl = process.env.FACETLIGHT_BASE_URL.replace(/\/$/, '');
    } else {
      server = await startServer();
      baseUrl = server.url;
    }
    userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'facetlight-chromium-'));
    browser = await chromium.launchPersistentContext(userDataDir, {
      executablePath: chromiumPath,
      headless: true,
      viewport: DESKTOP,
      args: CHROMIUM_ARGS,
    });
    page = browser.pages()[0] || await browser.newPage();
    page.setDefaultTimeout(30_000);
    page.on('request', (req) => {
      const url = req.url();
      if (!url.startsWith(`${baseUrl}/`) && !url.startsWith('data:')) foreignRequests.push(url);
    });
    page.on('pageerror', (err) => pageErrors.push(String(err)));
    // Chromium logs every 4xx answer as an error; the tests provoke some on purpose.
    page.on('console', (msg) => {
      if (msg.type() === 'error' && !/status of 4\d\d/.test(msg.text())) pageErrors.push(msg.text());
    });
    await page.goto(`${baseUrl}/`);
  });

  after(async () => {
    if (browser) await browser.close();
    if (userDataDir) fs.rmSync(userDataDir, { recursive: true, force: true });
    if (server) {
      server.process.kill('SIGTERM');
      await new Promise((resolve) => {
        const timer = setTimeout(() => { server.process.kill('SIGKILL'); resolve(); }, 10_000);
        server.process.once('exit', () => { clearTimeout(timer); resolve(); });
      });
      fs.rmSync(server.dataDir, { recursive: true, force: true });
    }
  });

  test('the page loads with its form, labels and the shapes the API lists', async () => {
    await page.waitForFunction(() => document.querySelector('#server-status').textContent.startsWith('Service ready'));
    // The select holds a "Loading shapes…" placeholder (no value) until the list arrives.
    await page.waitForSelector('#f-mesh option:not([value=""])', { state: 'attached' });
    const listed = await (await fetch(`${baseUrl}/api/meshes`)).json();
    const usable = [...listed.shipped, ...listed.uploaded].filter((m) => !m.error).length;
    const options = await page.$$eval('#f-mesh option:not([disabled])', (os) => os.filter((o) => o.value).length);
    assert.equal(options, usable, 'the shape select offers every readable mesh of GET /api/meshes');
    // Every form control has an accessible name.
    const unnamed = await page.$$eval('#job-form input, #job-form select', (els) => els
      .filter((el) => !(el.labels && el.labels.length) && !el.getAttribute('aria-label'))
      .map((el) => el.name || el.id));
    assert.deepEqual(unnamed, []);
    // The form starts from the server's defaults (what a job that leaves a setting out gets), not a copy.
    const defaults = await (await fetch(`${baseUrl}/api/defaults`)).json();
    assert.equal(await page.inputValue('#f-photons'), String(defaults.photons));
    assert.equal(await page.inputValue('#f-threads'), String(defaults.threads));
    assert.equal(await page.inputValue('#f-width'), String(defaults.render.width));
    assert.equal(await page.inputValue('#f-map-photons'), String(defaults.render.map_photons));
    assert.equal(await page.inputValue('#f-tilt-max'), String(defaults.tilt_series.max_deg));
    assert.equal(await page.inputValue('#f-light-model'), defaults.light.model);
    assert.equal(await page.isChecked('#f-dispersion'), defaults.dispersion);
    assert.equal(await page.isChecked('#f-fire'), defaults.fire.enabled);
    await shot('01-home');
  });

  test('a bad photon count is shown next to the photons field', async () => {
    await page.fill('#f-photons', '-5');
    await page.click('#submit-button');
    const error = await page.waitForSelector('#err-photons:not([hidden])');
    const text = await error.textContent();
    assert.match(text, /photons/i);
    assert.equal(await page.getAttribute('#f-photons', 'aria-invalid'), 'true');
    // The message is the server's (the page leaves range checks to the API): it names the allowed range.
    assert.match(text, /between|at least|must/i);
    assert.equal(await page.isHidden('#err-threads'), true, 'only the field at fault is marked');
    await shot('02-photon-error');
    // Typing in the field clears its error.
    await page.fill('#f-photons', '20000');
    assert.equal(await page.isHidden('#err-photons'), true);
  });

  test('a bad upload is refused next to the file field', async () => {
    const junk = path.join(os.tmpdir(), `facetlight-junk-${process.pid}.stl`);
    fs.writeFileSync(junk, 'solid junk\nthis is not a mesh\n');
    try {
      await page.setInputFiles('#f-file', junk);
      await page.click('#upload-button');
      const error = await page.waitForSelector('#err-file:not([hidden])');
      assert.ok((await error.textContent()).length > 0);
    } finally {
      fs.rmSync(junk, { force: true });
    }
  });

  test('submit a small job: the page goes to it and shows its progress live until its result', async () => {
    jobIds.brilliantMesh = await uploadThroughPage('tests/data/brilliant.asc');
    assert.match(jobIds.brilliantMesh, /^[0-9a-f]{32}$/);
    await fillSmallJob();
    const id = await submitAndGetId({ stay: true });
    jobIds.brilliant = id;
    assert.equal(await page.isVisible('#view-result'), true, 'the job\'s view is shown');
    assert.equal(await page.isVisible('#job-form'), false);
    // Watch the job's own bar, in view at the top of the page: it never goes backwards, then the result replaces it.
    const bar = '#result-body [role="progressbar"]';
    const seen = [];
    const until = Date.now() + JOB_TIMEOUT_MS;
    let shotRunning = false;
    while (Date.now() < until && !(await page.locator('#result-body .figures').count())) {
      // Read at once: each poll draws the bar anew.
      const now = await page.evaluate((sel) => {
        const el = document.querySelector(sel);
        return el && { value: el.getAttribute('aria-valuenow'), bottom: el.getBoundingClientRect().bottom };
      }, bar);
      if (now) {
        seen.push(Number(now.value));
        assert.ok(now.bottom > 0 && now.bottom <= DESKTOP.height, `the progress bar is out of view (${now.bottom})`);
        if (!shotRunning && seen.at(-1) > 0) {
          await shot('03-job-running');
          shotRunning = true;
        }
      }
      await page.waitForTimeout(100);
    }
    assert.ok(seen.length > 0, 'the progress was shown before the result');
    assert.ok(seen.every((v, i) => i === 0 || v >= seen[i - 1]), `progress went backwards: ${seen.join(',')}`);
    await page.waitForSelector('#result-body .figures');
    assert.match(await page.textContent('#result-title'), /brilliant\.asc/);
    // The status beside the button follows the job: finished, never a stale "queued".
    await page.waitForFunction(() => /finished/.test(document.querySelector('#submit-status').textContent));
    assert.doesNotMatch(await page.textContent('#submit-status'), /queued|running/);
    await page.evaluate(() => { location.hash = '#/'; });
    const item = `#job-list li[data-id="${id}"]`;
    await waitForFinished(id);
    assert.match(await page.textContent(`${item} .progress-text`), /100 %/);
    assert.match(await page.textContent(`${item} .state`), /Finished/);
    assert.match(await page.textContent(`${item} .job-name`), /^brilliant\.asc$/);
    await shot('04-job-finished');
  });

  test('open the result: pictures load, figures carry standard errors, the facet table sorts', async () => {
    const id = jobIds.brilliant;
    await page.click(`#job-list li[data-id="${id}"] a[data-action="open"]`);
    await page.waitForSelector('#result-body .figures');
    const pics = await picturesLoaded('#result-body .pictures');
    assert.equal(pics.length, 3);
    for (const p of pics) assert.ok(p.width > 0, `${p.src} did not load`);
    assert.deepEqual(pics.map((p) => p.src.split('/').pop()), ['render.png', 'heatmap.png', 'angular.png']);
    // Legible: every picture at least 480 px wide, the heat-map across the card with its facets' shapes on it.
    const legible = await assertLegiblePictures('#result-body .pictures');
    const heatmapWidth = legible.find((p) => p.src.endsWith('heatmap.png')).width;
    assert.ok(heatmapWidth >= 1000, `the heat-map shown ${Math.round(heatmapWidth)} px wide`);
    await page.waitForSelector('.pic-heatmap svg.heatmap-overlay');
    const overlay = await page.$eval('.pic-heatmap svg.heatmap-overlay', (el) => el.getBoundingClientRect().width);
    assert.ok(Math.abs(overlay - heatmapWidth) < 1, `the facets' shapes (${overlay} px) lie over the picture (${heatmapWidth} px)`);

    const stats = await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json();
    // The verdict comes first: the score, every viewer figure beside the reference's with its set-up, the faults.
    assert.equal(await page.$eval('#result-body article.result > section', (s) => s.dataset.section), 'verdict');
    const score = await page.textContent('.verdict .score-value');
    assert.equal(score, `${stats.viewer.score.value.toFixed(1)} ± ${stats.viewer.score.stderr.toFixed(1)}`);
    for (const [key, f] of Object.entries(stats.viewer.figures)) {
      const row = await page.textContent(`.verdict-table tr[data-figure="${key}"]`);
      assert.match(row, f.set_up === 'spot' ? /Spot: 6 lamps/ : /Office: cosine dome/, key);
      assert.match(row, /\d % ± \d/, key);
    }
    assert.equal(await page.locator('.verdict .fault-list li').count(), stats.viewer.faults.filter((f) => f.applies).length);
    const crown = await page.textContent('[data-figure="crown_return"] .figure-value');
    assert.ok(Math.abs(parseFloat(crown) - stats.totals.crown_return * 100) <= 0.05, `${crown} vs ${stats.totals.crown_return}`);
    assert.match(await page.textContent('[data-figure="crown_return"] .figure-err'), /± \d/);
    for (const region of ['table', 'crown', 'pavilion']) {
      assert.equal(await page.locator(`table.regions tr[data-region="${region}"]`).count(), 1, region);
    }
    // The standard error shown is the one the server sent, to the decimals shown.
    const tableShare = await page.textContent('table.regions tr[data-region="table"] td:nth-of-type(2)');
    const [, shown, err] = tableShare.match(/^(\d+(?:\.\d+)?) % ± (\d+(?:\.\d+)?)$/) || [];
    assert.ok(err, tableShare);
    const decimals = (err.split('.')[1] || '').length;
    assert.equal(err, (stats.regions.table.share_stderr * 100).toFixed(decimals));
    assert.equal(shown, (stats.regions.table.share * 100).toFixed(decimals));

    // Grouped by tier at first, each tier closed: its facets' sums, the share with its error.
    const tierOf = (name) => name.replace(/_\d+$/, '');
    const tierNames = [...new Set(stats.facets.map((f) => tierOf(f.name)))];
    const tierRows = await page.$$eval('table.facets tr.tier-row', (trs) => trs.map((tr) => [tr.querySelector('.tier-toggle').dataset.tier, tr.textContent]));
    assert.deepEqual(tierRows.map(([t]) => t).sort(), [...tierNames].sort());
    assert.equal(await page.locator('table.facets tr[data-facet]').count(), 0, 'every tier closed');
    const byTierShare = tierNames.map((t) => [t, stats.facets.filter((f) => tierOf(f.name) === t).reduce((s, f) => s + f.leaving_share, 0)])
      .sort((a, b) => b[1] - a[1]);
    assert.equal(tierRows[0][0], byTierShare[0][0], 'the tier sending most light out first');
    const hit = stats.totals.hit;
    const [topTier, topShare] = byTierShare[0];
    const shareText = await page.textContent(`table.facets tr.tier-row:has(button[data-tier="${topTier}"]) .share-text`);
    const [, sharePct, errPct] = shareText.match(/^([\d.]+) % ± ([\d.]+)$/) || [];
    assert.ok(errPct, shareText);
    assert.ok(Math.abs(Number(sharePct) - topShare * 100) < 0.06, `${shareText} vs ${topShare}`);
    assert.ok(Math.abs(Number(errPct) - 100 * Math.sqrt(topShare * (1 - topShare) / hit)) < 0.06, `${shareText}: binomial error of ${hit}`);
    // Opening a tier shows its facets, each share with its error.
    const starTier = tierNames.find((t) => stats.facets.filter((f) => tierOf(f.name) === t).length > 1);
    await page.click(`button.tier-toggle[data-tier="${starTier}"]`);
    assert.equal(await page.getAttribute(`button.tier-toggle[data-tier="${starTier}"]`, 'aria-expanded'), 'true');
    const opened = stats.facets.filter((f) => tierOf(f.name) === starTier);
    assert.equal(await page.locator('table.facets tr[data-facet]').count(), opened.length);
    assert.match(await page.textContent(`table.facets tr[data-facet="${opened[0].id}"] .share-text`), /^[\d.]+ % ± [\d.]+$/);
    await page.click(`button.tier-toggle[data-tier="${starTier}"]`);
    // Hovering a facet of a closed tier on the heat-map lights its tier.
    const pavilionFacet = stats.facets.find((f) => f.region === 'pavilion');
    await page.hover(`.pic-heatmap polygon[data-facet="${pavilionFacet.id}"]`);
    assert.equal(await page.locator(`table.facets tr.tier-row.linked:has(button[data-tier="${tierOf(pavilionFacet.name)}"])`).count(), 1);
    // Ungrouped, every facet in one sortable list.
    await page.uncheck('.facet-grouping input');
    const rows = () => page.$$eval('table.facets tr[data-facet]', (trs) => trs.map((tr) => Number(tr.dataset.facet)));
    assert.equal((await rows()).length, stats.facets.length);
    // Default order: most light leaving first.
    const byShare = [...stats.facets].sort((a, b) => b.leaving_share - a.leaving_share || a.id - b.id).map((f) => f.id);
    assert.deepEqual(await rows(), byShare);
    await page.click('table.facets button[data-sort="id"]');
    assert.deepEqual(await rows(), [...stats.facets].map((f) => f.id).sort((a, b) => b - a));
    assert.equal(await page.getAttribute('table.facets th:has(button[data-sort="id"])', 'aria-sort'), 'descending');
    await page.click('table.facets button[data-sort="id"]');
    assert.deepEqual(await rows(), [...stats.facets].map((f) => f.id).sort((a, b) => a - b));

    // The heat-map and the facet table point at each other.
    const table = stats.facets.find((f) => f.region === 'table');
    await page.hover(`.pic-heatmap polygon[data-facet="${table.id}"]`);
    assert.ok(await page.locator(`table.facets tr[data-facet="${table.id}"].linked`).count() === 1, 'hovering the table lights its row');
    const readout = await page.textContent('.pic-heatmap .heatmap-readout');
    assert.ok(readout.startsWith(`${table.name.replace(/_/g, ' ')} (crown): `), readout);
    assert.match(readout, /: \d+(\.\d+)? % ± [\d.]+ of the light leaving$/);
    const pavilion = stats.facets.find((f) => f.region === 'pavilion');
    await page.hover(`table.facets tr[data-facet="${pavilion.id}"]`);
    assert.equal(await page.locator(`.pic-heatmap polygon[data-facet="${pavilion.id}"].linked`).count(), 1);
    assert.equal(await page.locator(`table.facets tr[data-facet="${table.id}"].linked`).count(), 0);

    const json = await page.getAttribute('a[href$="/stats"]', 'href');
    const csv = await page.getAttribute('a[href$="/stats.csv"]', 'href');
    assert.equal((await fetch(`${baseUrl}${json}`)).status, 200);
    assert.equal((await fetch(`${baseUrl}${csv}`)).status, 200);
    await shot('05-result-desktop');
    await page.setViewportSize(PHONE);
    await page.waitForTimeout(200);
    await shot('06-result-phone');
    assert.ok(await noHorizontalOverflow(), 'the result page fits a phone');
    await page.setViewportSize(DESKTOP);
  });

  test('a result prints as a clean report: verdict, figures, pictures and the stone, without the page\'s controls', async () => {
    await page.goto(`${baseUrl}/#/jobs/${jobIds.brilliant}`);
    await page.waitForSelector('#result-body .figures');
    await picturesLoaded('#result-body .pictures');
    await page.check('.facet-grouping input');  // the report prints the facets by tier
    await page.emulateMedia({ media: 'print' });
    try {
      for (const sel of ['.site-header', '.site-footer', '.back-link', '.downloads', '#job-form', '#sweep-form']) {
        assert.equal(await page.locator(sel).first().isVisible(), false, `${sel} is printed`);
      }
      const buttons = await page.$$eval('#main button:not(.sort):not(.tier-toggle)', (bs) => bs.filter((b) => b.offsetParent !== null).length);
      assert.equal(buttons, 0, 'no button is printed');
      for (const sel of ['[data-section="verdict"]', '.figures', '.pictures img >> nth=0', '#stone-title', 'table.regions', 'table.facets th']) {
        assert.equal(await page.locator(sel).first().isVisible(), true, `${sel} is missing from the print`);
      }
      // The facet table's column titles and tiers print as text, not as buttons.
      assert.equal(await page.$eval('table.facets button.sort', (b) => getComputedStyle(b).borderTopStyle), 'none');
      assert.equal(await page.$eval('table.facets button.tier-toggle', (b) => getComputedStyle(b).borderTopStyle), 'none');
      const pdf = await page.pdf({ format: 'A4', printBackground: true });
      fs.mkdirSync(screenshotDir, { recursive: true });
      fs.writeFileSync(path.join(screenshotDir, '05b-result-print.pdf'), pdf);
      assert.equal(pdf.subarray(0, 5).toString(), '%PDF-');
      assert.ok(pdf.length > 20_000, `a report with pictures, not ${pdf.length} bytes`);
    } finally {
      await page.emulateMedia({ media: 'screen' });
    }
    assert.equal(await page.locator('.site-header').isVisible(), true);
  });

  test('the 3-D view draws the stone, colours it by the chosen figure and names a facet clicked, with its numbers', async () => {
    const id = jobIds.brilliant;
    await page.goto(`${baseUrl}/#/jobs/${id}`);
    const view = '[data-section="stone3d"] .stone3d';
    await page.waitForSelector(`${view}[data-triangles]`);
    const stats = await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json();
    const stone = await (await fetch(`${baseUrl}/api/jobs/${id}/stone.json`)).json();
    assert.equal(stone.units, 'mm');
    assert.deepEqual(stone.facets.map((f) => f.id), stats.facets.map((f) => f.id));
    // three drew every facet: a polygon of n corners is n - 2 triangles.
    const triangles = stone.facets.reduce((n, f) => n + f.vertices.length - 2, 0);
    assert.equal(Number(await page.getAttribute(view, 'data-triangles')), triangles);
    const before = await stoneCanvasPixels();
    assert.ok(before.drawn > 0.25 * before.samples.length, `${before.drawn} of ${before.samples.length} samples drawn`);
    // A text alternative, and the view takes the keyboard's focus.
    const canvas = page.locator('canvas.stone3d-canvas');
    assert.match(await canvas.getAttribute('aria-label'), /in 3-D, coloured by light leaving/);
    assert.match(await page.textContent('#stone3d-summary'), new RegExp(`${stats.facets.length} facets coloured by light leaving`));
    assert.equal(await canvas.getAttribute('tabindex'), '0');
    // The legend: the viridis ramp with its scale, and the table beyond it.
    assert.equal(await page.$$eval('.stone3d-ticks span', (s) => s.length), 5);
    const table = stats.facets.find((f) => f.region === 'table');
    const beyond = await page.textContent('.stone3d-beyond');
    assert.ok(beyond.includes(`${table.name.replace(/_/g, ' ')} ${(100 * table.leaving_share).toFixed(2)} %`), beyond);

    // Another figure: other colours, its legend and the text alternative follow.
    await page.selectOption('#stone3d-figure', 'internal_reflections');
    assert.equal(await page.getAttribute(view, 'data-figure'), 'internal_reflections');
    const after = await stoneCanvasPixels();
    assert.equal(after.samples.length, before.samples.length, 'the canvas kept its size');
    const changed = after.samples.filter((v, i) => v !== before.samples[i]).length;
    assert.ok(changed > 0.05 * after.samples.length, `${changed} of ${after.samples.length} samples changed colour`);
    assert.equal(await page.textContent('.stone3d-legend-title'), 'Internal reflections');
    await page.selectOption('#stone3d-figure', 'leaving_share');

    // Seen from above at an angle, the canvas's centre is the table: a click names it with its numbers.
    await canvas.click();  // at its centre, scrolled into view
    await page.waitForSelector(`${view}[data-picked="${table.id}"]`);
    assert.equal(await page.textContent('.stone3d-readout h3'), table.name.replace(/_/g, ' '));
    const share = await page.textContent('.stone3d-numbers dd[data-figure="leaving_share"]');
    const [, shown, err] = share.match(/^(\d+(?:\.\d+)?) % ± (\d+(?:\.\d+)?)$/) || [];
    assert.ok(err, share);
    const decimals = (err.split('.')[1] || '').length;
    assert.equal(shown, (table.leaving_share * 100).toFixed(decimals));
    assert.equal(err, (table.leaving_share_stderr * 100).toFixed(decimals));
    assert.equal(await page.textContent('.stone3d-numbers dd[data-figure="entering"]'), table.entering.toLocaleString('en-US'));
    // Its row of the facet table lights up (its tier's row while the table is grouped by tier).
    const rows = `table.facets tr.linked[data-facet="${table.id}"], table.facets tr.linked[data-facets~="${table.id}"]`;
    assert.equal(await page.locator(rows).count(), 1, 'the table\'s row lights up');
    await shot('05c-result-3d');
    // The keyboard: N picks the next facet, an arrow key turns the stone.
    await canvas.focus();
    await page.keyboard.press('n');
    await page.waitForSelector(`${view}[data-picked="${stone.facets[(stone.facets.findIndex((f) => f.id === table.id) + 1) % stone.facets.length].id}"]`);
    const unturned = await stoneCanvasPixels();
    await page.keyboard.press('ArrowLeft');
    const turned = await stoneCanvasPixels();
    assert.equal(turned.samples.length, unturned.samples.length, 'the canvas kept its size');
    assert.ok(turned.samples.some((v, i) => v !== unturned.samples[i]), 'the arrow key turned the stone');
  });

  test('without three.js on the server the result page works and says the 3-D view needs libjs-three', async () => {
    await page.route('**/vendor/three/**', (route) => route.fulfill({ status: 404, body: '' }));
    try {
      await page.goto(`${baseUrl}/#/jobs/${jobIds.brilliant}`);
      await page.reload();
      await page.waitForSelector('#result-body .figures');
      await page.waitForSelector('[data-section="stone3d"] .stone3d-missing');
      assert.match(await page.textContent('[data-section="stone3d"] .stone3d-missing'), /needs three\.js from Debian's libjs-three/);
      assert.equal(await page.locator('canvas.stone3d-canvas').count(), 0);
    } finally {
      await page.unroute('**/vendor/three/**');
    }
  });

  test('compare two finished jobs, ranked by crown return, with their pictures', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector(`#job-list li[data-id="${jobIds.brilliant}"]`);
    // A second design: an uploaded cube, lit the same way.
    await uploadThroughPage('tests/data/cube_quads.obj');
    await fillSmallJob();
    jobIds.cube = await submitAndGetId();
    await waitForFinished(jobIds.cube);

    for (const id of [jobIds.brilliant, jobIds.cube]) await page.check(`#job-list li[data-id="${id}"] input.compare-box`);
    assert.match(await page.textContent('#compare-selected'), /\(2\)/);
    await page.click('#compare-selected');
    await page.waitForSelector('.rank-list li:nth-child(2)');

    const crown = {};
    for (const id of [jobIds.brilliant, jobIds.cube]) {
      crown[id] = (await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json()).totals.crown_return;
    }
    const ranked = await page.$$eval('.rank-list li', (lis) => lis.map((li) => li.dataset.id));
    const expected = Object.keys(crown).sort((a, b) => crown[b] - crown[a]);
    assert.deepEqual(ranked, expected, 'ranked by crown return, most first');
    assert.match(await page.textContent('.rank-list li:first-child'), /Most light out of the top/);
    assert.match(await page.textContent('.rank-list li:first-child .rank-no'), /#1/);

    // The verdicts side by side: a score for each design in the ranking's order, the cube's the lower.
    const scores = await page.$$eval('.verdict-compare-table tbody tr:first-child td', (tds) => tds.map((td) => parseFloat(td.textContent)));
    assert.equal(scores.length, 2);
    const cubeScore = scores[expected.indexOf(jobIds.cube)];
    assert.ok(cubeScore < scores[expected.indexOf(jobIds.brilliant)], JSON.stringify(scores));
    assert.equal(await page.locator('.verdict-compare-table tbody tr').count(), 2 + 6);

    const cards = await page.$$eval('.compare-card', (cs) => cs.map((c) => c.dataset.id));
    assert.deepEqual(cards, expected);
    const pics = await picturesLoaded('.compare-grid');
    assert.equal(pics.length, 4);
    for (const p of pics) assert.ok(p.width > 0, `${p.src} did not load`);
    // The heat-maps are drawn on the page on one colour scale (here the cube's, whose facets other than a table
    // take more of the light than the brilliant's table).
    const light = await assertCommonHeatScale('.compare-card', expected,
      (s) => s.facets.map((f) => ({ id: f.id, share: f.leaving_share })));
    assert.match(await page.textContent('[aria-labelledby="side-title"] > .hint'), new RegExp(`0 to ${(light.scale * 100).toFixed(1)} % of the light`));
    // The best value of each figure is marked in words, not only by colour.
    assert.ok(await page.locator('.compare-table .best-mark').count() >= 7);
    await shot('07-compare-desktop');
    await page.setViewportSize(PHONE);
    await page.waitForTimeout(200);
    await shot('08-compare-phone');
    assert.ok(await noHorizontalOverflow(), 'the comparison fits a phone');
    await page.setViewportSize(DESKTOP);
  });

  test('the comparison shows the designs in 3-D, one at a time, on one colour scale, loaded when scrolled to', async () => {
    await page.goto(`${baseUrl}/#/compare/${jobIds.brilliant},${jobIds.cube}`);
    const section = '[data-section="compare3d"]';
    const view = `${section} .stone3d`;
    await page.waitForSelector(section);
    const order = await page.$$eval('.compare-card', (cs) => cs.map((c) => c.dataset.id));
    // Out of the window, nothing loads; brought near, the first design of the ranking is drawn.
    assert.equal(await page.locator(`${section} canvas`).count(), 0, 'the 3-D view waits until scrolled to');
    await page.locator(section).scrollIntoViewIfNeeded();
    await page.waitForSelector(`${view}[data-triangles]`);
    const shapes = {};
    const stats = {};
    for (const id of order) {
      shapes[id] = await (await fetch(`${baseUrl}/api/jobs/${id}/stone.json`)).json();
      stats[id] = await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json();
    }
    const triangles = (id) => shapes[id].facets.reduce((n, f) => n + f.vertices.length - 2, 0);
    assert.equal(await page.getAttribute(view, 'data-stone'), order[0]);
    assert.equal(Number(await page.getAttribute(view, 'data-triangles')), triangles(order[0]));
    // One scale: the largest of the designs' own (the 95th percentile of the facets other than the table).
    const own = await page.evaluate(async (lists) => {
      const { scaleEnd } = await import('/js/heatmap.js');
      return lists.map((l) => {
        const others = l.filter((f) => f.region !== 'table').map((f) => f.leaving_share).sort((x, y) => x - y);
        return scaleEnd(others[Math.ceil(0.95 * others.length) - 1]);
      });
    }, order.map((id) => stats[id].facets));
    assert.notEqual(own[0], own[1], 'designs whose own scales differ');
    const top = Number(await page.getAttribute(view, 'data-top'));
    assert.equal(top, Math.max(...own));
    assert.equal(await page.textContent(`${section} .stone3d-shared`), 'One scale for the 2 designs compared');
    assert.doesNotMatch(await page.textContent(`${section} .stone3d-legend`), /null|undefined|NaN/);
    const before = await stoneCanvasPixels(section);
    assert.ok(before.drawn > 0.1 * before.samples.length, `${before.drawn} of ${before.samples.length} samples drawn`);

    // The other design: its shape, on the same scale.
    await page.selectOption('#compare3d-stone', '1');
    await page.waitForSelector(`${view}[data-stone="${order[1]}"]`);
    assert.equal(Number(await page.getAttribute(view, 'data-triangles')), triangles(order[1]));
    assert.equal(Number(await page.getAttribute(view, 'data-top')), top, 'the scale stays');
    const after = await stoneCanvasPixels(section);
    assert.ok(after.samples.some((v, i) => v !== before.samples[i]), 'another stone drawn');
    assert.match(await page.textContent('#compare3d-summary'), new RegExp(`${stats[order[1]].facets.length} facets coloured by light leaving`));

    // A click at the centre names the facet there with its numbers, from this design's statistics.
    await page.locator(`${section} canvas.stone3d-canvas`).click();
    await page.waitForSelector(`${view}[data-picked]`);
    const pickedId = await page.getAttribute(view, 'data-picked');
    const picked = stats[order[1]].facets.find((f) => String(f.id) === pickedId);
    assert.ok(picked);
    assert.equal(await page.textContent(`${section} .stone3d-readout h3`), picked.name.replace(/_/g, ' '));
    assert.equal(await page.textContent(`${section} .stone3d-numbers dd[data-figure="entering"]`), picked.entering.toLocaleString('en-US'));
    await shot('07c-compare-3d');
  });

  test('a comparison prints as a clean report: the ranking, the figures and each design, without the page\'s controls', async () => {
    await page.goto(`${baseUrl}/#/compare/${jobIds.brilliant},${jobIds.cube}`);
    await page.waitForSelector('.compare-grid .compare-card');
    await page.emulateMedia({ media: 'print' });
    try {
      for (const sel of ['.site-header', '.site-footer', '.compare-pick', '#compare-choices']) {
        assert.equal(await page.locator(sel).first().isVisible(), false, `${sel} is printed`);
      }
      const buttons = await page.$$eval('#main button:not(.sort):not(.tier-toggle)', (bs) => bs.filter((b) => b.offsetParent !== null).length);
      assert.equal(buttons, 0, 'no button is printed');
      for (const sel of ['.ranking', '.compare-card', 'table.compare-table']) {
        assert.equal(await page.locator(sel).first().isVisible(), true, `${sel} is missing from the print`);
      }
      assert.equal(await page.locator('.compare-card').count(), 2, 'both designs are printed');
      const pdf = await page.pdf({ format: 'A4', printBackground: true });
      fs.mkdirSync(screenshotDir, { recursive: true });
      fs.writeFileSync(path.join(screenshotDir, '07b-compare-print.pdf'), pdf);
      assert.equal(pdf.subarray(0, 5).toString(), '%PDF-');
      assert.ok(pdf.length > 20_000, `a report with pictures, not ${pdf.length} bytes`);
    } finally {
      await page.emulateMedia({ media: 'screen' });
    }
  });

  test('jobs go by their names on the list, the result page and the comparison', async () => {
    // A design the API names from the proportions it changes; the page shows the server's name.
    const res = await fetch(`${baseUrl}/api/jobs`, {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ mesh: 'round_brilliant', photons: 2000, threads: 2, render: false, cut: { pavilion: 43.5 } }),
    });
    const created = await res.json();
    assert.equal(created.name, 'round brilliant P 43.5');
    await page.goto(`${baseUrl}/#/`);
    await waitForFinished(created.id);
    assert.equal(await page.textContent(`#job-list li[data-id="${created.id}"] .job-name`), 'round brilliant P 43.5');
    assert.equal(await page.textContent(`#job-list li[data-id="${jobIds.cube}"] .job-name`), 'cube_quads.obj');
    await page.click(`#job-list li[data-id="${created.id}"] a[data-action="open"]`);
    await page.waitForSelector('#result-body .figures');
    assert.match(await page.textContent('#result-title'), /^round brilliant P 43\.5/);
    assert.equal(await page.title(), 'round brilliant P 43.5 — facetlight');
    assert.equal(await page.textContent('.cut-values'), 'round brilliant cut with pavilion 43.5');
    await page.goto(`${baseUrl}/#/compare/${created.id},${jobIds.brilliant}`);
    await page.waitForSelector(`.rank-list li[data-id="${created.id}"]`);
    const names = await page.$$eval('.rank-list .rank-name a', (as) => as.map((a) => a.textContent));
    assert.deepEqual(names.sort(), ['brilliant.asc', 'round brilliant P 43.5']);
    assert.match(await page.textContent('.compare-table thead'), /round brilliant P 43\.5/);
    assert.match(await page.textContent('#compare-choices'), /round brilliant P 43\.5/);
  });

  test('the study form edits the chosen shape\'s proportions and sends them as the job\'s cut', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    // The material menu shows its options whole.
    const cut = await page.$eval('#f-material', (sel) => {
      const ctx = document.createElement('canvas').getContext('2d');
      ctx.font = getComputedStyle(sel).font;
      const widest = Math.max(...[...sel.options].map((o) => ctx.measureText(o.text).width));
      return { widest, room: sel.clientWidth - 40 };
    });
    assert.ok(cut.widest <= cut.room, `the material menu cuts its options off: ${JSON.stringify(cut)}`);
    // It tells singly from doubly refracting materials, the latter with their birefringence.
    const groups = await page.$$eval('#f-material optgroup', (gs) => Object.fromEntries(
      gs.map((g) => [g.label.split(' ')[0], [...g.children].map((o) => [o.value, o.text])])));
    assert.deepEqual(groups.Singly.map(([v]) => v), ['diamond', 'cubic_zirconia', 'fused_silica', 'bk7']);
    assert.ok(groups.Doubly.some(([v, t]) => v === 'calcite' && /biref\. 0\.172/.test(t)), JSON.stringify(groups));
    // An upload has no parameters; a shape of the cut library shows the ones GET /api/meshes lists.
    await page.selectOption('#f-mesh', jobIds.brilliantMesh);
    assert.equal(await page.isHidden('#cut-fields'), true);
    await page.selectOption('#f-mesh', 'round_brilliant');
    const listed = (await (await fetch(`${baseUrl}/api/meshes`)).json()).shipped.find((m) => m.mesh === 'round_brilliant');
    const pavilion = listed.parameters.find((p) => p.name === 'pavilion');
    assert.equal(await page.inputValue('#f-cut-pavilion'), String(pavilion.default));
    assert.equal(await page.getAttribute('#f-cut-pavilion', 'min'), String(pavilion.min));
    assert.equal(await page.getAttribute('#f-cut-pavilion', 'max'), String(pavilion.max));
    assert.equal(await page.locator('#cut-params .field').count(), listed.parameters.length);
    assert.match(await page.textContent('label[for="f-cut-pavilion"]'), /pavilion \(°\)/);
    assert.equal(await page.locator('#f-cut-halves option').count(), 2, 'a choice is a menu');
    // A value outside the shape's range is the server's to refuse, next to the field.
    await fillSmallJob({ photons: '2000' });
    await page.setChecked('#f-render', false);
    await page.fill('#f-cut-pavilion', '89');
    await page.click('#submit-button');
    const error = await page.waitForSelector('[id="err-cut.pavilion"]:not([hidden])');
    assert.match(await error.textContent(), /pavilion/);
    await page.fill('#f-cut-pavilion', '43.5');
    const id = await submitAndGetId();
    const job = await (await fetch(`${baseUrl}/api/jobs/${id}`)).json();
    assert.deepEqual(job.settings.cut, { pavilion: 43.5 }, 'only the changed parameter is sent');
    assert.equal(job.name, 'round brilliant P 43.5');
    await page.fill('#f-cut-pavilion', String(pavilion.default));
    await page.setChecked('#f-render', true);
    await shot('09a-form-proportions');
  });

  test('cancel a queued job and delete finished ones', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    // A long job, canceled while it waits or runs.
    await page.selectOption('#f-mesh', jobIds.brilliantMesh);
    await fillSmallJob({ photons: '50000000' });
    const id = await submitAndGetId();
    const item = `#job-list li[data-id="${id}"]`;
    await page.click(`${item} button[data-action="cancel"]`);
    await page.waitForFunction((sel) => document.querySelector(sel)?.dataset.state === 'canceled', item, { timeout: 30_000 });
    assert.match(await page.textContent(`${item} .state`), /Canceled/);
    await shot('09-canceled');
    // Delete takes two clicks.
    await page.click(`${item} button[data-action="delete"]`);
    assert.match(await page.textContent(`${item} button[data-action="delete"]`), /again/);
    await page.click(`${item} button[data-action="delete"]`);
    await page.waitForSelector(item, { state: 'detached' });
    assert.equal((await fetch(`${baseUrl}/api/jobs/${id}`)).status, 404);
  });

  test('a job with the ASET view and a tilt series shows the picture, its shares, the animation and the chart', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    await page.selectOption('#f-mesh', jobIds.brilliantMesh);
    await fillSmallJob({ width: '48', height: '48' });
    await page.setChecked('#f-aset', true);
    // The rocking range and axis are only editable with a tilt series asked for.
    assert.ok(await page.isDisabled('#f-tilt-axis'));
    await page.setChecked('#f-tilt-series', true);
    await page.fill('#f-tilt-max', '6');
    await page.selectOption('#f-tilt-axis', '90');
    const id = await submitAndGetId();
    jobIds.viewer = id;
    await waitForFinished(id);
    await page.setChecked('#f-aset', false);
    await page.fill('#f-tilt-max', '10');
    await page.selectOption('#f-tilt-axis', '0');
    await page.setChecked('#f-tilt-series', false);
    await page.click(`#job-list li[data-id="${id}"] a[data-action="open"]`);
    await page.waitForSelector('[data-section="viewer"]');
    await page.locator('[data-section="viewer"]').scrollIntoViewIfNeeded();  // its pictures load lazily
    const pics = await picturesLoaded('[data-section="viewer"]');
    assert.deepEqual(pics.map((p) => p.src.split('/').pop()), ['aset.png', 'tilt.webp', 'tilt.png']);
    // The browser decodes the animated WebP.
    for (const p of pics) assert.ok(p.width > 0, `${p.src} did not load`);
    await assertLegiblePictures('[data-section="viewer"]');
    assert.equal(await page.locator('table.aset-shares tbody tr').count(), 5);
    const stats = await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json();
    const head = await page.textContent('table.aset-shares tr[data-aset="head"] td');
    assert.ok(Math.abs(parseFloat(head) - stats.aset.shares.head.share * 100) <= 0.05, `${head} vs ${stats.aset.shares.head.share}`);
    assert.deepEqual(stats.tilt_series.settings, { max_deg: 6, step_deg: 1, axis_deg: 90 });
    assert.match(await page.textContent('[data-section="viewer"] figcaption'), /±6° about the front–back \(y\) axis: scintillation .* 13 frames/);
    await shot('09b-viewer-views');
    await page.setViewportSize(PHONE);
    await page.waitForTimeout(200);
    assert.ok(await noHorizontalOverflow(), 'the viewer views fit a phone');
    await page.setViewportSize(DESKTOP);
  });

  test('a job with fire shows its figures with errors, the histogram chart and the fire heat-map', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    await page.selectOption('#f-mesh', jobIds.brilliantMesh);
    await fillSmallJob({ width: '48', height: '48' });
    await page.setChecked('#f-fire', true);
    const id = await submitAndGetId();
    await waitForFinished(id);
    await page.setChecked('#f-fire', false);
    await page.click(`#job-list li[data-id="${id}"] a[data-action="open"]`);
    await page.waitForSelector('[data-section="fire"]');
    const pics = await picturesLoaded('[data-section="fire"]');
    assert.deepEqual(pics.map((p) => p.src.split('/').pop()), ['heatmap_fire.png']);
    await assertLegiblePictures('[data-section="fire"]');
    const stats = await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json();
    const mean = await page.textContent('[data-figure="fire.mean_separation_deg"] .figure-value');
    assert.match(mean, /° ± /);
    assert.ok(Math.abs(parseFloat(mean) - stats.fire.mean_separation_deg) < 0.01, `${mean} vs ${stats.fire.mean_separation_deg}`);
    assert.match(await page.textContent('[data-figure="fire.coloured_share"] .figure-value'), /% ± /);
    // Every share the statistics report has a place on the page, split_share too.
    for (const key of ['pair_share', 'split_share']) {
      const shown = parseFloat(await page.textContent(`[data-figure="fire.${key}"] .figure-value`));
      assert.ok(Math.abs(shown - 100 * stats.fire[key]) < 0.51, `${key}: ${shown} vs ${stats.fire[key]}`);
    }
    assert.ok(await page.locator('.fire-histogram-chart rect').count() > 2, 'the histogram has filled cells');
    await shot('09c-fire');
  });

  // Issue 30: the compare view's fire heat-maps are drawn on the page on one colour scale, as its light heat-maps
  // are: the same colour is the same share of the fire in each.
  test('the comparison draws the fire heat-maps on one colour scale', async () => {
    const ids = [];
    for (const pavilion of [40.7, 43]) {
      const res = await fetch(`${baseUrl}/api/jobs`, {
        method: 'POST', headers: { 'Content-Type': 'application/json' },
        body: JSON.stringify({ mesh: 'round_brilliant', photons: 20000, threads: 2, render: false, fire: { enabled: true }, cut: { pavilion } }),
      });
      assert.equal(res.status, 202);
      ids.push((await res.json()).id);
    }
    await page.goto(`${baseUrl}/#/`);
    for (const id of ids) await waitForFinished(id);
    await page.goto(`${baseUrl}/#/compare/${ids.join(',')}`);
    await page.waitForSelector('[data-section="fire-compare"]');
    await page.locator('[data-section="fire-compare"]').scrollIntoViewIfNeeded();
    // Two brilliants: the scale is their crown facets', the tables beyond it, hatched.
    jobIds.fire = ids;
    const fire = await assertCommonHeatScale('.fire-compare-card', ids, (s) => s.fire.facets);
    assert.ok(fire.hatched >= 1, 'a table beyond the scale');
    assert.match(await page.textContent('[data-section="fire-compare"] .hint'), new RegExp(`0 to ${(fire.scale * 100).toFixed(1)} % of the fire`));
    const [a] = ids;
    // A job without rendering still shows its heat-map (from its statistics), and says why there is no render.
    assert.equal(await page.locator(`.compare-card[data-id="${a}"] .pic-heatmap`).count(), 1);
    assert.equal(await page.locator(`.compare-card[data-id="${a}"] .pic-render`).count(), 0);
    assert.match(await page.textContent(`.compare-card[data-id="${a}"] .pictures .hint`), /ran without rendering/);
    // Pointing at a facet names its share of the fire.
    const first = await page.$(`.fire-compare-card[data-id="${a}"] .heatmap-drawing polygon`);
    await first.hover();
    assert.match(await page.textContent(`.fire-compare-card[data-id="${a}"] .heatmap-readout`), /of the fire leaving/);
    await shot('09d-compare-fire');
  });

  test('the comparison shows each design\'s ASET picture with its shares, and the tilt series where present', async () => {
    // A second design seen by the viewer: the brilliant tilted by 8 deg, with the ASET view and a tilt series.
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    await page.selectOption('#f-mesh', jobIds.brilliantMesh);
    await fillSmallJob({ width: '48', height: '48' });
    await page.fill('#f-tilt', '8');
    await page.setChecked('#f-aset', true);
    await page.setChecked('#f-tilt-series', true);
    const tilted = await submitAndGetId();
    await waitForFinished(tilted);
    await page.setChecked('#f-tilt-series', false);
    await page.setChecked('#f-aset', false);
    await page.fill('#f-tilt', '0');

    await page.goto(`${baseUrl}/#/compare/${jobIds.viewer},${tilted},${jobIds.brilliant}`);
    await page.waitForSelector('[data-section="viewer-compare"] .viewer-card:nth-child(3)');
    const order = await page.$$eval('.compare-card', (cs) => cs.map((c) => c.dataset.id));
    const cards = await page.$$eval('.viewer-card', (cs) => cs.map((c) => c.dataset.id));
    assert.deepEqual(cards, order, 'the viewer cards in the ranking\'s order');
    // The pictures load lazily, as they come near the window.
    await page.locator('[data-section="viewer-compare"] .compare-grid').scrollIntoViewIfNeeded();
    const pics = await picturesLoaded('[data-section="viewer-compare"]');
    for (const p of pics) assert.ok(p.width > 0, `${p.src} did not load`);
    const picsOf = async (id) => page.$$eval(`.viewer-card[data-id="${id}"] img`, (imgs) => imgs.map((i) => i.getAttribute('src').split('/').pop()));
    // The two tilt charts drawn on the page on one y range, the one around both designs' frames; each a link
    // to its own tilt.png.
    assert.deepEqual(await picsOf(jobIds.viewer), ['aset.png', 'tilt.webp']);
    assert.deepEqual(await picsOf(tilted), ['aset.png', 'tilt.webp']);
    const charts = await page.$$eval('.viewer-card .tilt-chart', (cs) => cs.map((c) => ({
      range: c.dataset.range, link: c.closest('a').getAttribute('href'), width: c.getBoundingClientRect().width })));
    assert.equal(charts.length, 2);
    const frames = [];
    for (const id of [jobIds.viewer, tilted]) frames.push(...(await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json()).tilt_series.frames);
    const low = Math.min(...frames.map((f) => 100 * (f.light_return - f.light_return_stderr)));
    const high = Math.max(...frames.map((f) => 100 * (f.light_return + f.light_return_stderr)));
    for (const c of charts) {
      assert.equal(c.range, charts[0].range, 'one y range for every tilt chart');
      const [lo, hi] = c.range.split(' ').map(Number);
      assert.ok(lo <= low && hi >= high && hi - lo <= high - low + 10, `${c.range} around ${low}..${high}`);
      assert.match(c.link, /\/tilt\.png$/);
    }
    assert.deepEqual(await picsOf(jobIds.brilliant), []);
    assert.match(await page.textContent(`.viewer-card[data-id="${jobIds.brilliant}"]`), /no ASET view/);
    // Each picture says which light it uses.
    assert.match(await page.textContent(`.compare-card[data-id="${jobIds.brilliant}"] .pic-render figcaption`), /studio light, the viewer's head shadow/);
    assert.match(await page.textContent(`.compare-card[data-id="${jobIds.brilliant}"] .pic-heatmap figcaption`), /light/);
    assert.match(await page.textContent(`.viewer-card[data-id="${jobIds.viewer}"] figcaption`), /front–back \(y\) axis: scintillation .* 13 frames/);
    // Each design's shares, as its statistics give them, in its card and in the table's column.
    const column = 1 + order.indexOf(tilted);
    for (const id of [jobIds.viewer, tilted]) {
      const stats = await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json();
      assert.equal(await page.locator(`.viewer-card[data-id="${id}"] table.aset-shares tbody tr`).count(), 5);
      const bright = await page.textContent(`.viewer-card[data-id="${id}"] tr[data-aset="bright"] td`);
      assert.ok(Math.abs(parseFloat(bright) - stats.aset.shares.bright.share * 100) <= 0.05, `${bright} vs ${stats.aset.shares.bright.share}`);
      if (id === tilted) {
        const cell = await page.textContent(`.viewer-compare-table tbody tr:nth-child(2) td:nth-child(${column + 1})`);
        assert.equal(cell, bright);
      }
    }
    const rows = await page.$$eval('.viewer-compare-table tbody tr', (trs) => trs.map((tr) => tr.textContent));
    const sparkle = rows.find((r) => r.startsWith('Scintillation'));
    assert.equal((sparkle.match(/not asked for/g) || []).length, 1, sparkle);
    await shot('09c-compare-viewer');
    await page.setViewportSize(PHONE);
    await page.waitForTimeout(200);
    assert.ok(await noHorizontalOverflow(), 'the viewer comparison fits a phone');
    await page.setViewportSize(DESKTOP);
  });

  test('a job with the fire picture shows fire.png beside render.png, each captioned with its light', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    await page.selectOption('#f-mesh', jobIds.brilliantMesh);
    await fillSmallJob({ width: '48', height: '48' });
    await page.setChecked('#f-fire-picture', true);
    const id = await submitAndGetId();
    await waitForFinished(id);
    await page.setChecked('#f-fire-picture', false);
    const job = await (await fetch(`${baseUrl}/api/jobs/${id}`)).json();
    assert.equal(job.links.fire_picture, `/api/jobs/${id}/fire.png`);
    await page.click(`#job-list li[data-id="${id}"] a[data-action="open"]`);
    await page.waitForSelector('#result-body .pictures');
    const pics = await picturesLoaded('#result-body .pictures');
    assert.deepEqual(pics.map((p) => p.src.split('/').pop()).slice(0, 2), ['render.png', 'fire.png']);
    for (const p of pics) assert.ok(p.width > 0, `${p.src} did not load`);
    assert.match(await page.textContent('.pic-render figcaption'), /studio light/);
    assert.match(await page.textContent('.pic-fire figcaption'), /one small light 20° from vertical, 4° radius/);
    await shot('09d-fire-picture');
  });

  test('a sweep: its chart fills in with axes and units, hover shows a point, click traces it for compare', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.fill('#s-step-0', '0');
    await page.click('#sweep-submit');
    const stepError = await page.waitForSelector('[id="err-sweep.axes[0].step"]:not([hidden])');
    assert.match(await stepError.textContent(), /step/);
    await fillSweepAxis(0, ['pavilion', '39', '41', '1']);
    await page.fill('#s-photons', '4000');
    await page.click('#sweep-submit');
    await page.waitForFunction(() => location.hash.startsWith('#/sweeps/'));
    const id = await page.evaluate(() => location.hash.split('/')[2]);
    await page.waitForFunction(() => document.querySelectorAll('#sweep-chart circle.sweep-point').length === 3, null,
      { timeout: JOB_TIMEOUT_MS, polling: 100 });
    await page.waitForFunction(() => /^succeeded/.test(document.querySelector('#sweep-progress').textContent), null,
      { timeout: JOB_TIMEOUT_MS });
    assert.match(await page.textContent('#sweep-progress'), /3 of 3 points/);
    assert.match(await page.textContent('#sweep-view-title'), /^round brilliant, sweep of pavilion: brightness$/);
    assert.equal(await page.textContent(`#job-list li[data-id="${id}"] .job-name`), 'round brilliant, sweep of pavilion');
    // The status beside the sweep form's button follows the sweep too.
    await page.waitForFunction(() => /finished: round brilliant, sweep of pavilion\.$/.test(document.querySelector('#sweep-status').textContent));
    const chartText = await page.textContent('#sweep-chart svg');
    for (const label of ['pavilion (deg)', 'Brightness (%)', '±1σ']) assert.ok(chartText.includes(label), label);
    assert.ok(await page.isVisible('#sweep-chart polygon.sweep-band'), 'the ±1σ band is drawn');
    assert.deepEqual(await chartTextsCutOff(), []);
    assert.ok(await page.isVisible('#sweep-links a[href$="/sweep.csv"]'));
    await shot('12-sweep-chart');
    await page.hover('#sweep-chart circle.sweep-point >> nth=1');
    const tip = await page.textContent('#sweep-tooltip');
    assert.match(tip, /^pavilion 40: /);
    assert.match(tip, /brightness \d+\.\d+ % ± \d/);
    assert.match(tip, /light-performance score \d+\.\d ± \d/);
    assert.match(tip, /cosine-weighted return \d+\.\d+ % ± \d/);
    await page.click('#sweep-chart circle.sweep-point >> nth=1');
    await page.waitForFunction(() => location.hash.startsWith('#/compare/'), null, { timeout: JOB_TIMEOUT_MS });
    const design = await page.evaluate(() => location.hash.split('/')[2]);
    const job = await (await fetch(`${baseUrl}/api/jobs/${design}`)).json();
    assert.equal(job.state, 'succeeded');
    assert.equal(job.settings.cut.pavilion, 40);
    assert.equal(job.name, 'round brilliant P 40', 'a point opened from a sweep is named by its design');
    // The design's trace is the sweep's point, bit for bit.
    const stats = await (await fetch(`${baseUrl}/api/jobs/${design}/stats`)).json();
    const sweep = await (await fetch(`${baseUrl}/api/jobs/${id}/sweep.json`)).json();
    assert.equal(stats.totals.weighted_return, sweep.points[1].totals.weighted_return);
  });

  test('a sweep over two axes draws a filled map of a fire figure with its best point starred and a colour legend', async () => {
    await page.goto(`${baseUrl}/#/`);
    await fillSweepAxis(0, ['pavilion', '39', '41', '1']);
    await page.setChecked('#s-second', true);
    await fillSweepAxis(1, ['crown', '30', '36', '3']);
    await page.fill('#s-photons', '2000');
    await page.selectOption('#s-figure', 'coloured_share');
    assert.ok(await page.isChecked('#s-fire'), 'a fire figure turns the fire trace on');
    await page.click('#sweep-submit');
    await page.waitForFunction(() => location.hash.startsWith('#/sweeps/'));
    await page.waitForFunction(() => /^succeeded/.test(document.querySelector('#sweep-progress').textContent), null,
      { timeout: JOB_TIMEOUT_MS });
    await page.waitForFunction(() => document.querySelectorAll('#sweep-chart rect.sweep-cell').length === 9);
    const chartText = await page.textContent('#sweep-chart svg');
    for (const label of ['pavilion (deg)', 'crown (deg)', '★', '%', 'Seen as colour']) assert.ok(chartText.includes(label), label);
    const fills = await page.$$eval('#sweep-chart rect.sweep-cell', (cells) => new Set(cells.map((c) => c.getAttribute('fill'))).size);
    assert.ok(fills > 1, 'the map has more than one colour');
    await page.hover('#sweep-chart rect.sweep-cell >> nth=4');
    const tip = await page.textContent('#sweep-tooltip');
    assert.match(tip, /^pavilion 40, crown 33: /);
    assert.match(tip, /mean red–blue separation \d+\.\d+° ± \d/);
    // One perceptual palette, viridis as the CLI's pictures: dark purple at the low end of the legend,
    // which is labelled at several round values.
    const low = await page.getAttribute('#sweep-chart rect.legend-step >> nth=0', 'fill');
    const [r, g, b] = low.match(/\d+/g).map(Number);
    assert.ok(r < 90 && g < 20 && b > 60, `the legend starts at ${low}, not viridis' dark purple`);
    assert.ok(await page.locator('#sweep-chart .legend-label').count() >= 3, 'the legend is labelled at several steps');
    assert.equal(await page.textContent('#sweep-chart .legend-title'), 'Seen as colour (%)', 'the legend names the figure and its unit');
    // The axes as the CLI's map (sweep_pictures.cpp's sweepMap, docs/sweeps.md): the first axis across, the second up.
    const id = await page.evaluate(() => location.hash.split('/')[2]);
    jobIds.sweepMap = id;
    const points = await (await fetch(`${baseUrl}/api/jobs/${id}/points`)).json();
    assert.deepEqual(points.axes.map((a) => a.name), ['pavilion', 'crown']);
    const titles = await page.$$eval('#sweep-chart .axis-title', (ts) => ts.map((t) => ({ text: t.textContent, turned: t.hasAttribute('transform') })));
    assert.deepEqual(titles, [{ text: 'pavilion (deg)', turned: false }, { text: 'crown (deg)', turned: true }]);
    const cell = async (at) => page.$eval(`#sweep-chart rect.sweep-cell[data-at="${at}"]`, (r) => ({ x: Number(r.getAttribute('x')), y: Number(r.getAttribute('y')) }));
    const [origin, across, up] = [await cell('0,0'), await cell('2,0'), await cell('0,2')];
    assert.ok(across.x > origin.x && across.y === origin.y, 'the first axis (pavilion) runs across');
    assert.ok(up.y < origin.y && up.x === origin.x, 'the second axis (crown) runs up');
    // The reference designs the CLI rings, from the points answer, at their proportions between the cells.
    assert.deepEqual(points.references.map((r) => [r.label, r.values.pavilion, r.values.crown]),
      [['GIA reference', 40.7, 34], ['Tolkowsky 1919', 40.75, 34.5]]);
    const rings = await page.$$eval('#sweep-chart g.sweep-reference', (gs) => gs.map((g) => ({
      label: g.querySelector('text').textContent, x: Number(g.querySelector('circle').getAttribute('cx')), y: Number(g.querySelector('circle').getAttribute('cy')) })));
    assert.deepEqual(rings.map((r) => r.label), ['GIA reference', 'Tolkowsky 1919']);
    const centre = async (at) => { const c = await cell(at); const w = (across.x - origin.x) / 2; return { x: c.x + w / 2, y: c.y + (origin.y - up.y) / 4 }; };
    const [c11, c21, c12] = [await centre('1,1'), await centre('2,1'), await centre('1,2')];
    const expectX = c11.x + 0.7 * (c21.x - c11.x);   // pavilion 40.7 between 40 and 41
    const expectY = c11.y + (1 / 3) * (c12.y - c11.y);  // crown 34 between 33 and 36
    assert.ok(Math.abs(rings[0].x - expectX) < 0.5 && Math.abs(rings[0].y - expectY) < 0.5,
      `the GIA reference ringed at ${rings[0].x},${rings[0].y}, not ${expectX},${expectY}`);
    assert.ok(chartText.includes('◯ reference designs'));
    assert.deepEqual(await chartTextsCutOff(), []);
    await shot('13-sweep-map');

    // The map of another of the sweep's figures, picked from those it measured (the job's first), as the CLI's
    // map_<figure>.png draws it: viridis from its lowest point to its highest, its name on the legend, the star
    // on its own highest point.
    const offered = await page.$$eval('#sweep-map-figure option', (os) => os.map((o) => o.value));
    assert.deepEqual([...offered].sort(), [...points.figures].sort());
    assert.equal(offered[0], 'coloured_share');
    assert.equal(await page.inputValue('#sweep-map-figure'), 'coloured_share');
    const starAt = async () => page.$eval('#sweep-chart .sweep-best', (t) => [Number(t.getAttribute('x')), Number(t.getAttribute('y')) - 7]);
    const centreOf = async (at) => page.$eval(`#sweep-chart rect.sweep-cell[data-at="${at}"]`, (r) => [
      Number(r.getAttribute('x')) + Number(r.getAttribute('width')) / 2, Number(r.getAttribute('y')) + Number(r.getAttribute('height')) / 2]);
    const valueOf = (p, key) => [p.totals, p.viewer, p.colour, p.fire].find((o) => o && key in o)[key];
    const traced = points.points.filter((p) => !p.error);
    const highestOf = (key) => traced.reduce((b, p) => (valueOf(p, key) > valueOf(b, key) ? p : b)).at.join(',');
    const lowestOf = (key) => traced.reduce((b, p) => (valueOf(p, key) < valueOf(b, key) ? p : b)).at.join(',');
    assert.deepEqual(await starAt(), await centreOf(highestOf('coloured_share')));
    // A figure whose highest point lies elsewhere.
    const other = points.figures.find((k) => highestOf(k) !== highestOf('coloured_share'));
    assert.ok(other, JSON.stringify(points.figures));
    const label = await page.textContent(`#sweep-map-figure option[value="${other}"]`);
    await page.selectOption('#sweep-map-figure', other);
    await page.waitForFunction((l) => document.querySelector('#sweep-chart .legend-title').textContent === l, label);
    assert.deepEqual(await starAt(), await centreOf(highestOf(other)));
    const fillAt = async (at) => page.getAttribute(`#sweep-chart rect.sweep-cell[data-at="${at}"]`, 'fill');
    const ends = await page.evaluate(async () => {
      const { viridis } = await import('/js/heatmap.js');
      return [viridis(0), viridis(1)];
    });
    assert.deepEqual([await fillAt(lowestOf(other)), await fillAt(highestOf(other))], ends);
    assert.ok((await page.getAttribute('#sweep-chart svg', 'aria-label')).startsWith(`${label.replace(/ \(.*\)$/, '')} over pavilion and crown`));
    assert.ok((await page.textContent('#sweep-view-title')).endsWith(`: ${label.replace(/ \(.*\)$/, '').toLowerCase()}`), 'the title names the figure mapped');
    assert.deepEqual(await chartTextsCutOff(), []);
    await shot('13b-sweep-map-figure');
  });

  test('a sweep over one axis draws several figures, each its own colour, fire among them, its legend whole', async () => {
    // Through the API: fire on, no viewer, few photons, so that it takes seconds.
    const res = await fetch(`${baseUrl}/api/jobs`, {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ mesh: 'round_brilliant', photons: 2000, threads: 2, viewer: { enabled: false }, fire: { enabled: true },
        sweep: { axes: [{ name: 'pavilion', from: 39, to: 41, step: 1 }], figure: 'weighted_return' } }),
    });
    const { id } = await res.json();
    await page.goto(`${baseUrl}/#/sweeps/${id}`);
    await page.waitForFunction(() => /^succeeded/.test(document.querySelector('#sweep-progress').textContent), null,
      { timeout: JOB_TIMEOUT_MS });
    await page.waitForFunction(() => document.querySelectorAll('#sweep-chart circle.sweep-point').length === 3);
    // The figures the sweep measured, the job's figure first and ticked.
    const points = await (await fetch(`${baseUrl}/api/jobs/${id}/points`)).json();
    const offered = await page.$$eval('#sweep-figures input', (is) => is.map((i) => ({ key: i.value, checked: i.checked })));
    assert.deepEqual(offered.map((o) => o.key).sort(), [...points.figures].sort());
    assert.deepEqual(offered[0], { key: 'weighted_return', checked: true });
    assert.equal(offered.filter((o) => o.checked).length, 1);
    assert.ok(points.figures.includes('coloured_return_weighted'));
    await page.check('#sweep-figures input[value="coloured_return_weighted"]');
    await page.check('#sweep-figures input[value="leakage"]');
    const curves = await page.$$eval('#sweep-chart polyline.sweep-line[data-figure]', (ls) => ls.map((l) => ({ key: l.dataset.figure, colour: getComputedStyle(l).stroke })));
    assert.deepEqual(curves.map((c) => c.key), ['weighted_return', 'coloured_return_weighted', 'leakage']);
    assert.equal(new Set(curves.map((c) => c.colour)).size, 3, 'each figure its own colour');
    assert.equal(await page.locator('#sweep-chart polygon.sweep-band').count(), 3, 'each with its ±1σ band');
    assert.equal(await page.locator('#sweep-chart circle.sweep-point').count(), 9);
    // Each figure named whole in the legend, broken into lines where it is long.
    const names = await page.$$eval('#sweep-chart .legend-figure', (ts) => ts.map((t) => [...t.querySelectorAll('tspan')].map((l) => l.textContent).join(' ')));
    assert.deepEqual(names, ['cosine-weighted return', 'coloured return, cosine-weighted', 'leakage']);
    assert.deepEqual(await chartTextsCutOff(), [], 'no legend text reaches past the chart');
    assert.deepEqual(await page.$$eval('#sweep-chart .axis-title', (ts) => ts.map((t) => t.textContent)), ['pavilion (deg)', 'Share (%)']);
    // The mean separation is in degrees: it waits until the shares are unticked, and the last one ticked stays.
    assert.ok(await page.isDisabled('#sweep-figures input[value="mean_separation_deg"]'));
    await shot('12b-sweep-figures');
    await page.uncheck('#sweep-figures input[value="coloured_return_weighted"]');
    await page.uncheck('#sweep-figures input[value="leakage"]');
    assert.ok(await page.isDisabled('#sweep-figures input[value="weighted_return"]'), 'the last figure ticked stays');
    assert.equal(await page.locator('#sweep-chart polyline.sweep-line[data-figure]').count(), 1);
  });

  test('a search: its progress names the round and never goes back, the star sits on the refined best', async () => {
    // Submitted through the API with a short search and no viewer, so that its rounds pass in seconds.
    const res = await fetch(`${baseUrl}/api/jobs`, {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ mesh: 'round_brilliant', photons: 1000, threads: 2, viewer: { enabled: false },
        sweep: { axes: [{ name: 'pavilion', from: 39, to: 41, step: 1 }], figure: 'weighted_return',
          maximize: 'weighted_return', refine_rounds: 2 } }),
    });
    const { id } = await res.json();
    await page.goto(`${baseUrl}/#/sweeps/${id}`);
    // The last sweep's point is not shown once the new sweep's page is drawn.
    await page.waitForFunction(() => /^Hover a point/.test(document.querySelector('#sweep-tooltip').textContent), null, { timeout: 5000 });
    const api = [];
    const shown = [];
    for (;;) {
      const job = await (await fetch(`${baseUrl}/api/jobs/${id}`)).json();
      api.push(job.progress.overall);
      const text = await page.textContent('#sweep-progress');
      if (text) shown.push(text);
      if (!['queued', 'running'].includes(job.state)) break;
      await page.waitForTimeout(50);
    }
    const overall = (list) => list.map((t) => Number((t.match(/(\d+) %$/) || [])[1])).filter(Number.isFinite);
    assert.ok(api.every((v, i) => i === 0 || v >= api[i - 1]), `the server's progress went back: ${api.join(',')}`);
    assert.ok(overall(shown).every((v, i, a) => i === 0 || v >= a[i - 1]), `the page's progress went back: ${shown.join(' | ')}`);
    assert.ok(shown.filter((t) => /^running/.test(t)).every((t) => /round [1-3] of 3: \d+ of \d+ points/.test(t)), shown.join(' | '));
    await page.waitForSelector('.sweep-best-card');
    assert.match(await page.textContent('#sweep-progress'), /^succeeded · round 3 of 3: 3 of 3 points · 100 %$/);
    const best = await (await fetch(`${baseUrl}/api/jobs/${id}/best.json`)).json();
    const card = await page.textContent('.sweep-best-card');
    assert.ok(card.includes(`${best.best.command} --out best.obj`), card);
    assert.match(card, /95 % interval \d+(\.\d+)? % to \d+(\.\d+)? %/);
    assert.match(card, new RegExp(`pavilion ${best.best.values.pavilion.toLocaleString('en-US', { maximumFractionDigits: 4 }).replace('.', '\\.')}°`));
    // The star sits at the refined pavilion, between the grid's points where it lies.
    const xs = await page.$$eval('#sweep-chart circle.sweep-point', (cs) => cs.map((c) => Number(c.getAttribute('cx'))));
    const starX = Number(await page.getAttribute('#sweep-chart text.sweep-best', 'x'));
    const expected = xs[0] + ((best.best.values.pavilion - 39) / 2) * (xs[2] - xs[0]);
    assert.ok(Math.abs(starX - expected) < 0.5, `star at ${starX}, the refined best at ${expected}`);
    assert.ok(await page.locator('#sweep-chart line.sweep-interval').count() === 1, 'the interval is drawn');
    assert.deepEqual(await chartTextsCutOff(), [], 'the legend names cosine-weighted return whole');
    // "Open as a job" traces the best design on its own, named by its proportions.
    await page.click('.sweep-best-card button[data-action="open-best"]');
    await page.waitForFunction(() => /^#\/jobs\/[0-9a-f]{32}$/.test(location.hash));
    const design = await (await fetch(`${baseUrl}/api/jobs/${await page.evaluate(() => location.hash.split('/')[2])}`)).json();
    assert.equal(design.settings.cut.pavilion, best.best.values.pavilion);
    assert.equal(design.settings.photons, best.best.photons);
    assert.match(design.name, /^round brilliant P \d/);
    await shot('14-sweep-search');
  });

  test('the sweep form holds parameters and bounds the search by constraints, each error at its field', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.selectOption('#s-shape', 'round_brilliant');
    await page.setChecked('#s-second', false);
    await page.setChecked('#s-fire', false);
    await page.setChecked('#s-maximize', false);
    await page.selectOption('#s-figure', 'weighted_return');
    await fillSweepAxis(0, ['pavilion', '39', '41', '1']);
    await page.fill('#s-photons', '1000');
    assert.equal(await page.isDisabled('#s-constraints'), true, 'constraints wait for a search');
    try {
      // A held value that is not a number is caught on the page; a parameter the shape lacks, by the server.
      await page.fill('#s-set', 'table=wide');
      await page.click('#sweep-submit');
      assert.match(await (await page.waitForSelector('[id="err-sweep.set"]:not([hidden])')).textContent(), /"table=wide" is not NAME=VALUE/);
      await page.fill('#s-set', 'sparkle=3');
      await page.click('#sweep-submit');
      await page.waitForFunction(() => /sparkle/.test(document.querySelector('[id="err-sweep.set"]').textContent)
        && !document.querySelector('[id="err-sweep.set"]').hidden);
      await page.fill('#s-set', 'table=56');
      await page.check('#s-maximize');
      assert.equal(await page.isDisabled('#s-constraints'), false);
      await page.fill('#s-constraints', 'depth<=62');
      await page.click('#sweep-submit');
      await page.waitForFunction(() => !document.querySelector('[id="err-sweep.constraints"]').hidden);
      assert.match(await page.textContent('[id="err-sweep.constraints"]'), /depth/);
      await page.fill('#s-constraints', 'total_depth <= 62, crown_height>=10');
      const answered = page.waitForResponse((r) => r.request().method() === 'POST' && r.url().endsWith('/api/jobs'));
      await page.click('#sweep-submit');
      const response = await answered;
      const sent = JSON.parse(response.request().postData());
      assert.deepEqual(sent.sweep.set, { table: 56 });
      assert.deepEqual(sent.sweep.constraints, ['total_depth<=62', 'crown_height>=10']);
      assert.equal(sent.sweep.maximize, sent.sweep.figure);
      // The page's search traces the viewer's figures at every point: on a slow machine it may be over the
      // server's --max-job-seconds. Either way the held values and constraints were accepted.
      const answer = await response.json();
      if (response.status() === 202) {
        const stored = await (await fetch(`${baseUrl}/api/jobs/${answer.id}`)).json();
        assert.deepEqual(stored.settings.sweep.set, { table: 56 });
        assert.deepEqual(stored.settings.sweep.constraints, ['total_depth<=62', 'crown_height>=10']);
        await fetch(`${baseUrl}/api/jobs/${answer.id}/cancel`, { method: 'POST' });
      } else {
        assert.equal(response.status(), 422, JSON.stringify(answer));
        assert.match(answer.detail, /s of the \d+ s a job may take/, JSON.stringify(answer));
      }
    } finally {
      // The form as the next test expects it: no held values, no search.
      await page.goto(`${baseUrl}/#/`);
      await page.fill('#s-set', '');
      await page.fill('#s-constraints', '');
      await page.setChecked('#s-maximize', false);
    }
  });

  test('a GemCad design: its cutting sheet, diagram and weight on the result page, its tiers in the sweep form', async () => {
    await page.goto(`${baseUrl}/#/`);
    const mesh = await uploadThroughPage('tests/data/brilliant.asc');
    assert.match(await page.textContent('#hint-mesh'), /GemCad design: 5 tiers to sweep/);
    await page.fill('#f-photons', '5000');
    await page.fill('#f-threads', '2');
    await page.setChecked('#f-render', false);
    const id = await submitAndGetId();
    await waitForFinished(id);
    await page.click(`#job-list li[data-id="${id}"] a[data-action="open"]`);
    await page.waitForSelector('[data-section="design"]');
    const rows = await page.$$eval('table.cutting-sheet tbody tr', (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent)));
    assert.equal(rows.length, 7);
    assert.deepEqual(rows[0].slice(0, 5), ['P1', 'pavilion', '41°', '41°', '0.668']);
    assert.equal(rows[0][6], '03-15-27-39-51-63-75-87');
    await page.locator('[data-section="design"] img').scrollIntoViewIfNeeded();  // lazy, below the heat-map
    const pics = await picturesLoaded('[data-section="design"]');
    assert.equal(pics.length, 1);
    assert.ok(pics[0].width >= 1000, `the diagram is ${pics[0].width} px wide`);
    assert.match(await page.textContent('[data-section="design"]'), /design file's own index/);
    await shot('15-design');
    await page.setViewportSize(PHONE);
    await page.waitForTimeout(200);
    assert.ok(await noHorizontalOverflow(), 'the design section fits a phone');
    await page.setViewportSize(DESKTOP);
    // The sweep form offers the design, and its tiers as the quantities to vary.
    await page.goto(`${baseUrl}/#/`);
    await page.selectOption('#s-shape', mesh);
    assert.equal(await page.inputValue('#s-name-0'), 'tier:P1');
    const quantities = await page.$$eval('#sweep-quantities option', (os) => os.map((o) => o.value));
    for (const q of ['tier:P1', 'tier:C2', 'tilt']) assert.ok(quantities.includes(q), quantities.join(' '));
    // A sweep of its main pavilion tier runs from the page, and its chart fills in.
    await fillSweepAxis(0, ['tier:P1', '40', '42', '1']);
    await page.setChecked('#s-second', false);
    await page.fill('#s-photons', '3000');
    await page.click('#sweep-submit');
    await page.waitForFunction(() => location.hash.startsWith('#/sweeps/'));
    await page.waitForFunction(() => document.querySelectorAll('#sweep-chart circle.sweep-point').length === 3, null,
      { timeout: JOB_TIMEOUT_MS, polling: 100 });
    assert.match(await page.textContent('#sweep-view-title'), /^brilliant\.asc, sweep of tier:P1/);
    assert.ok((await page.textContent('#sweep-chart svg')).includes('tier:P1 (deg)'));
  });

  test('polarisation: a uniaxial stone\'s optic axis is asked for and sent with it on, and the result says how it was traced', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#f-mesh option:not([value=""])', { state: 'attached' });
    await page.selectOption('#f-mesh', 'round_brilliant');
    await fillSmallJob({ photons: '2000', material: 'diamond' });
    await page.setChecked('#f-render', false);
    // The group label says how doubly refracting stones are traced now.
    assert.match(await page.getAttribute('#f-material optgroup:nth-of-type(2)', 'label'), /polarisation/);
    await page.selectOption('#f-polarization', 'on');
    assert.equal(await page.isHidden('#optic-axis-fields'), true, 'a diamond has no optic axis');
    await page.selectOption('#f-material', 'sapphire');
    assert.equal(await page.isVisible('#optic-axis-fields'), true, 'a uniaxial stone traced polarised has one');
    assert.deepEqual(await page.$$eval('#optic-axis-fields input:not(:disabled)', (ins) => ins.map((i) => [i.name, i.min, i.max])),
      [['optic_axis.tilt_deg', '0', '180'], ['optic_axis.azimuth_deg', '0', '360']]);
    assert.equal(await page.isHidden('#axis-rotation-field'), true, 'a uniaxial stone has one axis to place');
    // A biaxial stone: its Z axis placed by tilt and azimuth, its X turned about Z.
    await page.selectOption('#f-material', 'topaz');
    assert.equal(await page.isVisible('#axis-rotation-field'), true, 'a biaxial stone has three axes');
    await shot('15b-form-biaxial');
    await page.selectOption('#f-material', 'sapphire');
    await page.selectOption('#f-polarization', 'off');
    assert.equal(await page.isHidden('#optic-axis-fields'), true, 'unpolarised, the axis does not matter');
    assert.equal(await page.isVisible('#hint-material-split'), true, 'a uniaxial stone suggests polarisation');
    await page.selectOption('#f-polarization', 'on');
    assert.equal(await page.isHidden('#hint-material-split'), true);
    await page.fill('#f-axis-tilt', '30');
    await page.fill('#f-axis-azimuth', '45');
    await page.setChecked('#f-polariscope', true);
    await page.selectOption('#f-polariscope-lamp', 'diffuse');
    await page.setChecked('#f-doubling', true);
    await shot('15a-form-polarised');
    const posted = page.waitForRequest((r) => r.method() === 'POST' && r.url().endsWith('/api/jobs'));
    const formId = await submitAndGetId({ stay: true });
    const sent = JSON.parse((await posted).postData());
    assert.equal(sent.polarization, 'on');
    assert.deepEqual(sent.optic_axis, { tilt_deg: 30, azimuth_deg: 45 });
    assert.deepEqual(sent.polariscope, { lamp: 'diffuse' }, 'the polariscope box asks for one with its defaults and the lamp chosen');
    assert.deepEqual(sent.doubling, {}, 'the doubling box asks for one with its defaults');
    const formJob = await (await fetch(`${baseUrl}/api/jobs/${formId}`)).json();
    assert.equal(formJob.settings.polarization, 'on');
    assert.deepEqual(formJob.settings.optic_axis, { tilt_deg: 30, azimuth_deg: 45, rotation_deg: 0 }, 'the settings echo every field');
    await fetch(`${baseUrl}/api/jobs/${formId}/cancel`, { method: 'POST' });
    await page.evaluate(() => { location.hash = '#/'; });
    await page.selectOption('#f-polarization', 'off');
    await page.selectOption('#f-material', 'auto');
    await page.setChecked('#f-polariscope', false);
    await page.selectOption('#f-polariscope-lamp', 'collimated');
    await page.setChecked('#f-doubling', false);
    // The same stone without the viewer's figures (quick), its result page read.
    const res = await fetch(`${baseUrl}/api/jobs`, {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ ...sent, viewer: { enabled: false }, polariscope: { angles: 8, photons: 1000, picture_size: 48 }, doubling: { picture_size: 96 } }),
    });
    const created = await res.json();
    assert.equal(res.status, 202, JSON.stringify(created));
    const { id } = created;
    await page.evaluate((jobId) => { location.hash = `#/jobs/${jobId}`; }, id);
    await page.waitForSelector('[data-section="design"]', { timeout: JOB_TIMEOUT_MS });
    const text = await page.textContent('[data-section="design"]');
    assert.match(text, /Double refraction\s*uniaxial, birefringence 0\.008; traced: each ray splits into its ordinary and extraordinary waves \(optic axis 30° from the table's normal, toward 45° from x\)/);
    assert.match(text, /Polarisation\s*on: each photon carries its polarisation through every facet/);
    assert.doesNotMatch(await page.textContent('#view-result .lede'), /unpolarised/, 'polarised is the default, not named');
    // The polariscope's animation with its verdict, and its chart.
    await page.waitForSelector('figure.viewer-polariscope img[src$="polariscope.webp"]');
    assert.match(await page.textContent('figure.viewer-polariscope figcaption'), /^Polariscope: (dark at .* doubly refracting|stays (dark|light) as it turns)/);
    assert.ok(await page.$('figure.viewer-polariscope-chart img[src$="polariscope.png"]'));
    // The doubling's face-up view with what was measured: sapphire at 30 deg to its axis doubles a little.
    await page.waitForSelector('figure.viewer-doubling img[src$="doubling.png"]');
    assert.match(await page.textContent('figure.viewer-doubling figcaption'),
      /^Doubling: through the table 0\.0\d\d mm \(quartiles .*\), .* % of the girdle, .*′ through a 10× loupe; .* seen 30° from the optic axis$/);
    await shot('15b-result-polarised');
    // The same stone unpolarised, compared: what polarisation changes in each figure, and each job's crystal optics.
    const offRes = await fetch(`${baseUrl}/api/jobs`, {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ ...sent, polarization: 'off', viewer: { enabled: false }, polariscope: undefined, doubling: undefined }),
    });
    const offId = (await offRes.json()).id;
    assert.equal(offRes.status, 202);
    for (const jobId of [id, offId]) {  // the comparison reads finished jobs only
      const deadline = Date.now() + JOB_TIMEOUT_MS;
      while ((await (await fetch(`${baseUrl}/api/jobs/${jobId}`)).json()).state !== 'succeeded') {
        assert.ok(Date.now() < deadline, `job ${jobId} did not finish`);
        await new Promise((r) => setTimeout(r, 200));
      }
    }
    await page.evaluate((ids) => { location.hash = `#/compare/${ids}`; }, `${id},${offId}`);
    await page.waitForSelector('[data-section="crystal-compare"] table.polarization-effect', { timeout: JOB_TIMEOUT_MS });
    const effect = await page.$('[data-section="crystal-compare"] table.polarization-effect');
    assert.equal(await effect.getAttribute('data-on'), id);
    assert.equal(await effect.getAttribute('data-off'), offId);
    const rows = await effect.$$eval('tbody tr', (trs) => trs.map((tr) => tr.textContent));
    assert.equal(rows.length, 7, rows.join(' | '));
    assert.ok(rows.every((r) => /^[A-Z][^+−]*[+−][\d.]+ pts ± [\d.]+.*(real|within noise)$/.test(r)), rows.join(' | '));
    const cards = await page.$$eval('.crystal-card', (cs) => cs.map((c) => [c.dataset.id, c.querySelector('.traced-as').textContent]));
    assert.deepEqual(cards.map(([cid]) => cid).sort(), [id, offId].sort());
    assert.match(cards.find(([cid]) => cid === id)[1], /^polarised · sapphire, n 1\.7\d\d · .*splits/);
    assert.match(cards.find(([cid]) => cid === offId)[1], /^unpolarised · sapphire/);
    assert.match(await page.textContent(`.crystal-card[data-id="${id}"]`), /Polariscope: .*Doubling: through the table/);
    await shot('15c-compare-polarised-unpolarised');
  });

  test('a doubly refracting material is named on the result page with its birefringence', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    await fillSmallJob({ material: 'calcite' });
    await page.setChecked('#f-render', false);
    const id = await submitAndGetId();
    await waitForFinished(id);
    await page.click(`#job-list li[data-id="${id}"] a[data-action="open"]`);
    await page.waitForSelector('[data-section="design"]');
    const text = await page.textContent('[data-section="design"]');
    assert.match(text, /calcite, n 1\.6583/i);
    assert.match(text, /Double refraction\s*uniaxial, birefringence 0\.172; not traced: with polarization off every ray sees n_o/);
    assert.match(text, /Polarisation\s*off: each facet reflects the unpolarised Fresnel average/);
  });

  // Issue 29: a material of one's own, typed as a gem table gives it; the page shows its fields only when chosen,
  // takes the optic class from the number of indices, and the result names it.
  test('your own material is sent as custom_material and named on the result page', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    await fillSmallJob({ photons: '3000' });
    await page.setChecked('#f-render', false);
    assert.equal(await page.isHidden('#custom-material-fields'), true);
    await page.selectOption('#f-material', 'custom');
    assert.equal(await page.isVisible('#custom-material-fields'), true);
    await page.selectOption('#f-polarization', 'on');
    await page.fill('#f-custom-indices', '1.644 1.624');
    assert.equal(await page.isVisible('#optic-axis-fields'), true, 'two indices: uniaxial, with its optic axis');
    await page.fill('#f-custom-indices', '1.54');
    assert.equal(await page.isHidden('#optic-axis-fields'), true, 'one index: singly refracting');
    // Four indices are refused on the page; equal n_o and n_e by the server, each under the indices.
    await page.fill('#f-custom-indices', '1.6 1.7 1.8 1.9');
    await page.click('#submit-button');
    await page.waitForSelector('#err-custom_material:not([hidden])');
    assert.match(await page.textContent('#err-custom_material'), /one index, two \(n_o n_e\) or three/);
    await page.fill('#f-custom-indices', '1.6 1.6');
    await page.click('#submit-button');
    await page.waitForFunction(() => /equals n_o/.test(document.querySelector('#err-custom_material').textContent));
    await page.selectOption('#f-polarization', 'off');
    await page.fill('#f-custom-name', 'green tourmaline');
    await page.fill('#f-custom-indices', '1.644 1.624');
    await page.fill('#f-custom-dispersion', '0.017');
    await page.fill('#f-custom-density', '3.06');
    const id = await submitAndGetId();
    const sent = await (await fetch(`${baseUrl}/api/jobs/${id}`)).json();
    assert.deepEqual(sent.settings.custom_material,
      { name: 'green tourmaline', n_o: 1.644, n_e: 1.624, dispersion: 0.017, density_g_cm3: 3.06 });
    await waitForFinished(id);
    await page.click(`#job-list li[data-id="${id}"] a[data-action="open"]`);
    await page.waitForSelector('[data-section="design"]');
    const text = await page.textContent('[data-section="design"]');
    assert.match(text, /green tourmaline, n 1\.644/i);
    assert.match(text, /uniaxial, birefringence 0\.020?;/);
    await shot('16-own-material');
    await page.goto(`${baseUrl}/#/`);
    await page.selectOption('#f-material', 'auto');
    await page.selectOption('#f-polarization', 'on');
  });

  // Issue 29: colour by transmission fills the absorption table with the server's spectrum for the colour 1 mm
  // transmits, and the swatch beside it shows that colour back.
  test('the colour 1 mm transmits fills the absorption table, whose 1 mm swatch is that colour', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    await page.selectOption('#f-material', 'diamond');
    await page.fill('#f-absorption', '');
    await page.$eval('#f-transmitted-colour', (el) => { el.value = '#5b8fd0'; });
    await page.click('#fill-from-colour');
    await page.waitForFunction(() => document.querySelector('#f-absorption').value.split('\n').length === 41);
    assert.match(await page.inputValue('#f-absorption'), /^380 [\d.e-]+\n390 /);
    const swatch = await page.waitForSelector('#absorption-swatches .swatch-item[data-mm="1"]');
    const srgb = await swatch.getAttribute('data-srgb');
    const channels = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
    channels(srgb).forEach((c, i) => assert.ok(Math.abs(c - channels('#5b8fd0')[i]) <= 3, `${srgb} against #5b8fd0`));
    await page.fill('#f-absorption', '');
    await page.selectOption('#f-material', 'auto');
  });

  // Issue 31: an upload can be deleted from the page; while a queued or running job uses it the server refuses,
  // and the page shows the server's reason under it.
  test('an upload is deleted with its Delete button, and the server\'s refusal is shown while a job uses it', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#f-mesh option:not([value=""])', { state: 'attached' });
    const mesh = await uploadThroughPage('tests/data/cube_quads.obj');
    const item = `#upload-list li[data-mesh="${mesh}"]`;
    assert.equal(await page.isVisible(item), true, 'the upload is listed with its Delete button');
    assert.match(await page.textContent(item), /cube_quads\.obj/);
    const res = await fetch(`${baseUrl}/api/jobs`, {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ mesh, photons: 100000000, threads: 1 }),
    });
    assert.equal(res.status, 202);
    const job = await res.json();
    await page.click(`${item} button[data-action="delete-mesh"]`);
    const error = await page.waitForSelector(`${item} .field-error:not([hidden])`);
    assert.match(await error.textContent(), /Cannot delete cube_quads\.obj: a queued or running job uses this mesh/);
    await shot('11-upload-in-use');
    assert.equal((await (await fetch(`${baseUrl}/api/meshes`)).json()).uploaded.some((m) => m.mesh === mesh), true);
    await fetch(`${baseUrl}/api/jobs/${job.id}/cancel`, { method: 'POST' });
    for (let i = 0; i < 300; ++i) {
      if (!['queued', 'running'].includes((await (await fetch(`${baseUrl}/api/jobs/${job.id}`)).json()).state)) break;
      await new Promise((r) => setTimeout(r, 200));
    }
    await page.click(`${item} button[data-action="delete-mesh"]`);
    await page.waitForSelector(item, { state: 'detached' });
    assert.match(await page.textContent('#upload-status'), /Deleted cube_quads\.obj/);
    assert.equal(await page.$(`#f-mesh option[value="${mesh}"]`), null, 'the shape select no longer offers it');
    assert.equal((await (await fetch(`${baseUrl}/api/meshes`)).json()).uploaded.some((m) => m.mesh === mesh), false);
  });

  // Issue 31: the form shows the server's estimate as it is edited (asked for once typing pauses), in red with the
  // server's reason when the job is over --max-job-seconds, and such a job cannot be submitted.
  test('the form shows the job\'s estimate as it is edited, and blocks a job over the server\'s limit', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#f-mesh option[value="round_brilliant"]', { state: 'attached' });
    await page.selectOption('#f-mesh', 'round_brilliant');
    const estimates = [];
    const count = (req) => { if (req.url().endsWith('/api/jobs/estimate')) estimates.push(req.postData()); };
    page.on('request', count);
    try {
      await fillSmallJob();
      await page.waitForFunction(() => /^Estimated time here: about .* with 2 threads, most of it the /
        .test(document.querySelector('#job-estimate').textContent), null, { timeout: 15_000 });
      assert.equal(await page.getAttribute('#job-estimate', 'class'), 'job-estimate');
      assert.equal(await page.isDisabled('#submit-button'), false);
      // Typed a key at a time: one estimate once typing pauses, not one per key.
      const before = estimates.length;
      await page.fill('#f-photons', '');
      const asked = page.waitForRequest((req) => req.url().endsWith('/api/jobs/estimate')
        && JSON.parse(req.postData()).photons === 300000, { timeout: 15_000 });
      await page.type('#f-photons', '300000', { delay: 40 });
      await asked;
      await page.waitForTimeout(800);  // a second estimate for the same form would have been asked by now
      const typed = estimates.slice(before);
      assert.ok(typed.length >= 1 && typed.length <= 2, `${typed.length} estimates for 6 keys`);
      assert.equal(JSON.parse(typed.at(-1)).photons, 300000);
      const jobsBefore = (await (await fetch(`${baseUrl}/api/jobs`)).json()).total;
      // A render of 2048 x 2048 at 256 samples and a tilt series of 91 such frames: about an hour on this 2-core
      // VM, red, the server's reason (which part is costliest depends on the machine's rates), blocked.
      await page.fill('#f-width', '2048');
      await page.fill('#f-height', '2048');
      await page.fill('#f-samples', '256');
      await page.setChecked('#f-tilt-series', true);
      await page.fill('#f-tilt-max', '45');
      await page.waitForSelector('#job-estimate.over', { timeout: 15_000 });
      const over = await page.textContent('#job-estimate');
      assert.match(over, /^Too long for this server: [a-zA-Z ]+: about \d+ s of the 600 s a job may take on this server/);
      assert.match(over, /: lower (render\.\w+|tilt_series\.\w+|aset\.samples)$/);
      const colour = await page.$eval('#job-estimate', (el) => getComputedStyle(el).color);
      assert.equal(colour, await page.$eval('.job-error, .field-error', (el) => getComputedStyle(el).color));
      assert.equal(await page.isDisabled('#submit-button'), true);
      await shot('12-estimate-over');
      // Enter in a field submits the form without the button: still refused by the page.
      await page.$eval('#job-form', (form) => form.requestSubmit());
      assert.match(await page.textContent('#form-error'), /longer than this server allows/);
      assert.equal((await (await fetch(`${baseUrl}/api/jobs`)).json()).total, jobsBefore, 'nothing was submitted');
      // Back within the limit: the estimate is plain again and the job may be submitted.
      await page.fill('#f-samples', '1');
      await page.setChecked('#f-tilt-series', false);
      await page.waitForSelector('#job-estimate:not(.over)', { timeout: 15_000 });
      assert.equal(await page.isDisabled('#submit-button'), false);
    } finally {
      page.off('request', count);
    }
    await fillSmallJob();
  });

  test('absorption and colour: the form sends a spectrum, its size and the colour view, shows the table\'s errors beside it, and the result and the comparison show the colours', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#f-mesh option[value="round_brilliant"]', { state: 'attached' });
    await page.selectOption('#f-mesh', 'round_brilliant');
    await fillSmallJob({ photons: '2000', material: 'diamond' });
    await page.setChecked('#f-render', false);
    // The size and the colour view's settings start from the server's defaults.
    const defaults = await (await fetch(`${baseUrl}/api/defaults`)).json();
    assert.equal(await page.inputValue('#f-size'), String(defaults.size_mm));
    assert.equal(await page.inputValue('#f-colour-illuminant'), defaults.colour.illuminant);
    assert.equal(await page.inputValue('#f-colour-size'), String(defaults.colour.picture_size));
    assert.equal(await page.isDisabled('#f-colour-size'), true, 'the colour view\'s settings wait for its box');
    // The extraordinary column is offered for a uniaxial material only.
    assert.doesNotMatch(await page.textContent('#absorption-columns'), /extraordinary/);
    await page.selectOption('#f-material', 'tourmaline');
    assert.match(await page.textContent('#absorption-columns'), /α ordinary \(1\/mm\), α extraordinary/);
    // A table that does not read is named beside it, by its line, once it is left.
    await page.fill('#f-absorption', '400 0.3\n550 abc');
    await page.press('#f-absorption', 'Tab');
    assert.match(await page.textContent('#err-absorption'), /^Line 2: "abc" is not a number$/);
    assert.equal(await page.getAttribute('#f-absorption', 'aria-invalid'), 'true');
    // A pleochroic table: what 1 mm and the stone's 6.5 mm transmit, each wave, darker the longer the path.
    await page.fill('#f-absorption', '400 0.30 0.05\n550 0.05 0.05\n700 0.15 0.40');
    await page.press('#f-absorption', 'Tab');
    assert.equal(await page.isHidden('#err-absorption'), true);
    await page.waitForSelector('#absorption-swatches [data-mm="6.5"][data-wave="e"]');
    const swatches = await page.$$eval('#absorption-swatches .swatch-item', (items) => items.map((i) => [i.dataset.mm, i.dataset.wave, i.dataset.srgb]));
    assert.deepEqual(swatches.map(([mm, wave]) => `${mm} ${wave}`), ['1 o', '1 e', '6.5 o', '6.5 e']);
    const lightness = (hex) => [1, 3, 5].reduce((s, k) => s + parseInt(hex.slice(k, k + 2), 16), 0);
    for (const wave of ['o', 'e']) {
      const [one, size] = ['1', '6.5'].map((mm) => swatches.find(([m, w]) => m === mm && w === wave)[2]);
      assert.ok(lightness(size) < lightness(one), `${wave}: ${size} at 6.5 mm is not darker than ${one} at 1 mm`);
    }
    assert.notEqual(swatches[2][2], swatches[3][2], 'the two waves transmit different colours');
    // Three rays (X, Y, Z) need a biaxial material: refused beside the table for tourmaline, a swatch each for peridot.
    await page.fill('#f-absorption', '400 0.30 0.05 0.01\n550 0.05 0.05 0.30\n700 0.15 0.40 0.02');
    await page.press('#f-absorption', 'Tab');
    assert.match(await page.textContent('#err-absorption'), /X, Y and Z rays\) need a biaxial material/);
    await page.selectOption('#f-material', 'peridot');
    assert.match(await page.textContent('#absorption-columns'), /X, Y and Z rays/);
    await page.waitForSelector('#absorption-swatches [data-mm="6.5"][data-wave="Z"]');
    assert.equal(await page.isHidden('#err-absorption'), true);
    const rays = await page.$$eval('#absorption-swatches .swatch-item', (items) => items.map((i) => `${i.dataset.mm} ${i.dataset.wave}`));
    assert.deepEqual(rays, ['1 X', '1 Y', '1 Z', '6.5 X', '6.5 Y', '6.5 Z']);
    // A flat (grey) spectrum transmits a neutral grey under D65: exp(-0.5) = 0.607 of the light, sRGB 0.607 encoded.
    await page.selectOption('#f-material', 'diamond');
    await page.fill('#f-absorption', '400 0.5\n700 0.5');
    await page.waitForFunction(() => document.querySelector('#absorption-swatches [data-mm="1"]')?.dataset.wave === 'both');
    const grey = await page.getAttribute('#absorption-swatches [data-mm="1"]', 'data-srgb');
    const channels = [1, 3, 5].map((k) => parseInt(grey.slice(k, k + 2), 16));
    const expected = Math.round(255 * (1.055 * Math.exp(-0.5) ** (1 / 2.4) - 0.055));
    for (const c of channels) assert.ok(Math.abs(c - expected) <= 1, `${grey} is not the grey ${expected}`);
    await shot('16a-form-absorption');
    // The server's refusal of a table (a wavelength below its range) stands beside the table.
    const jobsBefore = (await (await fetch(`${baseUrl}/api/jobs`)).json()).total;
    await page.fill('#f-absorption', '50 0.3\n550 0.05\n700 0.15');
    await page.click('#submit-button');
    await page.waitForSelector('#err-absorption:not([hidden])');
    assert.match(await page.textContent('#err-absorption'), /absorption\.wavelength_nm/);
    assert.equal(await page.isHidden('#form-error'), true);
    assert.equal((await (await fetch(`${baseUrl}/api/jobs`)).json()).total, jobsBefore, 'nothing was submitted');
    // A good table and the colour view: both sent.
    await page.fill('#f-absorption', '# a pink stone\n400 0.30\n550 0.05\n700 0.15');
    await page.fill('#f-size', '8');
    await page.setChecked('#f-colour', true);
    await page.fill('#f-colour-size', '48');
    await page.fill('#f-colour-samples', '1');
    await page.fill('#f-colour-wavelengths', '8');
    await page.selectOption('#f-colour-illuminant', 'A');
    const posted = page.waitForRequest((r) => r.method() === 'POST' && r.url().endsWith('/api/jobs'));
    const formId = await submitAndGetId({ stay: true });
    const sent = JSON.parse((await posted).postData());
    assert.deepEqual(sent.absorption, { wavelength_nm: [400, 550, 700], ordinary_per_mm: [0.3, 0.05, 0.15] });
    assert.equal(sent.size_mm, 8);
    assert.deepEqual(sent.colour, { ...defaults.colour, illuminant: 'A', picture_size: 48, samples: 1, wavelengths: 8 });
    await fetch(`${baseUrl}/api/jobs/${formId}/cancel`, { method: 'POST' });
    await page.evaluate(() => { location.hash = '#/'; });
    await page.setChecked('#f-colour', false);
    await page.fill('#f-absorption', '');
    // The same stone without the viewer's figures (quick), and a clear one, read on their pages and compared.
    const post = async (job) => {
      const res = await fetch(`${baseUrl}/api/jobs`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(job) });
      const body = await res.json();
      assert.equal(res.status, 202, JSON.stringify(body));
      return body.id;
    };
    const quick = { ...sent, viewer: { enabled: false }, colour: { ...sent.colour, illuminant: 'D65' } };
    const id = await post(quick);
    const clearId = await post({ ...quick, absorption: null });
    for (const jobId of [id, clearId]) {
      const deadline = Date.now() + JOB_TIMEOUT_MS;
      while ((await (await fetch(`${baseUrl}/api/jobs/${jobId}`)).json()).state !== 'succeeded') {
        assert.ok(Date.now() < deadline, `job ${jobId} did not finish`);
        await new Promise((r) => setTimeout(r, 200));
      }
    }
    const stats = await (await fetch(`${baseUrl}/api/jobs/${id}/stats`)).json();
    await page.evaluate((jobId) => { location.hash = `#/jobs/${jobId}`; }, id);
    await page.waitForSelector('[data-section="colour"] img[src$="colour.png"]');
    await page.$eval('[data-section="colour"]', (el) => el.scrollIntoView());
    await picturesLoaded('[data-section="colour"]');
    const [picture] = await shownPictures('[data-section="colour"]');
    assert.ok(picture.width >= 400, `colour.png shown ${Math.round(picture.width)} px wide`);
    assert.equal(picture.link, picture.src, 'colour.png opens at full size');
    const c = stats.colour;
    const rgb = `rgb(${[1, 3, 5].map((k) => parseInt(c.mean_colour.srgb.slice(k, k + 2), 16)).join(', ')})`;
    assert.equal(await page.$eval('[data-section="colour"] .colour-mean .colour-swatch', (el) => getComputedStyle(el).backgroundColor), rgb);
    assert.match(await page.textContent('[data-section="colour"] .colour-mean'), new RegExp(`${c.mean_colour.srgb}: L\\* ${c.mean_colour.L.toFixed(1)}`));
    assert.match(await page.textContent('[data-section="colour"] .hint'), /at 8 mm under a dome of CIE illuminant D65/);
    for (const key of ['L', 'a', 'b', 'chroma']) {
      const [mean, spread] = await page.$$eval(`[data-section="colour"] tr[data-lab="${key}"] td`, (tds) => tds.map((td) => td.textContent));
      assert.match(mean, /^-?\d+(\.\d+)? ± \d+(\.\d+)?$/, `${key} mean`);
      assert.ok(Math.abs(parseFloat(mean) - c[key].mean) <= 0.5, `${key}: ${mean} against ${c[key].mean}`);
      assert.match(spread, /^\d+(\.\d+)? ± \d+(\.\d+)?$/, `${key} spread`);
    }
    for (const key of ['windowed', 'extinct', 'saturated']) {
      assert.match(await page.textContent(`[data-section="colour"] tr[data-share="${key}"] td`), /^\d+(\.\d+)? % ± \d+(\.\d+)?$/, key);
    }
    // The absorbed share among the figures, as the statistics say it.
    assert.equal(await page.textContent('[data-figure="absorbed_share"] dt'), 'Absorbed');
    const absorbed = await page.textContent('[data-figure="absorbed_share"] .figure-value');
    assert.ok(Math.abs(parseFloat(absorbed) - 100 * stats.totals.absorbed_share) < 0.1, `${absorbed} against ${stats.totals.absorbed_share}`);
    assert.match(await page.textContent('[data-figure="absorbed_share"] .figure-err'), /^± [\d.]+ pts$/);
    await shot('16b-result-colour');
    // A clear stone has no absorbed figure, but its colour all the same.
    await page.evaluate((jobId) => { location.hash = `#/jobs/${jobId}`; }, clearId);
    await page.waitForSelector('[data-section="colour"] .colour-mean');
    assert.equal(await page.$('[data-figure="absorbed_share"]'), null, 'a clear stone absorbs nothing');
    // Compared: both colours side by side, the clear stone named so in the absorbed row.
    await page.evaluate((ids) => { location.hash = `#/compare/${ids}`; }, `${id},${clearId}`);
    await page.waitForSelector('[data-section="colour-compare"] table.colour-compare-table');
    const cell = (row, jobId) => page.textContent(`[data-section="colour-compare"] tr[data-colour-row="${row}"] td[data-id="${jobId}"]`);
    const clearStats = await (await fetch(`${baseUrl}/api/jobs/${clearId}/stats`)).json();
    for (const [jobId, s] of [[id, stats], [clearId, clearStats]]) {
      assert.equal(await cell('mean', jobId), s.colour.mean_colour.srgb);
      assert.ok(await page.$(`[data-section="colour-compare"] tr[data-colour-row="mean"] td[data-id="${jobId}"] .colour-swatch`));
      for (const row of ['L', 'a', 'b', 'chroma', 'L-spread']) assert.match(await cell(row, jobId), /^-?[\d.]+ ± [\d.]+$/, row);
      for (const row of ['windowed', 'extinct', 'saturated']) assert.match(await cell(row, jobId), /^[\d.]+ % ± [\d.]+$/, row);
    }
    assert.match(await cell('absorbed', id), /^[\d.]+ % ± [\d.]+$/);
    assert.equal(await cell('absorbed', clearId), 'clear stone');
    assert.ok(stats.colour.L.mean < clearStats.colour.L.mean, 'the absorbing stone is the darker');
    assert.equal((await page.$$('[data-section="colour-compare"] .colour-card img[src$="colour.png"]')).length, 2);
    await shot('16c-compare-colour');
  });

  // Issue 29: a corundum coloured by its chromophores (docs/optics.md, "Corundum by its chromophores").
  test('corundum takes its Cr and Fe-Ti concentrations: two fields for corundum only, sent as corundum_ppma, refused beside a table', async () => {
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#f-mesh option[value="round_brilliant"]', { state: 'attached' });
    await page.selectOption('#f-mesh', 'round_brilliant');
    await fillSmallJob({ photons: '2000', material: 'diamond' });
    await page.setChecked('#f-render', false);
    assert.equal(await page.isHidden('#corundum-fields'), true, 'diamond is not corundum');
    for (const material of ['sapphire', 'ruby', 'blue_sapphire']) {
      await page.selectOption('#f-material', material);
      assert.equal(await page.isVisible('#corundum-fields'), true, `${material} is corundum`);
    }
    await page.selectOption('#f-material', 'emerald');
    assert.equal(await page.isHidden('#corundum-fields'), true, 'emerald is not corundum');
    await page.selectOption('#f-material', 'ruby');
    await page.fill('#f-absorption', '');
    await page.fill('#f-corundum-cr', '300');
    await page.fill('#f-corundum-fe-ti', '');
    await page.waitForFunction(() => /chromophores/.test(document.querySelector('#absorption-swatches').textContent));
    await shot('16b-form-corundum');
    // Beside a table: the server refuses it, naming the table.
    await page.fill('#f-absorption', '400 0.3\n700 0.1');
    await page.click('#submit-button');
    await page.waitForSelector('#err-absorption:not([hidden])');
    assert.match(await page.textContent('#err-absorption'), /cannot go with absorption\.corundum_ppma/);
    // Alone: sent as the concentrations given.
    await page.fill('#f-absorption', '');
    const posted = page.waitForRequest((r) => r.method() === 'POST' && r.url().endsWith('/api/jobs'));
    const id = await submitAndGetId({ stay: true });
    assert.deepEqual(JSON.parse((await posted).postData()).absorption, { corundum_ppma: { cr: 300 } });
    await fetch(`${baseUrl}/api/jobs/${id}/cancel`, { method: 'POST' });
    // A quick one without the viewer: its result page says what coloured the stone, not the ruby's spectrum.
    const res = await fetch(`${baseUrl}/api/jobs`, {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ mesh: 'round_brilliant', photons: 2000, threads: 2, material: 'ruby', viewer: { enabled: false }, absorption: { corundum_ppma: { cr: 300 } } }),
    });
    const created = await res.json();
    assert.equal(res.status, 202, JSON.stringify(created));
    await page.evaluate((jobId) => { location.hash = `#/jobs/${jobId}`; }, created.id);
    await page.waitForSelector('[data-section="design"]', { timeout: JOB_TIMEOUT_MS });
    assert.match(await page.textContent('[data-section="design"]'), /Coloured by\s*Cr³⁺ 300 ppma \(GIA's absorption cross sections\)/);
    await page.evaluate(() => { location.hash = '#/'; });
    await page.fill('#f-corundum-cr', '');
    await page.selectOption('#f-material', 'diamond');
  });

  // Issue 30: the result, compare and sweep pages at 1400 x 1000 read without zooming: no text on them under
  // 11 px (the pictures the server draws are checked for their width elsewhere).
  test('the result, compare and sweep pages at 1400 x 1000 show no text under 11 px', async () => {
    await page.setViewportSize({ width: 1400, height: 1000 });
    try {
      const pages = [
        ['20-result-1400', `#/jobs/${jobIds.viewer}`, '#view-result', '#result-body .figures'],
        ['21-compare-1400', `#/compare/${jobIds.viewer},${jobIds.brilliant}`, '#view-compare', '[data-section="viewer-compare"]'],
        ['22-compare-fire-1400', `#/compare/${jobIds.fire.join(',')}`, '#view-compare', '[data-section="fire-compare"]'],
        ['23-sweep-1400', `#/sweeps/${jobIds.sweepMap}`, '#view-sweep', '#sweep-chart rect.sweep-cell'],
      ];
      const small = {};
      for (const [name, hash, scope, ready] of pages) {
        await page.goto(`${baseUrl}/${hash}`);
        await page.waitForSelector(ready);
        await scrollThrough();
        await page.waitForTimeout(300);
        await shot(name);
        if (name === '21-compare-1400') await assertLegiblePictures('.compare-card .pictures');
        const found = await smallTexts(scope);
        // Grouped by where and size, with a sample, to read in the failure.
        const groups = {};
        for (const t of found) groups[`${t.where} ${t.px}px`] = `${t.text} (×${((groups[`${t.where} ${t.px}px`] || '').match(/×(\d+)/) || [0, 0])[1] * 1 + 1})`;
        if (found.length) small[name] = groups;
      }
      assert.deepEqual(small, {}, JSON.stringify(small, null, 1));
    } finally {
      await page.setViewportSize(DESKTOP);
    }
  });

  test('the home page fits a phone', async () => {
    await page.setViewportSize(PHONE);
    await page.goto(`${baseUrl}/#/`);
    await page.waitForSelector('#job-list li');
    await shot('10-home-phone');
    assert.ok(await noHorizontalOverflow(), 'the home page fits a phone');
    await page.setViewportSize(DESKTOP);
  });

  test('no request left the server and the page logged no errors', () => {
    assert.deepEqual(foreignRequests, []);
    assert.deepEqual(pageErrors, []);
  });
});

// Issue 31, item 1: a server started with --token-file answers /api only with its token. The page asks for it
// once, on the first 401, keeps it for the tab and sends it on every request: the lists, a job, its pictures.
describe('a server that asks for a token', { timeout: 600_000 }, () => {
  const TOKEN = 'page-test-token-0123456789';
  const prompts = [];
  let tokenServer;
  let tokenDir;
  let context;
  let tab;

  before(async () => {
    tokenDir = fs.mkdtempSync(path.join(os.tmpdir(), 'facetlight-token-'));
    fs.writeFileSync(path.join(tokenDir, 'token'), `${TOKEN}\n`);
    tokenServer = await startServer(['--token-file', path.join(tokenDir, 'token')]);
    context = await chromium.launchPersistentContext(path.join(tokenDir, 'chromium'), {
      executablePath: chromiumPath,
      headless: true,
      viewport: DESKTOP,
      args: CHROMIUM_ARGS,
    });
    tab = context.pages()[0] || await context.newPage();
    tab.setDefaultTimeout(30_000);
    tab.on('dialog', (dialog) => {
      prompts.push(dialog.message());
      dialog.accept(TOKEN);
    });
    await tab.goto(`${tokenServer.url}/`);
  });

  after(async () => {
    if (context) await context.close();
    if (tokenServer) {
      tokenServer.process.kill('SIGKILL');
      fs.rmSync(tokenServer.dataDir, { recursive: true, force: true });
    }
    if (tokenDir) fs.rmSync(tokenDir, { recursive: true, force: true });
  });

  test('asks for the token once, then lists the shapes, runs a job and shows its pictures', async () => {
    assert.equal((await fetch(`${tokenServer.url}/api/meshes`)).status, 401);
    await tab.waitForSelector('#f-mesh option:not([value=""])', { state: 'attached' });
    assert.equal(prompts.length, 1, `asked ${prompts.length} times: ${prompts.join(' | ')}`);
    assert.match(prompts[0], /token/);
    assert.equal(await tab.evaluate(() => sessionStorage.getItem('facetlight-token')), TOKEN);
    await fillSmallJob({}, tab);
    await tab.click('#submit-button');
    await tab.waitForSelector('#result-body .figures', { timeout: JOB_TIMEOUT_MS });
    const pics = await picturesLoaded('#result-body .pictures', tab);
    assert.equal(pics.length, 3);
    for (const p of pics) {
      assert.ok(p.width > 0, `${p.src} did not load`);
      assert.match(p.src, /^blob:/, 'fetched with the token');
    }
    await tab.reload();
    await tab.waitForSelector('#f-mesh option:not([value=""])', { state: 'attached' });
    assert.equal(prompts.length, 1, 'asked again after a reload in the same tab');
  });
});
