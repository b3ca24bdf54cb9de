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
//   2. each workspace folder's virtual environment (.venv, then venv);
//   3. the environment the editor was started from ($VIRTUAL_ENV, $CONDA_PREFIX);
//   4. PATH.
// Returns { command, tried }: command is null when nothing was found; tried lists every place
// looked at, for the error message.
function findServer({ serverPath = '', folders = [], env = process.env } = {}) {
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
  for (const folder of folders) {
    for (const venv of ['.venv', 'venv']) {
      for (const exe of EXE) {
        const hit = check(path.join(folder, venv, bin, exe));
        if (hit) return { command: hit, tried };
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

// The options handed to vscode-languageclient's LanguageClient.
function serverOptions(command, args = ['lsp']) {
  return { command, args, transport: TransportKind.stdio };
}

function clientOptions() {
  return {
    documentSelector: [{ language: 'aidl-cad' }],
    outputChannelName: 'AIDL language server',
  };
}

function notFoundMessage(tried) {
  const shown = tried.slice(0, 8).join(', ') + (tried.length > 8 ? `, ... (${tried.length} places)` : '');
  return 'AIDL: could not find the `aidl` command for the language server. Looked at: ' +
    `${shown}. Install it into the workspace (python3 -m venv .venv && .venv/bin/pip install ` +
    '-e /path/to/aidl) or set "aidl.serverPath" to the full path of `aidl`.';
}

module.exports = { findServer, serverOptions, clientOptions, notFoundMessage, isExecutable };
