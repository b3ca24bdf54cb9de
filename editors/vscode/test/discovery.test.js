// Finding `aidl`: the nearest .venv/venv above the workspace folder or the file (server.js), and
// the extension picking up a server installed after it started, without a window reload; the
// snippets, each expanded with its defaults, compile with `aidl check`.
'use strict';
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { execFileSync } = require('node:child_process');

const { vscode, ROOT, waitFor } = require('./helpers');
const { findServer } = require('../server');

const AIDL = path.join(ROOT, '.venv', 'bin', 'aidl');
const PYTHON = path.join(ROOT, '.venv', 'bin', 'python');

function fakeAidl(dir) {
  fs.mkdirSync(dir, { recursive: true });
  fs.writeFileSync(path.join(dir, 'aidl'), '#!/bin/sh\n');
  fs.chmodSync(path.join(dir, 'aidl'), 0o755);
  return path.join(dir, 'aidl');
}

test('findServer walks up from the workspace folder, then from the file, to the nearest venv', (t) => {
  const tmp = fs.realpathSync(fs.mkdtempSync(path.join(os.tmpdir(), 'aidl-walk-')));
  t.after(() => fs.rmSync(tmp, { recursive: true, force: true }));
  const env = { PATH: path.join(tmp, 'nothing') };
  const top = fakeAidl(path.join(tmp, 'proj', '.venv', 'bin'));
  const nested = fakeAidl(path.join(tmp, 'proj', 'sub', 'venv', 'bin'));
  fs.mkdirSync(path.join(tmp, 'proj', 'sub', 'deep', 'er'), { recursive: true });
  fs.mkdirSync(path.join(tmp, 'proj', 'docs'), { recursive: true });
  // from a folder two levels below the project: the project's .venv
  assert.equal(findServer({ folders: [path.join(tmp, 'proj', 'docs')], env }).command, top);
  // nearest first: sub/venv for a folder inside sub
  assert.equal(findServer({ folders: [path.join(tmp, 'proj', 'sub', 'deep', 'er')], env }).command, nested);
  // no workspace folder: the open file's folder
  const file = path.join(tmp, 'proj', 'sub', 'deep', 'part.aidl');
  assert.equal(findServer({ files: [file], env }).command, nested);
  // a workspace with no venv above it, a file with one: the file's
  fs.mkdirSync(path.join(tmp, 'elsewhere'));
  const r = findServer({ folders: [path.join(tmp, 'elsewhere')], files: [file], env });
  assert.equal(r.command, nested);
  assert.ok(r.tried.includes(path.join(tmp, 'elsewhere', '.venv', 'bin', 'aidl')));
  assert.ok(r.tried.includes(path.join(tmp, '.venv', 'bin', 'aidl')));
  // each directory is looked at once
  assert.equal(r.tried.filter((t) => t === path.join(tmp, 'venv', 'bin', 'aidl')).length, 1);
});

test('a server installed after activation is picked up without a reload', async (t) => {
  const tmp = fs.realpathSync(fs.mkdtempSync(path.join(os.tmpdir(), 'aidl-late-')));
  t.after(() => fs.rmSync(tmp, { recursive: true, force: true }));
  const ws = path.join(tmp, 'ws');
  fs.mkdirSync(ws);
  const saved = { PATH: process.env.PATH, VIRTUAL_ENV: process.env.VIRTUAL_ENV, CONDA_PREFIX: process.env.CONDA_PREFIX };
  process.env.PATH = path.join(tmp, 'empty');
  delete process.env.VIRTUAL_ENV;
  delete process.env.CONDA_PREFIX;
  const extension = require('../extension');
  extension.POLL.ms = 100;
  const { messages, setFolders } = vscode._shim;
  setFolders([ws]);
  try {
    const api = await extension.activate({ subscriptions: [] });
    const status = api.status();
    assert.equal(status.state, 'missing');
    assert.equal(api.getClient(), undefined);
    const msg = messages.find(([kind, m]) => kind === 'error' && /no `aidl` command found/.test(m));
    assert.ok(msg, JSON.stringify(messages));
    assert.match(msg[1], /\.venv\/bin\/pip install/);
    assert.match(msg[1], /no reload needed/);
    assert.match(msg[1], /aidl\.serverPath/);
    // install: the workspace gets a .venv whose bin/aidl is the repository's
    fs.mkdirSync(path.join(ws, '.venv', 'bin'), { recursive: true });
    fs.symlinkSync(AIDL, path.join(ws, '.venv', 'bin', 'aidl'));
    await waitFor(() => status.state === 'running', 60000, 'the new server to run');
    assert.ok(api.getClient().isRunning());
    await extension.deactivate();
  } finally {
    await extension.deactivate();
    Object.entries(saved).forEach(([k, v]) => { if (v === undefined) delete process.env[k]; else process.env[k] = v; });
  }
});

// Where each snippet goes to be checked: top-level ones as they are, others inside a solid.
const CONTEXT = {
  solid: (s) => s,
  assembly: (s) => s,
  param: (s) => `${s}\nsolid t {\n    c = Circle(center=(0, 0), radius=width / 4)\n}\n`,
  def: (s) => `${s}\nsolid t {\n    b = boss()\n}\n`,
  Coincident: (s) => `drawing t {\n    a = Line((0, 0), (10, 0))\n    b = Line((10, 1), (10, 10))\n    ${s}\n}\n`,
  Distance: (s) => `drawing t {\n    a = Circle(center=(0, 0), radius=2)\n    b = Circle(center=(15, 0), radius=2)\n    ${s}\n}\n`,
  drawing: (s) => `assembly t {\n    solid p {\n        c = Circle(center=(0, 0), radius=5)\n    }\n    ${s.replace(/\n/g, '\n    ')}\n}\n`,
  Text: (s) => `drawing t {\n    ${s}\n}\n`,
  Line: (s) => `drawing t {\n    ${s}\n}\n`,
  Arc: (s) => `drawing t {\n    ${s}\n}\n`,
};
const BODY = (s) => `solid t {\n    base = Rectangle(center=(0, 0), width=100, height=100)\n    ${s.replace(/\n/g, '\n    ')}\n}\n`;

function expand(body) {
  return body.join('\n').replace(/\$\{\d+:([^}]*)\}/g, '$1').replace(/\$\d+/g, '').replace(/\t/g, '    ');
}

test('every snippet, expanded with its defaults, compiles', (t) => {
  const snippets = JSON.parse(fs.readFileSync(path.join(__dirname, '..', 'snippets', 'aidl.json'), 'utf8'));
  const pkg = JSON.parse(fs.readFileSync(path.join(__dirname, '..', 'package.json'), 'utf8'));
  assert.deepEqual(pkg.contributes.snippets, [{ language: 'aidl-cad', path: './snippets/aidl.json' }]);
  assert.equal(pkg.contributes.configurationDefaults['[aidl-cad]']['editor.tabSize'], 4);
  // hovers fence their code as `aidl_cad` (analysis.py): an alias of the language, so VS Code
  // colours it with this grammar
  assert.ok(pkg.contributes.languages[0].aliases.includes('aidl_cad'));
  const analysis = fs.readFileSync(path.join(ROOT, 'aidl_lang', 'editor', 'lsp', 'analysis.py'), 'utf8');
  assert.ok(analysis.includes('```aidl_cad\\n') && !analysis.includes('```aidl-cad'));
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'aidl-snip-'));
  t.after(() => fs.rmSync(tmp, { recursive: true, force: true }));
  assert.ok(Object.keys(snippets).length >= 15);
  const files = [];
  for (const [name, s] of Object.entries(snippets)) {
    assert.ok(s.prefix && s.description && Array.isArray(s.body), name);
    const file = path.join(tmp, `${name}.aidl`);
    fs.writeFileSync(file, (CONTEXT[name] || BODY)(expand(s.body)));
    files.push(file);
  }
  // all in one process (aidl_lang.compile, what `aidl check` runs): each file's diagnostics
  const report = execFileSync(PYTHON, ['-c', `
import sys, aidl_lang
for f in sys.argv[1:]:
    r = aidl_lang.compile(path=f)
    print(f, "ok" if r.ok and not r.diagnostics else [(d.code, d.message) for d in r.diagnostics])
`, ...files], { encoding: 'utf8' });
  const bad = report.split('\n').filter((l) => l && !l.endsWith(' ok'));
  assert.deepEqual(bad, [], bad.map((l) => `${l}\n${fs.readFileSync(l.split(' ')[0], 'utf8')}`).join('\n'));
  assert.equal(report.split('\n').filter((l) => l.endsWith(' ok')).length, files.length);
});
