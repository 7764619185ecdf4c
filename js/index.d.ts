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

  /** Frees the WebAssembly memory now (otherwise when the curve is garbage collected). */
  dispose(): void;
}

/** A curve through the points (arrays of 1..16 coordinates, {x, y, z?} objects, or flat numbers with options.dimension). */
export function catmullRom(points: ArrayLike<PointLike> | ArrayLike<number>, options?: CurveOptions): CatmullRom;

export interface Crspline {
  init: typeof init;
  isReady: typeof isReady;
  version: typeof version;
  wasmMemoryBytes: typeof wasmMemoryBytes;
  catmullRom: typeof catmullRom;
  CatmullRom: typeof CatmullRom;
}
declare const crspline: Crspline;
export default crspline;
