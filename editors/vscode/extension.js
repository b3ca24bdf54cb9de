// VS Code extension for AIDL (.aidl, language id `aidl-cad`): highlighting comes from
// syntaxes/aidl.tmLanguage.json, snippets from snippets/aidl.json; everything else from the
// language server `aidl lsp`, found by server.js (aidl.serverPath, else the nearest .venv/venv
// above the workspace or the file, else the active venv, else PATH).
//
// Commands (category AIDL): Open Preview (preview.js, on the server's `aidl/preview`), Restart
// Language Server, Render to SVG / DXF (a save dialog, then `aidl render`), Explain Code
// (`aidl explain` for the diagnostic or code under the cursor), Show Output. A status-bar item
// shows the server's state; the "AIDL" output channel holds the server's log and ours.
// When no `aidl` is found, the places are looked at again every few seconds (and when a
// file named aidl appears in the workspace), so a newly installed server starts by itself.
'use strict';
const vscode = require('vscode');
const path = require('node:path');
const { execFile } = require('node:child_process');
const { LanguageClient, State } = require('vscode-languageclient/node');
const { findServer, serverOptions, clientOptions, notFoundMessage } = require('./server');
const { Preview } = require('./preview');

const POLL = { ms: 3000 };      // how often to look again for `aidl` while none is found

let client;
let command;                    // the `aidl` found (also runs render and explain)
let output;
let status;
let previewButton;
let poller;
let starting;
const previews = new Map();     // uri -> Preview

function log(line) { if (output) output.appendLine(`[aidl-cad] ${line}`); }

function setStatus(state, detail) {
  if (!status) return;
  const icon = { running: '$(check)', starting: '$(sync~spin)', stopped: '$(circle-slash)', missing: '$(error)' }[state];
  status.text = `${icon} AIDL`;
  status.tooltip = detail;
  status.command = state === 'missing' ? 'aidl.restartServer' : 'aidl.showOutput';
  status.state = state;                 // read by the tests
  status.show();
}

function discover() {
  const cfg = vscode.workspace.getConfiguration('aidl');
  const folders = (vscode.workspace.workspaceFolders || [])
    .filter((f) => f.uri.scheme === 'file').map((f) => f.uri.fsPath);
  const files = (vscode.workspace.textDocuments || [])
    .filter((d) => d.languageId === 'aidl-cad' && d.uri.scheme === 'file').map((d) => d.uri.fsPath);
  return findServer({ serverPath: cfg.get('serverPath', ''), folders, files });
}

async function start() {
  const found = discover();
  if (!found.command) {
    command = undefined;
    const msg = notFoundMessage(found.tried);
    log(msg);
    setStatus('missing', 'No `aidl` command found: click to look again. ' +
      'Install it into the workspace (.venv) or set "aidl.serverPath".');
    watchForServer();
    vscode.window.showErrorMessage(msg, 'Open Settings', 'Look Again').then((pick) => {
      if (pick === 'Open Settings') vscode.commands.executeCommand('workbench.action.openSettings', 'aidl.serverPath');
      else if (pick === 'Look Again') restart();
    });
    return;
  }
  stopWatching();
  command = found.command;
  const cfg = vscode.workspace.getConfiguration('aidl');
  const args = cfg.get('serverArgs', ['lsp']);
  log(`starting ${command} ${args.join(' ')}`);
  setStatus('starting', `Starting ${command} ${args.join(' ')}`);
  client = new LanguageClient('aidl', 'AIDL language server', serverOptions(command, args),
    clientOptions(output, cfg));
  client.onDidChangeState((e) => {
    if (e.newState === State.Running) setStatus('running', `AIDL language server: ${command} (click for its log)`);
    else if (e.newState === State.Starting) setStatus('starting', `Starting ${command}`);
    else setStatus('stopped', 'The AIDL language server stopped (click for its log; "AIDL: Restart Language Server")');
  });
  try {
    await client.start();
    for (const p of previews.values()) p.schedule(0);
  } catch (err) {
    setStatus('stopped', `${command} did not start`);
    vscode.window.showErrorMessage(
      `AIDL: \`${command} ${args.join(' ')} --stdio\` did not start (${err.message || err}). ` +
      'See the "AIDL" output; set "aidl.serverPath" to another `aidl`.');
  }
}

// Look again for `aidl` every POLL.ms (cheap: a few file checks) and when one appears in the
// workspace, until found.
let watcher;
function watchForServer() {
  if (poller) return;
  const again = () => {
    if (client || starting) return;
    if (discover().command) restart();
  };
  poller = setInterval(again, POLL.ms);
  if (poller.unref) poller.unref();
  try {
    watcher = vscode.workspace.createFileSystemWatcher('**/{.venv,venv}/{bin,Scripts}/aidl*');
    watcher.onDidCreate(again);
    watcher.onDidChange(again);
  } catch (e) {
    watcher = undefined;
  }
}

function stopWatching() {
  if (poller) clearInterval(poller);
  poller = undefined;
  if (watcher) watcher.dispose();
  watcher = undefined;
}

async function stop() {
  const c = client;
  client = undefined;
  if (c) {
    try { await c.stop(); } catch (e) { log(`stopping the server: ${e.message || e}`); }
  }
}

async function restart() {
  if (starting) return starting;
  starting = (async () => {
    await stop();
    await start();
  })().finally(() => { starting = undefined; });
  return starting;
}

function activeAidl(uri) {
  if (uri instanceof vscode.Uri) {
    return vscode.workspace.textDocuments.find((d) => d.uri.toString() === uri.toString());
  }
  const ed = vscode.window.activeTextEditor;
  if (ed && ed.document.languageId === 'aidl-cad') return ed.document;
  for (const p of previews.values()) if (p.panel.active) return p.document;
  return undefined;
}

function openPreview(uri) {
  const doc = activeAidl(uri);
  if (!doc) {
    vscode.window.showInformationMessage('AIDL: open a .aidl file to preview it.');
    return undefined;
  }
  const key = doc.uri.toString();
  let p = previews.get(key);
  if (p) { p.reveal(); return p; }
  p = new Preview(doc, () => client, log, (gone) => previews.delete(gone.uri), extensionPath);
  previews.set(key, p);
  return p;
}

function run(args, { cwd, input } = {}) {
  return new Promise((resolve) => {
    const child = execFile(command, args, { cwd, maxBuffer: 64 * 1024 * 1024, timeout: 120000 },
      (err, stdout, stderr) => resolve({ code: err ? (err.code || 1) : 0, stdout, stderr, err }));
    if (input !== undefined) child.stdin.end(input);
  });
}

// Render to `format` (svg, dxf, ...) through `aidl render`: a save dialog beside the file; the
// editor's text (saved or not) with the preview's slider values as --set.
async function render(format = 'svg', uri) {
  const doc = activeAidl(uri);
  if (!doc) { vscode.window.showInformationMessage('AIDL: open a .aidl file to render it.'); return undefined; }
  if (!command) { vscode.window.showErrorMessage('AIDL: no `aidl` command found (see "AIDL: Restart Language Server").'); return undefined; }
  const fmt = String(format).toLowerCase().replace(/^\./, '');
  const file = doc.uri.scheme === 'file' ? doc.uri.fsPath : path.join(folderOf(doc), 'untitled.aidl');
  const target = await vscode.window.showSaveDialog({
    defaultUri: vscode.Uri.file(file.replace(/\.aidl$/i, '') + '.' + fmt),
    filters: { [fmt.toUpperCase()]: [fmt] },
    title: `Render ${path.basename(file)} to ${fmt.toUpperCase()}`,
  });
  if (!target) return undefined;
  const p = previews.get(doc.uri.toString());
  const sets = Object.entries((p && p.values) || {}).flatMap(([k, v]) => ['--set', `${k}=${v}`]);
  const saved = doc.uri.scheme === 'file' && !doc.isDirty;
  const args = ['render', saved ? file : '-', '-o', target.fsPath, ...sets];
  log(`${command} ${args.join(' ')}`);
  const r = await run(args, { cwd: path.dirname(file), input: saved ? undefined : doc.getText() });
  if (r.code !== 0) {
    output.append(r.stderr || String(r.err));
    const first = (r.stderr || '').split('\n').find((l) => l.trim()) || String(r.err);
    vscode.window.showErrorMessage(`AIDL: render failed: ${first}`, 'Show Output').then((pick) => {
      if (pick) output.show(true);
    });
    return r;
  }
  vscode.window.showInformationMessage(`AIDL: wrote ${target.fsPath}`);
  return r;
}

function folderOf(doc) {
  const f = (vscode.workspace.workspaceFolders || [])[0];
  return f ? f.uri.fsPath : require('node:os').homedir();
}

// The code to explain: an AIDL diagnostic under the cursor, else a code (E0103, W0507) at the
// cursor, else one typed in.
function codeAtCursor() {
  const ed = vscode.window.activeTextEditor;
  if (!ed) return undefined;
  const pos = ed.selection.active;
  const diags = vscode.languages.getDiagnostics(ed.document.uri) || [];
  const within = (r) => (pos.line > r.start.line || (pos.line === r.start.line && pos.character >= r.start.character))
    && (pos.line < r.end.line || (pos.line === r.end.line && pos.character <= r.end.character));
  for (const d of diags) {
    const code = typeof d.code === 'object' && d.code ? d.code.value : d.code;
    if (within(d.range) && /^[EW]\d{4}$/.test(String(code))) return String(code);
  }
  const line = ed.document.lineAt(pos.line).text;
  for (const m of line.matchAll(/\b[EW]\d{4}\b/g)) {
    if (m.index <= pos.character && pos.character <= m.index + m[0].length) return m[0];
  }
  const onLine = diags.find((d) => d.range.start.line <= pos.line && pos.line <= d.range.end.line);
  if (onLine) {
    const code = typeof onLine.code === 'object' && onLine.code ? onLine.code.value : onLine.code;
    if (/^[EW]\d{4}$/.test(String(code))) return String(code);
  }
  return undefined;
}

let explainChannel;
async function explain(code) {
  if (!command) { vscode.window.showErrorMessage('AIDL: no `aidl` command found (see "AIDL: Restart Language Server").'); return undefined; }
  let c = typeof code === 'string' ? code : codeAtCursor();
  if (!c) {
    c = await vscode.window.showInputBox({ prompt: 'AIDL diagnostic code to explain', placeHolder: 'E0103',
      validateInput: (v) => (/^\s*[EWew]\d{4}\s*$/.test(v) ? undefined : 'a code like E0103 or W0507') });
    if (!c) return undefined;
  }
  c = c.trim().toUpperCase();
  const r = await run(['explain', c]);
  if (!explainChannel) explainChannel = vscode.window.createOutputChannel('AIDL Explain');
  explainChannel.clear();
  explainChannel.append(r.code === 0 ? r.stdout : (r.stderr || r.stdout || String(r.err)));
  explainChannel.show(true);
  return r;
}

let extensionPath = null;        // the extension's folder (dist/webview/three.js: the preview's 3D view)

async function activate(context) {
  extensionPath = context.extensionPath || null;
  output = vscode.window.createOutputChannel('AIDL');
  status = vscode.window.createStatusBarItem(vscode.StatusBarAlignment.Right, 100);
  status.name = 'AIDL language server';
  previewButton = vscode.window.createStatusBarItem(vscode.StatusBarAlignment.Right, 99);
  previewButton.name = 'AIDL preview';
  previewButton.text = '$(open-preview) Preview';
  previewButton.tooltip = 'AIDL: Open Preview (the picture beside the code, with param sliders)';
  previewButton.command = 'aidl.openPreview';
  const showButton = (ed) => {
    if (ed && ed.document && ed.document.languageId === 'aidl-cad') previewButton.show(); else previewButton.hide();
  };
  showButton(vscode.window.activeTextEditor);
  const reg = (name, fn) => context.subscriptions.push(vscode.commands.registerCommand(name, fn));
  reg('aidl.openPreview', (uri) => openPreview(uri));
  reg('aidl.restartServer', () => restart());
  reg('aidl.render', (format, uri) => render(format, uri));
  reg('aidl.renderSvg', (uri) => render('svg', uri));
  reg('aidl.renderDxf', (uri) => render('dxf', uri));
  reg('aidl.explain', (code) => explain(code));
  reg('aidl.showOutput', () => output.show(true));
  context.subscriptions.push(output, status, previewButton,
    vscode.window.onDidChangeActiveTextEditor(showButton),
    vscode.workspace.onDidOpenTextDocument((d) => {
      if (d.languageId === 'aidl-cad' && !client && !starting && poller && d.uri.scheme === 'file') {
        if (discover().command) restart();          // a file beside a venv the workspace lacked
      }
    }),
    vscode.workspace.onDidChangeConfiguration(async (e) => {
      if (e.affectsConfiguration('aidl')) await restart();
    }),
    { dispose: () => { stopWatching(); previews.forEach((p) => p.dispose()); } });
  await restart();
  return { getClient: () => client, previews, openPreview, status: () => status, POLL };
}

async function deactivate() {
  stopWatching();
  await stop();
}

module.exports = { activate, deactivate, POLL };
