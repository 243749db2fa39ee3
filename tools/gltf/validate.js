// Validates glTF binaries with the Khronos glTF validator: one line per file,
// "<file>: <errors> errors, <warnings> warnings, <infos> infos, <hints> hints",
// then each message. Exit 1 when any file has an error or a warning.
// Usage: node tools/gltf/validate.js FILE.glb...
'use strict';
const fs = require('fs');
const validator = require('gltf-validator');

async function main(files) {
  let failed = false;
  for (const file of files) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {maxIssues: 100});
    const n = report.issues;
    console.log(`${file}: ${n.numErrors} errors, ${n.numWarnings} warnings, ${n.numInfos} infos, ${n.numHints} hints`);
    for (const m of n.messages) console.log(`  ${['error', 'warning', 'info', 'hint'][m.severity]} ${m.code} ${m.pointer || ''}: ${m.message}`);
    if (n.numErrors > 0 || n.numWarnings > 0) failed = true;
  }
  return failed ? 1 : 0;
}

if (process.argv.length < 3) {
  console.error('usage: node validate.js FILE.glb...');
  process.exit(2);
}
main(process.argv.slice(2)).then((code) => process.exit(code), (e) => { console.error(String(e)); process.exit(2); });
