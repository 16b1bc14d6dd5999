'use strict';
// `collide backends` runs this: one line per engine of engines.json, "NAME PRECISION DESCRIPTION",
// the description naming the installed package version, or what to run when it is missing.
const fs = require('fs');
const path = require('path');

for (const e of JSON.parse(fs.readFileSync(path.join(__dirname, 'engines.json'), 'utf8'))) {
  const manifest = path.join(__dirname, 'node_modules', e.package, 'package.json');
  const installed = fs.existsSync(manifest) ? JSON.parse(fs.readFileSync(manifest, 'utf8')).version : '';
  const state = installed ? `${e.package} ${installed}` : `not installed: run \`npm ci\` in ${__dirname} (scripts/install-deps.sh does)`;
  console.log(`${e.name.padEnd(11)} ${e.precision.padEnd(13)} outside engine, ${e.about}: ${state}`);
}
