// The page `relpos view` writes (docs/spec.md §3.12): the fixed object with its features and
// mesh, the obstacles, the mobile object at each branch's nearest pose, ghosts at the chosen
// branch's samples, and a slider per parameter of the chosen branch that moves it (PMF's Fig. 11).
// The scene is the JSON in <script id="relpos-scene">; window.relposViewer lets tests drive it.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

import { branchPose, matrixOf } from './pose.js';
import { colours, objectGroup, paint, setPose } from './objects.js';
import { buildPanel } from './panel.js';

const scene = JSON.parse(document.getElementById('relpos-scene').textContent);
const size = scene.size > 0 ? scene.size : 1;
const background = 0xf4f5f7;

const viewport = document.getElementById('viewport');
let renderer;
try {
  // preserveDrawingBuffer: the pixels stay readable after a frame (a screenshot, stats()).
  renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
} catch (e) {
  document.getElementById('message').textContent = 'This browser cannot draw WebGL: ' + e.message;
  window.relposViewer = { ready: false, error: String(e.message || e) };
  throw e;
}
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setClearColor(background);
viewport.appendChild(renderer.domElement);

const world = new THREE.Scene();
world.add(new THREE.HemisphereLight(0xffffff, 0x667080, 2.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.6);
sun.position.set(1, -2, 3);
world.add(sun);
const axes = new THREE.AxesHelper(0.5 * size);
world.add(axes);

// Robots' convention: z up.
const camera = new THREE.PerspectiveCamera(40, 1, 1e-3 * size, 1e3 * size);
camera.up.set(0, 0, 1);
const controls = new OrbitControls(camera, renderer.domElement);

const fixed = objectGroup(scene.fixed, colours.fixed, 1, size);
setPose(fixed, matrixOf(scene.fixed.pose));
world.add(fixed);
for (const o of scene.obstacles) {
  const g = objectGroup(o, colours.obstacle, 0.8, size);
  setPose(g, matrixOf(o.pose));
  world.add(g);
}

// The mobile object: one copy per branch at its nearest pose (the chosen one solid), or at its
// initial pose when there is no branch.
const copies = scene.branches.map((b) => {
  const g = objectGroup(scene.mobile, colours.mobile, 1, size);
  const frameAxes = new THREE.AxesHelper(0.25 * size);  // the mobile frame: its turn shows
  frameAxes.userData.keepColour = true;
  g.add(frameAxes);
  setPose(g, matrixOf(b.nearest.pose));
  world.add(g);
  return g;
});
if (scene.branches.length === 0) {
  const g = objectGroup(scene.mobile, colours.mobile, 0.5, size);
  setPose(g, matrixOf(scene.mobile.pose));
  world.add(g);
}
const ghosts = new THREE.Group();
world.add(ghosts);

const state = { branch: -1, theta: [], showGhosts: true, showOthers: true };

function render() {
  renderer.render(world, camera);
}

function resize() {
  const w = viewport.clientWidth, h = viewport.clientHeight;
  renderer.setSize(w, h);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
  render();
}

function frame() {
  world.updateMatrixWorld(true);
  const box = new THREE.Box3().setFromObject(world);
  const sphere = box.getBoundingSphere(new THREE.Sphere());
  const r = Math.max(sphere.radius, 0.1 * size);
  const distance = (1.25 * r) / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
  camera.position.copy(sphere.center).add(new THREE.Vector3(1.1, -1.6, 0.9).normalize().multiplyScalar(distance));
  controls.target.copy(sphere.center);
  controls.update();
}

function collides(i) {
  const b = scene.branches[i];
  return b.collision !== undefined && b.collision.nearest_collides;
}

// With collision filtering, the chosen branch's nearest collision-free pose, in green.
const free = objectGroup(scene.mobile, colours.free, 0.45, size, !scene.mobile.mesh);
free.visible = false;
world.add(free);

// Moves the chosen branch's copy to its pose at state.theta (hidden where there is none).
function place() {
  const b = scene.branches[state.branch];
  const X = branchPose(b, state.theta);
  const copy = copies[state.branch];
  copy.visible = X !== null;
  if (X) setPose(copy, X);
  // The collision verdict is the nearest pose's: red there only.
  const atNearest = state.theta.every((v, k) => v === b.nearest.parameters[k]);
  paint(copy, atNearest && collides(state.branch) ? colours.collides : colours.mobile, 1, true);
  panel.showPose(X);
  render();
}

function select(i) {
  state.branch = i;
  const b = scene.branches[i];
  state.theta = b.nearest.parameters.slice();
  copies.forEach((g, k) => {
    setPose(g, matrixOf(scene.branches[k].nearest.pose));
    g.visible = k === i || state.showOthers;
    paint(g, k === i ? colours.mobile : 0xb9bcc4, k === i ? 1 : 0.25);
  });
  const nearestFree = b.collision ? b.collision.nearest_free : null;
  free.visible = nearestFree !== null;
  if (nearestFree) setPose(free, matrixOf(nearestFree));
  ghosts.clear();
  for (const X of b.samples) {
    // A mesh alone when there is one: features at every sample would hide the picture.
    const g = objectGroup(scene.mobile, colours.ghost, 0.18, size, !scene.mobile.mesh);
    setPose(g, matrixOf(X));
    ghosts.add(g);
  }
  ghosts.visible = state.showGhosts;
  panel.showBranch(i, state.theta);
  place();
}

const panel = buildPanel(scene, {
  select,
  setParameter(k, value) {
    state.theta[k] = value;
    place();
  },
  reset() {
    select(state.branch);
  },
  showGhosts(on) {
    state.showGhosts = on;
    ghosts.visible = on;
    render();
  },
  showOthers(on) {
    state.showOthers = on;
    copies.forEach((g, k) => (g.visible = k === state.branch || on));
    render();
  },
});

controls.addEventListener('change', render);
window.addEventListener('resize', resize);
frame();
if (scene.branches.length > 0) select(scene.best >= 0 ? scene.best : 0);
resize();

// What the tests read: the chosen branch's pose as the page draws it, and the drawn pixels.
window.relposViewer = {
  ready: true,
  scene,
  branch: () => state.branch,
  theta: () => state.theta.slice(),
  select,
  mobileMatrix: () => (state.branch >= 0 && copies[state.branch].visible ? copies[state.branch].matrix.toArray() : null),
  freeMatrix: () => (free.visible ? free.matrix.toArray() : null),
  stats() {
    render();
    const gl = renderer.getContext();
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const pixels = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    // The clear colour as stored: its sRGB bytes (a THREE.Color would hold it linear).
    const [r0, g0, b0] = [(background >> 16) & 255, (background >> 8) & 255, background & 255];
    let drawn = 0, checksum = 0;
    for (let k = 0; k < pixels.length; k += 4) {
      if (Math.abs(pixels[k] - r0) + Math.abs(pixels[k + 1] - g0) + Math.abs(pixels[k + 2] - b0) > 12) ++drawn;
      checksum = (checksum * 31 + pixels[k] + 7 * pixels[k + 1] + 13 * pixels[k + 2]) >>> 0;
    }
    return { width: w, height: h, drawn, checksum };
  },
};
