// The whole-curve overlays, which cost more than a frame on long curves:
// the Section-5 certificate (with the exact self-intersection search when
// it fails), the paper's bounding volumes and arc-length ticks. The editor
// runs this in a worker (worker.mjs), or on the main thread without one.

/// req: { version, points (flat Float64Array), options (Spline options),
///        volumes: 'tightened' | 'local' | null, ticks: spacing | null,
///        maxTicks }
/// Returns plain data (structured-clone friendly) tagged with req.version.
export function computeGlobal(M, req) {
  const t0 = performance.now();
  const out = { version: req.version, error: null };
  let spline = null;
  try {
    spline = new M.Spline(req.points, 2, req.options);
    const cert = spline.certify({ searchOnFailure: true });
    out.cert = {
      certified: cert.certified,
      failedRule: cert.failedRule,
      detail: cert.detail,
      vertex: cert.vertex,
      segment: cert.segment,
      segments: cert.segments,
      angle: cert.angle,
      intersects: cert.intersects,
      complete: cert.search ? cert.search.complete : true,
    };
    // Crossing points, flat x, y: none when certified (the certificate is
    // the proof), else what the exact search found.
    const found = cert.search ? cert.search.intersections : [];
    out.intersections = Float64Array.from(found.flatMap((x) => [x.point[0], x.point[1]]));
    out.intersectionSegments = found.map((x) => x.segments);
    out.folds = cert.search ? cert.search.folds : [];
    if (req.volumes) out.volumes = spline.boundingVolumes(req.volumes);
    if (req.ticks) out.ticks = spline.arcLengthTicks(req.ticks, req.maxTicks ?? 20000);
  } catch (e) {
    out.error = e.message;
  } finally {
    if (spline) spline.delete();
  }
  out.ms = performance.now() - t0;
  return out;
}
