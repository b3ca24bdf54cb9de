// VS Code extension for AIDL (.aidl, language id `aidl-cad`): highlighting comes from
// syntaxes/aidl.tmLanguage.json; everything else from the language server `aidl lsp`.
'use strict';
const vscode = require('vscode');
const { LanguageClient, TransportKind } = require('vscode-languageclient/node');

let client;

async function start() {
  const cfg = vscode.workspace.getConfiguration('aidl');
  const command = cfg.get('serverPath', 'aidl');
  const args = cfg.get('serverArgs', ['lsp']);
  const serverOptions = { command, args, transport: TransportKind.stdio };
  const clientOptions = {
    documentSelector: [{ language: 'aidl-cad' }],
    outputChannelName: 'AIDL language server',
  };
  client = new LanguageClient('aidl', 'AIDL language server', serverOptions, clientOptions);
  try {
    await client.start();
  } catch (err) {
    vscode.window.showErrorMessage(
      `AIDL: could not start \`${command} ${args.join(' ')}\` (${err.message || err}). ` +
      'Install the aidl package (pip install -e .) or set "aidl.serverPath".');
  }
}

async function activate(context) {
  await start();
  context.subscriptions.push(vscode.workspace.onDidChangeConfiguration(async (e) => {
    if (e.affectsConfiguration('aidl')) {
      if (client) await client.stop();
      await start();
    }
  }));
}

async function deactivate() {
  if (client) await client.stop();
}

module.exports = { activate, deactivate };
