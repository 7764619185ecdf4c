// Type declarations for crspline/three (three.js).
import { Curve, Vector3 } from 'three';

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
