// Finding and launching `aidl lsp`: no `vscode` import here, so the node tests use exactly what
// the extension uses (test/client.test.js starts the real vscode-languageclient with it).
'use strict';
const fs = require('node:fs');
const path = require('node:path');
const { TransportKind } = require('vscode-languageclient/node');

const WIN = process.platform === 'win32';
const EXE = WIN ? ['aidl.exe', 'aidl.cmd', 'aidl'] : ['aidl'];

function isExecutable(p) {
  try {
    const st = fs.statSync(p);
    if (!st.isFile()) return false;
    if (!WIN) fs.accessSync(p, fs.constants.X_OK);
    return true;
  } catch (e) {
    return false;
  }
}

// Where to look for the `aidl` command, in order, the way Python tooling does:
//   1. the `aidl.serverPath` setting (a path, or a command looked up on PATH; `~` and
//      `${workspaceFolder}` are expanded);
//   2. a virtual environment (.venv, then venv) in each workspace folder or any folder above
//      it, nearest first; then the same from each open file's folder (a file outside the
//      workspace, or a project nested in it);
//   3. the environment the editor was started from ($VIRTUAL_ENV, $CONDA_PREFIX);
//   4. PATH.
// Returns { command, tried }: command is null when nothing was found; tried lists every place
// looked at, for the error message.
function findServer({ serverPath = '', folders = [], files = [], env = process.env } = {}) {
  const tried = [];
  const check = (p) => { tried.push(p); return isExecutable(p) ? p : null; };
  const onPath = (name) => {
    for (const dir of (env.PATH || '').split(path.delimiter).filter(Boolean)) {
      const hit = check(path.join(dir, name));
      if (hit) return hit;
    }
    return null;
  };
  const bin = WIN ? 'Scripts' : 'bin';
  if (serverPath) {
    const p = serverPath.replace(/^~(?=$|[\\/])/, env.HOME || '~')
      .replace(/\$\{workspaceFolder\}/g, folders[0] || '.');
    if (p.includes('/') || p.includes('\\')) {
      const abs = path.isAbsolute(p) ? p : path.resolve(folders[0] || '.', p);
      return { command: check(abs), tried };
    }
    return { command: onPath(p), tried: tried.length ? tried : [`${p} on PATH (empty)`] };
  }
  const seen = new Set();
  for (const start of [...folders, ...files.map((f) => path.dirname(f))]) {
    for (const dir of ancestors(path.resolve(start))) {
      if (seen.has(dir)) break;            // the rest of this walk was looked at already
      seen.add(dir);
      for (const venv of ['.venv', 'venv']) {
        for (const exe of EXE) {
          const hit = check(path.join(dir, venv, bin, exe));
          if (hit) return { command: hit, tried };
        }
      }
    }
  }
  for (const prefix of [env.VIRTUAL_ENV, env.CONDA_PREFIX].filter(Boolean)) {
    for (const exe of EXE) {
      const hit = check(path.join(prefix, bin, exe));
      if (hit) return { command: hit, tried };
    }
  }
  for (const exe of EXE) {
    const hit = onPath(exe);
    if (hit) return { command: hit, tried };
  }
  if (!(env.PATH || '').trim()) tried.push('aidl on PATH (PATH is empty)');
  return { command: null, tried };
}

// `dir`, its parent, ... up to the file system's root.
function ancestors(dir) {
  const out = [dir];
  for (let d = dir, up = path.dirname(d); up !== d; d = up, up = path.dirname(d)) out.push(up);
  return out;
}

// The options handed to vscode-languageclient's LanguageClient.
function serverOptions(command, args = ['lsp']) {
  return { command, args, transport: TransportKind.stdio };
}

// outputChannel: where the server's log (window/logMessage, stderr) goes; the extension passes
// its "AIDL" channel, so its own messages and the server's are in one place.
// settings: the "aidl" section (vscode.workspace.getConfiguration('aidl')); the server reads
// aidl.inlayHints.enabled and aidl.codeLens.enabled from the initialization options, then from
// each workspace/didChangeConfiguration the client sends for the "aidl" section.
function clientOptions(outputChannel, settings) {
  const opts = { documentSelector: [{ language: 'aidl-cad' }], synchronize: { configurationSection: 'aidl' } };
  if (settings) {
    opts.initializationOptions = { aidl: {
      inlayHints: { enabled: settings.get('inlayHints.enabled', true) },
      codeLens: { enabled: settings.get('codeLens.enabled', true) },
    } };
  }
  if (outputChannel) opts.outputChannel = outputChannel;
  else opts.outputChannelName = 'AIDL';
  return opts;
}

function notFoundMessage(tried) {
  const shown = tried.slice(0, 6).join(', ') + (tried.length > 6 ? `, ... (${tried.length} places)` : '');
  return 'AIDL: no `aidl` command found, so there are no diagnostics, hover or preview. ' +
    'Install it into the workspace: `python3 -m venv .venv && .venv/bin/pip install -e /path/to/aidl` ' +
    '(it is picked up within seconds, no reload needed; or run "AIDL: Restart Language Server"), ' +
    `or set "aidl.serverPath" to the full path of \`aidl\`. Looked at: ${shown}.`;
}

module.exports = { findServer, serverOptions, clientOptions, notFoundMessage, isExecutable, ancestors };
