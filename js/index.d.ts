// Type declarations for crspline (index.js).

/** Where the WebAssembly module comes from (default: dist/crspline.wasm next to the module). */
export interface InitOptions {
  /** The .wasm bytes, when the application loads them itself. */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** The .wasm URL (resolved against this module's URL). */
  wasmURL?: string | URL;
}

/** Loads the WebAssembly module once; every later call returns the same promise. */
export function init(options?: InitOptions): Promise<Crspline>;
/** true once init() has resolved. */
export function isReady(): boolean;
/** The C++ library's version. */
export function version(): string;
/** The size of the WebAssembly memory in bytes (it grows, never shrinks). */
export function wasmMemoryBytes(): number;

/** One end of an open curve: natural (zero second derivative), reflect (three.js' phantom point), or a given dx/dt. */
export type EndCondition = 'natural' | 'reflect' | { tangent: ArrayLike<number> } | ArrayLike<number>;

/** Per-point Kochanek-Bartels values (null: 0 at the two ends of an open curve). */
export interface KochanekBartels {
  tension?: ArrayLike<number | null>;
  continuity?: ArrayLike<number | null>;
  bias?: ArrayLike<number | null>;
}

export interface CurveOptions {
  /** Knot exponent in [0, 1]: 0 uniform, 0.5 centripetal (default), 1 chordal. Not with grid. */
  alpha?: number;
  /** Explicit knots: one per point (one more when closed), strictly increasing. */
  grid?: ArrayLike<number>;
  /** A closed loop (the first point is not repeated). */
  closed?: boolean;
  /** In [0, 1]: computed tangents scaled by 1 - tension. */
  tension?: number;
  start?: EndCondition;
  end?: EndCondition;
  /** Reject coincident consecutive points. */
  strict?: boolean;
  kb?: KochanekBartels;
  /** Given tangents dx/dt per point (a cubic Hermite curve through the points). */
  tangents?: ArrayLike<number> | ArrayLike<ArrayLike<number>>;
  /** Incoming tangents where they differ from the outgoing ones. */
  tangentsIn?: ArrayLike<number> | ArrayLike<ArrayLike<number>>;
  /** The dimension of flat coordinates (points given as x0, y0, x1, y1, ...). */
  dimension?: number;
}

/** A point: an array of 1 to 16 coordinates, or an object with x, y and optionally z. */
export type PointLike = ArrayLike<number> | { x: number; y: number; z?: number };

/**
 * An invalid description or argument. For a bad curve description the core's
 * words, and where it is: field ("points", "alpha", "grid", "closed",
 * "start", "end", "tension", "kb.tension", "kb.continuity", "kb.bias",
 * "strict", "dimension", or an option name), index (point, knot or vertex),
 * component (coordinate) and value (as text). Other errors (a t outside the
 * domain) are plain Errors without field.
 */
export interface CrsplineError extends Error {
  field?: string;
  index?: number | null;
  component?: number | null;
  value?: string;
}

export interface Polyline {
  /** Flat points: point k is [k * dimension, (k + 1) * dimension). */
  points: Float64Array;
  t: Float64Array;
}

export interface ArcLengthSamples extends Polyline {
  s: Float64Array;
}

export interface Nearest {
  t: number;
  distance: number;
  distanceSq: number;
  segment: number;
  point: Float64Array;
}

export interface BoundingBox {
  lo: Float64Array;
  hi: Float64Array;
}

export interface CertifyOptions {
  safeAngle?: number;
  searchOnFailure?: boolean;
  tolerance?: number;
}

/** The intersection search as the core reports it. */
export interface Intersections {
  intersections: { segments: [number, number]; u: Float64Array; point: Float64Array; distance: number }[];
  folds: number[];
  complete: boolean;
  any: boolean;
}

/**
 * The analysis report, passed through from the WebAssembly module as the core
 * writes it (one schema across the CLI, Python and JavaScript; see
 * docs/report.md): its fields are not restated here.
 */
export type AnalysisReport = any;
/** The intersection-free certificate, passed through as the core writes it. */
export type Certificate = { certified: boolean; [key: string]: any };

/** A Catmull-Rom curve. t is the curve's own parameter (tMin..tMax, the knots); s is arc length. */
export class CatmullRom {
  private constructor();
  readonly dimension: number;
  readonly pointCount: number;
  readonly segmentCount: number;
  readonly closed: boolean;
  readonly tMin: number;
  readonly tMax: number;
  /** The knots. */
  readonly grid: Float64Array;
  /** The points, flat. */
  readonly points: Float64Array;
  /** true after dispose(). */
  readonly disposed: boolean;

  /** Position (order 0) or the order-th derivative with respect to t (order 1..3). */
  evaluate(t: number, order?: 0 | 1 | 2 | 3): Float64Array;
  /** Many parameters: point k is [k * dimension, (k + 1) * dimension); written into out when given. */
  evaluateMany(t: ArrayLike<number>, order?: 0 | 1 | 2 | 3, out?: Float64Array): Float64Array;
  /** The segment holding t. */
  locate(t: number): number;
  /** Curvature at t, null where the speed is zero. */
  curvature(t: number): number | null;
  /** B0..B3 of segment i (4 * dimension numbers), or of every segment in turn. */
  bezier(i?: number): Float64Array;

  /** Total arc length (cached table), or to the given accuracy. */
  arcLength(accuracy?: number): number;
  arcLengthBetween(t0: number, t1: number): number;
  /** Arc length from the start to t. */
  sAt(t: number): number;
  /** The t at arc length s from the start. */
  tAtArcLength(s: number): number;
  /** Arc length at every knot. */
  knotLengths(): Float64Array;
  /** n points evenly spaced in arc length. */
  sampleArcLength(n: number, accuracy?: number): ArcLengthSamples;
  /** n points evenly spaced in t, flat. */
  sampleT(n: number): Float64Array;
  /** A polyline within tolerance (a distance) of the curve; 0 or none: the default. */
  tessellate(tolerance?: number): Polyline;
  boundingBox(): BoundingBox;
  /** The point of the curve nearest to p. */
  nearest(p: ArrayLike<number>): Nearest;

  /** The paper's analysis of every segment. */
  analyze(): AnalysisReport;
  certify(options?: CertifyOptions): Certificate;
  intersections(tolerance?: number): Intersections;
  /** Cusps: (segment, u, t, point...) per cusp, flat. */
  cusps(): Float64Array;
  /** Does the curve cross itself? A proved verdict (plane curves only; an Error otherwise). */
  decide(options?: DecisionOptions): Decision;
  /** The least distance between non-adjacent segments (any dimension). */
  clearance(accuracy?: number): Clearance;

  /** Frees the WebAssembly memory now (otherwise when the curve is garbage collected). */
  dispose(): void;
}

/** A curve through the points (arrays of 1..16 coordinates, {x, y, z?} objects, or flat numbers with options.dimension). */
export function catmullRom(points: ArrayLike<PointLike> | ArrayLike<number>, options?: CurveOptions): CatmullRom;

export type Verdict = 'simple' | 'crosses' | 'touches';
export type DecisionArgument = 'paper_rule' | 'separation' | 'joint' | 'monotone' | 'crossing' | 'unresolved';

export interface DecisionOptions {
  /** Try the paper's certificate first (single curves; default true). */
  fastPath?: boolean;
  /** Visits in all before the remaining pairs are contacts (0: the core's default). */
  budget?: number;
  /** Visits for one pair of pieces. */
  pairBudget?: number;
  /** Fill `pairs` (default true). */
  recordPairs?: boolean;
}

/** The decision (docs/report.md, "The decision object"; what each verdict guarantees: docs/analysis.md). */
export interface Decision {
  verdict: Verdict;
  fast_path: boolean;
  /** delta, the contact floor: 4 eps of the largest absolute coordinate (4 to 8 of its ulps). */
  floor: number;
  /** Proved transversal crossings: u[k] is an interval of segments[k]'s local parameter on curves[k]. */
  crossings: { curves: [number, number]; segments: [number, number]; u: [[number, number], [number, number]]; point: [number, number] }[];
  touches: { curves: [number, number]; segments: [number, number]; u: [number, number]; distance: number; budget_exhausted: boolean }[];
  pairs: { curves: [number, number]; segments: [number, number]; arguments: DecisionArgument[] }[];
}

/** The least distance and where: the true one lies in [lowerBound, distance]. */
export interface Clearance {
  distance: number;
  lowerBound: number;
  curves: [number, number];
  segments: [number, number];
  u: [number, number];
  points: [Float64Array, Float64Array];
  exhausted: boolean;
}

/** The decision of one curve (curve.decide()). */
export function decide(curve: CatmullRom, options?: DecisionOptions): Decision;
/** Do two plane curves cross each other? Crossings name curve 0 (a) and 1 (b). */
export function decidePair(a: CatmullRom, b: CatmullRom, options?: DecisionOptions): Decision;
/** Do any two curves of the set cross? self: each curve's own crossings too. */
export function decideSet(curves: CatmullRom[], options?: DecisionOptions & { self?: boolean }): Decision;
/** Between non-adjacent segments of one curve, or between two curves of one dimension. */
export function clearance(curve: CatmullRom, accuracy?: number): Clearance;
export function clearance(a: CatmullRom, b: CatmullRom, accuracy?: number): Clearance;

// --- fit (issue 40), sweeps and strokes (issue 41) -------------------------

export interface FitOptions {
  /** Distance allowed both ways, in the points' units (> 0, above the coordinates' rounding floor). */
  tolerance: number;
  /** 'subset' (default): the control points are input points; 'free': they may also sit at the middles of the input segments (noisy data). */
  mode?: 'subset' | 'free';
  /** Knot exponent in [0, 1] (default 0.5, centripetal). */
  alpha?: number;
  /** The points are a ring (the first point not repeated). */
  closed?: boolean;
  /** The curve's own tension in [0, 1]; the fit raises it per vertex where needed. */
  tension?: number;
  start?: 'natural' | 'reflect';
  end?: 'natural' | 'reflect';
  /** The dimension of flat coordinates. */
  dimension?: number;
}

export interface FitResult {
  /** The fitted curve (Kochanek-Bartels tension per vertex where the fit raised it). */
  curve: CatmullRom;
  /** The proved bound (<= tolerance) on the distance both ways. */
  deviation: number;
  curveToInput: number;
  inputToCurve: number;
  /** Subset mode: the input index of each control point; null in free mode. */
  indices: Float64Array | null;
  /** Number of control points. */
  count: number;
  /** Vertices whose tension the fit raised. */
  tensioned: number;
  /** The input's rounding floor (tolerances at or below it are refused). */
  roundingFloor: number;
}

export function fit(points: ArrayLike<PointLike> | ArrayLike<number>, options: FitOptions): FitResult;

/** A cross-section: a polyline ([[x, y], ...]) or {points, closed, curve: true for a Catmull-Rom profile, alpha}. */
export type SweepProfile = ArrayLike<ArrayLike<number>> | {
  points: ArrayLike<ArrayLike<number>> | ArrayLike<number>;
  closed?: boolean;
  curve?: boolean;
  alpha?: number;
};

export interface SweepOptions {
  /** A circle of this radius (default 1) when no profile is given. */
  radius?: number;
  profile?: SweepProfile;
  /** Roll angles (radians) about the tangent: one per knot, or at rollS arc lengths. */
  roll?: ArrayLike<number>;
  rollAt?: 'knots' | 'arcLength';
  rollS?: ArrayLike<number>;
  /** Scale of the profile at the arc lengths scaleS (interpolated smoothly). */
  scale?: ArrayLike<number>;
  scaleS?: ArrayLike<number>;
  /** The normal follows this vector's projection (frames never flip through vertical). */
  up?: ArrayLike<number> | { x: number; y: number; z: number };
  /** Distance of the mesh to the true surface (0: the default); not with given counts. */
  tolerance?: number;
  tubularSegments?: number;
  radialSegments?: number;
  /** false: a closed curve's frame is not closed up (the seam, for comparison). Default true. */
  spreadHolonomy?: boolean;
  /** Measure the centre line's clearance for the report (default true). */
  clearance?: boolean;
}

export interface SweepReport {
  tolerance: number;
  bound: number;
  toleranceMet: boolean;
  proved: boolean;
  holonomy: number;
  /** A bound on the ring frames' angle from the exact rotation-minimizing frame (radians; 0 with `up`); `bound` includes it. */
  frameDrift: number;
  length: number;
  largestRadius: number;
  clearance: number;
  minRadiusOfCurvature: number;
  farContact: boolean;
  localFold: boolean;
  selfIntersects: boolean;
  seamGap: number;
  seamNormalGap: number;
}

export interface SweepMesh {
  /** 3 per vertex; vertex ring * ringSize + j. */
  positions: Float32Array;
  normals: Float32Array;
  /** 2 per vertex: u around the profile, v = s / length along the curve. */
  uvs: Float32Array;
  /** 3 per triangle. */
  indices: Uint32Array;
  rings: number;
  ringSize: number;
  /** The curve parameter and arc length of each ring. */
  t: Float64Array;
  s: Float64Array;
  report: SweepReport;
}

export function sweep(curve: CatmullRom, options?: SweepOptions): SweepMesh;

export interface StrokeOptions {
  join?: 'round' | 'miter' | 'bevel';
  cap?: 'butt' | 'round' | 'square';
  miterLimit?: number;
  tolerance?: number;
}

export interface Stroke {
  /** Each polygon: its exterior ring, then its holes; a ring is flat [x0, y0, x1, y1, ...]. */
  polygons: Float64Array[][];
  tolerance: number;
  tessellationVertices: number;
}

export function stroke(curve: CatmullRom, width: number, options?: StrokeOptions): Stroke;


/** A unit quaternion [w, x, y, z]. */
// --- rotations (quaternions [w, x, y, z], crspline's order) ---------------

export type QuaternionWXYZ = ArrayLike<number>;
export type RotationFrame = 'world' | 'body';
export type RotationKind = 'catmull_rom' | 'kochanek_bartels' | 'piecewise_slerp' | 'barry_goldman' | 'squad';
/** An angular velocity at an end, rad per unit t. */
export interface AngularVelocityEnd { omega: ArrayLike<number>; frame?: RotationFrame }

export interface QuaternionSplineOptions {
  kind?: RotationKind;
  /** On the rotation angle, in [0, 1]; none and no grid: 0, 1, 2, ... */
  alpha?: number;
  grid?: ArrayLike<number>;
  closed?: boolean;
  start?: 'natural' | 'natural_splines' | AngularVelocityEnd;
  end?: 'natural' | 'natural_splines' | AngularVelocityEnd;
  kb?: { tension?: number | number[]; continuity?: number | number[]; bias?: number | number[] };
  /** Keep the given signs (the long way where a key's dot with the previous is negative). */
  keepSigns?: boolean;
  /** Refuse repeated keys with alpha > 0. */
  strict?: boolean;
  /** Keys are normalized, as SciPy's from_quat does; zero or non-finite keys are refused.
   * A finite tolerance also refuses keys farther than it from unit norm (default: none). */
  unitTolerance?: number;
}

export interface RotationSplineOptions {
  closed?: boolean;
  start?: 'scipy' | 'natural' | AngularVelocityEnd;
  end?: 'scipy' | 'natural' | AngularVelocityEnd;
  keepSigns?: boolean;
  /** As QuaternionSplineOptions.unitTolerance. */
  unitTolerance?: number;
}

export interface RotationJet {
  q: Float64Array;
  omega: Float64Array | null;
  alpha: Float64Array | null;
}

export class RotationCurve {
  private constructor();
  readonly kind: RotationKind | 'c2';
  readonly closed: boolean;
  readonly segmentCount: number;
  readonly grid: Float64Array;
  readonly tMin: number;
  readonly tMax: number;
  /** The keys after the sign rule, flat [w, x, y, z]. */
  readonly keys: Float64Array;
  /** The C2 spline's Newton residual and iterations; null for the Catmull-Rom family. */
  readonly residual: number | null;
  readonly iterations: number | null;
  readonly disposed: boolean;
  evaluate(t: number, order?: 0 | 1 | 2, frame?: RotationFrame): RotationJet;
  /** The rotation at t, [w, x, y, z]. */
  quaternion(t: number): Float64Array;
  evaluateMany(t: ArrayLike<number>, order?: 0 | 1 | 2, frame?: RotationFrame): RotationJet;
  /** The total angle turned through (radians). */
  angleLength(accuracy?: number): number;
  constantAngularSpeedTimes(n: number, accuracy?: number): Float64Array;
  dispose(): void;
}

export interface PoseSample {
  position: Float64Array;
  /** [w, x, y, z] */
  orientation: Float64Array;
  velocity: Float64Array;
  omega: Float64Array;
}

export interface PoseCurveOptions {
  alpha?: number;
  grid?: ArrayLike<number>;
  closed?: boolean;
  /** C2 rotation spline (default) or quaternion Catmull-Rom. */
  c2Rotation?: boolean;
}

export class PoseCurve {
  private constructor();
  readonly grid: Float64Array;
  readonly tMin: number;
  readonly tMax: number;
  readonly disposed: boolean;
  evaluate(t: number, frame?: RotationFrame): PoseSample;
  evaluateMany(t: ArrayLike<number>): { positions: Float64Array; orientations: Float64Array };
  constantSpeedTimes(n: number, positionWeight?: number, angleWeight?: number, accuracy?: number): Float64Array;
  dispose(): void;
}

/** The quaternion Catmull-Rom family through keys ([w, x, y, z] each, or flat). */
export function quaternionSpline(keys: ArrayLike<QuaternionWXYZ> | ArrayLike<number>, options?: QuaternionSplineOptions): RotationCurve;
/** The C2 rotation spline (SciPy's RotationSpline, converged). */
export function rotationSpline(times: ArrayLike<number>, keys: ArrayLike<QuaternionWXYZ> | ArrayLike<number>, options?: RotationSplineOptions): RotationCurve;
export function poseCurve(positions: ArrayLike<ArrayLike<number> | { x: number; y: number; z: number }> | ArrayLike<number>,
  rotations: ArrayLike<QuaternionWXYZ> | ArrayLike<number>, options?: PoseCurveOptions): PoseCurve;
/** [w, x, y, z] -> [x, y, z, w] (three.js, SciPy, glTF). */
export function toXYZW(q: ArrayLike<number>, out?: Float64Array): Float64Array;
/** [x, y, z, w] -> [w, x, y, z]. */
export function fromXYZW(q: ArrayLike<number>, out?: Float64Array): Float64Array;

export interface Crspline {
  init: typeof init;
  isReady: typeof isReady;
  version: typeof version;
  wasmMemoryBytes: typeof wasmMemoryBytes;
  catmullRom: typeof catmullRom;
  CatmullRom: typeof CatmullRom;
  decide: typeof decide;
  decidePair: typeof decidePair;
  decideSet: typeof decideSet;
  clearance: typeof clearance;
  fit: typeof fit;
  sweep: typeof sweep;
  stroke: typeof stroke;
  quaternionSpline: typeof quaternionSpline;
  rotationSpline: typeof rotationSpline;
  poseCurve: typeof poseCurve;
  RotationCurve: typeof RotationCurve;
  PoseCurve: typeof PoseCurve;
  toXYZW: typeof toXYZW;
  fromXYZW: typeof fromXYZW;
}
declare const crspline: Crspline;
export default crspline;
