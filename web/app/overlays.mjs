// The whole-curve overlays, which cost more than a frame on long curves:
// the decision (simple, crosses or touches, proved), the Section-5
// certificate (with the exact self-intersection search when it fails), the paper's bounding volumes and arc-length ticks. The editor
// runs this in a worker (worker.mjs), or on the main thread without one.

/// req: { version, points (flat Float64Array, `dimension` numbers per point;
///        2 when absent), pair (the two coordinates drawn; [0, 1]), options
///        (Spline options), volumes: 'tightened' | 'local' | null (plane
///        curves), ticks: spacing | null, maxTicks }
/// Returns plain data (structured-clone friendly) tagged with req.version;
/// points in it are the drawn pair's (x, y). The certificate, the search
/// and the ticks' arc length are those of the whole `dimension`-D curve.
export function computeGlobal(M, req) {
  const t0 = performance.now();
  const out = { version: req.version, error: null };
  let spline = null;
  try {
    const d = req.dimension ?? 2, [a, b] = req.pair ?? [0, 1];
    spline = new M.Spline(req.points, d, req.options);
    const cert = spline.certify({ searchOnFailure: true });
    out.cert = {
      certified: cert.certified,
      failed_rule: cert.failed_rule,
      detail: cert.detail,
      vertex: cert.vertex,
      segment: cert.segment,
      segments: cert.segments,
      angle: cert.angle,
      intersects: cert.intersects,
      complete: cert.search ? cert.search.complete : true,
    };
    // The decision (issue 27): a proved verdict for every alpha, grid,
    // tension and end, where the certificate only speaks for centripetal
    // curves. Plane curves only (crossings are not generic in 3-D).
    if (d === 2) {
      const dec = spline.decide({ recordPairs: false });
      out.decision = {
        verdict: dec.verdict,
        fast_path: dec.fast_path,
        crossings: dec.crossings.length,
        touches: dec.touches.length,
        closest: dec.touches.reduce((m, t) => Math.min(m, t.distance), Infinity),
        floor: dec.floor,
      };
    } else {
      out.decision = null;
    }
    // Crossing points, flat x, y: none when certified (the certificate is
    // the proof), else what the exact search found.
    const found = cert.search ? cert.search.intersections : [];
    out.intersections = Float64Array.from(found.flatMap((x) => [x.point[a], x.point[b]]));
    out.intersectionSegments = found.map((x) => x.segments);
    out.folds = cert.search ? cert.search.folds : [];
    if (req.volumes) out.volumes = spline.boundingVolumes(req.volumes);
    if (req.ticks) {
      const t = spline.arcLengthTicks(req.ticks, req.maxTicks ?? 20000);
      if (d === 2) {
        out.ticks = t;
      } else {
        // Positions, then unit tangents, of the drawn pair (the tangent of
        // the projection, normalized; 0 where it vanishes).
        const n = t.length / (2 * d), p = new Float64Array(4 * n);
        for (let k = 0; k < n; ++k) {
          p[2 * k] = t[k * d + a]; p[2 * k + 1] = t[k * d + b];
          const tx = t[(n + k) * d + a], ty = t[(n + k) * d + b], l = Math.hypot(tx, ty);
          p[2 * (n + k)] = l > 0 ? tx / l : 0; p[2 * (n + k) + 1] = l > 0 ? ty / l : 0;
        }
        out.ticks = p;
      }
    }
  } catch (e) {
    out.error = e.message;
  } finally {
    if (spline) spline.delete();
  }
  out.ms = performance.now() - t0;
  return out;
}
