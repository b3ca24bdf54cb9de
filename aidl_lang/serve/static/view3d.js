// aidl serve: the assembled product in 3D (three.js 0.170.0, vendored in vendor/three/; MIT,
// see its LICENSE and README.md). The server's GLB (/download/glb: every part extruded by its
// thickness, placed by its `Place`, one named node per part in the flat view's colours) is
// loaded into a scene with orbit (drag), zoom (wheel) and pan (right-drag); app.js calls load()
// on every new picture while the 3D view is shown, and the camera stays where the user left it
// (aidl studio loads a GLB blob the same way, with `reframe` when another design is opened).
import * as THREE from "three";
import { GLTFLoader } from "/static/vendor/three/examples/jsm/loaders/GLTFLoader.js";
import { OrbitControls } from "/static/vendor/three/examples/jsm/controls/OrbitControls.js";

const host = document.getElementById("viewer3d");
const state = { renderer: null, scene: null, camera: null, controls: null, root: null,
                framed: false, seq: 0 };
// read by the browser test: loads finished, the part names and their colours, the last error
window.aidl3d = { loaded: 0, frames: 0, parts: [], colours: {}, error: null, load, frame, clear, reach,
                 framed: 0, camera: () => state.camera ? state.camera.position.toArray() : null };

function init() {
  const r = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  r.setPixelRatio(window.devicePixelRatio || 1);
  // the keyboard reaches the view too: focused, arrow keys turn it, Shift+arrows pan, + and -
  // zoom, F (or Home) looks at the whole product again
  Object.assign(r.domElement, { tabIndex: 0 });
  r.domElement.setAttribute("role", "img");
  r.domElement.setAttribute("aria-label", "the assembled product in 3D: arrow keys turn it, "
    + "Shift and arrow keys pan, + and - zoom, F shows all of it");
  r.domElement.addEventListener("keydown", onKey);
  host.appendChild(r.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 1e7);
  camera.up.set(0, 0, 1);                       // the product's z is up (z = 0: the table)
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(-0.6, -1, 1.4);
  camera.add(sun);                              // a light that turns with the view
  scene.add(camera);
  const controls = new OrbitControls(camera, r.domElement);
  controls.enableDamping = false;
  // a page that scrolls (aidl studio on a phone: data-touch="scroll"): one finger scrolls the
  // page over the view, two fingers pinch to zoom and turn it (OrbitControls sets touch-action
  // none; the page's scroll gets one finger back). aidl serve's fixed page: one finger turns
  if (host.dataset.touch === "scroll") {
    controls.touches = { ONE: null, TWO: THREE.TOUCH.DOLLY_ROTATE };
    r.domElement.style.touchAction = "pan-x pan-y";
    r.domElement.addEventListener("touchmove", (e) => { if (e.touches.length > 1) e.preventDefault(); },
                                  { passive: false });
  }
  // drawn on change only (a camera move, a model, a resize): no frame while nothing moves
  controls.addEventListener("change", () => redraw());
  Object.assign(state, { renderer: r, scene, camera, controls });
  new ResizeObserver(resize).observe(host);
  resize();
}

// one frame at the next repaint, however many changes ask for it before then (`now`: at once,
// a new model: on the screen when `loaded` counts it)
function redraw(now = false) {
  if (now && state.renderer) {
    state.renderer.render(state.scene, state.camera);
    window.aidl3d.frames += 1;
    return;
  }
  if (state.pending || !state.renderer) return;
  state.pending = true;
  requestAnimationFrame(() => {
    state.pending = false;
    state.renderer.render(state.scene, state.camera);
    window.aidl3d.frames += 1;
  });
}

function resize() {
  const w = host.clientWidth || 1, h = host.clientHeight || 1;
  state.renderer.setSize(w, h, false);
  state.renderer.domElement.style.width = "100%";
  state.renderer.domElement.style.height = "100%";
  state.camera.aspect = w / h;
  state.camera.updateProjectionMatrix();
  redraw();
}

function onKey(e) {
  const c = state.controls;
  if (!c || e.altKey || e.ctrlKey || e.metaKey) return;
  const turn = Math.PI / 18, pan = 20;          // 10 degrees; 20 pixels
  const arrows = { ArrowLeft: [1, 0], ArrowRight: [-1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
  const a = arrows[e.key];
  if (a && e.shiftKey) c._pan(a[0] * pan, a[1] * pan);
  else if (a) { if (a[0]) c._rotateLeft(a[0] * turn); else c._rotateUp(a[1] * turn); }
  // (OrbitControls' _dollyOut(k) divides the distance by k: closer; _dollyIn(k) multiplies)
  else if (e.key === "+" || e.key === "=") c._dollyOut(1.25);
  else if (e.key === "-" || e.key === "_") c._dollyIn(1.25);
  else if (e.key === "f" || e.key === "F" || e.key === "Home") { frame(); e.preventDefault(); return; }
  else return;
  e.preventDefault();
  c.update();
  redraw();
}

// how far the product reaches across the view: the largest |x| or |y| of its bounding box's
// corners in normalized device coordinates (1: the pane's edge; more: it runs out of the
// pane; Infinity: a corner behind the camera); 0 with no model
function reach() {
  if (!state.root || !state.camera) return 0;
  const box = new THREE.Box3().setFromObject(state.root);
  if (box.isEmpty()) return 0;
  state.camera.updateMatrixWorld();
  let most = 0;
  for (let i = 0; i < 8; i++) {
    const p = new THREE.Vector3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                                i & 4 ? box.max.z : box.min.z);
    const v = p.clone().applyMatrix4(state.camera.matrixWorldInverse);
    if (v.z >= 0) return Infinity;
    p.project(state.camera);
    most = Math.max(most, Math.abs(p.x), Math.abs(p.y));
  }
  return most;
}

function frame() {    // look at the whole product from above its front-left corner
  if (!state.root) return;
  window.aidl3d.framed += 1;
  const box = new THREE.Box3().setFromObject(state.root);
  const c = box.getCenter(new THREE.Vector3());
  const r = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-3);
  // the narrower of the two angles of view: a tall, narrow pane sees less across than up
  const half = Math.atan(Math.tan((state.camera.fov * Math.PI) / 360) * Math.min(1, state.camera.aspect));
  const d = r / Math.sin(half) * 1.1;
  state.camera.position.copy(c).add(new THREE.Vector3(-0.55, -0.75, 0.45).normalize().multiplyScalar(d));
  state.camera.near = d / 1000; state.camera.far = d * 100;
  state.camera.updateProjectionMatrix();
  state.controls.target.copy(c);
  state.controls.update();
  redraw();
}

function clear() {    // no model on the screen (aidl studio: another design is being built)
  state.seq += 1;                                // a load still under way is dropped
  if (state.root) {
    state.scene.remove(state.root);
    state.root.traverse((o) => { if (o.geometry) o.geometry.dispose(); });
    state.root = null;
    redraw();
  }
  Object.assign(window.aidl3d, { parts: [], colours: {} });
}

async function load(url, opts = {}) {   // opts.reframe: a new design, look at all of it again
  if (!state.renderer) init();
  const seq = ++state.seq;
  if (opts.reframe) state.framed = false;
  try {
    const gltf = await new GLTFLoader().loadAsync(url);
    if (seq !== state.seq) return;               // a newer picture was asked for meanwhile
    const before = reach();                       // the old model all in view (<= 1)?
    if (state.root) {
      state.scene.remove(state.root);
      state.root.traverse((o) => { if (o.geometry) o.geometry.dispose(); });
    }
    state.root = gltf.scene;
    const parts = [], colours = {};
    const nodes = gltf.parser.json.nodes || [];
    state.root.traverse((o) => {
      if (!o.isMesh) return;
      // the part's name as the server wrote it (three.js drops the dots of `kit.box.lid`)
      const at = gltf.parser.associations.get(o) || gltf.parser.associations.get(o.parent) || {};
      const name = (nodes[at.nodes] && nodes[at.nodes].name) || o.name;
      // each part is one colour (its vertex colours, sRGB bytes): a matte material of it,
      // flat-shaded, so the faces of a panel read as in the flat view's colours
      // (aidl studio's view GLB gives it as the material's colour instead: shared meshes)
      const col = o.geometry.getAttribute("color");
      const colour = new THREE.Color(0x607d8b);
      if (col) colour.setRGB(col.getX(0), col.getY(0), col.getZ(0), THREE.SRGBColorSpace);
      else if (o.material && o.material.color) colour.copy(o.material.color);
      if (o.material && o.material.dispose) o.material.dispose();
      o.material = new THREE.MeshStandardMaterial({ color: colour, roughness: 0.9, metalness: 0,
                                                    flatShading: true, side: THREE.DoubleSide });
      o.name = name;
      parts.push(name);
      colours[name] = "#" + colour.getHexString(THREE.SRGBColorSpace);
    });
    state.scene.add(state.root);
    // a new design is framed; a changed one keeps the camera unless it grew out of the view
    // (the old model was all in view, the new one is not: not when the user zoomed in)
    if (!state.framed || (before <= 1 && reach() > 1)) { frame(); state.framed = true; }
    Object.assign(window.aidl3d, { parts, colours, error: null });
    redraw(true);
    window.aidl3d.loaded += 1;
  } catch (e) {
    window.aidl3d.error = String(e && e.message || e);
  }
}
