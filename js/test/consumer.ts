// A typed consumer of the package: `tsc --noEmit` checks the declarations
// against the way the docs use them (test/types.test.mjs runs it). Lines
// marked @ts-expect-error must fail to type-check: the declarations are not
// just `any`.
import crspline, { init, catmullRom, CatmullRom, type CurveOptions, type CrsplineError, type Nearest, decide, decidePair, decideSet,
  clearance, quaternionSpline, rotationSpline, poseCurve, type Decision, type Verdict, type RotationCurve } from 'crspline';
import { crsplineCurve, crsplineCurveClosed, crsplineCurveOpen } from 'crspline/d3';
import { CRSplineCurve3, CRSplineQuaternionCurve, CRSplinePoseCurve } from 'crspline/three';
import { line, area, type CurveFactory } from 'd3-shape';
import { TubeGeometry, Vector3, Quaternion, PerspectiveCamera, type Curve } from 'three';

async function main(): Promise<number> {
  const api = await init();
  const opts: CurveOptions = { alpha: 0.5, closed: false, tension: 0, start: 'reflect', end: { tangent: [1, 0] } };
  const curve: CatmullRom = api.catmullRom([[0, 0], [1, 2], [3, 1]], opts);
  const p: Float64Array = curve.evaluate(0.5, 1);
  const many: Float64Array = curve.evaluateMany(new Float64Array([0, 0.5]), 0, new Float64Array(4));
  const L: number = curve.arcLength();
  const t: number = curve.tAtArcLength(L / 2);
  const poly = curve.tessellate(1e-3);
  const n: Nearest = curve.nearest([1, 1]);
  const ok: boolean = curve.certify({ safeAngle: 1 }).certified;
  curve.analyze();
  curve.bezier(0);
  curve.dispose();
  // @ts-expect-error: order 4 is not a derivative order crspline computes
  catmullRom([[0], [1]]).evaluate(0, 4);
  // @ts-expect-error: alpha is a number
  catmullRom([[0], [1]], { alpha: 'centripetal' });
  try {
    catmullRom([[0, 0]]);
  } catch (e) {
    const err = e as CrsplineError;
    console.log(err.field, err.index, err.value);
  }
  const factory: CurveFactory = crsplineCurve.alpha(0.5).ends('d3');
  const d: string | null = line().curve(factory)([[0, 0], [1, 1], [2, 0]]);
  area().curve(crsplineCurveOpen.alpha(1))([[0, 0], [1, 1], [2, 0], [3, 1]]);
  line().curve(crsplineCurveClosed);
  // @ts-expect-error: ends are 'natural', 'd3' or 'reflect'
  crsplineCurve.ends('clamped');
  const c3 = new CRSplineCurve3([new Vector3(0, 0, 0), new Vector3(1, 1, 0), new Vector3(2, 0, 1)], false, 'chordal');
  const asCurve: Curve<Vector3> = c3;
  const tube = new TubeGeometry(c3, 32, 0.1, 8, false);
  const at: Vector3 = c3.getPointAt(0.5);
  // @ts-expect-error: curveType is one of three.js' three
  new CRSplineCurve3([], false, 'bspline');
  c3.dispose();
  // Issue 27: the decision; issue 28: rotations, three.js order handled by the adapter.
  const v: Verdict = decide(catmullRom([[0, 0], [1, 1], [2, 0]])).verdict;
  const pair: Decision = decidePair(curve, curve, { fastPath: false });
  const gap: number = clearance(curve, curve).distance + decideSet([curve], { self: true }).crossings.length;
  const rs: RotationCurve = rotationSpline([0, 1], [[1, 0, 0, 0], [0, 1, 0, 0]], { start: 'natural' });
  const qs = quaternionSpline([[1, 0, 0, 0], [0, 1, 0, 0]], { kind: 'squad', alpha: 0.5 });
  const w: Float64Array | null = rs.evaluate(0.5, 1, 'body').omega;
  // @ts-expect-error: frames are 'world' or 'body'
  qs.evaluate(0.5, 1, 'space');
  const pc = poseCurve([[0, 0, 0], [1, 0, 0]], [[1, 0, 0, 0], [0, 0, 0, 1]]);
  const qc = new CRSplineQuaternionCurve([new Quaternion(), new Quaternion(0, 0, 1, 0)]);
  const camPath = new CRSplinePoseCurve([new Vector3(), new Vector3(1, 0, 0)], [new Quaternion(), [0, 0, 0, 1]]);
  const cam: PerspectiveCamera = camPath.applyTo(new PerspectiveCamera(), 0.5);
  const qq: Quaternion = qc.getQuaternion(0.5);
  return v.length + pair.crossings.length + gap + (w?.[0] ?? 0) + pc.evaluate(0).position[0] + qq.w + cam.position.x +
    p[0] + many[0] + t + poly.points.length + n.distance + Number(ok) + (d?.length ?? 0) +
    tube.attributes.position.count + at.x + (asCurve.arcLengthDivisions) + crspline.version().length;
}
void main;

// fit, sweep, stroke (issues 40, 41) and CRSplineTubeGeometry.
import { fit, sweep, stroke, type FitResult, type SweepMesh, type Stroke } from 'crspline';
import { CRSplineTubeGeometry } from 'crspline/three';
import { BufferGeometry } from 'three';

async function shapes(): Promise<number> {
  await init();
  const r: FitResult = fit([[0, 0], [1, 1], [2, 0]], { tolerance: 0.1, mode: 'free', closed: false });
  // @ts-expect-error: the fit's tolerance is required
  fit([[0, 0], [1, 1]], { mode: 'subset' });
  // @ts-expect-error: modes are 'subset' or 'free'
  fit([[0, 0], [1, 1]], { tolerance: 1, mode: 'exact' });
  const c3 = catmullRom([[0, 0, 0], [1, 0, 0], [1, 1, 1]]);
  const m: SweepMesh = sweep(c3, { radius: 0.1, tubularSegments: 20, radialSegments: 8, up: { x: 0, y: 0, z: 1 } });
  const pos: Float32Array = m.positions, idx: Uint32Array = m.indices;
  const s: Stroke = stroke(r.curve, 2, { join: 'miter', cap: 'round', miterLimit: 4 });
  // @ts-expect-error: joins are 'round', 'miter' or 'bevel'
  stroke(r.curve, 2, { join: 'sharp' });
  const tube: BufferGeometry = new CRSplineTubeGeometry(new CRSplineCurve3([new Vector3(), new Vector3(1, 0, 0)]), 20, 0.1, 8, false,
    { scale: [1, 2], scaleS: [0, 1] });
  const g = new CRSplineTubeGeometry();
  // @ts-expect-error: options three.js' TubeGeometry lacks, and no others
  new CRSplineTubeGeometry(undefined, 20, 0.1, 8, false, { taper: 1 });
  return r.deviation + (r.indices?.length ?? 0) + pos.length + idx.length + s.polygons.length + m.report.holonomy +
    tube.attributes.position.count + g.report.length + g.normals.length + CRSplineTubeGeometry.fromJSON(g.toJSON()).parameters.radius;
}
void shapes;
