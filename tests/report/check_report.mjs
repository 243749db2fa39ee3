// Runs the browser checks of report_page.mjs on any report, by hand.
//
// usage: node tests/report/check_report.mjs REPORT_DIR [--expect-viewer shown|none]
//          [--expect-growth playing|none] [--expect-heatmap] [--plant-controls]
//          [--screenshot PNG] [--viewer-shot PNG]
//   --plant-controls: also the sway toggle and the level selector on the plant
//   the viewer opens with (it must have wind data).
// Exit 0: all checks passed; 1: a check failed (each printed); 2: bad usage;
// 77: chromium or tools/browser/node_modules is missing.
import { SKIP, launch, openReport, checkReport, checkPlantControls, waitStatus } from './report_page.mjs';

const USAGE = 'usage: node tests/report/check_report.mjs REPORT_DIR [--expect-viewer shown|none] ' +
  '[--expect-growth playing|none] [--expect-heatmap] [--plant-controls] [--screenshot PNG] [--viewer-shot PNG]';

function parse(argv) {
  const o = { expectViewer: 'shown' };
  const valued = { '--expect-viewer': 'expectViewer', '--expect-growth': 'expectGrowth', '--screenshot': 'screenshot',
    '--viewer-shot': 'viewerShot' };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (valued[a] && i + 1 < argv.length) o[valued[a]] = argv[++i];
    else if (a === '--expect-heatmap') o.expectHeatmap = true;
    else if (a === '--plant-controls') o.plantControls = true;
    else if (!a.startsWith('--') && !o.report) o.report = a;
    else return null;
  }
  return o.report ? o : null;
}

async function main() {
  const o = parse(process.argv.slice(2));
  if (!o) {
    console.log(USAGE);
    return 2;
  }
  const { browser, skip } = await launch();
  if (skip) {
    console.log('SKIPPED: ' + skip);
    return SKIP;
  }
  const failures = [];
  try {
    failures.push(...await checkReport(browser, o.report, o));
    if (o.plantControls) {
      const page = await openReport(browser, o.report);
      await waitStatus(page, (s) => s.viewer !== 'pending');
      failures.push(...await checkPlantControls(page), ...page.problems);
      await page.close();
    }
  } finally {
    await browser.close();
  }
  for (const f of failures) console.log('FAIL:', f);
  if (!failures.length) console.log('OK: no console errors or failed loads; plots; viewer ' + o.expectViewer);
  return failures.length ? 1 : 0;
}

process.exitCode = await main().catch((e) => {
  console.log('FAIL:', e.stack || e.message);
  return 1;
});
