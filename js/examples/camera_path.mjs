// The camera example's script (see camera_path.html). Flies a camera along a
// CRSplinePoseCurve; window.flight lets a test stop the clock and place the
// camera at a given u ({ready, keyU, setU(u), pose(u)}).
import { init } from 'crspline';
import { CRSplinePoseCurve } from 'crspline/three';
import * as THREE from 'three';

await init();

const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setClearColor(0xffffff);
const scene = new THREE.Scene();
scene.add(new THREE.AmbientLight(0xffffff, 1.5));
// The target: a red box at the origin; blue pillars around it.
const target = new THREE.Mesh(new THREE.BoxGeometry(1.2, 1.2, 1.2), new THREE.MeshBasicMaterial({ color: 0xd0021b }));
scene.add(target);
for (let k = 0; k < 8; ++k) {
  const a = ((k + 0.5) / 8) * 2 * Math.PI;  // between the keys' lines of sight
  const pillar = new THREE.Mesh(new THREE.BoxGeometry(0.4, 3, 0.4), new THREE.MeshBasicMaterial({ color: 0x1f5fbf }));
  pillar.position.set(3 * Math.cos(a), 0, 3 * Math.sin(a));
  scene.add(pillar);
}
const camera = new THREE.PerspectiveCamera(50, canvas.width / canvas.height, 0.1, 100);

// The keys: positions around the scene at varying height and distance, each
// looking at the target; keys 2 and 4 rolled by 30 degrees about the view
// direction (a pose curve interpolates roll too, which lookAt cannot).
const positions = [[8, 2, 0], [5, 4, 6], [-2, 1.5, 8], [-8, 3, 1], [-3, 5, -7], [4, 2, -6]].map((p) => new THREE.Vector3(...p));
const up = new THREE.Vector3(0, 1, 0);
const quaternions = positions.map((p, k) => {
  const q = new THREE.Quaternion().setFromRotationMatrix(new THREE.Matrix4().lookAt(p, new THREE.Vector3(), up));
  if (k === 2 || k === 4) q.multiply(new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 0, 1), Math.PI / 6));
  return q;
});
const path = new CRSplinePoseCurve(positions, quaternions);
// The path itself, drawn as a thin tube (a three.js Curve of the positions).
scene.add(new THREE.Mesh(new THREE.TubeGeometry(path, 300, 0.03, 6, false), new THREE.MeshBasicMaterial({ color: 0x888888 })));

// Constant speed along the path: 600 values of u at equal arc length.
const steps = path.constantSpeedU(600);
const grid = path.pose.grid;
const keyU = Array.from(grid, (t) => (t - grid[0]) / (grid[grid.length - 1] - grid[0]));

function place(u) {
  path.applyTo(camera, u);
  camera.updateMatrixWorld();
  renderer.render(scene, camera);
}

let running = true;
const t0 = performance.now();
function frame(now) {
  if (!running) return;
  // (the first frame's timestamp may precede t0)
  const k = Math.floor((Math.max(0, now - t0) / 20) % steps.length);
  place(steps[k]);
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);

window.flight = {
  ready: true,
  keyU,
  positions: positions.map((p) => p.toArray()),
  /// Stops the flight and places the camera at u: what three.js has.
  setU(u) {
    running = false;
    place(u);
    const dir = camera.getWorldDirection(new THREE.Vector3());
    const gl = renderer.getContext();
    const px = new Uint8Array(4);
    gl.readPixels(canvas.width / 2, canvas.height / 2, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    return { position: camera.position.toArray(), quaternion: camera.quaternion.toArray(), direction: dir.toArray(), center: Array.from(px) };
  },
  /// The pose curve's own numbers at u (crspline's [w, x, y, z]).
  pose(u) {
    const s = path.pose.evaluate(path.tAt(u));
    return { position: Array.from(s.position), orientation: Array.from(s.orientation) };
  },
};
