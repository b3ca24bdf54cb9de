// node test/load_time.js ENTRY: what require() of an extension's entry file costs under the
// `vscode` shim (the modules it reads, the CPU and wall time), for comparing the bundle with
// the unbundled sources, e.g. the `main` of two unzipped .vsix files:
//   node test/load_time.js X/extension/dist/extension.js
'use strict';
require('./helpers');
const path = require('node:path');

const entry = path.resolve(process.argv[2] || path.join(__dirname, '..', 'dist', 'extension.js'));
const before = Object.keys(require.cache).length;
const cpu0 = process.cpuUsage();
const t0 = process.hrtime.bigint();
require(entry);
const wall = Number(process.hrtime.bigint() - t0) / 1e6;
const cpu = process.cpuUsage(cpu0);
console.log(`${entry}: ${Object.keys(require.cache).length - before} modules, ` +
  `${((cpu.user + cpu.system) / 1000).toFixed(1)} ms CPU, ${wall.toFixed(1)} ms wall`);
