// Shared by the *.test.js files: `require('vscode')` resolves to the minimal shim
// (shim/vscode.js), so the extension's own modules and vscode-languageclient load under plain
// node; ROOT is the repository; waitFor polls a condition.
'use strict';
const path = require('node:path');
const Module = require('node:module');

const SHIM = path.join(__dirname, 'shim', 'vscode.js');
const resolve = Module._resolveFilename;
Module._resolveFilename = function (request, ...rest) {
  return request === 'vscode' ? SHIM : resolve.call(this, request, ...rest);
};
const vscode = require('vscode');

const ROOT = path.resolve(__dirname, '..', '..', '..');

// Resolves with pred()'s first truthy value (a throwing pred counts as false), polled every
// 20 ms; rejects naming `what` after `ms` milliseconds.
function waitFor(pred, ms, what) {
  return new Promise((res, rej) => {
    const t0 = Date.now();
    const tick = () => {
      let v;
      try { v = pred(); } catch (e) { v = undefined; }
      if (v) return res(v);
      if (Date.now() - t0 > ms) return rej(new Error(`timed out waiting for ${what}`));
      setTimeout(tick, 20);
    };
    tick();
  });
}

module.exports = { vscode, ROOT, waitFor };
