// aidl serve: the live preview page. No framework, no network beyond this server.
"use strict";
const $ = (id) => document.getElementById(id);
const state = {
  view: null,            // last view from the server
  params: [],            // param descriptions (name, kind, value, default, unit, min, max, step)
  values: {},            // the customizer's current values, by name (display units)
  paramKey: "",          // signature of the param list, to rebuild controls only when it changes
  userBox: null,         // viewBox chosen by pan/zoom, null = fit
  ws: null, nextId: 1, inFlight: null, pending: false, formats: ["svg"],
  shownSvg: null,        // the SVG text in the viewer
};
// measurements read by the browser test: slider input -> picture drawn, per request
window.aidl = { sliderMs: [], sliderParts: [], drawn: {}, version: 0, svgVersion: 0, ready: false, state };
window.aidlBusy = () => !!state.inFlight || state.pending;

function connect() {
  const ws = new WebSocket(`ws://${location.host}/ws`);
  state.ws = ws;
  ws.onopen = () => setStatus("connected", "");
  ws.onclose = () => { setStatus("disconnected: is `aidl serve` still running?", "err"); setTimeout(connect, 1000); };
  ws.onmessage = (ev) => {
    const msg = JSON.parse(ev.data);
    if (msg.type === "view") onView(msg);
  };
}

function setStatus(text, cls) { const s = $("status"); s.textContent = text; s.className = "status " + cls; }

function onView(v) {
  // a later message about the picture already shown (its shape checks, its DOF summary):
  // only the diagnostics and the summary change; the picture and the controls stay (the
  // slider may have moved on since)
  if (v.id == null && state.view && v.version === state.view.version && v.svg === state.view.svg) {
    state.view = v;
    showDiagnostics(v.diagnostics);
    showSource(v.source, v.diagnostics);
    showDof(v.dof);
    return;
  }
  const own = v.id != null && state.inFlight && v.id === state.inFlight.id;
  const t0 = own ? state.inFlight.t0 : null;
  const sent = own ? state.inFlight.sent : null, received = performance.now();
  if (own) state.inFlight = null;
  state.view = v;
  $("file").textContent = v.file;
  document.title = `${v.file} · aidl serve`;
  const nerr = v.diagnostics.filter((d) => d.severity === "error").length;
  setStatus(v.ok ? `ok · ${v.timing && v.timing.total_ms != null ? v.timing.total_ms.toFixed(0) + " ms" : ""}`
                 : `${nerr} error${nerr === 1 ? "" : "s"}`, v.ok ? "ok" : "err");
  // the server keeps the last good picture: a page opened (or reloaded) while the file is
  // broken draws it too, and says plainly when there is none yet
  if (v.svg && (v.ok || v.svg !== state.shownSvg)) drawSvg(v.svg);
  if (!v.svg && state.shownSvg != null) { $("viewer").innerHTML = ""; state.shownSvg = null; }
  $("stale").hidden = v.ok;
  $("stale").textContent = v.ok ? "" : v.svg
    ? "showing the last good picture: the program has errors"
    : "no picture yet: the program has not compiled without errors since `aidl serve` started; fix the errors listed on the right";
  if (v.ok && !$("viewer3d").hidden) load3d();
  showParams(v.params, v.values, !own);
  showDiagnostics(v.diagnostics);
  showSource(v.source, v.diagnostics);
  showDof(v.dof);
  updateSetLine();
  const draw = () => {
    window.aidl.version = v.version;
    if (v.ok) window.aidl.svgVersion = v.version;
    if (!(v.version in window.aidl.drawn)) window.aidl.drawn[v.version] = performance.timeOrigin + performance.now();
    if (t0 != null) {
      const now = performance.now();
      window.aidl.sliderMs.push(now - t0);
      window.aidl.sliderParts.push({ wait: sent - t0, roundTrip: received - sent,
        server: v.timing ? v.timing.total_ms : null, drawAndPaint: now - received });
    }
    window.aidl.ready = true;
  };
  afterPaint(draw);
  if (state.pending) send();
}

// run f just after the next frame is painted: a task queued from requestAnimationFrame runs
// once that frame's rendering (style, layout, paint) is done
const afterPaintQueue = [];
const afterPaintChannel = new MessageChannel();
afterPaintChannel.port1.onmessage = () => { const f = afterPaintQueue.shift(); if (f) f(); };
function afterPaint(f) {
  requestAnimationFrame(() => { afterPaintQueue.push(f); afterPaintChannel.port2.postMessage(0); });
}

// ------------------------------------------------------------------ picture, pan and zoom
function drawSvg(text) {
  const viewer = $("viewer");
  viewer.innerHTML = text;
  state.shownSvg = text;
  const svg = viewer.querySelector("svg");
  if (!svg) return;
  svg.removeAttribute("width"); svg.removeAttribute("height");
  svg.setAttribute("preserveAspectRatio", "xMidYMid meet");
  svg.dataset.fit = svg.getAttribute("viewBox");
  if (state.userBox) svg.setAttribute("viewBox", state.userBox.join(" "));
  for (const p of svg.querySelectorAll("[id^=part-]")) {
    const t = document.createElementNS("http://www.w3.org/2000/svg", "title");
    t.textContent = p.id.slice(5);
    p.appendChild(t);
  }
}

function box() {
  const svg = $("viewer").querySelector("svg");
  return svg ? svg.getAttribute("viewBox").split(/[\s,]+/).map(Number) : null;
}
function setBox(b) {
  const svg = $("viewer").querySelector("svg");
  if (!svg) return;
  state.userBox = b;
  svg.setAttribute("viewBox", b.join(" "));
}
function toModel(ev) {   // client point -> viewBox coordinates
  const svg = $("viewer").querySelector("svg");
  const pt = svg.createSVGPoint(); pt.x = ev.clientX; pt.y = ev.clientY;
  return pt.matrixTransform(svg.getScreenCTM().inverse());
}
$("viewer").addEventListener("wheel", (ev) => {
  const b = box(); if (!b) return;
  ev.preventDefault();
  const p = toModel(ev), k = Math.exp(ev.deltaY * 0.0015);
  setBox([p.x - (p.x - b[0]) * k, p.y - (p.y - b[1]) * k, b[2] * k, b[3] * k]);
}, { passive: false });
let drag = null;
$("viewer").addEventListener("pointerdown", (ev) => {
  if (!box()) return;
  drag = { p: toModel(ev), b: box() };
  $("viewer").setPointerCapture(ev.pointerId); $("viewer").classList.add("dragging");
});
$("viewer").addEventListener("pointermove", (ev) => {
  const t = ev.target.closest && ev.target.closest("[id^=part-]");
  $("hover").textContent = t ? t.id.slice(5) : "";
  if (!drag) return;
  const p = toModel(ev), b = box();
  setBox([b[0] - (p.x - drag.p.x), b[1] - (p.y - drag.p.y), b[2], b[3]]);
});
const endDrag = () => { drag = null; $("viewer").classList.remove("dragging"); };
$("viewer").addEventListener("pointerup", endDrag);
$("viewer").addEventListener("pointercancel", endDrag);
$("fit").onclick = () => {
  if (!$("viewer3d").hidden) { if (window.aidl3d) window.aidl3d.frame(); return; }
  state.userBox = null;
  const svg = $("viewer").querySelector("svg");
  if (svg && svg.dataset.fit) svg.setAttribute("viewBox", svg.dataset.fit);
};

// ------------------------------------------------------------------ customizer
function showParams(params, values, fromServer) {
  state.params = params;
  const key = JSON.stringify(params.map((p) => [p.name, p.kind, p.min, p.max, p.step, p.default]));
  const form = $("params");
  if (key !== state.paramKey) {
    state.paramKey = key;
    form.innerHTML = "";
    if (!params.length) form.textContent = "This file declares no `param`.";
    for (const p of params) {
      const row = control(p);
      form.appendChild(row);
      setControl(row, p, state.values[p.name] !== undefined && !fromServer ? state.values[p.name] : p.value);
    }
  }
  if (fromServer) {
    for (const p of params) {
      state.values[p.name] = p.value;
      const row = form.querySelector(`[data-name="${CSS.escape(p.name)}"]`);
      if (row) setControl(row, p, p.value);
    }
  }
  for (const p of params) {
    const row = form.querySelector(`[data-name="${CSS.escape(p.name)}"]`);
    if (row) row.classList.toggle("changed", state.values[p.name] !== p.default);
  }
}

function control(p) {
  const row = document.createElement("div");
  row.className = "param"; row.dataset.name = p.name;
  const label = document.createElement("label");
  label.textContent = p.name; label.title = `line ${p.line}` + (p.declared ? "" : " (no declared range: default span)");
  label.onclick = () => highlightLine(p.line);
  row.appendChild(label);
  if (p.kind === "bool") {
    const cb = document.createElement("input"); cb.type = "checkbox"; cb.name = p.name;
    cb.onchange = () => change(p, cb.checked);
    row.appendChild(cb);
  } else if (p.kind === "string") {
    const t = document.createElement("input"); t.type = "text"; t.name = p.name;
    t.oninput = () => change(p, t.value);
    t.style.gridColumn = "2 / 4";
    row.appendChild(t);
  } else {
    const r = document.createElement("input");
    r.type = "range"; r.name = p.name; r.min = p.min; r.max = p.max; r.step = p.step;
    const n = document.createElement("input");
    n.type = "number"; n.name = p.name + "-value"; n.step = p.step;
    if (p.declared) { n.min = p.min; n.max = p.max; }
    r.oninput = () => { n.value = r.value; change(p, Number(r.value)); };
    n.onchange = () => { const v = Number(n.value); if (Number.isFinite(v)) { r.value = v; change(p, v); } };
    row.appendChild(r); row.appendChild(n);
    const u = document.createElement("span"); u.className = "unit";
    u.textContent = `${p.unit || "number"} · ${fmt(p.min)}…${fmt(p.max)}`;
    row.appendChild(u);
  }
  return row;
}

function setControl(row, p, v) {
  if (p.kind === "bool") row.querySelector("input").checked = !!v;
  else if (p.kind === "string") row.querySelector("input").value = v;
  else { const [r, n] = row.querySelectorAll("input"); r.value = v; n.value = v; }
}

function fmt(x) { return x == null ? "" : String(Math.round(x * 1e6) / 1e6); }

// the --set text of a value: the CLI's syntax (172.5mm, 30deg, true, "text")
function setText(p, v) {
  if (p.kind === "length") return `${fmt(v)}mm`;
  if (p.kind === "angle") return `${fmt(v)}deg`;
  if (p.kind === "bool") return v ? "true" : "false";
  if (p.kind === "string") return JSON.stringify(String(v));
  return fmt(v);
}

function chosen() {   // values differing from the file's, as --set texts
  const out = {};
  for (const p of state.params) {
    const v = state.values[p.name];
    if (v !== undefined && v !== p.default) out[p.name] = setText(p, v);
  }
  return out;
}

function change(p, v) {
  state.values[p.name] = v;
  state.pending = true;
  state.t0 = performance.now();
  updateSetLine();
  if (!state.inFlight) send();
}

function send() {   // one request in flight; the newest values win
  if (!state.ws || state.ws.readyState !== 1) return;
  state.pending = false;
  const id = state.nextId++;
  state.inFlight = { id, t0: state.t0, sent: performance.now() };
  state.ws.send(JSON.stringify({ type: "set", id, values: chosen() }));
}

$("reset").onclick = () => {
  for (const p of state.params) state.values[p.name] = p.default;
  for (const p of state.params) {
    const row = $("params").querySelector(`[data-name="${CSS.escape(p.name)}"]`);
    if (row) setControl(row, p, p.default);
  }
  state.pending = true; state.t0 = performance.now();
  updateSetLine();
  if (!state.inFlight) send();
};

// ------------------------------------------------------------------ downloads, --set line
function shellQuote(s) { return /^[\w.=+\-/:]+$/.test(s) ? s : `'${s.replace(/'/g, `'\\''`)}'`; }

function updateSetLine() {
  const file = state.view ? state.view.file : "FILE";
  const sets = Object.entries(chosen()).map(([k, v]) => `--set ${shellQuote(`${k}=${v}`)}`);
  $("setline").value = ["aidl", "render", shellQuote(file), ...sets].join(" ");
  const q = Object.entries(chosen()).map(([k, v]) => "set=" + encodeURIComponent(`${k}=${v}`)).join("&");
  for (const a of $("downloads").querySelectorAll("a")) a.href = `/download/${a.dataset.fmt}` + (q ? "?" + q : "");
}

// ------------------------------------------------------------------ the assembled 3D view
function glbUrl() {   // the assembled product with the customizer's values (view3d.js loads it)
  const q = Object.entries(chosen()).map(([k, v]) => "set=" + encodeURIComponent(`${k}=${v}`)).join("&");
  return "/download/glb" + (q ? "?" + q : "");
}

function load3d() { if (window.aidl3d) window.aidl3d.load(glbUrl()); }

$("mode3d").onclick = () => {
  const on = $("viewer3d").hidden;          // switch to 3D, or back to the flat sheet
  $("viewer3d").hidden = !on;
  $("viewer").hidden = on;
  $("mode3d").setAttribute("aria-pressed", String(on));
  if (on) load3d();
};

$("copy").onclick = async () => {
  const text = $("setline").value;
  try { await navigator.clipboard.writeText(text); }
  catch (e) { $("setline").select(); document.execCommand("copy"); }
  $("copy").textContent = "Copied";
  setTimeout(() => { $("copy").textContent = "Copy --set line"; }, 1200);
};

fetch("/api/formats").then((r) => r.json()).then((fmts) => {
  state.formats = fmts;
  $("downloads").innerHTML = "";
  for (const f of fmts) {
    const a = document.createElement("a");
    a.dataset.fmt = f; a.textContent = `Download .${f}`; a.className = "button"; a.download = "";
    $("downloads").appendChild(a);
  }
  updateSetLine();
});

// ------------------------------------------------------------------ diagnostics, source, dof
function showDiagnostics(diags) {
  const ul = $("diagnostics"); ul.innerHTML = "";
  $("diag-count").textContent = diags.length ? `(${diags.length})` : "(none)";
  $("diag-detail").hidden = true;
  for (const d of diags) {
    const li = document.createElement("li");
    li.className = d.severity;
    const where = d.span ? `line ${d.span.line}:${d.span.column} ` : "";
    li.textContent = `${where}${d.severity}[${d.code}]: ${d.message}`;
    li.onclick = () => {
      if (d.span) highlightLine(d.span.line);
      $("diag-detail").textContent = d.rendered; $("diag-detail").hidden = false;
    };
    ul.appendChild(li);
  }
}

function showSource(src, diags) {
  const ol = $("source");
  if (ol.dataset.src !== src) {
    ol.dataset.src = src; ol.innerHTML = "";
    for (const line of src.split("\n")) { const li = document.createElement("li"); li.textContent = line || " "; ol.appendChild(li); }
  }
  for (const li of ol.children) li.classList.remove("err");
  for (const d of diags) if (d.span && d.severity === "error" && ol.children[d.span.line - 1]) ol.children[d.span.line - 1].classList.add("err");
}

function highlightLine(n) {
  const ol = $("source");
  for (const li of ol.querySelectorAll(".hl")) li.classList.remove("hl");
  const li = ol.children[n - 1];
  if (!li) return;
  li.classList.add("hl");
  li.closest("details").open = true;
  li.scrollIntoView({ block: "center" });
}

function showDof(dof) {
  const tb = $("dof").querySelector("tbody"); tb.innerHTML = "";
  let total = 0, unknown = 0;
  for (const d of dof) {
    // dof null: not counted within the budget (too large, or out of time)
    if (d.dof === null) unknown++; else total += d.dof;
    const tr = document.createElement("tr");
    for (const c of [d.structure, d.unknowns, d.dof ?? "?", d.floating.join(", ") || "-"]) {
      const td = document.createElement("td"); td.textContent = c; tr.appendChild(td);
    }
    tb.appendChild(tr);
  }
  $("dof-summary").textContent = !dof.length ? "" : unknown
    ? `degrees of freedom not counted in ${unknown} of ${dof.length} structures (too large)`
    : `${total} degrees of freedom left in ${dof.length} structures`;
}

connect();
