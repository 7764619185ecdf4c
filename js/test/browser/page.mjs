// The browser page's script: see index.html. Exposes window.result for the
// test ({ chart: {...}, tube: {...} } or { error }).
import { init, catmullRom } from 'crspline';
import { crsplineCurve } from 'crspline/d3';
import { CRSplineCurve3 } from 'crspline/three';
import * as d3 from 'd3-shape';
import * as THREE from 'three';

const NS = 'http://www.w3.org/2000/svg';

function chart() {
  const svg = document.getElementById('chart');
  const data = [[0, 12], [1, 30], [2, 26], [3, 48], [3.3, 61], [5, 40], [6, 44], [7, 15], [8, 22], [9, 35]];
  const W = 480, H = 320, m = 24;
  const x = (v) => m + (v / 9) * (W - 2 * m), y = (v) => H - m - (v / 70) * (H - 2 * m);
  const pts = data.map(([a, b]) => [x(a), y(b)]);
  const add = (name, attrs) => {
    const e = document.createElementNS(NS, name);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    svg.appendChild(e);
    return e;
  };
  add('path', { d: d3.area().y0(H - m).curve(crsplineCurve.alpha(0.5))(pts), fill: '#cfe3ff', stroke: 'none' });
  add('path', { d: d3.line().curve(d3.curveCatmullRom.alpha(0.5))(pts), fill: 'none', stroke: '#e07000', 'stroke-width': 1.5, 'stroke-dasharray': '5 4' });
  const line = add('path', { d: d3.line().curve(crsplineCurve.alpha(0.5))(pts), fill: 'none', stroke: '#1f5fbf', 'stroke-width': 2.5, 'stroke-linecap': 'round' });
  for (const [a, b] of pts) add('circle', { cx: a, cy: b, r: 4, fill: '#111' });
  // The drawn path passes through every data point.
  const onStroke = pts.map(([a, b]) => line.isPointInStroke(new DOMPoint(a, b)));
  // Its length as the browser measures the path, and as crspline computes it.
  const curve = catmullRom(pts, { alpha: 0.5 });
  const lengths = { browser: line.getTotalLength(), crspline: curve.arcLength() };
  curve.dispose();
  return { onStroke, lengths, commands: line.getAttribute('d').replace(/[^MLCZ]/g, '') };
}

function tube() {
  const W = 480, H = 320;
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(W, H);
  renderer.setClearColor(0xffffff);
  document.getElementById('tube').appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(45, W / H, 0.1, 100);
  camera.position.set(0, 0, 9);
  const pts = [[-3, -1, 0], [-2, 1.2, 1], [-0.5, -0.8, -1], [0.2, 1.4, 0.5], [1.2, 1.35, 0.6], [2, -1, 0], [3.2, 0.8, -0.5]]
    .map(([a, b, c]) => new THREE.Vector3(a, b, c));
  const curve = new CRSplineCurve3(pts, false, 'centripetal');
  const geometry = new THREE.TubeGeometry(curve, 200, 0.22, 16, false);
  const mesh = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ color: 0x2f7fdf, roughness: 0.45, metalness: 0.1 }));
  scene.add(mesh);
  for (const p of pts) {
    const ball = new THREE.Mesh(new THREE.SphereGeometry(0.28, 20, 14), new THREE.MeshStandardMaterial({ color: 0x222222 }));
    ball.position.copy(p);
    scene.add(ball);
  }
  scene.add(new THREE.AmbientLight(0xffffff, 0.6));
  const light = new THREE.DirectionalLight(0xffffff, 2.2);
  light.position.set(3, 4, 6);
  scene.add(light);
  renderer.render(scene, camera);
  // Pixels under the projection of points on the curve (they are inside
  // the tube, whose radius covers several pixels) and the fraction of
  // non-white pixels.
  const gl = renderer.getContext();
  const pixels = new Uint8Array(W * H * 4);
  gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  const at = (v) => {
    const p = v.clone().project(camera);
    const px = Math.round((p.x + 1) / 2 * W), py = Math.round((p.y + 1) / 2 * H);  // readPixels: y up
    const o = 4 * (py * W + px);
    return [pixels[o], pixels[o + 1], pixels[o + 2]];
  };
  const samples = [0.1, 0.3, 0.5, 0.7, 0.9].map((u) => at(curve.getPointAt(u)));
  let ink = 0;
  for (let i = 0; i < W * H; ++i) if (pixels[4 * i] < 240 || pixels[4 * i + 1] < 240 || pixels[4 * i + 2] < 240) ++ink;
  const vertices = geometry.attributes.position.count;
  return { samples, ink: ink / (W * H), vertices, renderer: gl.getParameter(gl.VERSION) };
}

try {
  await init();
  window.result = { chart: chart(), tube: tube() };
} catch (e) {
  window.result = { error: String(e && e.stack || e) };
}
