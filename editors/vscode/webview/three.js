// The preview's 3D view's libraries (three.js, its glTF loader and orbit controls), the entry
// that build.js bundles into dist/webview/three.js: one ES module the webview page imports
// through its resource URI (no CDN, no import map; see preview.js, view3d).
export * from 'three';
export { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
export { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
