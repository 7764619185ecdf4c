// Type declarations for crspline/three (three.js).
import { BufferGeometry, Curve, Object3D, Quaternion, Vector3 } from 'three';
import type { SweepReport, PoseCurve, PoseCurveOptions, QuaternionSplineOptions, RotationCurve, RotationFrame, RotationSplineOptions } from './index.js';

export type CurveType = 'centripetal' | 'chordal' | 'catmullrom';

/**
 * A drop-in for THREE.CatmullRomCurve3 (same constructor arguments), computed
 * by crspline: exact getPoint and getTangent, getPointAt through crspline's
 * arc length. A new points array is picked up; after moving points in place
 * call updateArcLengths(). dispose() frees the WebAssembly memory now.
 */
export class CRSplineCurve3 extends Curve<Vector3> {
  constructor(points?: Vector3[], closed?: boolean, curveType?: CurveType, tension?: number);
  readonly isCRSplineCurve3: true;
  /** True, as on THREE.CatmullRomCurve3: code that branches on it takes the adapter for that curve. */
  readonly isCatmullRomCurve3: true;
  points: Vector3[];
  closed: boolean;
  curveType: CurveType;
  /** Used by curveType 'catmullrom' only, in [0, 0.5] (0.5: the standard curve). */
  tension: number;
  getPoint(t: number, optionalTarget?: Vector3): Vector3;
  getTangent(t: number, optionalTarget?: Vector3): Vector3;
  getLength(): number;
  /** three.js' contract: cumulative chord lengths of the divisions-division polyline of getPoint (cached in cacheArcLengths). */
  getLengths(divisions?: number): number[];
  updateArcLengths(): void;
  getUtoTmapping(u: number, distance?: number | null): number;
  copy(source: CRSplineCurve3): this;
  fromJSON(json: object): this;
  dispose(): void;
}

/** A THREE.Quaternion or its toArray(): [x, y, z, w]. */
export type QuaternionLike = Quaternion | [number, number, number, number];

/**
 * A rotation curve through THREE.Quaternion keys, u in [0, 1] (the curve's t
 * mapped linearly). The [x, y, z, w] <-> [w, x, y, z] conversion is done here.
 * With options.times: the C2 spline; otherwise the quaternion Catmull-Rom family.
 */
export class CRSplineQuaternionCurve {
  constructor(quaternions: QuaternionLike[], options?: QuaternionSplineOptions | (RotationSplineOptions & { times: ArrayLike<number> }));
  readonly isCRSplineQuaternionCurve: true;
  readonly curve: RotationCurve;
  tAt(u: number): number;
  getQuaternion(u: number, optionalTarget?: Quaternion): Quaternion;
  /** rad per unit u. */
  getAngularVelocity(u: number, optionalTarget?: Vector3, frame?: RotationFrame): Vector3;
  dispose(): void;
}

/** A camera path: a Curve of the positions, with orientations (a C2 rotation spline) on the same grid. */
export class CRSplinePoseCurve extends Curve<Vector3> {
  constructor(positions: (Vector3 | [number, number, number])[], quaternions: QuaternionLike[], options?: PoseCurveOptions);
  readonly isCRSplinePoseCurve: true;
  readonly pose: PoseCurve;
  tAt(u: number): number;
  getPoint(u: number, optionalTarget?: Vector3): Vector3;
  getQuaternion(u: number, optionalTarget?: Quaternion): Quaternion;
  /** Sets object.position and object.quaternion to the pose at u (a camera looks along its -z). */
  applyTo<T extends Object3D>(object: T, u: number): T;
  constantSpeedU(n: number, positionWeight?: number, angleWeight?: number): number[];
  dispose(): void;
}

/** What CRSplineTubeGeometry takes beyond TubeGeometry's arguments (crspline's sweep options). */
export interface CRSplineTubeOptions {
  /** The radius's scale at the arc lengths scaleS (interpolated smoothly): a varying radius. */
  scale?: ArrayLike<number>;
  scaleS?: ArrayLike<number>;
  /** Roll angles (radians) about the tangent, per knot of a CRSplineCurve3 path or at rollS arc lengths. */
  roll?: ArrayLike<number>;
  rollAt?: 'knots' | 'arcLength';
  rollS?: ArrayLike<number>;
  /** The normal follows this vector's projection. */
  up?: ArrayLike<number> | { x: number; y: number; z: number };
  /** false: a closed path's frame twist is not spread (three.js' seam, for comparison). */
  spreadHolonomy?: boolean;
}

/**
 * A drop-in for THREE.TubeGeometry(path, tubularSegments, radius, radialSegments, closed): the same
 * attributes (position, normal, uv, index) and layout, computed by crspline's sweep: rotation-minimizing
 * frames, no seam on a closed path, no flips; optional varying radius, roll and up vector.
 */
export class CRSplineTubeGeometry extends BufferGeometry {
  constructor(path?: Curve<Vector3>, tubularSegments?: number, radius?: number, radialSegments?: number, closed?: boolean,
    options?: CRSplineTubeOptions);
  readonly isCRSplineTubeGeometry: true;
  parameters: {
    path: Curve<Vector3>;
    tubularSegments: number;
    radius: number;
    radialSegments: number;
    closed: boolean;
    options: CRSplineTubeOptions;
  };
  tangents: Vector3[];
  normals: Vector3[];
  binormals: Vector3[];
  /** The sweep's report: bound, holonomy, seamGap, selfIntersects, ... */
  report: SweepReport;
  copy(source: CRSplineTubeGeometry): this;
  static fromJSON(data: any): CRSplineTubeGeometry;
}
