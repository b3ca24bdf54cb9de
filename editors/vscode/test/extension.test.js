// The extension itself (extension.js, preview.js) under the `vscode` shim, against the real
// `aidl lsp` of the repository's .venv: activation and the status-bar state, "AIDL: Open
// Preview" on examples/telephone.aidl (the webview's HTML and the messages posted to it), the
// picture following an edit (not a save), the last good picture kept while the text is broken,
// a slider value, the shape under the cursor, render to DXF through the save dialog, explain,
// restart.
'use strict';
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');

const { vscode, ROOT, waitFor } = require('./helpers');
const extension = require('../extension');

const TELEPHONE = path.join(ROOT, 'examples', 'telephone.aidl');

// The viewBox width of an SVG text (mm).
function viewWidth(svg) {
  return Number(/viewBox="[^"]*?[ ,]([-\d.]+)[ ,]([-\d.]+)"/.exec(svg)[1]);
}

test('the extension previews telephone.aidl and follows edits, sliders and the cursor', async (t) => {
  // a failed assertion must not leave the server running: its child process would keep this
  // test file (and `npm test`, and CI) waiting forever
  t.after(() => extension.deactivate());
  const { events, panels, statusItems, commands, channels, textDocument, setFolders, setSaveDialog } = vscode._shim;
  setFolders([ROOT]);
  const context = { subscriptions: [], extensionPath: path.join(__dirname, '..') };
  const api = await extension.activate(context);
  const status = api.status();
  await waitFor(() => status.state === 'running', 60000, 'the server to run');
  assert.match(status.text, /\$\(check\) AIDL/);
  for (const c of ['aidl.openPreview', 'aidl.restartServer', 'aidl.renderSvg', 'aidl.renderDxf', 'aidl.explain']) {
    assert.ok(commands.has(c), c);
  }

  // open the example in an editor, then "AIDL: Open Preview"
  const text = fs.readFileSync(TELEPHONE, 'utf8');
  let doc = textDocument(TELEPHONE, text);
  vscode.workspace.textDocuments.push(doc);
  events.open.fire(doc);
  vscode.window.activeTextEditor = { document: doc, selection: new vscode.Selection(0, 0, 0, 0) };
  events.activeEditor.fire(vscode.window.activeTextEditor);
  assert.ok(statusItems.some((i) => /Preview/.test(i.text) && i.visible), 'the preview button shows for .aidl');
  await vscode.commands.executeCommand('aidl.openPreview');
  assert.equal(panels.length, 1);
  const panel = panels[0];
  assert.equal(panel.viewType, 'aidlPreview');
  assert.equal(panel.showOptions.viewColumn, vscode.ViewColumn.Beside);
  assert.match(panel.webview.html, /Content-Security-Policy/);
  assert.match(panel.webview.html, /acquireVsCodeApi/);
  panel.receive({ type: 'ready' });
  const updates = () => panel.posted.filter((m) => m.type === 'update').map((m) => m.result);
  const first = await waitFor(() => updates().find((r) => r.ok), 60000, 'the first picture');
  assert.match(first.svg, /^<svg[^>]*viewBox/);
  assert.match(first.svg, /<g id="aidl-shapes"/);
  assert.deepEqual(first.params.map((p) => p.name), ['base_w', 'base_h', 'dial_r', 'handset_len']);
  assert.equal(first.version, 1);
  const w1 = viewWidth(first.svg);
  // a second "Open Preview" reveals the same panel
  await vscode.commands.executeCommand('aidl.openPreview');
  assert.equal(panels.length, 1);

  // edit (no save): base_w 160 -> 240 mm widens the picture
  const edited = text.replace('param base_w = 160 mm', 'param base_w = 240 mm');
  const at = text.indexOf('160 mm');
  const line = text.slice(0, at).split('\n').length - 1;
  const col = at - text.lastIndexOf('\n', at) - 1;
  doc = textDocument(TELEPHONE, edited, 'aidl-cad', 2);
  vscode.workspace.textDocuments[vscode.workspace.textDocuments.length - 1] = doc;
  const tEdit = Date.now();
  events.change.fire({ document: doc, reason: undefined,
    contentChanges: [{ range: new vscode.Range(line, col, line, col + 3), rangeOffset: at, rangeLength: 3, text: '240' }] });
  const second = await waitFor(() => updates().find((r) => r.version === 2), 60000, 'the picture of the edit');
  const editMs = Date.now() - tEdit;
  assert.ok(second.ok && !second.stale);
  assert.ok(viewWidth(second.svg) > w1 + 60, `${viewWidth(second.svg)} vs ${w1}`);

  // broken: the last good picture stays, marked stale, with the error located
  const broken = edited.replace(' h = Circle(', ' h = Circel(');
  const bat = edited.indexOf(' h = Circle(') + 5;
  const bline = edited.slice(0, bat).split('\n').length - 1;
  const bcol = bat - edited.lastIndexOf('\n', bat) - 1;
  doc = textDocument(TELEPHONE, broken, 'aidl-cad', 3);
  vscode.workspace.textDocuments[vscode.workspace.textDocuments.length - 1] = doc;
  events.change.fire({ document: doc, reason: undefined,
    contentChanges: [{ range: new vscode.Range(bline, bcol, bline, bcol + 6), rangeOffset: bat, rangeLength: 6, text: 'Circel' }] });
  const third = await waitFor(() => updates().find((r) => r.version === 3), 60000, 'the broken version');
  assert.equal(third.ok, false);
  assert.equal(third.stale, true);
  assert.equal(third.svg, second.svg);
  assert.equal(third.diagnostics.first.code, 'E0103');
  assert.deepEqual(third.diagnostics.first.range.slice(0, 2), [bline, bcol]);

  // fix it again and move a slider: the picture is drawn with the value
  doc = textDocument(TELEPHONE, edited, 'aidl-cad', 4);
  vscode.workspace.textDocuments[vscode.workspace.textDocuments.length - 1] = doc;
  events.change.fire({ document: doc, reason: undefined,
    contentChanges: [{ range: new vscode.Range(bline, bcol, bline, bcol + 6), rangeOffset: bat, rangeLength: 6, text: 'Circle' }] });
  await waitFor(() => updates().find((r) => r.version === 4 && r.ok), 60000, 'the fixed version');
  panel.receive({ type: 'values', values: { base_w: '120 mm' } });
  const slid = await waitFor(() => updates().find((r) => r.values && r.values.base_w === '120 mm'), 60000, 'the slider picture');
  assert.ok(slid.ok);
  assert.equal(slid.params.find((p) => p.name === 'base_w').value, 120);
  assert.ok(viewWidth(slid.svg) < viewWidth(second.svg) - 60);

  // the cursor on the finger holes' Circle call: posted to the page, and that call's range
  // names overlay elements (the ten holes of the loop share it)
  const hl = edited.split('\n').findIndex((l) => /^\s*h = Circle\(/.test(l));
  const hc = edited.split('\n')[hl].indexOf('Circle') + 2;
  events.selection.fire({ textEditor: { document: doc }, selections: [new vscode.Selection(hl, hc, hl, hc)] });
  const cur = panel.posted.filter((m) => m.type === 'cursor').pop();
  assert.deepEqual([cur.line, cur.character], [hl, hc]);
  const holes = slid.shapes.filter((s) => s.range[0] === hl && s.range[1] <= hc && hc <= s.range[3] && s.class === 'aidl-shape');
  assert.equal(holes.length, 10);
  for (const s of holes) assert.match(slid.svg, new RegExp(`id="${s.id}"[^>]*data-range="${s.range.join(',')}"`));

  // render to DXF through the save dialog (the slider value goes along as --set)
  const outDir = fs.mkdtempSync(path.join(os.tmpdir(), 'aidl-render-'));
  t.after(() => fs.rmSync(outDir, { recursive: true, force: true }));
  const out = path.join(outDir, 'phone.dxf');
  setSaveDialog(vscode.Uri.file(out));
  const r = await vscode.commands.executeCommand('aidl.renderDxf');
  assert.equal(r.code, 0, r.stderr);
  const dxf = fs.readFileSync(out, 'utf8');
  assert.match(dxf, /ENTITIES/);
  assert.match(dxf, /\nCIRCLE\n|\nARC\n/);

  // explain
  await vscode.commands.executeCommand('aidl.explain', 'E0103');
  assert.match(channels['AIDL Explain'], /E0103: unknown function/);

  // restart: stopped, then running again, and the preview asks again
  const before = updates().length;
  await vscode.commands.executeCommand('aidl.restartServer');
  await waitFor(() => status.state === 'running', 60000, 'the restarted server');
  await waitFor(() => updates().length > before, 60000, 'a picture from the new server');
  assert.match(channels.AIDL, /starting .*aidl lsp/);

  panel.dispose();
  await extension.deactivate();
  console.log(`# an edit to its picture in the webview (120 ms debounce included): ${editMs} ms; `
    + `compile ${second.ms} ms`);
});
