// The extension's own client library starts the real server: vscode-languageclient (with the
// options extension.js uses, from server.js) under node with a minimal `vscode` shim spawns
// `aidl lsp --stdio`, completes `initialize`, opens an example and receives its diagnostics
// in a diagnostic collection, as VS Code would show them.
//
// The server is found the way the extension finds it (server.js: aidl.serverPath, the
// workspace's .venv, $VIRTUAL_ENV, PATH); the repository's .venv is the workspace's here.
'use strict';
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');

const { vscode, ROOT, waitFor } = require('./helpers');
const { LanguageClient } = require('vscode-languageclient/node');
const { findServer, serverOptions, clientOptions, notFoundMessage } = require('../server');


test('findServer: setting, then the workspace .venv, then PATH, naming what it tried', (t) => {
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'aidl-find-'));
  t.after(() => fs.rmSync(tmp, { recursive: true, force: true }));
  const venvBin = path.join(tmp, 'ws', '.venv', 'bin');
  const other = path.join(tmp, 'other');
  fs.mkdirSync(venvBin, { recursive: true });
  fs.mkdirSync(other);
  for (const d of [venvBin, other]) {
    fs.writeFileSync(path.join(d, 'aidl'), '#!/bin/sh\n');
    fs.chmodSync(path.join(d, 'aidl'), 0o755);
  }
  const env = { PATH: other };
  assert.equal(findServer({ folders: [path.join(tmp, 'ws')], env }).command, path.join(venvBin, 'aidl'));
  assert.equal(findServer({ folders: [tmp], env }).command, path.join(other, 'aidl'));
  assert.equal(findServer({ serverPath: path.join(other, 'aidl'), folders: [path.join(tmp, 'ws')], env }).command,
    path.join(other, 'aidl'));
  assert.equal(findServer({ serverPath: 'aidl', env }).command, path.join(other, 'aidl'));
  assert.equal(findServer({ serverPath: '${workspaceFolder}/.venv/bin/aidl', folders: [path.join(tmp, 'ws')], env }).command,
    path.join(venvBin, 'aidl'));
  const none = findServer({ folders: [tmp], env: { PATH: path.join(tmp, 'empty') } });
  assert.equal(none.command, null);
  assert.ok(none.tried.includes(path.join(tmp, '.venv', 'bin', 'aidl')));
  assert.ok(none.tried.includes(path.join(tmp, 'empty', 'aidl')));
  const msg = notFoundMessage(none.tried);
  assert.match(msg, /\.venv/);
  assert.match(msg, /aidl\.serverPath/);
  const missing = findServer({ serverPath: '/nowhere/aidl', env });
  assert.equal(missing.command, null);
  assert.deepEqual(missing.tried, ['/nowhere/aidl']);
});

test('clientOptions: the declared aidl.inlayHints/codeLens settings go to the server', () => {
  const declared = require('../package.json').contributes.configuration.properties;
  vscode._shim.setSettings({ 'aidl.inlayHints.enabled': false });
  const opts = clientOptions(undefined, vscode.workspace.getConfiguration('aidl'));
  vscode._shim.setSettings({});
  assert.equal(opts.synchronize.configurationSection, 'aidl');
  // every declared toggle arrives as {aidl: {name: {enabled}}}, the form features.configure reads
  const sent = Object.keys(opts.initializationOptions.aidl).map((k) => `aidl.${k}.enabled`);
  assert.deepEqual(sent.sort(), Object.keys(declared).filter((k) => k.endsWith('.enabled')).sort());
  assert.deepEqual(opts.initializationOptions.aidl, { inlayHints: { enabled: false }, codeLens: { enabled: true } });
  assert.equal(clientOptions().initializationOptions, undefined);
});

test('vscode-languageclient starts `aidl lsp`, opens an example and receives diagnostics', async (t) => {
  const { command, tried } = findServer({ folders: [ROOT] });
  assert.ok(command, notFoundMessage(tried));
  const client = new LanguageClient('aidl', 'AIDL language server', serverOptions(command), clientOptions());
  // stopped also when an assertion fails (a running server would keep `npm test` waiting)
  t.after(() => (client.isRunning() ? client.stop() : undefined));
  const t0 = Date.now();
  await client.start();
  assert.equal(client.initializeResult.serverInfo.name, 'aidl');
  const caps = client.initializeResult.capabilities;
  assert.ok(caps.codeActionProvider && caps.semanticTokensProvider && caps.renameProvider
    && caps.signatureHelpProvider, JSON.stringify(caps));
  const { events, collections, textDocument } = vscode._shim;

  // a good example: published with no diagnostics
  const good = path.join(ROOT, 'examples', 'telephone.aidl');
  events.open.fire(textDocument(good, fs.readFileSync(good, 'utf8')));
  const coll = await waitFor(() => collections.find((c) => c.has(vscode.Uri.file(good))), 60000, 'diagnostics of telephone.aidl');
  assert.deepEqual(coll.get(vscode.Uri.file(good)), []);
  const first = Date.now() - t0;
  // semantic tokens of the example, decoded with the legend the server announced
  const legend = caps.semanticTokensProvider.legend;
  const sem = await client.sendRequest('textDocument/semanticTokens/full',
    { textDocument: { uri: vscode.Uri.file(good).toString() } });
  const lines = fs.readFileSync(good, 'utf8').split('\n');
  const seen = new Set();
  let line = 0;
  let col = 0;
  for (let i = 0; i < sem.data.length; i += 5) {
    const [dl, dc, n, type] = sem.data.slice(i, i + 4);
    line += dl;
    col = dl ? dc : col + dc;
    seen.add(`${lines[line].slice(col, col + n)}:${legend.tokenTypes[type]}`);
  }
  for (const t of ['telephone:struct', 'Circle:class', 'OnCircle:macro', 'dial_r:variable', 'mm:keyword']) {
    assert.ok(seen.has(t), t);
  }

  // a misspelt primitive: one diagnostic, located, with the did-you-mean fix attached
  const bad = path.join(os.tmpdir(), 'aidl-client-test.aidl');
  const text = 'solid plate {\n    c = Circel(center=(0, 0), radius=3)\n}\n';
  events.open.fire(textDocument(bad, text));
  const diags = await waitFor(() => coll.get(vscode.Uri.file(bad)), 30000, 'diagnostics of the broken file');
  assert.equal(diags.length, 1);
  const d = diags[0];
  // the code links to its explanation (codeDescription.href -> docs/codes.md#e0103)
  assert.equal(typeof d.code === 'object' ? d.code.value : d.code, 'E0103');
  if (typeof d.code === 'object') assert.match(d.code.target.path, /docs\/codes\.md$/);
  assert.equal(d.severity, vscode.DiagnosticSeverity.Error);
  assert.deepEqual([d.range.start.line, d.range.start.character, d.range.end.character], [1, 8, 14]);
  assert.match(d.message, /did you mean `Circle`/);
  // and the quick fix the server offers for it
  const actions = await client.sendRequest('textDocument/codeAction', {
    textDocument: { uri: vscode.Uri.file(bad).toString() },
    range: { start: { line: 1, character: 8 }, end: { line: 1, character: 14 } },
    context: { diagnostics: [client.code2ProtocolConverter.asDiagnostic(d)] },
  });
  assert.equal(actions[0].title, 'Replace `Circel` with `Circle`');

  // apply it as VS Code would: an incremental change (the server syncs incrementally)
  const edit = actions[0].edit.changes[vscode.Uri.file(bad).toString()][0];
  assert.deepEqual(edit.range, { start: { line: 1, character: 8 }, end: { line: 1, character: 14 } });
  const fixed = text.replace('Circel', edit.newText);
  const doc2 = textDocument(bad, fixed, 'aidl-cad', 2);
  events.change.fire({
    document: doc2, reason: undefined,
    contentChanges: [{ range: new vscode.Range(1, 8, 1, 14), rangeOffset: text.indexOf('Circel'), rangeLength: 6, text: 'Circle' }],
  });
  await waitFor(() => coll.get(vscode.Uri.file(bad)).length === 0, 30000, 'the diagnostic to go away');
  await client.stop();
  console.log(`# cold start to first diagnostics through vscode-languageclient: ${first} ms`);
});
