'use strict';
// `collide backends` runs this: one line per engine of engines.json, "NAME PRECISION DESCRIPTION",
// the description naming the installed package version, or what to run when it is missing.
const { engineList, packageVersion } = require('./protocol');

for (const e of engineList()) {
  const installed = packageVersion(e.package);
  const state = installed ? `${e.package} ${installed}` : `not installed: run \`npm ci\` in ${__dirname} (scripts/install-deps.sh does)`;
  console.log(`${e.name.padEnd(11)} ${e.precision.padEnd(13)} outside engine, ${e.about}: ${state}`);
}
