// End-to-end checks of `morphogen report` pages in Debian's Chromium driven by
// playwright-core (CTest "report: browser"): a small GA run's report (its
// growth viewer plays; the final best sways with its wind data and shows each
// level of detail; the run's own engine-ready exports carry theirs), a report
// without three.js, a run with no exported meshes, and MAP-Elites runs (grid
// and CVT; a click on a heatmap cell opens its elite, engine-ready too).
//
// usage: node tests/report/browser_test.mjs MORPHOGEN_EXE
// Exit 0: passed; 1: failed; 77: skipped (no chromium or no tools/browser/node_modules).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { SKIP, launch, openReport, checkReport, checkPlantControls, status, waitStatus } from './report_page.mjs';

const CONFIG = {
  network: { outputs: 4, hidden: [5] },
  growth: { steps: 30, max_vertices: 400 },
  fitness: { type: 'canopy', height: 1, cell: 0.1 },
  evolution: { population: 12, batch: 4, mutation_rate: 0.2 },
  run: { seed: 5, generations: 4, export_every: 1 },
};

function morphogen(exe, args, env = process.env) {
  try {
    execFileSync(exe, args, { stdio: 'pipe', env });
  } catch (e) {
    throw new Error(`morphogen ${args.join(' ')} exited ${e.status}: ${e.stderr}`);
  }
}

function makeRun(exe, tmp, name, config, env = process.env) {
  const path = join(tmp, name + '.json');
  writeFileSync(path, JSON.stringify(config));
  const run = join(tmp, name);
  morphogen(exe, ['evolve', path, '--out', run, '--no-report', '--threads', '1']);
  morphogen(exe, ['report', run], env);
  return join(run, 'report');
}

// Runs `f(page)` on a loaded report; its failures and the page's problems.
async function onPage(browser, report, f) {
  const page = await openReport(browser, report);
  try {
    await waitStatus(page, (s) => s.viewer !== 'pending');
    const failures = await f(page);
    return [...failures, ...page.problems];
  } finally {
    await page.close();
  }
}

// The GA report opens on the last generation's export (engine-ready: the
// config asks for it); the final best, grown by the report, sways and shows
// its three levels.
async function plantControls(browser, report) {
  return onPage(browser, report, async (page) => {
    const failures = [];
    const last = await status(page);
    if (last.lods !== 3 || last.sway !== 'off')
      failures.push(`the last generation's export shows ${last.lods} levels and sway ${last.sway}, expected 3 and off`);
    await page.click('#show-best');
    const s = await waitStatus(page, (x) => x.shown === 'best');
    if (s.shown !== 'best') return [`the final best button shows ${s.shown}`];
    return [...failures, ...await checkPlantControls(page, { minLods: 3 })];
  });
}

// Clicks the first grown elite's cell; the viewer must then show it, with
// its wind data. Before, the viewer shows a plain export: no sway, no levels.
async function clickHeatmap(browser, report) {
  return onPage(browser, report, async (page) => {
    const failures = [];
    const before = await status(page);
    if (before.sway !== 'none' || before.lods !== 0 || !(await page.isDisabled('#sway')))
      failures.push(`a plain export shows sway ${before.sway} and ${before.lods} levels, expected none and 0`);
    const target = before.heatmapTarget;
    if (!target) return ['no grown elite on the heatmap'];
    const canvas = page.locator('#heatmap');
    await canvas.scrollIntoViewIfNeeded();
    const box = await canvas.boundingBox();
    const size = await canvas.evaluate((c) => ({ w: c.width, h: c.height }));
    await page.mouse.click(box.x + target.x * box.width / size.w, box.y + target.y * box.height / size.h);
    const s = await waitStatus(page, (x) => x.shown === target.key, 20);
    if (s.shown !== target.key) return [`after clicking ${target.key} the viewer shows ${s.shown}`];
    console.log(`OK: clicking ${target.key} opened it in the viewer (${s.lods} levels, sway ${s.sway})`);
    if (s.sway !== 'off' || !(s.lods >= 1)) failures.push(`the elite shows sway ${s.sway} and ${s.lods} levels`);
    return failures;
  });
}

async function main() {
  if (process.argv.length !== 3) {
    console.log('usage: node tests/report/browser_test.mjs MORPHOGEN_EXE');
    return 2;
  }
  const exe = resolve(process.argv[2]);
  const { browser, skip } = await launch();
  if (skip) {
    console.log('SKIPPED: ' + skip);
    return SKIP;
  }
  const tmp = mkdtempSync(join(tmpdir(), 'morphogen_report_browser_'));
  let failed = 0;
  const report = (name, failures) => {
    for (const f of failures) console.log(`FAIL (${name}): ${f}`);
    if (!failures.length) console.log(`OK: ${name}`);
    failed += failures.length ? 1 : 0;
  };
  try {
    const ga = makeRun(exe, tmp, 'ga', { ...CONFIG, run: { ...CONFIG.run, export_glb: { lods: 3, wind: true } } });
    report('ga', await checkReport(browser, ga, { expectViewer: 'shown', expectGrowth: 'playing' }));
    report('ga: sway and levels', await plantControls(browser, ga));

    const noThree = makeRun(exe, tmp, 'nothree', CONFIG, { ...process.env, MORPHOGEN_THREE_DIR: join(tmp, 'no-three') });
    report('no three.js', await checkReport(browser, noThree, { expectViewer: 'none', expectGrowth: 'none' }));

    const noMeshes = makeRun(exe, tmp, 'nomesh', { ...CONFIG, run: { ...CONFIG.run, export_every: 0 } });
    report('no exported meshes', await checkReport(browser, noMeshes, { expectViewer: 'shown' }));

    const elites = {
      ...CONFIG,
      evolution: { ...CONFIG.evolution, algorithm: 'map_elites' },
      descriptors: [{ measure: 'height', min: 0, max: 3, bins: 6 }, { measure: 'footprint', min: 0, max: 10, bins: 5 }],
      archive: { type: 'grid', qd_offset: -1 },
    };
    const eliteReport = makeRun(exe, tmp, 'elites', elites);
    report('grid archive', await checkReport(browser, eliteReport, { expectViewer: 'shown', expectHeatmap: true }));
    report('heatmap click', await clickHeatmap(browser, eliteReport));

    const cvt = {
      ...elites,
      descriptors: [{ measure: 'height', min: 0, max: 3 }, { measure: 'footprint', min: 0, max: 10 }],
      archive: { type: 'cvt', cells: 16 },
    };
    report('cvt archive', await checkReport(browser, makeRun(exe, tmp, 'cvt', cvt), { expectViewer: 'shown', expectHeatmap: true }));
  } finally {
    await browser.close();
    rmSync(tmp, { recursive: true, force: true });
  }
  console.log(failed ? `FAILED (${failed} failing)` : 'PASSED');
  return failed ? 1 : 0;
}

process.exitCode = await main().catch((e) => {
  console.log('FAIL:', e.stack || e.message);
  return 1;
});
