// Checks of a `morphogen report` page in Debian's Chromium, driven by npm's
// playwright-core (tools/browser; scripts/setup.sh installs it): what a
// person would see (no console errors or failed loads, the plots, a viewer
// canvas that is not blank in a screenshot, the growth animation playing, the
// archive heatmap), and the viewer's sway toggle and level-of-detail selector.
// Used by browser_test.mjs (CTest "report: browser") and check_report.mjs.
import { createRequire } from 'node:module';
import { existsSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

export const SKIP = 77;
const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
const CHROMIUM = process.env.MORPHOGEN_CHROMIUM || '/usr/bin/chromium';

// The browser, or a reason to skip (exit 77) where Chromium or
// tools/browser/node_modules is missing.
export async function launch() {
  if (!existsSync(CHROMIUM)) return { skip: `${CHROMIUM} is not installed (Debian package chromium; scripts/setup.sh installs it)` };
  const tools = join(ROOT, 'tools', 'browser');
  if (!existsSync(join(tools, 'node_modules', 'playwright-core')))
    return { skip: `${tools}/node_modules has no playwright-core (scripts/setup.sh runs npm ci there)` };
  const { chromium } = createRequire(join(tools, 'package.json'))('playwright-core');
  const browser = await chromium.launch({
    executablePath: CHROMIUM,
    // WebGL in software, as on a machine with no GPU; root needs --no-sandbox.
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  return { browser };
}

// A page of `reportDir` whose console errors and warnings, uncaught
// exceptions and failed loads are collected in page.problems.
export async function openReport(browser, reportDir) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 1100 }, deviceScaleFactor: 1 });
  page.problems = [];
  page.on('console', (m) => {
    if (['error', 'warning', 'assert'].includes(m.type())) page.problems.push(`console ${m.type()}: ${m.text()}`);
  });
  page.on('pageerror', (e) => page.problems.push(`uncaught: ${e.message}`));
  page.on('requestfailed', (r) => page.problems.push(`failed load: ${r.url()} (${r.failure()?.errorText})`));
  const index = join(resolve(reportDir), 'index.html');
  if (!existsSync(index)) throw new Error(`${index} does not exist`);
  await page.goto(pathToFileURL(index).href);
  return page;
}

export const status = (page) => page.evaluate(() => window.morphogenStatus || null);

// Waits until `test(status)` holds; the last status either way.
export async function waitStatus(page, test, seconds = 30) {
  const deadline = Date.now() + seconds * 1000;
  let s = null;
  for (;;) {
    s = await status(page);
    if ((s && test(s)) || Date.now() > deadline || page.problems.length) return s;
    await page.waitForTimeout(200);
  }
}

// Screenshots of an element decoded by the page's own canvas (no PNG code
// here): for each, the distinct colours and the share of pixels unlike the
// most common one; for two, also the pixels that differ, row by row.
export async function shot(page, selector) {
  const element = page.locator(selector);
  await element.scrollIntoViewIfNeeded();
  await page.waitForTimeout(100);  // a frame drawn where it now is
  return element.screenshot();
}

export async function pixels(page, pngs) {
  return page.evaluate(async (b64s) => {
    const decode = async (b64) => {
      const img = new Image();
      img.src = 'data:image/png;base64,' + b64;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      return ctx.getImageData(0, 0, c.width, c.height);
    };
    const images = [];
    for (const b of b64s) images.push(await decode(b));
    const a = images[0], n = a.width * a.height, counts = new Map();
    for (let i = 0; i < n * 4; i += 4) {
      const key = (a.data[i] << 16) | (a.data[i + 1] << 8) | a.data[i + 2];
      counts.set(key, (counts.get(key) || 0) + 1);
    }
    const result = { width: a.width, height: a.height, colours: counts.size, covered: 1 - Math.max(...counts.values()) / n };
    if (images.length === 2) {
      const b = images[1], rows = new Array(a.height).fill(0);
      let changed = 0;
      for (let i = 0; i < n; i++) {
        const j = i * 4;
        if (a.data[j] !== b.data[j] || a.data[j + 1] !== b.data[j + 1] || a.data[j + 2] !== b.data[j + 2]) {
          changed++;
          rows[Math.floor(i / a.width)]++;
        }
      }
      Object.assign(result, { changed, rows });
    }
    return result;
  }, pngs.map((p) => p.toString('base64')));
}

// The checks of one report; the failures, each a sentence.
//   expectViewer 'shown' | 'none'; expectGrowth 'playing' | 'none' | undefined;
//   expectHeatmap; screenshot / viewerShot: PNG paths to write.
export async function checkReport(browser, reportDir, options = {}) {
  const { expectViewer = 'shown', expectGrowth, expectHeatmap = false } = options;
  const failures = [];
  const page = await openReport(browser, reportDir);
  try {
    const s = await waitStatus(page, (x) => x.viewer !== 'pending' && x.growth !== 'pending' || x.errors.length > 0);
    await page.waitForTimeout(500);  // a few frames drawn
    console.log('page status:', JSON.stringify(s, (k, v) => (k === 'lodTriangles' ? v.join('/') : v)));
    if (!s) failures.push('report.js did not run (no window.morphogenStatus)');
    for (const e of s?.errors || []) failures.push('section failed: ' + e);
    const charts = await page.locator('#plot-grid canvas.chart').count();
    if ((s?.plots || 0) < 4 || charts < 4) failures.push(`expected at least 4 plots, found ${charts}`);
    if (s?.viewer !== expectViewer) failures.push(`viewer is ${s?.viewer}, expected ${expectViewer}`);
    if (expectViewer === 'shown') {
      const png = await shot(page, '#viewer');
      const p = await pixels(page, [png]);
      if (options.viewerShot) (await import('node:fs')).writeFileSync(options.viewerShot, png);
      console.log(`viewer canvas: ${p.colours} colours, ${(p.covered * 100).toFixed(1)} % of pixels not background`);
      if (p.colours < 20 || p.covered < 0.01) failures.push(`the viewer canvas looks blank (${p.colours} colours)`);
    }
    if (expectGrowth && s?.growth !== expectGrowth) failures.push(`growth is ${s?.growth}, expected ${expectGrowth}`);
    if (expectGrowth === 'playing') {
      const p = await pixels(page, [await shot(page, '#growth')]);
      console.log(`growth canvas: ${p.colours} colours, ${(p.covered * 100).toFixed(1)} % covered`);
      if (p.colours < 20 || p.covered < 0.005) failures.push('the growth canvas looks blank');
      const start = (await status(page)).growthTime || 0;
      await page.waitForTimeout(1000);
      const later = (await status(page)).growthTime || 0;
      console.log(`growth animation time: ${start.toFixed(2)} s, a second later ${later.toFixed(2)} s`);
      if (!(later > start)) failures.push('the growth animation does not advance');
    }
    if (expectHeatmap && !s?.heatmap) failures.push('no heatmap cells drawn');
    if (options.screenshot) {
      await page.evaluate(() => window.scrollTo(0, 0));
      await page.screenshot({ path: options.screenshot });
    }
    failures.push(...page.problems);
  } finally {
    await page.close();
  }
  return failures;
}

// The sway toggle and the level selector on the plant the viewer shows:
//   - each level draws the triangles its label shows (the renderer's count),
//     each about half of the level before;
//   - with sway off, the picture holds still and the sway clock stands; with
//     it on, the plant moves (screenshots differ), its upper half more than
//     its foot, at LOD0 and at the last level; off again, it is back at rest.
// The failures, each a sentence.
export async function checkPlantControls(page, { minLods = 1 } = {}) {
  const failures = [];
  const s0 = await status(page);
  if (s0.sway !== 'off') failures.push(`sway is ${s0.sway} on a plant with wind data, expected off`);
  if (!(s0.lods >= minLods)) failures.push(`the plant has ${s0.lods} levels, expected at least ${minLods}`);
  const levels = s0.lodTriangles || [];
  for (let i = 0; i < levels.length; i++) {
    await page.selectOption('#lod', String(i));
    const s = await waitStatus(page, (x) => x.lod === i && x.drawnTriangles === levels[i], 5);  // a frame drawn
    const label = await page.locator('#lod-label').textContent();
    console.log(`LOD${i}: ${s.drawnTriangles} triangles drawn; label "${label}"`);
    if (s.lod !== i || s.drawnTriangles !== levels[i]) failures.push(`LOD${i}: ${s.drawnTriangles} triangles drawn, expected ${levels[i]}`);
    if (!label.startsWith(String(levels[i]) + ' triangles')) failures.push(`LOD${i}: the label "${label}" does not show ${levels[i]} triangles`);
    if (i > 0 && !(levels[i] / levels[i - 1] >= 0.4 && levels[i] / levels[i - 1] <= 0.6))
      failures.push(`LOD${i} has ${levels[i]} triangles, LOD${i - 1} ${levels[i - 1]}: not about half`);
  }
  for (const lod of [...new Set([0, Math.max(0, levels.length - 1)])]) {
    if (levels.length) await page.selectOption('#lod', String(lod));
    await page.waitForTimeout(300);
    const rest = await shot(page, '#viewer');
    const t0 = (await status(page)).swayTime;
    await page.waitForTimeout(700);
    const still = await pixels(page, [rest, await shot(page, '#viewer')]);
    const t1 = (await status(page)).swayTime;
    console.log(`LOD${lod}, sway off: ${still.changed} pixels changed in 0.7 s, sway clock ${t0.toFixed(2)} -> ${t1.toFixed(2)} s`);
    if (still.changed !== 0 || t1 !== t0) failures.push(`LOD${lod}: the plant moves with sway off (${still.changed} pixels)`);

    await page.check('#sway');
    const on = await status(page);
    if (on.sway !== 'on') failures.push(`LOD${lod}: sway is ${on.sway} after checking the toggle`);
    const frames = [];  // three pictures 0.6 s apart: two of them differ whatever the phase
    for (let k = 0; k < 3; k++) {
      await page.waitForTimeout(600);
      frames.push(await shot(page, '#viewer'));
    }
    const moves = [await pixels(page, [frames[0], frames[1]]), await pixels(page, [frames[1], frames[2]])];
    const move = moves[0].changed >= moves[1].changed ? moves[0] : moves[1];
    const { top, foot } = (await status(page)).plantRows;
    const sum = (a, b) => move.rows.slice(Math.max(0, Math.round(a)), Math.round(b)).reduce((x, y) => x + y, 0);
    const upper = sum(top, (top + foot) / 2), lowest = sum(foot - 0.1 * (foot - top), foot + 1);
    const t2 = (await status(page)).swayTime;
    console.log(`LOD${lod}, sway on: ${move.changed} pixels changed in 0.6 s (upper half of the plant ${upper}, ` +
                `lowest tenth ${lowest}), sway clock at ${t2.toFixed(2)} s`);
    if (move.changed < 200) failures.push(`LOD${lod}: the plant barely moves with sway on (${move.changed} pixels)`);
    // (The camera looks down a little, so the lowest rows also hold some of
    // the plant's middle, in front of its foot: a margin of 2, not more.)
    if (!(lowest * 2 < upper)) failures.push(`LOD${lod}: the foot moves as much as the top (${lowest} against ${upper} pixels)`);
    if (!(t2 > t1 + 1)) failures.push(`LOD${lod}: the sway clock does not advance (${t1} -> ${t2})`);

    await page.uncheck('#sway');
    await page.waitForTimeout(200);
    const back = await pixels(page, [rest, await shot(page, '#viewer')]);
    if (back.changed !== 0) failures.push(`LOD${lod}: sway off again does not bring the plant back to rest (${back.changed} pixels)`);
  }
  return failures;
}
