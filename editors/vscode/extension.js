// VS Code extension for AIDL (.aidl, language id `aidl-cad`): highlighting comes from
// syntaxes/aidl.tmLanguage.json; everything else from the language server `aidl lsp`, found by
// server.js (aidl.serverPath, else the workspace's .venv, else the active venv, else PATH).
'use strict';
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');
const { findServer, serverOptions, clientOptions, notFoundMessage } = require('./server');

let client;

async function start() {
  const cfg = vscode.workspace.getConfiguration('aidl');
  const folders = (vscode.workspace.workspaceFolders || [])
    .filter((f) => f.uri.scheme === 'file').map((f) => f.uri.fsPath);
  const { command, tried } = findServer({ serverPath: cfg.get('serverPath', ''), folders });
  if (!command) {
    vscode.window.showErrorMessage(notFoundMessage(tried));
    return;
  }
  const args = cfg.get('serverArgs', ['lsp']);
  client = new LanguageClient('aidl', 'AIDL language server', serverOptions(command, args),
    clientOptions());
  try {
    await client.start();
  } catch (err) {
    vscode.window.showErrorMessage(
      `AIDL: \`${command} ${args.join(' ')} --stdio\` did not start (${err.message || err}). ` +
      'See the "AIDL language server" output; set "aidl.serverPath" to another `aidl`.');
  }
}

async function activate(context) {
  await start();
  context.subscriptions.push(vscode.workspace.onDidChangeConfiguration(async (e) => {
    if (e.affectsConfiguration('aidl')) {
      if (client) await client.stop();
      client = undefined;
      await start();
    }
  }));
}

async function deactivate() {
  if (client) await client.stop();
}

module.exports = { activate, deactivate };
