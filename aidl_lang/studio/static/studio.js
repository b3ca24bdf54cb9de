// aidl studio: the page. The server keeps no program: every request carries the program text,
// the customizer's values and the material settings (aidl_lang/studio/app.py).
import { createEditor } from "/static/vendor/codemirror/aidl-editor.js";
import "/static/view3d.js";

const $ = (id) => document.getElementById(id);
const EMBED = location.pathname === "/embed";
// values: what the visitor set ({name: number | bool | text}, display units: a slider moved, a
// shared link's), never a value the page was merely shown; params: the current program's, from
// its last answer ([] until the first: a new program's values are then sent as they are)
const state = {
  sid: null, source: "", values: {}, params: [], paramKey: "", entry: null,
  seq: 0, shown: 0, inflight: false, kerf: null, again: false, timer: null, glbSeq: 0, reframe: true,
  config: null, svgUrl: null, view: null,
  // the sweep of the program (/api/sweep): its answer, the program it is of, the one asked
  sweep: { answer: null, source: null, key: null, asked: null, ctrl: null, timer: null },
};
// read by the browser tests: views shown, 3D loads asked, the last view and its diagnostics
window.studio = { ready: false, idle: false, views: 0, passing: 0, answers: 0, passingAt: [], sweeps: 0, sweep: null, glbs: 0, glbView: 0, view: null, state, errors: [],
                  shownAt: {}, builtAt: {},      // view number -> performance.now() of its 2D, its 3D
                  // the page's benchmark (issue 104): view number -> where its time went, ms from
                  // the change (a slider's move): waited (the page's debounce and pacing), sent,
                  // answered (compile_ms of it in the worker, the rest transfer and queue), drawn
                  // (the picture decoded and on screen), built (its 3D on screen)
                  timeline: {} };

// ------------------------------------------------------------------ requests
// one request: an answer, or an Error with `retry` (seconds) when the studio is busy (429/503)
// or cannot be reached (no answer, 502/504: the proxy lost its studio process, docs/studio.md;
// another answers), said on the busy line
async function request(path, opts = {}) {
  let r;
  try { r = await fetch(path, opts); } catch (err) { r = null; }   // the network, or a dropped connection
  if (!r || r.status === 502 || r.status === 504) {
    const message = "the studio cannot be reached; your design is kept here";
    showBusy(message, 3);
    const e = new Error(message); e.retry = 3; throw e;
  }
  if (r.status === 429 || r.status === 503) {
    const doc = await r.json().catch(() => ({}));
    const wait = Number(r.headers.get("Retry-After")) || 5;
    showBusy(doc.error || "the studio is busy", wait);
    const e = new Error(doc.error || "busy"); e.retry = wait; throw e;
  }
  hideBusy();
  return r;
}
async function post(path, body, raw = false) {
  const r = await request(path, { method: "POST", headers: { "Content-Type": "application/json" },
                                  body: JSON.stringify(body) });
  return raw ? r : r.json();
}

function showBusy(message, wait) {
  const b = $("busy");
  b.textContent = `${message} (trying again in ${wait} s)`;
  b.hidden = false;
}
function hideBusy() { $("busy").hidden = true; }
function status(text) { $("status").textContent = text; }

// ------------------------------------------------------------------ the program
function settings() {
  const num = (id) => { const v = $(id).value; return v === "" ? null : Number(v); };
  // the thickness is the design's own `thickness` param (the Material field sets it): the
  // joints, the 3D view and the 3D files have one thickness (issue 94)
  return { thickness: null, kerf: state.kerf, machine: $("machine").value || "laser",
           layout: $("layout").checked, sheet: [num("sheet-w") || 600, num("sheet-h") || 400] };
}

// The values a request carries: those the visitor set that differ from the program's own (the
// params' `default`, which the server takes from the program itself, never from a request).
// One test for the preview, its 3D, the downloads and the share link.
function same(a, b) {
  if (typeof a === "number" && typeof b === "number") return Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(a), Math.abs(b));
  return a === b;
}
function chosenRaw(values = state.values) {
  const out = {};
  if (!state.params.length) {                 // a new program's first request: sent as they are
    for (const [k, v] of Object.entries(values)) if (v !== undefined) out[k] = v;
    return out;
  }
  for (const p of state.params) {
    const v = values[p.name];
    if (v !== undefined && !same(v, p.default)) out[p.name] = v;
  }
  return out;
}
// as `aidl render --set` takes them: by the param's kind; before the program's first answer, as
// a shared link wrote them (or a guess, for a link of before they were written)
function texts(raw) {
  const out = {}, given = state.givenTexts || {};
  for (const [k, v] of Object.entries(raw)) {
    const p = state.params.find((q) => q.name === k);
    out[k] = p ? setText(p, v) : typeof given[k] === "string" ? given[k]
      : typeof v === "boolean" ? String(v) : typeof v === "number" ? fmt(v) : JSON.stringify(String(v));
  }
  return out;
}
function chosen() { return texts(chosenRaw()); }
function sameValues(a, b) {
  const ka = Object.keys(a), kb = Object.keys(b);
  return ka.length === kb.length && ka.every((k) => k in b && same(a[k], b[k]));
}

function fmt(x) { return x == null ? "" : String(Math.round(x * 1e6) / 1e6); }
function setText(p, v) {       // the value as `aidl render --set` takes it
  if (p.kind === "length") return `${fmt(v)}mm`;
  if (p.kind === "angle") return `${fmt(v)}deg`;
  if (p.kind === "bool") return v ? "true" : "false";
  if (p.kind === "string") return JSON.stringify(String(v));
  return fmt(v);
}

// What a visitor asked for once (the gallery, a design, a download, their files) is asked again
// when the studio answers busy (429/503: the page's own previews and sweeps count in the rate
// too), after the wait it names, a few times; never left as a broken list or a lost click
async function again(ask, tries = 5) {
  for (let i = 1; ; i++) {
    try { return await ask(); } catch (e) {
      if (!e.retry || i >= tries) throw e;
      await new Promise((ok) => setTimeout(ok, e.retry * 1000));
    }
  }
}
async function getJSON(path) {
  return (await again(() => request(path))).json();
}

// The server's rate limit (`--rate`, /api/config: "300/minute", "40/10 seconds"): the page's
// previews and 3D views are spaced so that a visitor who drags a slider for minutes stays
// at 60 % of it (a drag is coalesced: the values of the moment a request leaves)
function paceGap() {
  const text = String((state.config && state.config.limits && state.config.limits.rate) || "300/minute");
  const m = /(\d+)\s*(?:\/|per)\s*(\d*)\s*(second|minute|hour|day)/i.exec(text);
  if (!m) return 0;
  const unit = { second: 1, minute: 60, hour: 3600, day: 86400 }[m[3].toLowerCase()];
  return (Number(m[2] || 1) * unit * 1000) / (0.6 * Number(m[1]));
}
// a burst of 10 goes at once (a click, its 3D), then one every paceGap() ms: in any window of
// the server's period at most 60 % of its rate and 10 (GCRA: each request reserves its slot;
// `cost`: the slots the server counts the request as, its route's cost in app.py)
async function pace(cost = 1) {
  const gap = paceGap(), now = performance.now();
  state.tat = Math.max(state.tat || 0, now);
  const wait = state.tat + (cost - 1) * gap - 9 * gap - now;
  state.tat += cost * gap;
  if (wait > 0) await new Promise((ok) => setTimeout(ok, wait));
}
window.studio.paceGap = paceGap;
// the slots of the pace's burst free now (10: none spent)
function paceRoom() {
  const gap = paceGap();
  return gap ? 10 - Math.max(0, (state.tat || 0) - performance.now()) / gap : 10;
}
window.studio.paceRoom = paceRoom;

function schedule(delay = 200) {
  clearTimeout(state.timer);
  if (!state.changedAt) state.changedAt = performance.now();     // (the benchmark's start)
  window.studio.idle = false;
  building2d(true);
  state.timer = setTimeout(() => { state.timer = null; compile(); }, delay);
}

// the flat view while its picture is not the sliders' (a change on its way): dimmed at once,
// "building…" when the right picture takes longer than a blink
function building2d(on) {
  const pane = $("flat");
  let note = $("building-flat");
  if (!note) {
    note = document.createElement("span");
    Object.assign(note, { id: "building-flat", className: "pane-note", hidden: true, textContent: "building…" });
    note.setAttribute("role", "status");
    pane.appendChild(note);
  }
  pane.classList.toggle("building", on);
  clearTimeout(state.building2dTimer);
  if (on) {
    status("building…");
    state.building2dTimer = setTimeout(() => { note.hidden = !pane.classList.contains("building"); }, 250);
  } else note.hidden = true;
}

// One preview in flight; a change made meanwhile is compiled when it answers (the latest values
// only: the values of the moment the request leaves). An answer of the current program with
// the values the sliders hold now is the sliders' picture (shown, then its 3D and checks); one
// whose values the sliders have left meanwhile (a drag) is shown too, as soon as it comes,
// marked with the values it is of (issue 113: a drag with a move every 250 ms showed no picture
// until the mouse was released), and the sliders' current values are asked at once.
async function compile() {
  if (state.inflight) { state.again = true; return; }
  state.inflight = true;
  try { await pace(); } catch (_) { /* never */ }
  const seq = ++state.seq;
  const t0 = performance.now();
  const changedAt = state.changedAt || t0;
  state.changedAt = 0;
  try {
    // held: the sliders' values as sent (raw leaves out those at their defaults: a value the
    // visitor has not changed since is one still equal to its held value, not to its raw one)
    const source = state.source, held = { ...state.values }, raw = chosenRaw(), values = texts(raw), defaults = {};
    for (const p of state.params) if (p.name in raw) defaults[p.name] = p.default;
    // the shape checks (the warnings) are asked apart, once the picture is shown (/api/checks)
    const view = await post("/api/view", { sid: state.sid, source, values, defaults, checks: "later" });
    window.studio.answers += 1;       // (every answer, shown or not: the browser tests count them)
    if (seq !== state.seq || source !== state.source) { /* another program since: dropped */ }
    else if (view.superseded) state.again = true;
    // a second request would be this one again (same program, same values): its answer is the
    // sliders' picture, shown; never asked again and again (issue 104: a slider released twice
    // to a value whose other param the server moves left the page asking forever)
    else if (answered(view, raw, held) || sameValues(chosenRaw(), raw)) {
      state.shownSent = values;
      const got = performance.now();
      show(view, got - t0);
      const t = view.timing || {};
      window.studio.timeline[window.studio.views] = { changed: changedAt, waited: t0 - changedAt, sent: t0,
        answered: got, compile_ms: t.worker_ms ?? t.total_ms ?? null, cpu_ms: t.cpu_ms ?? null,
        drawn: null, built: null };
    }
    else {                          // the sliders moved on meanwhile: not their picture yet
      state.again = true;
      passing(view);
    }
  } catch (e) {
    window.studio.errors.push(String(e.message || e));
    if (e.retry) { state.again = false; setTimeout(compile, e.retry * 1000); }
    else status("the server did not answer: " + (e.message || e));
  } finally {
    state.inflight = false;
    if (state.again) { state.again = false; compile(); }
    else if (!state.timer && !state.checking) window.studio.idle = true;     // read by the tests: nothing pending
  }
}

// The answer to a preview sent with the values `raw` (the sliders held `held` then): its
// program's params taken (their defaults and ranges), the values it dropped (not this
// program's) and moved into their ranges (clamped) applied where the visitor has not changed
// them since; true when the sliders now hold the values it was made for.  "Not changed since"
// is against `held`, not `raw`: a value at its default is not in `raw` (the planetary's sun,
// put back on 12 by one release, is moved to 13 by the next: it was left at 12 before)
function answered(view, raw, held = raw) {
  const made = { ...raw };
  const unchanged = (name) => {       // a value left out is the param's default (the params sent against)
    const p = state.params.find((q) => q.name === name), d = p ? p.default : undefined;
    return same(state.values[name] ?? d, held[name] ?? d);
  };
  for (const name of view.dropped || []) {
    delete made[name];
    if (unchanged(name)) delete state.values[name];
  }
  for (const [name, v] of Object.entries(view.clamped || {})) {
    made[name] = v;
    if (unchanged(name)) {
      state.values[name] = v;
      const p = (view.params || state.params).find((q) => q.name === name);
      // a slider's end sent rounded (to 1e-6) and put back on it: no move to speak of
      const moved = !(typeof raw[name] === "number" && Math.abs(v - raw[name]) <= 1e-6 * Math.max(1, Math.abs(v)));
      // (a text none of its param's choices: the server says which it used, issue 113)
      if (moved) typedNote(name, (view.moved && view.moved[name]) || `${name} moved to ${p ? onStep(p, v) : fmt(v)}${p && p.unit ? " " + p.unit : ""}: its range follows the other values`);
    }
  }
  if (view.params) state.params = view.params;
  view.made = made;                   // (the values it is of, said by passing())
  return sameValues(chosenRaw(made), chosenRaw());
}

// A picture of values the sliders have left (a drag goes on): on the flat view at once, marked
// with the values it is of where they differ from the sliders' ("width 134 mm"); the form, the
// 3D view, the messages and the checks wait for the sliders' own picture, which clears the mark.
// An error answer is not shown (the last picture stays): the next request is on its way.
function passing(view) {
  if (!view.ok || !view.svg || !view.made) return;
  const made = view.made, differ = [];
  for (const p of state.params) {
    const a = made[p.name] !== undefined ? made[p.name] : p.default;
    const b = state.values[p.name] !== undefined ? state.values[p.name] : p.default;
    if (same(a, b)) continue;
    differ.push(typeof a === "number" ? `${p.name} ${onStep(p, a)}${p.unit ? " " + p.unit : ""}`
      : typeof a === "boolean" ? `${p.name} ${a ? "on" : "off"}` : `${p.name} “${a}”`);
  }
  if (view.svg !== state.lastSvg) {
    state.lastSvg = view.svg;
    if (state.svgUrl) URL.revokeObjectURL(state.svgUrl);
    state.svgUrl = URL.createObjectURL(new Blob([view.svg], { type: "image/svg+xml" }));
    $("flat-img").src = state.svgUrl;
  }
  $("flat").classList.add("passing");
  markFor(differ.length ? `showing ${differ.join(", ")}` : "");
  window.studio.passing += 1;
  window.studio.passed = view;
  window.studio.passingAt.push([performance.now(), differ.join(", ")]);
}
// the flat view's mark: the values its picture is of, while they are not the sliders' ("" clears)
function markFor(text) {
  let mark = $("flat-for");
  if (!mark) {
    mark = document.createElement("span");
    Object.assign(mark, { id: "flat-for", className: "pane-mark", hidden: true });
    mark.setAttribute("role", "status");
    $("flat").appendChild(mark);
  }
  mark.textContent = text;
  mark.hidden = !text;
  if (!text) $("flat").classList.remove("passing");
}

// a design's name as the header says it: divider_tray -> Divider tray
function titleOf(name) {
  const words = String(name).split("_").filter(Boolean);
  return words.length ? [words[0][0].toUpperCase() + words[0].slice(1), ...words.slice(1)].join(" ") : String(name);
}

function show(view, ms) {
  state.view = view;
  if (state.ownTitle && view.ok && view.title) $("title").textContent = titleOf(view.title);
  window.studio.view = view;
  const diags = view.diagnostics || [];
  const errors = diags.filter((d) => d.severity === "error").length;
  if (view.params) showParams(view.params);     // the form first: the picture lands on its values
  // a text none of its choices, replaced: said under its list (a link's first answer builds the form)
  for (const [name, text] of Object.entries(view.moved || {})) typedNote(name, text);
  building2d(false);
  if (view.error) status(view.error);
  else status(view.ok ? `solved in ${Math.round(ms)} ms` + (diags.length ? ` · ${diags.length} message${diags.length > 1 ? "s" : ""}` : "")
                      : `${errors} error${errors === 1 ? "" : "s"}: showing the last good picture`);
  $("flat").classList.toggle("stale", !view.ok);
  // the sliders' own picture: the mark goes (an error keeps the picture on the page, and its mark)
  if (view.ok && view.svg) markFor("");
  // only a picture of this program with these values: an error keeps the page's last picture
  if (view.ok && view.svg && view.svg !== state.lastSvg) {
    state.lastSvg = view.svg;
    if (state.svgUrl) URL.revokeObjectURL(state.svgUrl);
    state.svgUrl = URL.createObjectURL(new Blob([view.svg], { type: "image/svg+xml" }));
    $("flat-img").src = state.svgUrl;         // an <img>: the SVG runs no script, loads nothing
  } else if (!state.lastSvg) {                // a new program with no picture yet: none
    $("flat-img").removeAttribute("src");
  }
  showDiagnostics(diags, view.error);
  window.studio.views += 1;
  window.studio.shownAt[window.studio.views] = performance.now();
  if (view.ok) {
    building(true);
    const model = !state.timer && !state.again ? load3d() : null;
    if (view.checks === "pending") {
      // after its 3D (the worker that drew the picture makes both, one at a time: the checks
      // first held the 3D back by their 0.1-0.3 s)
      const me = state.checkSeq = (state.checkSeq || 0) + 1;
      state.checking = true;
      window.studio.idle = false;
      if (model) model.finally(() => askChecks(view, me));
      else askChecks(view, me);
    }
    askSweep();
    if (state.kerf && (state.kerfFails || state.kerfRecheck)) tryKerf();
  }
  else {          // the last good model, dimmed like the last good picture, and why
    state.glbSeq += 1;
    building(true);
    clearTimeout(state.buildingTimer);
    $("building3d").textContent = "the 3D waits for a program that checks";
    $("building3d").hidden = false;
  }
}

// The shape checks of a picture (its warnings: a wall too thin, a hole that cuts nothing), asked
// once it is shown (issue 104: they were 0.2 s of a planetary move's 0.5 s before its picture):
// added to its messages when they come, if it is still the picture on the page
async function askChecks(view, me) {
  const source = state.source, values = view.values || {}, shown = view;
  try {
    if (me !== state.checkSeq) return;          // a later picture's checks are on their way
    await pace();
    if (state.view !== shown) return;           // another picture since: its own checks
    const got = await post("/api/checks", { sid: state.sid, source, values });
    if (state.view !== shown || source !== state.source || !got.ok) return;
    shown.diagnostics = got.diagnostics || [];
    delete shown.checks;
    showDiagnostics(shown.diagnostics, shown.error);
    const n = shown.diagnostics.length;
    if (!shown.error && n) status(`${$("status").textContent.replace(/ · \d+ messages?$/, "")} · ${n} message${n > 1 ? "s" : ""}`);
  } catch (e) {
    window.studio.errors.push("checks: " + (e.message || e));
  } finally {
    if (me === state.checkSeq) {                // (a later picture's checks: theirs)
      state.checking = false;
      if (!state.inflight && !state.timer && !state.again) window.studio.idle = true;
    }
  }
}

// the 3D pane says "building…" from the moment its model is not the picture's (a new design:
// the old model is taken away; a changed one: dimmed) until the picture's own model is there
function building(on, fresh = false) {
  const pane = $("viewer3d");
  pane.classList.toggle("building", on);
  if (fresh && window.aidl3d) window.aidl3d.clear();
  const empty = fresh || (pane.classList.contains("empty") && on);
  pane.classList.toggle("empty", empty);
  // an empty pane (a new design) says so at once; a slider move dims the model at once and
  // says so when its new model takes longer than a blink (no flicker on every move)
  clearTimeout(state.buildingTimer);
  $("building3d").hidden = !(on && empty);
  if (on && !empty) state.buildingTimer = setTimeout(() => { $("building3d").hidden = false; }, 250);
  $("building3d").textContent = "building…";
}

// a message's place: line:column in the code pane's program, else the file it is in (a
// standard-library file as the program imports it, std/gears.aidl:298:5), never that file's
// line numbers as if they were the program's
function inProgram(span) { return !span.file || /(^|\/)main\.aidl$/.test(span.file); }
function placeOf(span) {
  const at = `${span.line}:${span.column}`;
  return inProgram(span) ? at : `${String(span.file).replace(/^SESSION\//, "")}:${at}`;
}

function showDiagnostics(diags, error) {
  const ul = $("diagnostics");
  ul.innerHTML = "";
  if (error) diags = [{ severity: "error", code: "", message: error }];
  if (!diags.length) {
    const li = document.createElement("li"); li.className = "ok";
    li.textContent = "No messages: the program checks.";
    ul.appendChild(li);
  }
  for (const d of diags) {
    const li = document.createElement("li");
    li.className = d.severity;
    const where = d.span ? `${placeOf(d.span)} ` : "";
    li.textContent = `${where}${d.severity}${d.code ? "[" + d.code + "]" : ""}: ${d.message}`;
    if (d.hint) {
      const h = document.createElement("div"); h.className = "hint";
      h.textContent = "help: " + d.hint; li.appendChild(h);
    }
    if (d.span && editor && inProgram(d.span)) li.onclick = () => editor.goto(d.span.line, d.span.column);
    else li.classList.add("elsewhere");
    ul.appendChild(li);
  }
  if (editor) editor.setDiagnostics(diags.filter((d) => d.span && inProgram(d.span))
    .map((d) => ({ from: d.span.line, col: d.span.column, to_line: d.span.end_line,
                   to_col: d.span.end_column, severity: d.severity === "note" ? "info" : d.severity,
                   message: d.message + (d.hint ? "\nhelp: " + d.hint : ""), code: d.code })));
}

// ------------------------------------------------------------------ the flat view: zoom and pan
// The picture stays an <img> of the SVG (inert); zooming sets its layout size (the browser draws
// the SVG again at that size: sharp at any zoom) and panning its place in the pane. Wheel: zoom
// about the mouse; drag: pan; two fingers: pinch-zoom about their middle and pan; Fit (or a
// double-click): the whole picture. The view stays through slider moves, fits a new design.
const flat = { s: 1, x: 0, y: 0, fitW: 0, fitH: 0, pointers: new Map(), pinch: null };
window.studio.flat = flat;
const FLAT_MIN = 0.2, FLAT_MAX = 400;

function flatFit() { flat.s = 1; flat.x = 0; flat.y = 0; flatLayout(); }
function flatLayout() {
  const pane = $("flat"), img = $("flat-img");
  const pw = pane.clientWidth, ph = pane.clientHeight;
  const nw = img.naturalWidth || 1, nh = img.naturalHeight || 1;
  const k = Math.min(pw * 0.96 / nw, ph * 0.96 / nh);
  flat.fitW = nw * k; flat.fitH = nh * k;
  const w = flat.fitW * flat.s, h = flat.fitH * flat.s;
  img.style.width = `${w}px`; img.style.height = `${h}px`;
  img.style.left = `${(pw - w) / 2 + flat.x}px`; img.style.top = `${(ph - h) / 2 + flat.y}px`;
}
function flatZoom(f, cx, cy) {        // by f about the pane point (cx, cy)
  const pane = $("flat");
  const s = Math.min(FLAT_MAX, Math.max(FLAT_MIN, flat.s * f));
  const g = s / flat.s;
  const ox = cx - pane.clientWidth / 2, oy = cy - pane.clientHeight / 2;
  flat.x = ox - (ox - flat.x) * g; flat.y = oy - (oy - flat.y) * g;
  flat.s = s;
  flatLayout();
}
function panePoint(e) { const r = $("flat").getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; }
$("flat").addEventListener("wheel", (e) => {
  e.preventDefault();
  const unit = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1;
  flatZoom(Math.exp(-e.deltaY * unit * 0.0015), ...panePoint(e));
}, { passive: false });
$("flat").addEventListener("pointerdown", (e) => {
  if (e.target.closest(".pane-tools") || (e.pointerType === "mouse" && e.button !== 0)) return;
  try { $("flat").setPointerCapture(e.pointerId); } catch (_) { /* a synthetic pointer */ }
  flat.pointers.set(e.pointerId, panePoint(e));
  flat.pinch = null;
  $("flat").classList.add("dragging");
});
$("flat").addEventListener("pointermove", (e) => {
  const last = flat.pointers.get(e.pointerId);
  if (!last) return;
  const now = panePoint(e);
  // one finger on a touch screen scrolls the page (touch-action: pan-x pan-y), never pans
  if (e.pointerType === "touch" && flat.pointers.size < 2) { flat.pointers.set(e.pointerId, now); return; }
  if (flat.pointers.size >= 2) {              // pinch: the two first fingers
    flat.pointers.set(e.pointerId, now);
    const [a, b] = [...flat.pointers.values()];
    const d = Math.hypot(a[0] - b[0], a[1] - b[1]), m = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
    if (flat.pinch && flat.pinch.d > 0) {
      flat.x += m[0] - flat.pinch.m[0]; flat.y += m[1] - flat.pinch.m[1];
      flatZoom(d / flat.pinch.d, m[0], m[1]);
    }
    flat.pinch = { d, m };
    return;
  }
  flat.x += now[0] - last[0]; flat.y += now[1] - last[1];
  flat.pointers.set(e.pointerId, now);
  flatLayout();
});
function flatUp(e) {
  flat.pointers.delete(e.pointerId);
  flat.pinch = null;
  if (!flat.pointers.size) $("flat").classList.remove("dragging");
}
// two fingers are the picture's (pinch, pan), not the page's: the browser does not scroll them
$("flat").addEventListener("touchmove", (e) => { if (e.touches.length > 1) e.preventDefault(); }, { passive: false });
$("flat").addEventListener("pointerup", flatUp);
$("flat").addEventListener("pointercancel", flatUp);
$("flat").addEventListener("dblclick", (e) => { if (!e.target.closest(".pane-tools")) flatFit(); });
$("flat-fit").onclick = flatFit;
$("flat-zoom-in").onclick = () => flatZoom(1.5, $("flat").clientWidth / 2, $("flat").clientHeight / 2);
$("flat-zoom-out").onclick = () => flatZoom(1 / 1.5, $("flat").clientWidth / 2, $("flat").clientHeight / 2);
$("flat-img").addEventListener("load", () => {
  if (state.fitNext) { state.fitNext = false; flatFit(); } else flatLayout();
  const t = window.studio.timeline[window.studio.views];
  if (t && t.drawn === null) t.drawn = performance.now();
});
new ResizeObserver(() => flatLayout()).observe($("flat"));

// ------------------------------------------------------------------ the customizer
function showParams(params) {
  // the form is built again only for other params (a new program); a range that follows other
  // params (its min or max depends on them) and the values are updated in place, so a slider
  // being dragged stays in hand
  const key = JSON.stringify(params.map((p) => [p.name, p.kind, p.default, p.choices || null]));
  state.params = params;
  const form = $("params");
  if (key !== state.paramKey) {
    state.paramKey = key;
    form.innerHTML = "";
    if (!params.length) form.textContent = "This design has no sizes to change.";
    for (const p of params) form.appendChild(control(p));
  }
  for (const p of params) {
    const row = form.querySelector(`[data-name="${CSS.escape(p.name)}"]`);
    if (!row) continue;
    // the visitor's value, else the one this picture was made with (a param that follows others)
    const v = state.values[p.name] !== undefined ? state.values[p.name] : p.value;
    setControl(row, p, v);
    row.classList.toggle("changed", !same(v, p.default));
  }
  markRanges();
  bindThickness();
}

// A slider's stops: its grid (min + k step), its two ends and its default, exact: the range
// input has step="any" and its value is put on the nearest stop, so the end reads 480 when
// the grid from 0.4 by 0.8 stops at 479.6, and a default of 120 off the grid is reachable.
// The keys move stop by stop (arrows, Page Up/Down: 10, Home/End: the ends).
function snap(p, v) {
  const near = (a, b) => (Math.abs(a - v) <= Math.abs(b - v) ? a : b);
  let best = p.min;
  if (p.step > 0) {
    let g = p.min + Math.round((v - p.min) / p.step) * p.step;
    if (g > p.max) g -= p.step;
    best = near(Math.max(g, p.min), best);
  }
  best = near(p.max, best);
  if (typeof p.default === "number" && p.default >= p.min && p.default <= p.max) best = near(p.default, best);
  for (const c of cleanOf(p.name) || []) if (c >= p.min && c <= p.max) best = near(c, best);
  return Number(best.toFixed(9));
}
function nextStop(p, v, dir) {          // the stop after v in direction dir (+1, -1)
  const eps = 1e-9 * Math.max(1, Math.abs(v));
  const cands = [p.min, p.max];
  if (typeof p.default === "number") cands.push(p.default);
  cands.push(...(cleanOf(p.name) || []));         // the clean range's ends (the sweep's)
  if (p.step > 0) {
    const k = (v - p.min) / p.step;
    cands.push(p.min + (dir > 0 ? Math.floor(k + 1e-9) + 1 : Math.ceil(k - 1e-9) - 1) * p.step);
  }
  const ok = cands.filter((c) => c >= p.min - eps && c <= p.max + eps && (dir > 0 ? c > v + eps : c < v - eps));
  if (!ok.length) return v;
  return Number((dir > 0 ? Math.min(...ok) : Math.max(...ok)).toFixed(9));
}
function stopKeys(r, apply) {
  r.addEventListener("keydown", (e) => {
    const p = r._param;
    let v = Number(r.value);
    const k = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1, PageUp: 10, PageDown: -10 }[e.key];
    if (k) { for (let i = 0; i < Math.abs(k); i++) v = nextStop(p, v, Math.sign(k)); }
    else if (e.key === "Home") v = p.min;
    else if (e.key === "End") v = p.max;
    else return;
    e.preventDefault();
    if (v !== Number(r.value)) apply(v);
  });
}

function control(p) {
  const row = document.createElement("div");
  row.className = "param"; row.dataset.name = p.name;
  const id = "param-" + p.name.replace(/[^\w-]/g, "_");
  const name = document.createElement("label"); name.className = "name"; name.textContent = p.name;
  name.htmlFor = id;
  row.appendChild(name);
  const line = document.createElement("div"); line.className = "line";
  row.appendChild(line);
  // a change with nothing on its way is sent at once (a release waited 30 ms for moves that did
  // not come); one made while a picture is on its way waits for it (the latest values only)
  const change = (v) => { state.values[p.name] = v; row.classList.toggle("changed", !same(v, p.default)); downloadChanged();
                          schedule(state.inflight || state.timer ? 30 : 0); };
  if (p.kind === "bool") {
    const cb = document.createElement("input"); cb.type = "checkbox"; cb.name = p.name; cb.id = id;
    cb.onchange = () => change(cb.checked);
    line.appendChild(cb);
  } else if (p.kind === "string" && (p.choices || []).length) {
    // a text param of a few values (the program compares it with them): a list, never a
    // free-text field that takes `tight` and answers with the template's assertion
    const sel = document.createElement("select"); sel.name = p.name; sel.id = id;
    for (const c of p.choices) {
      const o = document.createElement("option"); o.value = c; o.textContent = c;
      sel.appendChild(o);
    }
    sel.onchange = () => change(sel.value);
    line.appendChild(sel);
    // the line that says a value none of its choices was replaced (issue 113: a share link's
    // `fit = "tight"`)
    const typed = document.createElement("div"); typed.className = "typed-note"; typed.id = id + "-typed";
    typed.setAttribute("role", "status");
    sel.setAttribute("aria-describedby", typed.id);
    row.append(typed);
  } else if (p.kind === "string") {
    const t = document.createElement("input"); t.type = "text"; t.name = p.name; t.id = id;
    t.oninput = () => change(t.value);
    line.appendChild(t);
  } else {
    const r = document.createElement("input");
    Object.assign(r, { type: "range", name: p.name, min: p.min, max: p.max, step: "any", id });
    r._param = p;
    const n = document.createElement("input");
    Object.assign(n, { type: "text", name: p.name + "-value", className: "value", inputMode: "decimal",
                       spellcheck: false, autocomplete: "off" });
    n.setAttribute("aria-label", `${p.name}${p.unit ? ", " + p.unit : ""}`);
    const put = (v) => { r.value = v; n.value = fmt(v); change(v); pastNote(row, p.name, v); };
    r.oninput = () => { typedNote(p.name, ""); put(snap(r._param, Number(r.value))); };
    stopKeys(r, (v) => { typedNote(p.name, ""); put(v); });
    n.oninput = () => { row._typing = true; };
    n.onchange = () => {
      row._typing = false;
      const [v, said] = typedValue(r._param, n.value);
      if (v !== null && !said && same(v, Number(r.value))) return;     // (a blur after Enter)
      typedNote(p.name, said);
      if (v === null) { n.value = fmt(Number(r.value)); return; }
      put(v);
    };
    n.onkeydown = (e) => { if (e.key === "Enter") { e.preventDefault(); n.dispatchEvent(new Event("change")); } };
    const u = document.createElement("span"); u.className = "unit";
    u.textContent = `${p.unit || ""} (${onStep(p, p.min)}–${onStep(p, p.max)})`;
    // the track: the slider over the parts of its range the sweep did not find clean
    const track = document.createElement("span"); track.className = "track";
    for (const side of ["below", "above"]) {
      const z = document.createElement("span"); z.className = `unclean ${side}`; z.hidden = true;
      track.appendChild(z);
    }
    track.prepend(r);
    const note = document.createElement("div"); note.className = "sweep-note"; note.id = id + "-sweep";
    r.setAttribute("aria-describedby", note.id);
    line.append(track, n, u);
    const typed = document.createElement("div"); typed.className = "typed-note"; typed.id = id + "-typed";
    typed.setAttribute("role", "status");
    n.setAttribute("aria-describedby", typed.id);
    row.append(note, typed);
  }
  return row;
}

function setControl(row, p, v) {
  const inputs = row.querySelectorAll("input");
  const sel = row.querySelector("select");
  if (p.kind === "bool") inputs[0].checked = !!v;
  else if (sel) sel.value = v;
  else if (p.kind === "string") inputs[0].value = v;
  else {
    inputs[0]._param = p;                   // its stops (a range may follow other params)
    if (String(inputs[0].min) !== String(p.min) || String(inputs[0].max) !== String(p.max)) {
      Object.assign(inputs[0], { min: p.min, max: p.max });
      const u = row.querySelector(".unit");
      if (u) u.textContent = `${p.unit || ""} (${onStep(p, p.min)}–${onStep(p, p.max)})`;
    }
    // a shown answer holds the sliders' values: the slider in hand is set to what it holds (or
    // to where its range moved it); a number being typed is left alone
    inputs[0].value = v;
    if (!row._typing) inputs[1].value = fmt(v);
    pastNote(row, p.name, v);
  }
}

// A number as a visitor types it: "12.5", "12,5" (a comma as the decimal mark, as in de-DE),
// "1,234.5" or "1.234,5" (grouped), "−3" (a minus sign)
function parseNumber(text) {
  let t = String(text).trim().replace(/[\u2212\u2012\u2013]/g, "-").replace(/[\s\u00a0\u202f']/g, "");
  const c = t.lastIndexOf(","), d = t.lastIndexOf(".");
  if (c >= 0 && d >= 0) t = c > d ? t.replace(/\./g, "").replace(",", ".") : t.replace(/,/g, "");
  else if (c >= 0) t = /^-?\d{1,3}(,\d{3}){2,}$/.test(t) ? t.replace(/,/g, "") : t.replace(",", ".");
  if (!/^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(t)) return NaN;
  return Number(t);
}
// a typed unit, converted to the param's own (display units: mm, deg): "150 mm", "15cm",
// "2 in", "90°"; [the number's text, its factor, the unit typed] (factor undefined: a unit of
// another kind, such as "40 deg" for a length)
const UNITS = { length: { mm: 1, cm: 10, m: 1000, in: 25.4, inch: 25.4, inches: 25.4, '"': 25.4 },
                angle: { deg: 1, "°": 1, rad: 180 / Math.PI } };
function withUnit(p, text) {
  const m = /^(.*?\d\.?)\s*(mm|cm|m|inch(?:es)?|in|"|deg|°|rad)$/i.exec(String(text).trim());
  if (!m) return [text, 1, null];
  return [m[1], (UNITS[p.kind] || {})[m[2].toLowerCase()], m[2]];
}
// a number as the slider of p shows it: to its step's decimals (14.52, not 14.520739)
function onStep(p, x) {
  if (x == null || !(p.step > 0)) return fmt(x);
  const d = (String(fmt(p.step)).split(".")[1] || "").length;
  return fmt(Number(Number(x).toFixed(Math.min(6, d))));
}
// the value a typed text gives the param p, and what the page says of it: [value, message]
// (value null: nothing usable, the field goes back to the slider's value)
function typedValue(p, text) {
  const unit = p.unit ? ` ${p.unit}` : "";
  const [digits, k, typedUnit] = withUnit(p, text);
  const now = `${p.name} stays at ${onStep(p, state.values[p.name] ?? p.value)}${unit}`;
  if (typedUnit && k === undefined) return [null, `“${String(text).trim()}” is not ${p.unit ? "in " + p.unit + " or another " + p.kind + " unit" : "a plain number"}: ${now}`];
  const x = parseNumber(digits) * k;
  if (!Number.isFinite(x)) return [null, `“${String(text).trim()}” is not a number: ${now}`];
  if (x > p.max + 1e-9) return [p.max, `${onStep(p, p.max)}${unit} is the most: ${p.name} is ${onStep(p, p.max)}${unit}, not ${fmt(x)}${unit}`];
  if (x < p.min - 1e-9) return [p.min, `${onStep(p, p.min)}${unit} is the least: ${p.name} is ${onStep(p, p.min)}${unit}, not ${fmt(x)}${unit}`];
  if (p.kind === "number" && p.step >= 1 && Number.isInteger(p.step) && Number.isInteger(p.min)) {
    const g = Math.min(p.max, p.min + Math.round((x - p.min) / p.step) * p.step);
    if (Math.abs(g - x) > 1e-9) return [g, `${p.name} is a whole number of steps of ${fmt(p.step)}: ${fmt(g)}, not ${fmt(x)}`];
  }
  return [x, ""];
}
function typedNote(name, text) {
  const row = $("params").querySelector(`[data-name="${CSS.escape(name)}"]`);
  const el = row && row.querySelector(".typed-note");
  if (el) el.textContent = text;
  if (name === (state.thicknessParam && state.thicknessParam.name)) $("thickness-note").textContent = text;
}

// One thickness (issue 94): a design with a `thickness` param has it set by the Material
// field too (so the joints, the 3D view and the 3D files follow); a design without one hides
// the field (its parts' thicknesses are the program's)
function bindThickness() {
  const p = state.params.find((q) => q.name === "thickness" && q.kind === "length") || null;
  state.thicknessParam = p;
  $("thickness-row").hidden = !p;
  if (!p) { $("thickness-note").textContent = ""; return; }
  const v = state.values[p.name] !== undefined ? state.values[p.name] : p.value;
  if (document.activeElement !== $("thickness")) $("thickness").value = fmt(v);
  $("thickness").setAttribute("aria-label", `thickness, mm (${onStep(p, p.min)}–${onStep(p, p.max)}): the design's thickness param`);
}
$("thickness").addEventListener("change", () => {
  const p = state.thicknessParam;
  if (!p) return;
  const [v, said] = typedValue(p, $("thickness").value);
  typedNote(p.name, said);
  const row = $("params").querySelector(`[data-name="${CSS.escape(p.name)}"]`);
  // text that is no thickness ("abc") is not kept on screen: the field shows the value used
  if (v === null) { $("thickness").value = fmt(state.values[p.name] !== undefined ? state.values[p.name] : p.value); return; }
  $("thickness").value = fmt(v);
  state.values[p.name] = v;
  downloadChanged();
  if (row) { setControl(row, p, v); row.classList.toggle("changed", !same(v, p.default)); }
  schedule(30);
});
$("thickness").addEventListener("keydown", (e) => { if (e.key === "Enter") { e.preventDefault(); $("thickness").dispatchEvent(new Event("change")); } });
$("params").addEventListener("submit", (e) => e.preventDefault());

// The kerf (issue 113): the width the cut takes, mm, 0 to 10 (the machine profiles' range);
// empty: the program's own `kerf`. Checked as typed, with a note beside it: a text that is no
// width, a negative kerf or one past 10 mm is not taken (the field shows the kerf in use); a kerf
// taken is tried on the design once (a cutting file made and thrown away: each outline offset
// by half of it), and when the design's features are too small for it the note says which, at
// once, not when a download fails. A failing kerf is tried again after the next settled picture
// (the values may have made room), a new design tries it afresh.
function kerfNote(text) { $("kerf-note").textContent = text; }
$("kerf").addEventListener("change", () => {
  const text = $("kerf").value.trim(), was = state.kerf;
  const stays = was === null ? "the program's kerf is used" : `the kerf stays ${fmt(was)} mm`;
  const back = () => { $("kerf").value = was === null ? "" : fmt(was); };
  if (text === "") {
    state.kerf = null; state.kerfFails = false; kerfNote(""); downloadChanged();
    return;
  }
  const [digits, k, unit] = withUnit({ kind: "length" }, text);
  const x = k === undefined ? NaN : parseNumber(digits) * k;
  if (unit && k === undefined) { kerfNote(`“${text}” is not a width in mm: ${stays}`); back(); return; }
  if (!Number.isFinite(x)) { kerfNote(`“${text}” is not a number: ${stays}`); back(); return; }
  if (x < 0) { kerfNote(`a kerf is the width the cut takes: 0 mm or more, not ${fmt(x)} mm; ${stays}`); back(); return; }
  if (x > 10) { kerfNote(`a kerf is at most 10 mm (a laser's is about 0.1–0.5 mm), not ${fmt(x)} mm; ${stays}`); back(); return; }
  state.kerf = x;
  $("kerf").value = fmt(x);
  kerfNote("");
  downloadChanged();
  tryKerf();
});
$("kerf").addEventListener("keydown", (e) => { if (e.key === "Enter") { e.preventDefault(); $("kerf").dispatchEvent(new Event("change")); } });
async function tryKerf() {
  const kerf = state.kerf, me = state.kerfSeq = (state.kerfSeq || 0) + 1;
  state.kerfRecheck = false;
  if (!kerf) { state.kerfFails = false; return; }
  kerfNote(`trying a kerf of ${fmt(kerf)} mm on this design…`);
  try {
    await pace(4);                            // (a download's cost in the server's rate)
    const r = await post(`/api/download/svg`, { sid: state.sid, source: state.source, values: chosen(),
      settings: { ...settings(), layout: false, style: "laser", name: "kerf" } }, true);
    if (me !== state.kerfSeq) return;
    if (r.ok) { state.kerfFails = false; kerfNote(""); return; }
    const doc = await r.json().catch(() => ({}));
    if (me !== state.kerfSeq) return;
    state.kerfFails = r.status === 422 && !!doc.error && /kerf|offset/i.test(doc.error);
    kerfNote(state.kerfFails ? `the cutting files cannot be made with this kerf: ${refusal(doc, r.status)}` : "");
  } catch (e) {
    if (me === state.kerfSeq) kerfNote("");   // busy or unreachable: the download will say
  }
}

// ------------------------------------------------------------------ the ranges the sweep found clean
// After a picture of a program not swept yet, the page asks /api/sweep for it in the background
// (a quiet moment later; an edit stops the one on its way). Each slider then shows the part of
// its range the sweep did not find clean hatched, and says what happens there (its title, its
// accessible description, and a line under it while its value is there): dragging into it is
// allowed, and said.
function cleanOf(name) {            // the clean values a slider stops at: its clean range's ends, each band's
  const a = state.sweep.answer, q = a && a.params && a.params[name];
  if (!q) return null;
  return [...q.clean, ...(q.bands || []).flatMap((b) => [b.from, b.to]).filter((x) => x !== null)];
}
// the band of the sweep's answer row q that holds the value v (a value the slider alone breaks the
// design at), or null
function bandAt(q, v) {
  if (!q || typeof v !== "number") return null;
  // strictly between the clean values judged beside it, or from its first broken value judged
  // to its last (both in: a value broken alone between parts not judged is a band of one value)
  const within = (b) => (b.lo != null && v >= b.lo - 1e-9 && v <= b.hi + 1e-9)
    || ((b.from === null || v > b.from + 1e-9) && (b.to === null || v < b.to - 1e-9));
  return (q.bands || []).find(within) || null;
}
// a sweep is of the program and the sliders where they are: each slider alone is hatched where
// it breaks the design at the other sliders' values
function sweepKey() { return state.source + "\u0000" + JSON.stringify(state.values || {}); }
function askSweep() {
  const sw = state.sweep, key = sweepKey();
  if (!state.config || !state.config.sweep || sw.key === key || sw.asked === key) return;
  clearTimeout(sw.timer);
  sw.timer = setTimeout(runSweep, 500);
}
// the program changed: the sweep on its way is stopped; the marks shown are of the program as it
// was (dimmed, said so) until the new one's sweep answers; `fresh`: another program, none kept
function sweepChanged(fresh) {
  const sw = state.sweep;
  clearTimeout(sw.timer);
  if (sw.ctrl) sw.ctrl.abort();
  sw.ctrl = null; sw.asked = null;
  if (fresh) { sw.answer = null; sw.source = null; sw.key = null; }
  markRanges();
}
// slots the sweep leaves in the burst: a release's picture and its 3D, twice (issue 104: a
// sweep after each release spent the burst, and the next release's picture waited for the pace)
const SWEEP_LEAVES = 4;
async function runSweep() {
  // paced with the previews and 3D models: a minute of dragging sent a sweep at each pause,
  // unpaced, and 31 requests fell in one 5 s window of a limit of 30
  // the server counts a sweep as 2 of its rate (paced as 1, a drag met 429 once the sweep
  // worker answered at once)
  const sw = state.sweep;
  // the background's turn comes when the pictures have theirs: never while a picture is on
  // its way, and never with the burst's last slots (what the visitor waits for)
  const room = paceRoom();
  if (state.inflight || state.timer || room < 2 + SWEEP_LEAVES) {
    clearTimeout(sw.timer);
    sw.timer = setTimeout(runSweep, Math.max(300, (2 + SWEEP_LEAVES - room) * paceGap()));
    return;
  }
  try { await pace(2); } catch (_) { /* never */ }
  const source = state.source, key = sweepKey(), values = { ...state.values };
  if (sw.ctrl) sw.ctrl.abort();
  const ctrl = sw.ctrl = new AbortController();
  sw.asked = key;
  sweepStatus("checking the sliders' ranges…");
  let r = null;
  try {
    r = await fetch("/api/sweep", { method: "POST", signal: ctrl.signal, headers: { "Content-Type": "application/json" },
                                    body: JSON.stringify({ sid: state.sid, source, values: texts(chosenRaw(values)) }) });
  } catch (e) { r = null; }
  if (ctrl !== sw.ctrl || key !== sweepKey()) return;      // stopped, or another program or values
  sw.ctrl = null;
  const doc = r ? await r.json().catch(() => null) : null;
  if (!r || r.status === 429 || r.status === 503 || !doc) {       // busy: asked again, quietly
    const wait = (r && Number(r.headers.get("Retry-After"))) || 10;
    sweepStatus(`the sliders' ranges are checked when the studio has a free worker (in ${wait} s)`);
    sw.asked = null;
    sw.timer = setTimeout(() => { if (key === sweepKey()) runSweep(); }, wait * 1000);
    return;
  }
  if (doc.superseded) { sw.asked = null; return; }
  sw.answer = doc; sw.source = source; sw.key = key;
  window.studio.sweeps += 1;
  window.studio.sweep = doc;
  markRanges();
}
function sweepStatus(text) { const el = $("sweep-status"); if (el) el.textContent = text; }
function markRanges() {
  const sw = state.sweep, a = sw.answer, stale = !!a && sw.key !== sweepKey();
  if (!a) sweepStatus("");
  else if (!a.ok) sweepStatus(a.error && !a.off ? `the sliders' ranges were not checked: ${a.error}` : "");
  else {
    const narrowed = Object.values(a.params || {}).filter((q) => (q.bands || []).length).length;
    const together = (a.combinations || []).length
      ? `; sliders that break it only together: ${a.combinations.join("; ")}` : "";
    // what the time allowed cut: said, never hatched nor cleared (dotted grey on the track)
    const open = Object.values(a.params || {}).filter((q) => (q.unjudged || []).length).length;
    const cut = (a.skipped ? `; ${a.skipped} planned values not checked in the time allowed` : "")
      + (open ? (a.skipped ? " (dotted: where a slider's edge was not narrowed down)"
        : "; dotted: not checked in the time allowed") : "");
    // what was judged, said as a share of what was planned: "15 of 147 values checked", never
    // "checks clean" of a range the time allowed only part of
    const checked = a.skipped ? `${a.points} of ${a.points + a.skipped} values checked` : `${a.points} values checked`;
    sweepStatus(stale ? "the hatched parts are of the design before your change: checking again…"
      : !a.swept.length ? "" : (narrowed
        ? `hatched: values at which the design breaks, each slider alone (${checked})`
        : a.skipped || open ? `no break found in the values checked, each slider alone (${checked})`
          : `every slider's range checks clean alone (${checked})`) + cut + together);
  }
  for (const p of state.params) {
    const row = $("params").querySelector(`[data-name="${CSS.escape(p.name)}"]`);
    const r = row && row.querySelector("input[type=range]");
    if (!r) continue;
    const q = a && a.ok && a.params ? a.params[p.name] : null;
    row.classList.toggle("swept-stale", !!q && stale);
    // each band where the slider alone breaks the design: the two next to its clean range in the
    // track's `below`/`above` marks, the others (a band between clean values, an odd count) each
    // a mark of its own
    const span = p.max - p.min, bands = (q && q.bands) || [];
    const frac = (x, end) => (x === null ? end : Math.min(1, Math.max(0, (x - p.min) / span)));
    // a band's clean values judged on either side are the slider's steps: the hatch stops
    // half a step short of them (a count's odd values each their own mark, not the track)
    const half = p.step > 0 ? p.step / 2 : 0;
    // (a band's broken values judged, lo to hi, are always in it: one value alone is a tick)
    const mark = (z, b, inset = half) => {
      z.hidden = !b || !(span > 0);
      if (z.hidden) return;
      const lo = b.from === null ? null : Math.min(b.from + inset, b.lo ?? Infinity);
      const hi = b.to === null ? null : Math.max(b.to - inset, b.hi ?? -Infinity);
      z.style.setProperty("--from", frac(lo, 0));
      z.style.setProperty("--to", frac(hi, 1));
      z.classList.toggle("tick", frac(hi, 1) - frac(lo, 0) < 0.01);
      z.title = b.text;
    };
    const track = row.querySelector(".track");
    for (const z of track.querySelectorAll(".unclean.band, .unjudged")) z.remove();
    for (const g of (q && q.unjudged) || []) {
      const z = document.createElement("span"); z.className = "unjudged";
      track.appendChild(z);
      mark(z, g, 0);
    }
    for (const side of ["below", "above"]) {
      const b = q && q[side] && bands.find((x) => x.text === q[side].text);
      mark(row.querySelector(`.unclean.${side}`), b || null);
    }
    for (const b of bands) {
      if ((q.below && b.text === q.below.text) || (q.above && b.text === q.above.text)) continue;
      const z = document.createElement("span"); z.className = "unclean band";
      track.appendChild(z);
      mark(z, b);
    }
    const u = row.querySelector(".unit");
    const counts = cleanCounts(p, q);
    const clean = !bands.length && !((q && q.unjudged) || []).length ? "" : counts ? `, clean at ${counts.map((x) => onStep(p, x)).join(", ")}`
      : !q.clean.length ? ", no clean value found" : `, ${cleanSaid(p, q)}`;
    u.textContent = `${p.unit || ""} (${onStep(p, p.min)}–${onStep(p, p.max)}${clean})`;
    r.title = [...bands, ...((q && q.unjudged) || [])].map((x) => x.text).join("\n");
    const v = state.values[p.name] !== undefined ? state.values[p.name] : p.value;
    pastNote(row, p.name, v);
  }
}
// the clean range as said: next to a part the time allowed left not checked, its end is only
// where the checking stopped (issue 113: a cut-short sweep read "clean 16–16")
function cleanSaid(p, q, long = false) {
  const [a, b] = q.clean, unit = p.unit ? ` ${p.unit}` : "";
  const cut = (q.unjudged || []).some((g) => Math.abs(g.to - a) < 1e-9 || Math.abs(g.from - b) < 1e-9);
  const said = a === b ? `at ${onStep(p, a)}` : `${onStep(p, a)}–${onStep(p, b)}`;
  return cut ? `clean ${said}${unit} of the values checked, the rest not checked in the time allowed`
    : long ? `clean from ${onStep(p, a)} to ${onStep(p, b)}${unit}` : `clean ${onStep(p, a)}–${onStep(p, b)}`;
}
// a count broken at scattered values: its clean values (`clean at 2, 4, 6, 8, 10`), else null
function cleanCounts(p, q) {
  const bands = (q && q.bands) || [], span = p.max - p.min;
  return p.step >= 1 && !p.unit && bands.length > 1 && span / p.step <= 12
    ? Array.from({ length: Math.round(span / p.step) + 1 }, (_, k) => p.min + k * p.step)
      .filter((x) => !bandAt(q, x)) : null;
}
// the slider's accessible text and the line under it: where its value is, against the clean range
// (the same clean values as its label says: a count's scattered ones named, never "the range
// found clean (4-4)" beside "clean at 2, 4, 6, 8, 10")
function pastNote(row, name, v) {
  const note = row.querySelector(".sweep-note"), r = row.querySelector("input[type=range]");
  if (!note || !r) return;
  const a = state.sweep.answer, q = a && a.ok && a.params ? a.params[name] : null;
  const p = state.params.find((x) => x.name === name) || {};
  const unit = p.unit ? ` ${p.unit}` : "";
  const past = bandAt(q, v);
  const ends = [...((q && q.bands) || []), ...((q && q.unjudged) || [])];
  const open = !past && q ? (q.unjudged || []).find((g) => typeof v === "number" && v > g.from + 1e-9 && v < g.to - 1e-9) : null;
  note.classList.toggle("past", !!past);
  note.classList.toggle("open", !!open);
  const counts = q ? cleanCounts(p, q) : null;
  if (past && counts && counts.length) {
    note.textContent = `${onStep(p, v)} is not one of the values the sweep found clean (${counts.map((x) => onStep(p, x)).join(", ")}): ${past.text}`;
    r.setAttribute("aria-valuetext", `${fmt(v)}, where the design breaks: ${past.text}`);
  } else if (past) {
    const beside = (q.below && past.text === q.below.text) || (q.above && past.text === q.above.text);
    note.textContent = beside
      ? `${onStep(p, v)}${unit} is outside the range the sweep found clean (${onStep(p, q.clean[0])}–${onStep(p, q.clean[1])}${unit}): ${past.text}`
      : !q.clean.length ? `${fmt(v)}${unit}: the design breaks at every value of this slider (the others where they are): ${past.text}`
        : past.from === past.lo || past.to === past.hi     // (an end beside a part not checked)
          ? `${fmt(v)}${unit} is in a part of the range where the design breaks: ${past.text}`
          : `${fmt(v)}${unit} is in a part of the range where the design breaks, between clean values: ${past.text}`;
    r.setAttribute("aria-valuetext", beside ? `${fmt(v)}${unit}, outside the clean range: ${past.text}`
      : `${fmt(v)}${unit}, where the design breaks: ${past.text}`);
  } else if (open) {
    note.textContent = `${fmt(v)}${unit} was not checked in the time allowed (${open.text})`;
    r.setAttribute("aria-valuetext", `${fmt(v)}${unit}, not checked in the time allowed`);
  } else {
    note.textContent = counts && counts.length
      ? `clean at ${counts.map((x) => onStep(p, x)).join(", ")}; ${ends.map((x) => x.text).join("; ")}`
      : ends.length && q.clean.length
      ? `${cleanSaid(p, q, true)}; ${ends.map((x) => x.text).join("; ")}` : "";
    if (typeof v === "number") r.setAttribute("aria-valuetext", `${fmt(v)}${unit}`);
  }
}

$("reset").onclick = () => { state.values = {}; state.paramKey = ""; schedule(0); };

// ------------------------------------------------------------------ 3D and downloads
// a download's name: the design and the values changed from its own (divider_tray-rows_5-cols_2)
// a pasted program's is its own title (the header's), an opened drawing's its file's name
// without the extension (flange80-d_90, not flange80.dxf-d_90)
function downloadName() {
  const slug = (t) => String(t).toLowerCase().replace(/[^a-z0-9.]+/g, "_").replace(/^_+|_+$/g, "");
  const base = (state.entry ? state.entry.replace(/^.*\//, "")
    : slug($("title").textContent).replace(/\.(dxf|svg|aidl)$/, "").replace(/\./g, "_")) || "design";
  const raw = chosenRaw();
  const parts = Object.keys(raw).sort().map((k) => {
    const v = raw[k];
    return `${slug(k)}_${typeof v === "boolean" ? (v ? "yes" : "no") : typeof v === "number" ? fmt(v) : slug(v)}`;
  });
  return [base, ...parts].join("-").slice(0, 96);
}
window.studio.downloadName = downloadName;

async function fetchFile(ext, extra = {}) {
  const r = await again(() => post(`/api/download/${ext}`, { sid: state.sid, source: state.source, values: chosen(),
                                                             settings: { ...settings(), name: downloadName(), ...extra } }, true));
  if (!r.ok) {
    const doc = await r.json().catch(() => ({}));
    throw new Error(refusal(doc, r.status));
  }
  const name = /filename="([^"]+)"/.exec(r.headers.get("Content-Disposition") || "");
  return { blob: await r.blob(), name: name ? name[1] : `part.${ext}` };
}

// why a download was refused, said once: the server's sentence, and its first message only
// when the sentence does not say it already ("nothing to make with these values: a hole removes
// all of `plate`" was followed by the same reason again)
function refusal(doc, status) {
  const error = doc.error || `HTTP ${status}`, first = doc.diagnostics && doc.diagnostics[0];
  const bare = (t) => String(t).replace(/[`'"“”‘’]/g, "").replace(/\s+/g, " ").trim().toLowerCase();
  return first && first.message && !bare(error).includes(bare(first.message)) ? `${error}: ${first.message}` : error;
}
window.studio.refusal = refusal;

async function load3d() {
  // the 3D view's GLB (/api/glb: made from the drawing the picture came from, fewer triangles
  // than the download); a newer picture's request makes this one's answer stale: dropped
  const seq = ++state.glbSeq;
  const shown = window.studio.views;
  // a share link's values are sent once the params are known: its 3D is framed again
  // until a model with all of them is shown (not left framed on the defaults)
  const sent = chosen();
  await pace();
  if (seq !== state.glbSeq) return;
  const withLink = !!state.linkValues && state.params.length > 0;   // the link's values were sent
  const reframe = state.reframe || !!state.linkValues;
  try {
    // the picture's own values (as the server drew it): its model is made from its outlines
    const values = (state.view && state.view.ok && state.view.values) || state.shownSent || sent;
    const r = await post("/api/glb", { sid: state.sid, source: state.source, values,
                                       settings: { thickness: settings().thickness } }, true);
    if (!r.ok) {
      const why = (await r.json().catch(() => ({}))).error || `HTTP ${r.status}`;
      if (r.status === 422 && seq === state.glbSeq) {      // nothing to show: say why, show nothing
        building(true, true);
        $("building3d").textContent = why;
        window.studio.glbView = shown;
      }
      throw new Error(why);
    }
    const blob = await r.blob();
    if (seq !== state.glbSeq || !window.aidl3d) return;
    const url = URL.createObjectURL(blob);
    const before = window.aidl3d.loaded;
    await window.aidl3d.load(url, { reframe });
    URL.revokeObjectURL(url);
    if (seq !== state.glbSeq || window.aidl3d.loaded === before) return;
    if (reframe) state.reframe = false;
    if (withLink) state.linkValues = null;
    window.studio.glbs += 1;
    window.studio.glbView = shown;          // the view whose 3D is on the screen
    window.studio.builtAt[shown] = performance.now();
    if (window.studio.timeline[shown]) window.studio.timeline[shown].built = window.studio.builtAt[shown];
    building(false);
    $("viewer3d").classList.remove("empty");
  } catch (e) {
    window.studio.errors.push("3D: " + (e.message || e));
    if (e.retry && seq === state.glbSeq) setTimeout(() => { if (seq === state.glbSeq) load3d(); }, e.retry * 1000);
  }
}

function showDownloads() {
  const box = $("downloads");
  const order = ["dxf", "svg", "pdf", "gcode", "lbrn2", "plt", "png", "stl", "3mf", "step", "glb"];
  // only the formats this server can make (STEP needs the `step` extra on the server)
  const formats = state.config.formats.filter((f) => f.available !== false).sort((a, b) => {
    const ia = order.indexOf(a.ext), ib = order.indexOf(b.ext);
    return (ia < 0 ? 99 : ia) - (ib < 0 ? 99 : ib);
  });
  for (const f of formats) {
    const b = document.createElement("button");
    b.type = "button"; b.textContent = f.ext.toUpperCase(); b.title = f.about;
    b.dataset.ext = f.ext;
    if (f.ext === "dxf") b.className = "main";
    b.onclick = () => download(f);
    box.appendChild(b);
  }
  for (const m of state.config.machines) {
    const o = document.createElement("option"); o.value = m; o.textContent = m;
    $("machine").appendChild(o);
  }
}

// the line under the buttons names the last file made: cleared when a value changes (it named
// the 3 mm STL after the thickness went to 6)
function downloadChanged() { $("download-status").textContent = ""; }

async function download(f) {
  $("download-status").textContent = `making ${f.ext.toUpperCase()}…`;
  try {
    const extra = f.cut ? {} : { layout: false, assembled: f.assembled };
    if (f.ext === "pdf" && $("page").value) extra.page = $("page").value;   // tiled 1:1 on paper
    // the SVG is the cutting file (hairlines, cut and engrave layers, no sheet outline) unless
    // the picture is chosen
    if (f.ext === "svg") extra.style = $("svg-style").value || "laser";
    const { blob, name } = await fetchFile(f.ext, extra);
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob); a.download = name;
    document.body.appendChild(a); a.click(); a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
    $("download-status").textContent = `${name}: ${blob.size.toLocaleString()} bytes`;
  } catch (e) {
    $("download-status").textContent = `${f.ext.toUpperCase()}: ${e.message || e}`;
  }
}
$("fit3d").onclick = () => { if (window.aidl3d) window.aidl3d.frame(); };

// ------------------------------------------------------------------ the gallery
async function openGallery() {
  const dlg = $("gallery");
  if (!state.gallery) {
    state.gallery = await getJSON("/api/gallery");
    const cards = $("cards");
    for (const e of state.gallery) {
      const c = document.createElement("button");
      c.type = "button"; c.className = "card"; c.dataset.id = e.id;
      c.dataset.text = `${e.title} ${e.purpose} ${(e.tags || []).join(" ")} ${e.kind}`.toLowerCase();
      const img = document.createElement("img");
      img.loading = "lazy"; img.alt = e.title; img.src = `/api/thumb/${e.id}.svg`;
      // a busy studio answers 503 (nothing kept): ask again a few times, later each time
      let tries = 0;
      img.onerror = () => {
        if (++tries <= 4) setTimeout(() => { img.src = `/api/thumb/${e.id}.svg?try=${tries}`; }, 1500 * tries);
      };
      const kind = document.createElement("div"); kind.className = "kind"; kind.textContent = e.kind;
      const t = document.createElement("strong"); t.textContent = e.title;
      const p = document.createElement("p"); p.textContent = e.purpose;
      c.append(img, kind, t, p);
      // the dialog gives the focus back to what opened it; a chosen design's parameters
      // are where a keyboard user goes next
      c.onclick = () => { dlg.close(); openEntry(e.id); $("params-summary").focus(); };
      cards.appendChild(c);
    }
  }
  dlg.showModal();
}
$("open-gallery").onclick = openGallery;
$("gallery-search").oninput = () => {
  const q = $("gallery-search").value.trim().toLowerCase();
  for (const c of $("cards").children) c.hidden = q && !c.dataset.text.includes(q);
};

async function openEntry(id) {
  const e = await getJSON(`/api/gallery/${id}`);
  state.entry = id;
  state.ownTitle = false;
  $("title").textContent = e.title;
  setProgram(e.source, {});
}

function setProgram(source, values, given = null) {
  state.source = source;
  freshProgram(values, given);
  if (editor) editor.setText(source);
  schedule(0);
}

// another program on the page (a card, a paste, a shared link, a drawing, a described part):
// nothing of the one before stays: its values, its picture, its 3D model and camera (framed
// again on the new one: a paste kept the old camera, its disc drawn 2.5 x smaller than when
// opened fresh), the line under the downloads, the kerf's note
function freshProgram(values, given = null) {
  newProgram(values, given);
  state.lastSvg = null;
  state.reframe = true;
  state.linkValues = null;                  // (a share link sets its own after this)
  state.glbSeq += 1;                        // a 3D still on its way is the old design's
  state.fitNext = true;                     // the flat view shows all of the new design
  markFor("");
  $("download-status").textContent = "";    // the last design's download is not this one's
  state.kerfFails = false;
  kerfNote("");
  if (state.kerf) state.kerfRecheck = true;  // the kerf checked again on the new design
  building(true, true);
}

// a session's values belong to one program: another program (a card, a paste, a shared link,
// a described part) starts from its own values, and from the given ones
function newProgram(values = {}, given = null) {
  state.values = { ...values };
  state.givenTexts = given;
  state.params = [];
  state.paramKey = "";
  sweepChanged(true);
}

// most of the program replaced at once (a paste over it, or the whole text deleted): another
// program, not an edit of this one
function replaced(before, after) {
  if (!after.trim()) return true;
  const n = Math.min(before.length, after.length);
  let i = 0, j = 0;
  while (i < n && before[i] === after[i]) i++;
  while (j < n - i && before[before.length - 1 - j] === after[after.length - 1 - j]) j++;
  return before.length - i - j > before.length / 2 && after.length - i - j > after.length / 2;
}

// ------------------------------------------------------------------ share links and embeds
function b64url(bytes) {
  let s = ""; for (const b of bytes) s += String.fromCharCode(b);
  return btoa(s).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}
function unb64url(text) {
  const s = atob(text.replace(/-/g, "+").replace(/_/g, "/"));
  return Uint8Array.from(s, (c) => c.charCodeAt(0));
}
async function pack(doc) {
  const stream = new Blob([JSON.stringify(doc)]).stream().pipeThrough(new CompressionStream("deflate-raw"));
  return b64url(new Uint8Array(await new Response(stream).arrayBuffer()));
}
async function unpack(text) {
  const stream = new Blob([unb64url(text)]).stream().pipeThrough(new DecompressionStream("deflate-raw"));
  return JSON.parse(await new Response(stream).text());
}
async function link(path) {
  const values = chosenRaw();
  const packed = await pack({ v: 1, source: state.source, values, set: texts(values), settings: settings(),
                              title: $("title").textContent });
  return `${location.origin}${path}#p=${packed}`;
}
async function share(kind) {
  const url = await link(kind === "embed" ? "/embed" : "/");
  $("share-what").textContent = kind === "embed"
    ? "Paste this on your page: it shows this design with its sliders."
    : "This link opens this design with these values (it is all in the link; nothing is stored).";
  $("share-text").value = kind === "embed"
    ? `<iframe src="${url}" width="900" height="520" style="border:1px solid #ccc" title="AIDL design"></iframe>`
    : url;
  $("share-dialog").showModal();
  $("share-text").select();
  window.studio.shared = $("share-text").value;
}
$("share").onclick = () => share("link");
$("embed").onclick = () => share("embed");
$("copy").onclick = () => navigator.clipboard && navigator.clipboard.writeText($("share-text").value);

// ------------------------------------------------------------------ describe the part
async function describe() {
  const text = $("describe-text").value.trim();
  if (!text) return;
  const list = $("rounds");
  list.innerHTML = "";
  $("describe-go").disabled = true;
  $("describe-status").textContent = "asking the model…";
  try {
    const r = await post("/api/describe", { sid: state.sid, description: text }, true);
    if (!r.ok) throw new Error((await r.json().catch(() => ({}))).error || `HTTP ${r.status}`);
    const reader = r.body.pipeThrough(new TextDecoderStream()).getReader();
    let buf = "";
    for (;;) {
      const { value, done } = await reader.read();
      if (done) break;
      buf += value;
      let i;
      while ((i = buf.indexOf("\n")) >= 0) {
        const line = buf.slice(0, i); buf = buf.slice(i + 1);
        if (line.trim()) onEvent(JSON.parse(line), list);
      }
    }
  } catch (e) {
    $("describe-status").textContent = String(e.message || e);
  } finally {
    $("describe-go").disabled = false;
  }
}

function onEvent(ev, list) {
  if (ev.type === "round") {
    const li = document.createElement("li");
    const head = document.createElement("div");
    const errs = (ev.diagnostics || []).filter((d) => d.severity === "error").length;
    head.textContent = `round ${ev.n}: ` + (ev.ok ? "checks" : `${errs} error${errs === 1 ? "" : "s"}`);
    li.appendChild(head);
    for (const d of (ev.diagnostics || []).slice(0, 4)) {
      const m = document.createElement("div"); m.className = "muted";
      m.textContent = `${d.line ? d.line + ":" + d.col + " " : ""}${d.code}: ${d.message}`;
      li.appendChild(m);
    }
    if (ev.svg) {
      const img = document.createElement("img");
      img.src = URL.createObjectURL(new Blob([ev.svg], { type: "image/svg+xml" }));
      img.alt = `round ${ev.n}`;
      li.appendChild(img);
    }
    const pre = document.createElement("pre"); pre.textContent = ev.code || "";
    li.appendChild(pre);
    list.appendChild(li);
    $("describe-status").textContent = `round ${ev.n}…`;
  } else if (ev.type === "done") {
    $("describe-status").textContent = ev.message || (ev.ok ? "done" : "no program checked");
    if (ev.code) { $("title").textContent = "Described part"; state.entry = null; state.ownTitle = true; setProgram(ev.code, {}); }
  } else if (ev.type === "error") {
    $("describe-status").textContent = ev.message;
  }
}
$("describe-go").onclick = describe;

// ------------------------------------------------------------------ uploads
async function refreshFiles() {
  const doc = await getJSON(`/api/files?sid=${state.sid}`);
  const ul = $("files"); ul.innerHTML = "";
  for (const f of doc.files || []) {
    const li = document.createElement("li");
    li.textContent = `${f.name} (${f.bytes.toLocaleString()} bytes) `;
    const del = document.createElement("button"); del.type = "button"; del.textContent = "delete";
    del.onclick = async () => { await again(() => post("/api/delete", { sid: state.sid, name: f.name })); refreshFiles(); schedule(0); };
    li.appendChild(del); ul.appendChild(li);
  }
}
// a file name the server takes: letters, digits, `.`, `_` and `-` (at most 64): `My plate
// (2).dxf` is sent as `My_plate_2_.dxf`
function fileName(name) {
  const ext = (/\.[A-Za-z0-9]+$/.exec(name) || [""])[0];
  return (name.slice(0, name.length - ext.length).replace(/[^\w.-]+/g, "_")
    .slice(0, 64 - ext.length) || "drawing") + ext;
}
async function send(f, how) {       // the upload's answer, or {error}
  const q = how ? `&import=${how}` : "";
  try {
    const r = await again(() => request(
      `/api/upload?sid=${state.sid}&name=${encodeURIComponent(fileName(f.name))}${q}`, { method: "POST", body: f }));
    const doc = await r.json().catch(() => ({}));
    return r.ok ? doc : { error: doc.error || `the upload failed (HTTP ${r.status})` };
  } catch (e) { return { error: String(e.message || e) }; }
}

// "Your drawings": a file kept for the program (Drawing2D("name.dxf"), import "name.aidl")
$("upload").onchange = async () => {
  const f = $("upload").files[0];
  if (!f) return;
  const doc = await send(f, null);
  $("upload").value = "";
  $("upload-status").textContent = doc.error || `${doc.name} is kept for your program`;
  refreshFiles(); schedule(0);
};

// "Open my drawing": a DXF or SVG opened as an editable design (`aidl import --infer`: its
// shapes, sizes and params as sliders) or as the drawing itself (`Drawing2D`)
$("open-drawing").onclick = () => { $("drawing-status").textContent = ""; $("drawing-dialog").showModal(); };
$("drawing-file").onchange = async () => {
  const f = $("drawing-file").files[0];
  if (!f) return;
  const how = document.querySelector('input[name="open-as"]:checked').value;
  const said = $("drawing-status");
  said.textContent = `reading ${f.name}…`;
  const doc = await send(f, how);
  $("drawing-file").value = "";
  window.studio.uploaded = doc;
  if (doc.error || doc.import_error) { said.textContent = doc.error || `${doc.name} cannot be opened: ${doc.import_error}`; return; }
  $("drawing-dialog").close();
  $("title").textContent = doc.name.replace(/\.(dxf|svg)$/i, "");
  state.entry = null;
  state.ownTitle = false;
  setProgram(doc.program, {});
  $("upload-status").textContent = `opened ${doc.name} ${how === "infer" ? "as an editable design" : "as a drawing"}`
    + (doc.notes && doc.notes.length ? `; ${doc.notes.join("; ")}` : "");
  refreshFiles();
  $("params-summary").focus();
};

// ------------------------------------------------------------------ start
let editor = null;
async function hover(text, pos) {
  let a = pos, b = pos;
  while (a > 0 && /[\w.]/.test(text[a - 1])) a--;
  while (b < text.length && /\w/.test(text[b])) b++;
  const word = text.slice(a, b).replace(/^.*\./, "");
  if (!/^[A-Za-z_]\w*$/.test(word)) return null;
  const doc = await fetch(`/api/docs?name=${encodeURIComponent(word)}`).then((r) => r.json()).catch(() => ({}));
  return doc.text || null;
}

async function start() {
  if (EMBED) document.body.classList.add("embed");
  state.config = await getJSON("/api/config");
  state.sid = (await again(() => post("/api/session", {}))).sid;
  window.addEventListener("pagehide", () =>
    navigator.sendBeacon("/api/close", new Blob([JSON.stringify({ sid: state.sid })], { type: "application/json" })));
  if (!EMBED) {
    editor = createEditor($("code"), { doc: "", hover, wrap: true, label: "the program",
      onChange: (text) => {
        // another program pasted over this one: its own title (the header and the
        // downloads' names follow it, not the gallery design it replaced)
        if (replaced(state.source, text)) {
          state.entry = null; state.ownTitle = true;
          $("title").textContent = "";        // its own title once it compiles (view.title)
          freshProgram({});
        }
        else sweepChanged(false);
        state.source = text; schedule(250);
      } });
    editor.goto = (line, col) => {
      const doc = editor.view.state.doc;
      const l = doc.line(Math.max(1, Math.min(line, doc.lines)));
      editor.view.dispatch({ selection: { anchor: Math.min(l.from + Math.max(0, col - 1), l.to) }, scrollIntoView: true });
      editor.view.focus();
    };
    window.studio.editor = editor;
    $("describe").hidden = !state.config.model;
  }
  showDownloads();
  const m = /#p=([A-Za-z0-9_-]+)/.exec(location.hash);
  if (m) {
    try {
      const doc = await unpack(m[1]);
      $("title").textContent = doc.title || "Shared design";
      const s = doc.settings || {};
      if (typeof s.kerf === "number" && s.kerf >= 0 && s.kerf <= 10) { state.kerf = s.kerf; $("kerf").value = fmt(s.kerf); }
      if (s.sheet) { $("sheet-w").value = s.sheet[0]; $("sheet-h").value = s.sheet[1]; }
      if (s.machine) $("machine").value = s.machine;
      if (s.layout != null) $("layout").checked = !!s.layout;
      setProgram(String(doc.source || ""), doc.values || {}, doc.set || null);
      if (doc.values && Object.keys(doc.values).length) state.linkValues = doc.values;
    } catch (e) {
      status("this link is damaged: it does not hold a design");
    }
  } else if (!EMBED) {
    await openEntry("generator/divider_tray").catch(() => {});
    openGallery();
  }
  window.studio.ready = true;
}
start();
