// The run-through of `morphogen breed`'s page in Debian's Chromium, driven by
// playwright-core (tools/browser): the real command, the real server, the real
// page. Load (with each plant's tips, limbs and first fork, and one opened
// large), choose two plants, breed, undo/redo (buttons and keys), lineage,
// export (and a refused export), reload, two tabs on one session, explore
// (to the end, and stopped), Ctrl-C and --resume.
//
//   node tests/breed/page_test.mjs MORPHOGEN_EXE
//   MORPHOGEN_BREED_SCREENSHOT=docs/images/breed.png node tests/breed/page_test.mjs MORPHOGEN_EXE
//
// Exit 0: passed; 1: failed; 77: skipped (no chromium or no playwright-core).
import { spawn } from 'node:child_process';
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const CHROMIUM = process.env.MORPHOGEN_CHROMIUM || '/usr/bin/chromium';
const exe = process.argv[2];
if (!exe) {
  console.error('usage: node page_test.mjs MORPHOGEN_EXE');
  process.exit(2);
}
let chromium;
try {
  ({ chromium } = createRequire(path.join(repo, 'tools/browser/package.json'))('playwright-core'));
} catch (e) {
  console.log('SKIP: playwright-core is not installed (cd tools/browser && npm ci)');
  process.exit(77);
}
if (!fs.existsSync(CHROMIUM)) {
  console.log(`SKIP: no chromium at ${CHROMIUM} (Debian package chromium)`);
  process.exit(77);
}

function check(ok, what) {
  if (!ok) throw new Error('FAILED: ' + what);
  console.log('ok - ' + what);
}
const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
const sorted = (a) => [...a].sort();

// ---- the server ---------------------------------------------------------

// Starts `morphogen breed ARGS`; resolves with the address on its first line.
function startServer(args) {
  const proc = spawn(exe, ['breed', '--no-browser', '--port', '0', ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
  let stdout = '', stderr = '';
  proc.stderr.on('data', (d) => { stderr += d; });
  const address = new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`no address from morphogen breed in 60 s; stderr:\n${stderr}`)), 60000);
    proc.stdout.on('data', (d) => {
      stdout += d;
      const newline = stdout.indexOf('\n');
      if (newline >= 0) { clearTimeout(timer); resolve(stdout.slice(0, newline).trim()); }
    });
    proc.on('exit', (code) => { clearTimeout(timer); reject(new Error(`morphogen breed exited ${code} before its address; stderr:\n${stderr}`)); });
  });
  const exited = new Promise((resolve) => proc.on('exit', (code, signal) => resolve({ code, signal })));
  return { proc, address, exited, stderr: () => stderr };
}

function parseAddress(line) {
  const m = /^http:\/\/127\.0\.0\.1:(\d+)\/\?token=([0-9a-f]{32})$/.exec(line);
  check(m !== null, `the first line of stdout is the page's address (${line})`);
  return { url: line, base: `http://127.0.0.1:${m[1]}`, token: m[2] };
}

async function getState(server) {
  const r = await fetch(server.base + '/api/state', { headers: { Authorization: 'Bearer ' + server.token } });
  if (!r.ok) throw new Error(`GET /api/state answered ${r.status}`);
  return r.json();
}

// ---- the page -----------------------------------------------------------

const gridIds = (page) => page.$$eval('#grid .cell', (cells) => cells.map((c) => c.dataset.id));
const generation = async (page) => Number(await page.textContent('#generation'));

// Waits until the grid shows 9-16 plants whose meshes have loaded, and the
// first one has been drawn (pixels unlike the background in its rectangle of
// the shared WebGL canvas).
async function gridReady(page) {
  await page.waitForFunction(() => {
    const cells = [...document.querySelectorAll('#grid .cell')];
    return document.body.dataset.ready === '1' && cells.length >= 9 && cells.length <= 16 &&
      cells.every((c) => c.dataset.loaded === '1');
  }, null, { timeout: 60000 });
  await page.waitForFunction(`(${firstCellPixels})().plant > 30`, null, { timeout: 30000 });
}

// What the shared WebGL canvas shows in the first cell's rectangle: how many
// pixels are unlike the cell's background, and a checksum of them all.
function firstCellPixels() {
  const view = document.querySelector('#grid .cell .view').getBoundingClientRect();
  const canvas = document.getElementById('views');
  const scale = canvas.width / canvas.clientWidth;
  const copy = document.createElement('canvas');
  copy.width = Math.floor(view.width * scale);
  copy.height = Math.floor(view.height * scale);
  const ctx = copy.getContext('2d');
  ctx.drawImage(canvas, view.left * scale, view.top * scale, copy.width, copy.height, 0, 0, copy.width, copy.height);
  const px = ctx.getImageData(0, 0, copy.width, copy.height).data;
  let plant = 0, sum = 0;
  for (let i = 0; i < px.length; i += 4) {
    const off = Math.abs(px[i] - 0xf1) + Math.abs(px[i + 1] - 0xf4) + Math.abs(px[i + 2] - 0xee);
    const offSelected = Math.abs(px[i] - 0xff) + Math.abs(px[i + 1] - 0xf3) + Math.abs(px[i + 2] - 0xc4);
    if (px[i + 3] > 0 && off > 60 && offSelected > 60) plant++;
    sum = (sum * 31 + px[i] + 7 * px[i + 1] + 13 * px[i + 2]) % 1000000007;
  }
  return { plant, sum };
}

// What a WebGL canvas shows: `plant`, the pixels unlike the views'
// background (0xf1f4ee); `bark`, those in bark's hues (red to orange, 0-50
// degrees, clearly saturated): the colours from growth history put them at
// the plants' feet; the old uniform green (0x6f9a4c) under the page's lights
// gives none (its darkest, ground-lit side is still about 70 degrees).
function canvasPixels(id) {
  const canvas = document.getElementById(id);
  const copy = document.createElement('canvas');
  copy.width = canvas.width;
  copy.height = canvas.height;
  const ctx = copy.getContext('2d');
  ctx.drawImage(canvas, 0, 0);
  const px = ctx.getImageData(0, 0, copy.width, copy.height).data;
  let bark = 0, plant = 0;
  for (let i = 0; i < px.length; i += 4) {
    const r = px[i], g = px[i + 1], b = px[i + 2];
    if (px[i + 3] > 0 && Math.abs(r - 0xf1) + Math.abs(g - 0xf4) + Math.abs(b - 0xee) > 60) plant++;
    const max = Math.max(r, g, b), min = Math.min(r, g, b);
    if (px[i + 3] === 0 || max - min < 12 || max !== r) continue;
    const hue = 60 * ((g - b) / (max - min));  // red is the largest: -60 .. 60 degrees
    if (hue >= 0 && hue <= 50) bark++;
  }
  return { bark, plant };
}

async function waitGeneration(page, g, timeout = 30000) {
  await page.waitForFunction((want) => Number(document.getElementById('generation').textContent) === want, g, { timeout });
}

async function select(page, indices) {
  for (const i of indices) await page.click(`#grid .cell:nth-child(${i + 1})`);
}

async function setValue(page, selector, value) {
  await page.$eval(selector, (e, v) => { e.value = v; e.dispatchEvent(new Event('input', { bubbles: true })); }, value);
}

// Each cell's line of tips, limbs and first fork says what the API's measures say.
async function checkArchitecture(page, address) {
  const lines = await page.$$eval('#grid .cell .architecture', (ps) => ps.map((p) => p.textContent));
  const want = (await getState(address)).grid.map((p) => {
    const m = p.measures;
    const fork = m.first_fork >= 1 ? 'none' : Math.round(m.first_fork * 100) + ' %';
    return `tips ${m.tips} · limbs ${m.limbs} · first fork ${fork}`;
  });
  check(same(lines, want), `load: tips, limbs and first fork under each plant, as the API gives them (${lines[0]})`);
}

// The large view: a dialog whose own canvas draws the plant (pixels unlike
// its background), with its measures; it closes, and choosing is unchanged.
async function checkLarge(page, id) {
  await page.click('#grid .cell:first-child .open-large');
  await page.waitForSelector('#large[open]');
  check(await page.textContent('#large-title') === 'plant ' + id, 'large: the button opens the plant in a dialog');
  await page.waitForFunction((want) => document.getElementById('large-view').dataset.drawn === want, id, { timeout: 30000 });
  const large = await page.evaluate(`(${canvasPixels})('large-view')`);
  large.width = await page.$eval('#large-view', (c) => c.clientWidth);
  large.cell = await page.$eval('#grid .cell .view', (v) => v.clientWidth);
  check(large.width > 2 * large.cell && large.plant > 2000,
    `large: drawn ${large.width} pixels wide (a cell: ${large.cell}), ${large.plant} pixels of plant`);
  check(/^tips \d+ · limbs \d+ · first fork/.test(await page.textContent('#large-measures')), 'large: with its tips, limbs and first fork');
  await page.click('#close-large');
  check(!(await page.$eval('#large', (d) => d.open)), 'large: closes');
  check(await page.locator('#grid .cell.selected').count() === 0, 'large: opening a plant does not choose it');
}

// ---- the run-through ------------------------------------------------------

async function runThrough(browser, tmp) {
  const dir = path.join(tmp, 'session');
  let server = startServer(['--out', dir]);
  let address = parseAddress(await server.address);
  const errors = [];
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const watch = (page, name) => {
    page.on('pageerror', (e) => errors.push(`${name}: ${e.message}`));
    page.on('console', (m) => {
      if (m.type() === 'error' && !/Failed to load resource/.test(m.text())) errors.push(`${name}: ${m.text()}`);
    });
  };
  try {
    const page = await context.newPage();
    watch(page, 'tab 1');
    await page.goto(address.url);
    await gridReady(page);
    const first = await gridIds(page);
    const g0 = await generation(page);
    check(first.length >= 9 && first.length <= 16, `load: ${first.length} plants turn in 3-D`);
    check(same(first, (await getState(address)).grid.map((p) => p.id)), 'load: the page shows the API\'s grid');
    check(await page.locator('#grid .cell .fitness').first().textContent() !== '', 'load: fitness under each plant');
    check(await page.locator('#grid .cell:first-child .measures dt').count() > 0, 'load: measures under each plant');
    await checkArchitecture(page, address);
    await checkLarge(page, first[0]);
    const { bark } = await page.evaluate(`(${canvasPixels})('views')`);
    check(bark > 200, `load: the plants are drawn in their colours from growth history (${bark} pixels in bark's hues)`);

    // Choose two, breed with strength 0.3.
    await select(page, [1, 4]);
    const parents = [first[1], first[4]];
    check(same(await page.$$eval('#grid .cell.selected', (c) => c.map((e) => e.dataset.id)), parents), 'choose: two plants are marked');
    check(/cross/.test(await page.textContent('#breed')), 'choose: with two, the button says it crosses them');
    await setValue(page, '#strength', '0.3');
    check(await page.textContent('#strength-value') === '0.30', 'choose: the strength slider shows 0.30');
    await page.click('#breed');
    await waitGeneration(page, g0 + 1);
    await gridReady(page);
    const bred = await gridIds(page);
    check(same(sorted(bred.slice(0, 2)), sorted(parents)), 'breed: the parents are kept, in the first cells');
    check(bred.slice(2).every((id) => !first.includes(id)), 'breed: the other cells are new plants');
    check(await page.locator('#grid .cell .badge').count() === 2, 'breed: the parents are marked');
    const afterBreed = await getState(address);
    check(same(sorted(afterBreed.chosen), sorted(parents)), 'breed: the server recorded the two parents');
    const log = fs.readFileSync(path.join(dir, 'choices.jsonl'), 'utf8');
    check(parents.every((id) => log.includes(id)) && log.includes('0.3'), 'breed: choices.jsonl has the parents and the strength');

    // Undo and redo, by buttons and keys.
    await page.click('#undo');
    await waitGeneration(page, g0);
    check(same(await gridIds(page), first), 'undo: the grid is back');
    await page.keyboard.press('Control+Shift+Z');
    await waitGeneration(page, g0 + 1);
    check(same(await gridIds(page), bred), 'Ctrl-Shift-Z redoes');
    await page.keyboard.press('Control+Z');
    await waitGeneration(page, g0);
    check(same(await gridIds(page), first), 'Ctrl-Z undoes');
    await page.click('#redo');
    await waitGeneration(page, g0 + 1);
    check(same(await gridIds(page), bred), 'redo: the bred grid is back');

    // A second choice: one child, mutated.
    await gridReady(page);
    await select(page, [2]);
    await page.click('#breed');
    await waitGeneration(page, g0 + 2);
    await gridReady(page);
    check((await gridIds(page))[0] === bred[2], 'breed one: the parent is kept in the first cell');

    // The lineage: the three chosen plants, the child below its two parents.
    await page.click('#show-lineage');
    await page.waitForSelector('#lineage[open] .tree .node');
    await page.waitForFunction(() => [...document.querySelectorAll('#lineage .node img')].every((i) => i.complete && i.naturalWidth > 0),
      null, { timeout: 30000 });
    const nodes = await page.$$eval('#lineage .node', (ns) => ns.map((n) => ({ id: n.dataset.id, chosen: n.classList.contains('chosen'), top: n.offsetTop })));
    const chosen = nodes.filter((n) => n.chosen).map((n) => n.id);
    check(sorted(chosen).join() === sorted([...parents, bred[2]]).join(), 'lineage: the three chosen plants, thumbnails loaded');
    const top = (id) => nodes.find((n) => n.id === id).top;
    check(parents.every((p) => top(p) < top(bred[2])), 'lineage: the child sits below its parents');
    check(await page.locator('#lineage svg path').count() >= 2, 'lineage: lines join the child to its two parents');
    await page.click('#close-lineage');
    check(!(await page.$eval('#lineage', (d) => d.open)), 'lineage: closes');

    // Export: a refused request says why; then the files.
    const grid2 = await gridIds(page);
    await select(page, [3]);
    await page.click('.export-options summary');
    await page.fill('#export-height', '-1');
    await page.click('#export');
    await page.waitForSelector('#message.error');
    const refusal = await page.textContent('#message');
    check(/refused \(4\d\d\)/.test(refusal), `export: a bad height is refused with the server's sentence (${refusal})`);
    await page.fill('#export-height', '2');
    await page.click('#export');
    await page.waitForSelector('#export-result:not([hidden]) code');
    check(await page.isHidden('#message'), 'export: the error message goes once a request succeeds');
    const written = await page.$$eval('#export-result code', (cs) => Object.fromEntries(cs.map((c) => [c.dataset.kind, c.textContent])));
    check(written.genome && written.mesh, `export: the page shows the written paths (${Object.values(written).join(', ')})`);
    const glb = fs.readFileSync(path.join(dir, written.mesh));
    check(glb.subarray(0, 4).toString() === 'glTF', `export: ${written.mesh} is a GLB`);
    JSON.parse(fs.readFileSync(path.join(dir, written.genome), 'utf8'));
    check(written.genome.includes(grid2[3]), `export: ${written.genome} is the chosen plant's genome (JSON)`);

    // Reload: the state is the server's.
    const g2 = await generation(page);
    await page.reload();
    await gridReady(page);
    check(same(await gridIds(page), grid2) && (await generation(page)) === g2, 'reload: the same grid and generation');

    // Two tabs on one session: a breed in one shows in the other.
    const tab2 = await context.newPage();
    watch(tab2, 'tab 2');
    await tab2.goto(address.url);
    await gridReady(tab2);
    check(same(await gridIds(tab2), grid2), 'two tabs: the second shows the same grid');
    await select(tab2, [5]);
    await tab2.click('#breed');
    await waitGeneration(tab2, g2 + 1);
    await waitGeneration(page, g2 + 1, 15000);
    await gridReady(page);
    check(same(await gridIds(page), await gridIds(tab2)), 'two tabs: the first tab shows the breed made in the second');
    await page.keyboard.press('Control+Z');
    await waitGeneration(tab2, g2, 15000);
    check(same(await gridIds(tab2), grid2), 'two tabs: an undo in the first shows in the second');
    await tab2.close();

    // Explore around one plant: a short search that runs to its end ...
    await select(page, [0]);
    await setValue(page, '#births', '40');
    await page.click('#explore');
    await waitGeneration(page, g2 + 1, 120000);
    await gridReady(page);
    check(await page.isHidden('#search'), 'explore: a short search ends and its results become the next grid');
    // ... and a long one, stopped while it runs; the page stays responsive.
    const g3 = await generation(page);
    await select(page, [1]);
    await setValue(page, '#births', '100000');  // the most; stopped long before its end
    await page.click('#explore');
    await page.waitForSelector('#search:not([hidden])');
    await page.waitForFunction(() => document.getElementById('search-progress').value > 0, null, { timeout: 60000 });
    check(await page.isDisabled('#breed'), 'explore: breeding waits while the search runs');
    const pixels = await page.evaluate(`(${firstCellPixels})().sum`);
    await page.waitForFunction(`(${firstCellPixels})().sum !== ${pixels}`, null, { timeout: 30000 });
    check(await page.isVisible('#search'), 'explore: the plants keep turning while the search runs (the page is not blocked)');
    await page.click('#stop');
    await waitGeneration(page, g3 + 1, 60000);
    await page.waitForSelector('#search', { state: 'hidden' });
    await gridReady(page);
    check(!(await getState(address)).search.running, 'explore: stop ends the search, its results so far are the grid');

    // Ctrl-C saves; --resume continues with the same grid.
    const before = await getState(address);
    server.proc.kill('SIGINT');
    const exit = await server.exited;
    check(exit.code === 0 || exit.code === 130, `Ctrl-C: morphogen breed saves and exits (${exit.code})`);
    server = startServer(['--resume', dir]);
    address = parseAddress(await server.address);
    await page.goto(address.url);
    await gridReady(page);
    check(same(await gridIds(page), before.grid.map((p) => p.id)) && (await generation(page)) === before.generation,
      '--resume: the same grid and generation');

    if (process.env.MORPHOGEN_BREED_SCREENSHOT) {
      await select(page, [2]);
      await page.waitForTimeout(500);
      await page.screenshot({ path: process.env.MORPHOGEN_BREED_SCREENSHOT });
      console.log('screenshot: ' + process.env.MORPHOGEN_BREED_SCREENSHOT);
    }
    check(errors.length === 0, 'no errors in the pages' + (errors.length ? ': ' + errors.join('; ') : ''));
  } catch (e) {
    console.log('morphogen breed stderr:\n' + server.stderr());
    throw e;
  } finally {
    await context.close();
    if (server.proc.exitCode === null) {
      server.proc.kill('SIGINT');
      await server.exited;
    }
  }
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'breed-page-'));
const browser = await chromium.launch({
  executablePath: CHROMIUM,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
let failed = false;
try {
  await runThrough(browser, tmp);
} catch (e) {
  console.log(e.stack || String(e));
  failed = true;
} finally {
  await browser.close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
console.log(failed ? 'FAILED' : 'passed');
process.exit(failed ? 1 : 0);
