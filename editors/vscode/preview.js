// "AIDL: Open Preview": a webview beside the code showing the document's picture, redrawn on
// every change (not only on save), with a slider per `param` and the shape under the cursor
// highlighted. The picture comes from the language server's `aidl/preview` request
// (aidl_lang/editor/lsp/preview.py): SVG text whose last group, `#aidl-shapes`, holds one
// invisible element per shape with `data-range` = the LSP range of the source that made it.
//
// Extension -> page messages: {type: 'update', result} (the request's result), {type: 'cursor',
// line, character}, {type: 'error', message}. Page -> extension: {type: 'ready'},
// {type: 'values', values} (slider values, `--set` texts), {type: 'reveal', range},
// {type: 'render', format}, {type: 'assembled', on} (the 3D button: ask for the assembled
// product's GLB with every picture while on).
'use strict';
const vscode = require('vscode');
const path = require('node:path');
const crypto = require('node:crypto');
const fs = require('node:fs');

const DEBOUNCE_MS = 120;        // quiet after a keystroke before the picture is asked for

class Preview {
  // getClient(): the running LanguageClient or undefined; log(line): the output channel;
  // extensionPath: the extension's folder (the 3D view's bundled three.js is its
  // dist/webview/three.js).
  constructor(document, getClient, log, onDispose, extensionPath) {
    this.uri = document.uri.toString();
    this.document = document;
    this.getClient = getClient;
    this.log = log;
    this.values = {};
    this.inflight = null;
    this.pending = false;
    this.timer = null;
    this.last = null;             // the last result posted
    this.assembled = false;       // the 3D view is shown: ask for the assembled product too
    // the bundled three.js (dist/webview/three.js, made by `npm run bundle`), the one folder the
    // page may read; without it (the sources run unbuilt) the 3D button is hidden, and said
    const webviewDir = extensionPath ? path.join(extensionPath, 'dist', 'webview') : null;
    const threeFile = webviewDir && path.join(webviewDir, 'three.js');
    const hasThree = Boolean(threeFile) && fs.existsSync(threeFile);
    if (threeFile && !hasThree) log(`no 3D view: ${threeFile} is missing (npm run bundle makes it)`);
    this.panel = vscode.window.createWebviewPanel('aidlPreview', title(document),
      { viewColumn: vscode.ViewColumn.Beside, preserveFocus: true },
      { enableScripts: true, retainContextWhenHidden: true,
        localResourceRoots: hasThree ? [vscode.Uri.file(webviewDir)] : [] });
    const threeUrl = hasThree ? String(this.panel.webview.asWebviewUri(vscode.Uri.file(threeFile))) : null;
    this.panel.webview.html = html(this.panel.webview.cspSource, threeUrl);
    const subs = [];
    subs.push(this.panel.webview.onDidReceiveMessage((m) => this.receive(m)));
    subs.push(vscode.workspace.onDidChangeTextDocument((e) => {
      if (e.document.uri.toString() === this.uri) {
        this.document = e.document;
        this.schedule(DEBOUNCE_MS);
      }
    }));
    subs.push(vscode.workspace.onDidSaveTextDocument((d) => {
      if (d.uri.toString() === this.uri) this.schedule(0);
    }));
    subs.push(vscode.window.onDidChangeTextEditorSelection((e) => {
      if (e.textEditor.document.uri.toString() === this.uri && e.selections.length) {
        const p = e.selections[0].active;
        this.cursor = { line: p.line, character: p.character };
        this.post({ type: 'cursor', ...this.cursor });
      }
    }));
    this.subs = subs;
    this.panel.onDidDispose(() => {
      clearTimeout(this.timer);
      subs.forEach((d) => d.dispose());
      onDispose(this);
    });
    this.schedule(0);
  }

  reveal() { this.panel.reveal(vscode.ViewColumn.Beside, true); }

  post(msg) { return this.panel.webview.postMessage(msg); }

  schedule(ms) {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.refresh(), ms);
  }

  // One request at a time; changes meanwhile ask again once it is answered.
  async refresh() {
    if (this.inflight) { this.pending = true; return; }
    const client = this.getClient();
    if (!client || !client.isRunning()) {
      this.post({ type: 'error', message: 'The AIDL language server is not running (see the AIDL output).' });
      return;
    }
    this.inflight = client.sendRequest('aidl/preview', { uri: this.uri, values: this.values,
                                                        ...(this.assembled ? { assembled: true } : {}) });
    try {
      const res = await this.inflight;
      if (res && !res.superseded) {
        this.last = res;
        await this.post({ type: 'update', result: res });
        if (this.cursor) await this.post({ type: 'cursor', ...this.cursor });
      }
    } catch (err) {
      this.log(`preview: ${err && err.message ? err.message : err}`);
      this.post({ type: 'error', message: `The preview request failed: ${err && err.message ? err.message : err}` });
    } finally {
      this.inflight = null;
      if (this.pending) { this.pending = false; this.refresh(); }
    }
  }

  async receive(m) {
    if (!m || typeof m !== 'object') return;
    if (m.type === 'ready') this.schedule(0);
    else if (m.type === 'values' && m.values && typeof m.values === 'object') {
      this.values = Object.fromEntries(Object.entries(m.values).map(([k, v]) => [k, String(v)]));
      this.schedule(0);
    } else if (m.type === 'reveal' && Array.isArray(m.range)) {
      const [l0, c0, l1, c1] = m.range;
      const doc = await vscode.workspace.openTextDocument(vscode.Uri.parse(this.uri));
      const ed = await vscode.window.showTextDocument(doc, { viewColumn: vscode.ViewColumn.One, preserveFocus: false });
      const sel = new vscode.Selection(l0, c0, l1, c1);
      ed.selection = sel;
      ed.revealRange(sel, vscode.TextEditorRevealType.InCenterIfOutsideViewport);
    } else if (m.type === 'assembled') {
      this.assembled = !!m.on;
      this.schedule(0);
    } else if (m.type === 'render' && typeof m.format === 'string') {
      vscode.commands.executeCommand('aidl.render', m.format, vscode.Uri.parse(this.uri));
    }
  }

  dispose() { this.panel.dispose(); }
}

function title(document) {
  return `Preview ${path.basename(document.uri.fsPath || document.uri.path || 'untitled')}`;
}

// The 3D view: three.js (the extension's own npm dependency, bundled with its glTF loader and
// orbit controls into one ES module, dist/webview/three.js, loaded through the webview's
// resource URI `threeUrl`; no CDN) shows the assembled product the server sends as base64
// GLB (`aidl/preview` with `assembled: true`): orbit (drag), zoom (wheel), pan (right-drag),
// the parts in the flat view's colours; the camera stays put across updates.
function view3d(threeUrl, nonce) {
  if (!threeUrl) return '';
  return `<script type="module" nonce="${nonce}">
import * as THREE from "${threeUrl}";
const { GLTFLoader, OrbitControls } = THREE;
const host = document.getElementById("view3d");
let r = null, scene, camera, controls, root = null, framed = false;
function init() {
  r = new THREE.WebGLRenderer({ antialias: true });
  r.setPixelRatio(window.devicePixelRatio || 1);
  host.appendChild(r.domElement);
  scene = new THREE.Scene(); scene.background = new THREE.Color(0xffffff);
  camera = new THREE.PerspectiveCamera(35, 1, 0.1, 1e7); camera.up.set(0, 0, 1);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6); sun.position.set(-0.6, -1, 1.4);
  camera.add(sun); scene.add(camera);
  controls = new OrbitControls(camera, r.domElement);
  const resize = () => { const w = host.clientWidth || 1, h = host.clientHeight || 1;
    r.setSize(w, h, false); r.domElement.style.width = "100%"; r.domElement.style.height = "100%";
    camera.aspect = w / h; camera.updateProjectionMatrix(); };
  new ResizeObserver(resize).observe(host); resize();
  r.setAnimationLoop(() => { controls.update(); r.render(scene, camera); });
}
function frame() {
  if (!root) return;
  const box = new THREE.Box3().setFromObject(root), c = box.getCenter(new THREE.Vector3());
  const rad = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-3);
  const d = rad / Math.sin(camera.fov * Math.PI / 360) * 1.1;
  camera.position.copy(c).add(new THREE.Vector3(-0.55, -0.75, 0.45).normalize().multiplyScalar(d));
  camera.near = d / 1000; camera.far = d * 100; camera.updateProjectionMatrix();
  controls.target.copy(c); controls.update();
}
function show(b64) {
  if (!r) init();
  const bin = atob(b64), buf = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) buf[i] = bin.charCodeAt(i);
  new GLTFLoader().parse(buf.buffer, "", (gltf) => {
    if (root) scene.remove(root);
    root = gltf.scene;
    const nodes = gltf.parser.json.nodes || [];
    root.traverse((o) => {
      if (!o.isMesh) return;
      const at = gltf.parser.associations.get(o) || {};
      const col = o.geometry.getAttribute("color"), colour = new THREE.Color(0x607d8b);
      if (col) colour.setRGB(col.getX(0), col.getY(0), col.getZ(0), THREE.SRGBColorSpace);
      o.material = new THREE.MeshStandardMaterial({ color: colour, roughness: 0.9, metalness: 0,
                                                    flatShading: true, side: THREE.DoubleSide });
      o.name = (nodes[at.nodes] && nodes[at.nodes].name) || o.name;
    });
    scene.add(root);
    if (!framed) { frame(); framed = true; }
    document.body.dataset.loaded3d = String(Number(document.body.dataset.loaded3d || 0) + 1);
  }, (e) => { document.body.dataset.error3d = String(e && e.message || e); });
}
window.aidl3d = { show, frame };
</script>`;
}

// The page. Everything inline or from the extension's own folder (no CDN, works offline); a
// nonce-only script policy.
function html(cspSource, threeUrl) {
  const nonce = crypto.randomBytes(16).toString('base64');
  return `<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src data: ${cspSource}; style-src 'unsafe-inline' ${cspSource}; script-src 'nonce-${nonce}' ${cspSource};">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>AIDL preview</title>
<style>
  html, body { height: 100%; margin: 0; }
  body { display: flex; flex-direction: column; font-family: var(--vscode-font-family, sans-serif);
    font-size: var(--vscode-font-size, 13px); color: var(--vscode-foreground, #333);
    background: var(--vscode-editor-background, #fff); }
  header { display: flex; gap: .6em; align-items: center; padding: 4px 8px;
    border-bottom: 1px solid var(--vscode-panel-border, #ddd); min-height: 24px; }
  #status { flex: 1; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; cursor: default; }
  #status.ok::before { content: "\\2713  "; color: #2e7d32; }
  #status.bad { color: var(--vscode-errorForeground, #c62828); cursor: pointer; }
  #hover { opacity: .75; white-space: nowrap; }
  button { font: inherit; color: var(--vscode-button-foreground, #fff); background: var(--vscode-button-background, #0e639c);
    border: none; padding: 2px 8px; border-radius: 2px; cursor: pointer; }
  #params { display: grid; grid-template-columns: max-content 1fr max-content; gap: 2px 8px;
    padding: 4px 8px; align-items: center; border-bottom: 1px solid var(--vscode-panel-border, #ddd); }
  #params:empty { display: none; }
  #params label { font-family: var(--vscode-editor-font-family, monospace); cursor: pointer; }
  #params output { font-family: var(--vscode-editor-font-family, monospace); min-width: 6em; text-align: right; }
  #params .changed { font-weight: bold; }
  main { flex: 1; min-height: 0; position: relative; }
  #view { position: absolute; inset: 0; padding: 8px; box-sizing: border-box; }
  #view svg { width: 100%; height: 100%; display: block; }
  #view.stale svg { opacity: .45; }
  #view3d { position: absolute; inset: 0; }
  #view3d canvas { display: block; }
  [hidden] { display: none !important; }
  #empty { padding: 1em; opacity: .7; }
  #aidl-shapes .aidl-shape, #aidl-shapes .aidl-stroke { cursor: pointer; }
  #aidl-shapes .hover { stroke: rgba(255, 143, 0, .6); }
  #aidl-shapes .hl { fill: rgba(255, 193, 7, .45); stroke: #ff6f00; }
  #aidl-shapes .aidl-stroke.hl { fill: transparent; }
  #aidl-shapes .aidl-struct.hl { fill: rgba(255, 193, 7, .18); stroke: #ff8f00; stroke-dasharray: 2 1; }
</style></head>
<body>
<header><span id="status">Compiling&hellip;</span><span id="hover"></span>
  <button id="reset" title="Back to the file's values" hidden>Reset</button>
  <button id="mode3d" title="The parts placed in 3D by their Place (aidl render --assembled); again: the flat sheet"${threeUrl ? '' : ' hidden'}>3D</button>
  <button id="svg" title="Render to SVG (aidl render)">SVG</button>
  <button id="dxf" title="Render to DXF (aidl render)">DXF</button></header>
<section id="params"></section>
<main><div id="view"><div id="empty">Waiting for the language server&hellip;</div></div><div id="view3d" hidden></div></main>
${view3d(threeUrl, nonce)}
<script nonce="${nonce}">
(function () {
  const vscode = acquireVsCodeApi();
  const $ = (id) => document.getElementById(id);
  let values = {};
  let params = [];
  let cursor = null;
  let firstError = null;
  let userBox = null;             // a viewBox set by zooming/panning, kept across updates

  function fmt(v, step) {
    const d = step && step < 1 ? Math.min(6, Math.ceil(-Math.log10(step))) : 0;
    return Number(v).toFixed(d);
  }

  function send() { vscode.postMessage({ type: 'values', values }); $('reset').hidden = !Object.keys(values).length; }

  function renderParams(list) {
    const same = list.length === params.length && list.every((p, i) => p.name === params[i].name && p.kind === params[i].kind
      && p.min === params[i].min && p.max === params[i].max && p.step === params[i].step);
    params = list;
    const box = $('params');
    if (!same) {
      box.textContent = '';
      for (const p of list) {
        const label = document.createElement('label');
        label.textContent = p.name;
        label.title = 'Go to the param';
        label.addEventListener('click', () => p.range && vscode.postMessage({ type: 'reveal', range: p.range }));
        let input;
        const out = document.createElement('output');
        if (p.kind === 'bool') {
          input = document.createElement('input'); input.type = 'checkbox';
          input.addEventListener('change', () => { values[p.name] = input.checked ? 'true' : 'false'; send(); });
        } else if (p.kind === 'string') {
          input = document.createElement('input'); input.type = 'text';
          input.addEventListener('change', () => { values[p.name] = JSON.stringify(input.value); send(); });
        } else {
          input = document.createElement('input'); input.type = 'range';
          input.min = p.min; input.max = p.max; input.step = p.step;
          input.addEventListener('input', () => {
            values[p.name] = input.value + (p.unit ? ' ' + p.unit : '');
            out.textContent = fmt(input.value, p.step) + (p.unit ? ' ' + p.unit : '');
            send();
          });
        }
        input.id = 'param-' + p.name;
        input.dataset.name = p.name;
        label.htmlFor = input.id;
        box.append(label, input, out);
      }
    }
    for (const p of list) {
      const input = $('param-' + p.name);
      if (!input) continue;
      const out = input.nextElementSibling;
      const changed = p.name in values;
      input.previousElementSibling.classList.toggle('changed', changed);
      if (document.activeElement === input) continue;       // do not fight the user's drag
      if (p.kind === 'bool') input.checked = !!p.value;
      else if (p.kind === 'string') input.value = p.value;
      else { input.value = p.value; out.textContent = fmt(p.value, p.step) + (p.unit ? ' ' + p.unit : ''); }
    }
  }

  function inside(r, l, c) {
    const after = l > r[0] || (l === r[0] && c >= r[1]);
    const before = l < r[2] || (l === r[2] && c <= r[3]);
    return after && before;
  }

  // The shape(s) made by the smallest source range around the cursor (a template's shape is
  // every instance's: they share the range). Ranges over fewer lines first, so the cursor
  // anywhere on the line of \`h = Circle(...)\` shows that circle, not its structure; on one
  // line, the range around the cursor first.
  function highlight() {
    const els = document.querySelectorAll('#aidl-shapes [data-range]');
    let best = null;
    let bestScore = Infinity;
    if (cursor) {
      for (const e of els) {
        const r = e.dataset.range.split(',').map(Number);
        const around = inside(r, cursor.line, cursor.character);
        if (!around && !(r[0] <= cursor.line && cursor.line <= r[2])) continue;
        const score = (r[2] - r[0]) * 1e9 + (around ? 0 : 1e6) + (r[3] - r[1]);
        if (score < bestScore) { best = e.dataset.range; bestScore = score; }
      }
    }
    let n = 0;
    for (const e of els) {
      const on = e.dataset.range === best;
      e.classList.toggle('hl', on);
      if (on) n += 1;
    }
    document.body.dataset.highlighted = String(n);
  }

  function wire(svg) {
    svg.removeAttribute('width'); svg.removeAttribute('height');
    svg.setAttribute('preserveAspectRatio', 'xMidYMid meet');
    if (userBox) svg.setAttribute('viewBox', userBox);
    for (const e of svg.querySelectorAll('#aidl-shapes [data-range]')) {
      if (e.classList.contains('aidl-struct')) continue;
      e.addEventListener('mouseenter', () => { e.classList.add('hover'); $('hover').textContent = e.dataset.kind + ' ' + e.dataset.name; });
      e.addEventListener('mouseleave', () => { e.classList.remove('hover'); $('hover').textContent = ''; });
      e.addEventListener('click', (ev) => { ev.stopPropagation(); vscode.postMessage({ type: 'reveal', range: e.dataset.range.split(',').map(Number) }); });
    }
    svg.addEventListener('wheel', (ev) => {
      ev.preventDefault();
      const [x, y, w, h] = svg.getAttribute('viewBox').split(/[ ,]+/).map(Number);
      const rect = svg.getBoundingClientRect();
      const k = ev.deltaY > 0 ? 1.15 : 1 / 1.15;
      const s = Math.max(w / rect.width, h / rect.height);
      const px = x + (ev.clientX - rect.left - (rect.width - w / s) / 2) * s;
      const py = y + (ev.clientY - rect.top - (rect.height - h / s) / 2) * s;
      userBox = [px - (px - x) * k, py - (py - y) * k, w * k, h * k].join(' ');
      svg.setAttribute('viewBox', userBox);
    }, { passive: false });
    svg.addEventListener('dblclick', () => { userBox = null; vscode.postMessage({ type: 'ready' }); });
  }

  function update(r) {
    const view = $('view');
    const d = r.diagnostics || { errors: 0, warnings: 0 };
    const st = $('status');
    firstError = d.first;
    if (r.ok) {
      st.className = 'ok';
      st.textContent = (d.warnings ? d.warnings + ' warning' + (d.warnings > 1 ? 's' : '') + ' \\u00b7 ' : '') + r.ms + ' ms';
      st.title = d.first ? d.first.code + ': ' + d.first.message : '';
    } else {
      st.className = 'bad';
      const where = d.first && d.first.range ? ' (line ' + (d.first.range[0] + 1) + ')' : '';
      st.textContent = (d.first ? d.first.code + ': ' + d.first.message + where : d.errors + ' errors')
        + (r.svg ? ' \\u2014 showing the last good picture' : '');
      st.title = st.textContent;
    }
    document.body.dataset.ok = String(!!r.ok);
    document.body.dataset.version = String(r.version);
    view.classList.toggle('stale', !!r.stale);
    if (r.svg) {
      view.innerHTML = r.svg;
      const svg = view.querySelector('svg');
      if (svg) wire(svg);
    } else {
      view.innerHTML = '<div id="empty"></div>';
      $('empty').textContent = 'No picture yet: fix the errors and it appears.';
    }
    renderParams(r.params || []);
    highlight();
    if (r.glb && !$('view3d').hidden && window.aidl3d) window.aidl3d.show(r.glb);
  }

  $('status').addEventListener('click', () => { if (firstError && firstError.range) vscode.postMessage({ type: 'reveal', range: firstError.range }); });
  $('reset').addEventListener('click', () => { values = {}; params = []; send(); });
  $('mode3d').addEventListener('click', () => {
    const on = $('view3d').hidden;
    $('view3d').hidden = !on; $('view').hidden = on;
    $('mode3d').textContent = on ? 'Flat' : '3D';
    vscode.postMessage({ type: 'assembled', on });
  });
  $('svg').addEventListener('click', () => vscode.postMessage({ type: 'render', format: 'svg' }));
  $('dxf').addEventListener('click', () => vscode.postMessage({ type: 'render', format: 'dxf' }));
  window.addEventListener('message', (ev) => {
    const m = ev.data || {};
    if (m.type === 'update') update(m.result);
    else if (m.type === 'cursor') { cursor = { line: m.line, character: m.character }; highlight(); }
    else if (m.type === 'error') { const st = $('status'); st.className = 'bad'; st.textContent = m.message; }
  });
  vscode.postMessage({ type: 'ready' });
}());
</script>
</body></html>`;
}

module.exports = { Preview, html, DEBOUNCE_MS };
