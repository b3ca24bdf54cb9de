// A minimal stand-in for the `vscode` module, enough for vscode-languageclient to start a
// server, open a document and hand diagnostics to a diagnostic collection. Anything not modelled
// here is a harmless stub (a function returning a disposable), so that the client's feature
// registration runs; what the test checks (documents, diagnostics, output) is real.
'use strict';
const { EventEmitter: NodeEmitter } = require('node:events');
const url = require('node:url');

function stub(name) {
  const fn = function () { return stub(`${name}()`); };
  return new Proxy(fn, {
    get(target, prop) {
      if (prop === 'then' || typeof prop === 'symbol') return undefined;
      if (prop === 'dispose') return () => {};
      if (prop === 'toString') return () => `[stub ${name}]`;
      return stub(`${name}.${String(prop)}`);
    },
    construct() { return stub(`new ${name}`); },
  });
}

class Disposable {
  constructor(fn) { this._fn = fn; }
  static from(...items) { return new Disposable(() => items.forEach((d) => d && d.dispose && d.dispose())); }
  dispose() { if (this._fn) this._fn(); this._fn = undefined; }
}

class EventEmitter {
  constructor() { this._e = new NodeEmitter(); this._e.setMaxListeners(0); }
  get event() {
    return (listener, thisArg) => {
      const f = (x) => listener.call(thisArg, x);
      this._e.on('fire', f);
      return new Disposable(() => this._e.off('fire', f));
    };
  }
  fire(x) { this._e.emit('fire', x); }
  dispose() { this._e.removeAllListeners(); }
}

class Uri {
  constructor(scheme, fsPath) { this.scheme = scheme; this.fsPath = fsPath; this.path = fsPath; }
  static file(p) { return new Uri('file', p); }
  static parse(s) { return s.startsWith('file:') ? new Uri('file', url.fileURLToPath(s)) : new Uri('untitled', s); }
  toString() { return this.scheme === 'file' ? url.pathToFileURL(this.fsPath).href : this.fsPath; }
  toJSON() { return this.toString(); }
  with() { return this; }
}

class Position { constructor(line, character) { this.line = line; this.character = character; } }
class Range {
  constructor(a, b, c, d) {
    if (typeof a === 'number') { this.start = new Position(a, b); this.end = new Position(c, d); } else { this.start = a; this.end = b; }
  }
}
class Diagnostic {
  constructor(range, message, severity) { this.range = range; this.message = message; this.severity = severity; }
}
class Location { constructor(uri, range) { this.uri = uri; this.range = range; } }
class DiagnosticRelatedInformation { constructor(location, message) { this.location = location; this.message = message; } }
class MarkdownString { constructor(value) { this.value = value || ''; } appendMarkdown(s) { this.value += s; return this; } }
class CancellationTokenSource {
  constructor() { const e = new EventEmitter(); this.token = { isCancellationRequested: false, onCancellationRequested: e.event }; this._e = e; }
  cancel() { this.token.isCancellationRequested = true; this._e.fire(); }
  dispose() {}
}
class CancellationError extends Error {}

class Selection extends Range {
  constructor(a, b, c, d) { super(a, b, c, d); this.anchor = this.start; this.active = this.end; }
}

// what the test drives and observes
const events = {
  open: new EventEmitter(), close: new EventEmitter(), change: new EventEmitter(),
  save: new EventEmitter(), config: new EventEmitter(), folders: new EventEmitter(),
  selection: new EventEmitter(), activeEditor: new EventEmitter(),
};
const collections = [];
const output = [];
const channels = {};            // name -> the text appended to that output channel
const messages = [];
const commands = new Map();     // registered command -> its callback
const panels = [];              // webview panels: { html, posted: [messages], receive(msg), ... }
const statusItems = [];
let settings = {};
let saveDialog;                 // what showSaveDialog answers

function createDiagnosticCollection(name) {
  const map = new Map();
  const em = new EventEmitter();
  const col = {
    name,
    set(uri, diags) {
      if (Array.isArray(uri)) { uri.forEach(([u, d]) => col.set(u, d)); return; }
      map.set(uri.toString(), diags || []);
      em.fire({ uri, diagnostics: diags || [] });
    },
    get(uri) { return map.get(uri.toString()); },
    delete(uri) { map.delete(uri.toString()); },
    clear() { map.clear(); },
    forEach(f) { map.forEach((d, u) => f(Uri.parse(u), d, col)); },
    has(uri) { return map.has(uri.toString()); },
    dispose() {},
    onDidChange: em.event,
  };
  collections.push(col);
  return col;
}

function outputChannel(name) {
  channels[name] = channels[name] || '';
  const put = (s) => { output.push(String(s)); channels[name] += String(s); };
  const ch = {
    name,
    append: (s) => put(s), appendLine: (s) => put(`${s}\n`),
    replace(s) { channels[name] = String(s); }, clear() { channels[name] = ''; }, show() {}, hide() {}, dispose() {},
    trace: (s) => output.push(String(s)), debug: (s) => output.push(String(s)), info: (s) => output.push(String(s)),
    warn: (s) => output.push(String(s)), error: (s) => output.push(String(s)),
    logLevel: 0, onDidChangeLogLevel: new EventEmitter().event,
  };
  return ch;
}

// A webview panel: the HTML the extension sets and every message it posts are kept;
// receive(msg) plays a message from the page.
function createWebviewPanel(viewType, title, showOptions, options) {
  const fromPage = new EventEmitter();
  const disposed = new EventEmitter();
  const panel = {
    viewType, title, options, showOptions, active: true, visible: true, posted: [], disposed: false,
    webview: {
      html: '', cspSource: 'vscode-resource:', options,
      postMessage: async (m) => { panel.posted.push(JSON.parse(JSON.stringify(m))); return true; },
      onDidReceiveMessage: fromPage.event,
      asWebviewUri: (u) => u,
    },
    reveal() { panel.revealed = (panel.revealed || 0) + 1; },
    onDidDispose: disposed.event,
    onDidChangeViewState: () => new Disposable(),
    dispose() { if (!panel.disposed) { panel.disposed = true; disposed.fire(); } },
    receive: (m) => fromPage.fire(m),
  };
  panels.push(panel);
  return panel;
}

function createStatusBarItem(alignment, priority) {
  const item = { alignment, priority, text: '', tooltip: '', command: undefined, visible: false,
    show() { item.visible = true; }, hide() { item.visible = false; }, dispose() {} };
  statusItems.push(item);
  return item;
}

const workspace = new Proxy({
  workspaceFolders: undefined,
  textDocuments: [],
  openTextDocument: async (u) => workspace.textDocuments.find((d) => d.uri.toString() === u.toString()),
  notebookDocuments: [],
  getConfiguration: (section) => ({
    get: (key, dflt) => {
      const k = section ? `${section}.${key}` : key;
      return k in settings ? settings[k] : dflt;
    },
    has: () => false, inspect: () => undefined, update: async () => {},
  }),
  getWorkspaceFolder: () => undefined,
  onDidOpenTextDocument: events.open.event,
  onDidCloseTextDocument: events.close.event,
  onDidChangeTextDocument: events.change.event,
  onDidSaveTextDocument: events.save.event,
  onDidChangeConfiguration: events.config.event,
  onDidChangeWorkspaceFolders: events.folders.event,
  createFileSystemWatcher: () => ({ onDidCreate: () => new Disposable(), onDidChange: () => new Disposable(), onDidDelete: () => new Disposable(), dispose() {} }),
}, { get: (t, p) => (p in t ? t[p] : (typeof p === 'string' && /^on(Did|Will)/.test(p) ? () => new Disposable() : stub(`workspace.${String(p)}`))) });

const languages = new Proxy({
  createDiagnosticCollection,
  getDiagnostics: (uri) => collections.flatMap((c) => c.get(uri) || []),
  match: (selector, doc) => {
    const sels = Array.isArray(selector) ? selector : [selector];
    return sels.some((s) => (typeof s === 'string' ? s === doc.languageId : (!s.language || s.language === doc.languageId)
      && (!s.scheme || s.scheme === doc.uri.scheme))) ? 10 : 0;
  },
}, { get: (t, p) => (p in t ? t[p] : (typeof p === 'string' && p.startsWith('register') ? () => new Disposable() : stub(`languages.${String(p)}`))) });

const window = new Proxy({
  createOutputChannel: outputChannel,
  createWebviewPanel,
  createStatusBarItem,
  showSaveDialog: async () => saveDialog,
  showInputBox: async () => undefined,
  showTextDocument: async (doc) => { const ed = { document: doc, selection: new Selection(0, 0, 0, 0), revealRange() {} }; window.activeTextEditor = ed; return ed; },
  onDidChangeTextEditorSelection: events.selection.event,
  onDidChangeActiveTextEditor: events.activeEditor.event,
  showErrorMessage: async (m) => { messages.push(['error', m]); return undefined; },
  showWarningMessage: async (m) => { messages.push(['warning', m]); return undefined; },
  showInformationMessage: async (m) => { messages.push(['info', m]); return undefined; },
  activeTextEditor: undefined,
  visibleTextEditors: [],
  tabGroups: { all: [], onDidChangeTabs: () => new Disposable(), onDidChangeTabGroups: () => new Disposable() },
}, { get: (t, p) => (p in t ? t[p] : (typeof p === 'string' && p.startsWith('onDid') ? () => new Disposable() : stub(`window.${String(p)}`))) });

// A text document as the client sees it.
function textDocument(fsPath, text, languageId = 'aidl-cad', version = 1) {
  const lines = text.split('\n');
  return {
    uri: Uri.file(fsPath), fileName: fsPath, languageId, version, isClosed: false, isDirty: false,
    isUntitled: false, lineCount: lines.length, eol: 1,
    getText: () => text,
    lineAt: (i) => ({ text: lines[typeof i === 'number' ? i : i.line] }),
    save: async () => true,
  };
}

const base = {
  version: '1.95.0',
  env: { appName: 'vscode-shim', language: 'en', machineId: 'shim', sessionId: 'shim', uiKind: 1, openExternal: async () => true },
  commands: new Proxy({
    registerCommand: (name, fn) => { commands.set(name, fn); return new Disposable(() => commands.delete(name)); },
    executeCommand: async (name, ...args) => (commands.has(name) ? commands.get(name)(...args) : undefined),
  }, { get: (t, p) => (p in t ? t[p] : stub(`commands.${String(p)}`)) }),
  workspace, languages, window,
  Disposable, EventEmitter, Uri, Position, Range, Diagnostic, Location, DiagnosticRelatedInformation,
  MarkdownString, CancellationTokenSource, CancellationError, Selection,
  ViewColumn: { Active: -1, Beside: -2, One: 1, Two: 2 },
  StatusBarAlignment: { Left: 1, Right: 2 },
  TextEditorRevealType: { Default: 0, InCenter: 1, InCenterIfOutsideViewport: 2, AtTop: 3 },
  DiagnosticSeverity: { Error: 0, Warning: 1, Information: 2, Hint: 3 },
  DiagnosticTag: { Unnecessary: 1, Deprecated: 2 },
  ProgressLocation: { SourceControl: 1, Window: 10, Notification: 15 },
  TextDocumentSaveReason: { Manual: 1, AfterDelay: 2, FocusOut: 3 },
  ConfigurationTarget: { Global: 1, Workspace: 2, WorkspaceFolder: 3 },
  // test hooks (not part of VS Code)
  _shim: {
    events, collections, output, channels, messages, commands, panels, statusItems, textDocument,
    setSettings: (s) => { settings = s; },
    setSaveDialog: (u) => { saveDialog = u; },
    setFolders: (paths) => { workspace.workspaceFolders = paths.map((p, index) => ({ uri: Uri.file(p), name: p, index })); },
  },
};

module.exports = new Proxy(base, {
  get: (t, p) => (p in t ? t[p] : (typeof p === 'symbol' || p === 'then' ? undefined : stub(String(p)))),
});
