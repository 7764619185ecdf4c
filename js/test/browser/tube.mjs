// The closed trefoil knot as a tube, twice: three.js' TubeGeometry (or
// crspline's sweep without the holonomy spread) and CRSplineTubeGeometry.
// A texture of 8 bands around the tube shows the frame: where it jumps at
// the closing ring the bands break. window.result: for each tube, the
// pixels of a close-up on the closing ring (a camera looking at it from
// outside, the tangent up the image) compared row against row across it.
import { init } from 'crspline';
import { CRSplineCurve3, CRSplineTubeGeometry } from 'crspline/three';
import * as THREE from 'three';

const W = 400, H = 400, R = 0.3;

const trefoil = Array.from({ length: 12 }, (_, i) => {
  const a = (2 * Math.PI * i) / 12;
  return new THREE.Vector3(Math.sin(a) + 2 * Math.sin(2 * a), Math.cos(a) - 2 * Math.cos(2 * a), -Math.sin(3 * a));
});

// 8 bands around (uv.y), none along.
function bands() {
  const c = document.createElement('canvas');
  c.width = 4;
  c.height = 256;
  const g = c.getContext('2d');
  const colours = ['#1f5fbf', '#f0c020', '#d03030', '#30a050', '#1f5fbf', '#f0c020', '#d03030', '#30a050'];
  colours.forEach((col, k) => { g.fillStyle = col; g.fillRect(0, k * 32, 4, 32); });
  const t = new THREE.CanvasTexture(c);
  t.magFilter = THREE.NearestFilter;
  t.minFilter = THREE.NearestFilter;
  t.generateMipmaps = false;
  return t;
}

function renderer(id) {
  const r = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  r.setPixelRatio(1);
  r.setSize(W, H);
  r.setClearColor(0xffffff);
  document.getElementById(id).appendChild(r.domElement);
  return r;
}

function pixels(r) {
  const gl = r.getContext(), out = new Uint8Array(W * H * 4);
  gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, out);
  return out;
}

// Mean channel difference of pixel rows y - d and y + d (readPixels' rows)
// over the middle half of the width, where the tube is.
function rowDifference(px, y, d) {
  let sum = 0, n = 0;
  for (let x = W / 4; x < (3 * W) / 4; ++x)
    for (let c = 0; c < 3; ++c) { sum += Math.abs(px[4 * ((y - d) * W + x) + c] - px[4 * ((y + d) * W + x) + c]); ++n; }
  return sum / n;
}

function draw(id, geometry, caption) {
  const r = renderer(id);
  const scene = new THREE.Scene();
  scene.add(new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ map: bands() })));
  // The whole knot.
  const camera = new THREE.PerspectiveCamera(40, 1, 0.1, 100);
  camera.position.set(0, 0, 10);
  r.render(scene, camera);
  const whole = r.domElement.toDataURL('image/png');
  // The close-up on the closing ring: its centre, the normal of its first
  // vertex (from outside), the tangent up the image.
  const P = geometry.parameters.path.getPointAt(0), T = geometry.parameters.path.getTangentAt(0);
  const first = new THREE.Vector3().fromBufferAttribute(geometry.getAttribute('position'), 0);
  const N = first.clone().sub(P).normalize();
  const close = new THREE.PerspectiveCamera(30, 1, 0.01, 10);
  close.position.copy(P).addScaledVector(N, 6 * R);
  close.up.copy(T);
  close.lookAt(P);
  r.render(scene, close);
  const px = pixels(r);
  // Across the ring (the image's middle row) against rows elsewhere.
  const seam = rowDifference(px, H / 2, 3);
  const elsewhere = Math.max(rowDifference(px, H / 2 - 60, 3), rowDifference(px, H / 2 + 60, 3));
  // Draw the whole knot again for the page (and the figure).
  r.render(scene, camera);
  document.getElementById(`${id}-caption`).textContent = caption;
  return { seam, elsewhere, whole: whole.length };
}

try {
  await init();
  const path = new CRSplineCurve3(trefoil, true, 'centripetal');
  const which = new URLSearchParams(location.search).get('left') ?? 'three';
  // The same arguments on both sides: (path, 200, 0.3, 32), closed left to
  // its default (false) unless asked, as most code calls TubeGeometry.
  const closed = which === 'three-closed';
  const left = {
    three: [new THREE.TubeGeometry(path, 200, R, 32), 'three.js TubeGeometry(path, 200, 0.3, 32) on the closed path: its frame does not close, the bands break (the seam)'],
    'three-closed': [new THREE.TubeGeometry(path, 200, R, 32, true), 'three.js TubeGeometry(path, 200, 0.3, 32, true)'],
    raw: [new CRSplineTubeGeometry(path, 200, R, 32, true, { spreadHolonomy: false }), 'rotation-minimizing frame without the twist spread: the seam'],
  }[which];
  const right = [new CRSplineTubeGeometry(path, 200, R, 32, closed), `CRSplineTubeGeometry(path, 200, 0.3, 32${closed ? ', true' : ''}): the twist spread, no seam`];
  const a = draw('a', ...left), b = draw('b', ...right);
  window.result = { left: a, right: b, which, holonomy: right[0].report.holonomy };
} catch (e) {
  window.result = { error: String(e && e.stack || e) };
}
