// Type declarations for crspline/d3 (d3.js). Structural: assignable to
// d3-shape's CurveFactory without importing d3's types.

/** The path context d3 passes to a curve (d3-path's Path or a canvas 2D context). */
export interface PathContext {
  moveTo(x: number, y: number): void;
  lineTo(x: number, y: number): void;
  bezierCurveTo(cpx1: number, cpy1: number, cpx2: number, cpy2: number, x: number, y: number): void;
  closePath(): void;
}

/** d3's curve protocol. */
export interface CurveGenerator {
  areaStart(): void;
  areaEnd(): void;
  lineStart(): void;
  lineEnd(): void;
  point(x: number, y: number): void;
}

/** The two ends of an open curve: crspline's natural (default), d3's zero-length handles, or three.js' reflection. */
export type Ends = 'natural' | 'd3' | 'reflect';

export interface CRSplineCurveFactory {
  (context: PathContext): CurveGenerator;
  /** Knot exponent in [0, 1]: 0 uniform, 0.5 centripetal (default), 1 chordal. */
  alpha(alpha: number): CRSplineCurveFactory;
  ends(ends: Ends): CRSplineCurveFactory;
}

/** An open curve through every point. */
export const crsplineCurve: CRSplineCurveFactory;
/** A closed loop through every point (starts at the first, ends with Z). */
export const crsplineCurveClosed: CRSplineCurveFactory;
/** d3's open variant: the first and last points only steer; drawn from the second to the next-to-last. */
export const crsplineCurveOpen: CRSplineCurveFactory;
