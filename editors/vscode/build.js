// `npm run bundle` (and `vscode:prepublish`, so `vsce package` runs it): esbuild bundles the
// extension (extension.js with server.js, preview.js and vscode-languageclient) into
// dist/extension.js, the `main` of package.json, and the preview's 3D view (webview/three.js:
// three.js, GLTFLoader, OrbitControls) into dist/webview/three.js, the one asset the webview
// loads.  The .vsix then holds these two files and no node_modules (.vscodeignore).
'use strict';
const esbuild = require('esbuild');
const path = require('node:path');

const here = (p) => path.join(__dirname, p);

async function main() {
  const common = { bundle: true, minify: true, legalComments: 'eof', logLevel: 'warning' };
  await esbuild.build({
    ...common,
    entryPoints: [here('extension.js')],
    outfile: here('dist/extension.js'),
    platform: 'node',
    format: 'cjs',
    target: 'node18',                 // VS Code 1.82 (engines.vscode) runs extensions on Node 18
    external: ['vscode'],
    keepNames: true,                  // readable names in a stack trace in the AIDL output
  });
  await esbuild.build({
    ...common,
    entryPoints: [here('webview/three.js')],
    outfile: here('dist/webview/three.js'),
    platform: 'browser',
    format: 'esm',
    target: 'es2020',
  });
}

main().catch((e) => { console.error(e.message || e); process.exit(1); });
