// The esbuild bundle the .vsix ships (build.js, `npm run bundle`; package.json's `main`): built
// here, it loads as ONE module (vscode-languageclient, server.js and preview.js inside it, no
// node_modules beside it at run time), and activated under the `vscode` shim against the real
// `aidl lsp` of the repository's .venv it runs the server and previews examples/phone_stand.aidl,
// the webview page importing the bundled three.js (dist/webview/three.js) from the one folder
// the panel may read.  The .vsix itself in a real VS Code: tests/test_vscode_code_server.py.
'use strict';
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const { execFileSync } = require('node:child_process');

const { vscode, ROOT, waitFor } = require('./helpers');

const EXT = path.join(__dirname, '..');
const MAIN = path.join(EXT, require('../package.json').main);
const THREE = path.join(EXT, 'dist', 'webview', 'three.js');
const STAND = path.join(ROOT, 'examples', 'phone_stand.aidl');

test('the bundle builds, loads as one module, runs the server and the preview', async (t) => {
  execFileSync(process.execPath, [path.join(EXT, 'build.js')], { cwd: EXT, timeout: 120000 });
  assert.equal(MAIN, path.join(EXT, 'dist', 'extension.js'));
  // three.js with the glTF loader and the orbit controls, as one ES module
  const three = fs.readFileSync(THREE, 'utf8');
  assert.match(three, /export\{[^}]*\bGLTFLoader\b/);
  assert.match(three, /\bOrbitControls\b/);
  assert.doesNotMatch(three, /\bimport\s*[{*"']|\brequire\(/);     // nothing left to fetch

  const before = new Set(Object.keys(require.cache));
  const extension = require(MAIN);
  const loaded = Object.keys(require.cache).filter((k) => !before.has(k));
  assert.deepEqual(loaded, [MAIN]);
  t.after(() => extension.deactivate());

  const { events, panels, textDocument, setFolders } = vscode._shim;
  setFolders([ROOT]);
  const api = await extension.activate({ subscriptions: [], extensionPath: EXT });
  await waitFor(() => api.status().state === 'running', 60000, 'the server to run');
  const doc = textDocument(STAND, fs.readFileSync(STAND, 'utf8'));
  vscode.workspace.textDocuments.push(doc);
  events.open.fire(doc);
  vscode.window.activeTextEditor = { document: doc, selection: new vscode.Selection(0, 0, 0, 0) };
  await vscode.commands.executeCommand('aidl.openPreview');
  assert.equal(panels.length, 1);
  const panel = panels[0];
  assert.deepEqual(panel.options.localResourceRoots.map((u) => u.fsPath),
    [path.join(EXT, 'dist', 'webview')]);
  const src = /import \* as THREE from "([^"]+)"/.exec(panel.webview.html);
  assert.ok(src, 'the page imports three.js');
  assert.equal(vscode.Uri.parse(src[1]).fsPath, THREE);
  assert.doesNotMatch(panel.webview.html, /importmap|node_modules/);
  assert.doesNotMatch(panel.webview.html, /id="mode3d"[^>]* hidden>/);
  panel.receive({ type: 'ready' });
  const first = await waitFor(() => panel.posted.find((m) => m.type === 'update' && m.result.ok),
    60000, 'the first picture');
  assert.match(first.result.svg, /<g id="aidl-shapes"/);
});
