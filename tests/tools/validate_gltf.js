#!/usr/bin/env node
// Validates glTF files with the Khronos glTF Validator (npm gltf-validator).
// Usage: validate_gltf.js FILE.gltf [...]
// Prints the validator's issue counts and every error; exits 1 when any
// file has an error (warnings and infos are printed, not fatal), 2 on a
// usage or I/O problem.
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function validate(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const dir = path.dirname(file);
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        // Resources must stay inside the glTF's folder.
        const p = path.resolve(dir, decodeURIComponent(uri));
        if (!p.startsWith(path.resolve(dir) + path.sep)) return reject(new Error('outside: ' + uri));
        fs.readFile(p, (err, data) => (err ? reject(err) : resolve(new Uint8Array(data))));
      }),
  });
  const i = report.issues;
  console.log(`${file}: errors ${i.numErrors}, warnings ${i.numWarnings}, infos ${i.numInfos}, hints ${i.numHints}`);
  for (const m of i.messages)
    if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'ERROR' : 'warning'} ${m.code} ${m.pointer || ''}: ${m.message}`);
  return i.numErrors;
}

(async () => {
  const files = process.argv.slice(2);
  if (files.length === 0) {
    console.error('usage: validate_gltf.js FILE.gltf [...]');
    process.exit(2);
  }
  let errors = 0;
  for (const f of files) {
    try {
      errors += await validate(f);
    } catch (e) {
      console.error(`${f}: cannot validate: ${e.message || e}`);
      process.exit(2);
    }
  }
  process.exit(errors > 0 ? 1 : 0);
})();
