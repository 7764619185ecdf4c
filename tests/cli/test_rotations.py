"""Rotation and pose curve files (issue 28): `crspline eval` and `sample` on a
file with "rotations". Checked: eval at the keys gives the keys; agreement
with Python's crspline.rotation (the same core through the bindings) and with
SciPy (an independent implementation) on seeded cases; every input form
(quaternions, rotation vectors, axis-angle, Euler with a convention,
matrices) gives the same curve; each bad input names its field and index;
CSV output parses.
"""
import csv
import io
import json
import math
import random

import numpy as np
import pytest

from cli_support import run, run_json

SEED = 2828


def random_keys(rng, n, step=1.2):
    """n unit quaternions [w, x, y, z], consecutive ones up to `step` rad apart."""
    keys = [[1.0, 0.0, 0.0, 0.0]]
    for _ in range(n - 1):
        axis = [rng.gauss(0, 1) for _ in range(3)]
        na = math.sqrt(sum(a * a for a in axis))
        ang = rng.uniform(0.2, step)
        d = [math.cos(ang / 2)] + [math.sin(ang / 2) * a / na for a in axis]
        keys.append(qmul(d, keys[-1]))
    return keys


def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return [aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw]


def angle(a, b):
    """The rotation angle between unit quaternions a and b, the short way (4 atan2, as the core)."""
    if sum(x * y for x, y in zip(a, b)) < 0:
        b = [-y for y in b]
    return 4 * math.atan2(math.dist(a, b), math.dist(a, [-y for y in b]))


def same_rotation(p, q):
    """Distance between two unit quaternions as rotations (q and -q are one rotation)."""
    return min(max(abs(a - b) for a, b in zip(p, q)), max(abs(a + b) for a, b in zip(p, q)))


def scipy_rotation():
    from scipy.spatial.transform import Rotation
    return Rotation


def to_xyzw(keys):
    return [[q[1], q[2], q[3], q[0]] for q in keys]


# ---------------------------------------------------------------------------------------------
def test_eval_at_the_keys_gives_the_keys(seed):
    # Every kind, open and closed, on the uniform grid and with alpha: at each
    # knot the curve is its key. 1e-14: the De Casteljau slerps at u = 0 or 1
    # are exact up to a few roundings of unit-size numbers.
    rng = random.Random(seed)
    checked = 0
    for kind in ("catmull_rom", "kochanek_bartels", "slerp", "barry_goldman", "squad", "c2"):
        for closed in (False, True):
            for alpha in (None, 0.5):
                keys = random_keys(rng, 6)
                doc = {"rotations": {"quaternions": keys}, "kind": kind, "closed": closed, "t": [0]}
                if alpha is not None:
                    doc["alpha"] = alpha
                knots = run_json("eval", dict(doc, knots=True))["grid"]
                n = len(keys) + (1 if closed else 0)
                assert len(knots) == n
                if alpha is not None:  # alpha's grid: t(i+1) - t(i) = angle^alpha, 1e-12 for the rounding of both
                    ring = keys + ([keys[0]] if closed else [])
                    for i, (a, b) in enumerate(zip(ring, ring[1:])):
                        assert abs(knots[i + 1] - knots[i] - angle(a, b) ** alpha) <= 1e-12, f"seed {seed}, {kind}"
                else:
                    assert knots == list(range(n))
                out = run_json("eval", dict(doc, t=knots))
                assert len(out["quaternions"]) == n
                for i, q in enumerate(out["quaternions"]):
                    key = keys[i % len(keys)]
                    assert same_rotation(q, key) <= 1e-14, f"seed {seed}, {kind}, closed {closed}, alpha {alpha}, key {i}"
                    checked += 1
    assert checked == 6 * (2 * (6 + 7))


def test_agrees_with_the_python_binding(seed):
    # The same core through pybind11: the CLI's parsing, kinds, ends, tcb, frames
    # and output must give the binding's numbers. Printed with the shortest
    # round-trip text, so the agreement is exact up to the last bit: 0 tolerance
    # would hold for one jet; 1e-14 of the scale allows the CLI's single jet of the
    # highest order asked against the binding's jet per order (a few roundings apart).
    rotation = pytest.importorskip("crspline.rotation")
    rng = random.Random(seed)
    keys = random_keys(rng, 7)
    ts = sorted(rng.uniform(0, 1) for _ in range(25))
    cases = [
        ({"kind": "catmull_rom", "alpha": 0.5}, lambda: rotation.QuaternionSpline(keys, alpha=0.5)),
        ({"kind": "catmull_rom", "start": "natural_splines", "end": {"angular_velocity": [0.1, -0.2, 0.3], "frame": "body"}},
         lambda: rotation.QuaternionSpline(keys, start="natural_splines", end=[0.1, -0.2, 0.3], velocity_frame="body")),
        ({"kind": "kochanek_bartels", "tcb": [0.2, -0.1, 0.3]},
         lambda: rotation.QuaternionSpline(keys, "kochanek_bartels", tcb=[0.2, -0.1, 0.3])),
        ({"kind": "squad", "closed": True}, lambda: rotation.QuaternionSpline(keys, "squad", closed=True)),
        ({"kind": "barry_goldman", "alpha": 1}, lambda: rotation.QuaternionSpline(keys, "barry_goldman", alpha=1.0)),
        ({"kind": "slerp"}, lambda: rotation.QuaternionSpline(keys, "piecewise_slerp")),
        ({"kind": "c2", "start": "natural"}, lambda: rotation.C2RotationSpline(list(range(7)), keys, start="natural")),
        ({"kind": "c2", "closed": True}, lambda: rotation.C2RotationSpline(list(range(8)), keys, closed=True)),
    ]
    checked = 0
    for fields, make in cases:
        ref = make()
        hi = ref.grid[-1]
        t = [x * hi for x in ts] + [hi]
        for frame in ("world", "body"):
            out = run_json("eval", dict(fields, rotations={"quaternions": keys}, t=t, derivatives=[0, 1, 2], frame=frame))
            assert out["frame"] == frame
            for order, key in ((0, "quaternions"), (1, "angular_velocities"), (2, "angular_accelerations")):
                expect = np.asarray(ref.evaluate(np.asarray(t), order, frame=frame))
                got = np.asarray(out[key])
                assert got.shape == expect.shape, f"{fields} {key}"
                scale = max(1.0, float(np.max(np.abs(expect))))
                assert float(np.max(np.abs(got - expect))) <= 1e-14 * scale, f"seed {seed}, {fields}, {frame}, {key}"
                checked += 1
    assert checked == len(cases) * 2 * 3


def test_agrees_with_scipy(seed):
    # SciPy, independently written: its Slerp is our "slerp" kind, and its
    # RotationSpline (10 fixed-point rounds) agrees with the converged C2
    # spline where its iteration converges (steps below 60 deg here): rotations
    # to 1e-9, body rates to 1e-8 of their scale (SciPy stops at TOL = 1e-9).
    Rotation = scipy_rotation()
    from scipy.spatial.transform import RotationSpline, Slerp
    rng = random.Random(seed)
    keys = random_keys(rng, 8, step=1.0)
    times = [0.0]
    for _ in range(7):
        times.append(times[-1] + rng.uniform(0.5, 1.5))
    t = sorted(rng.uniform(0, times[-1]) for _ in range(40))
    r = Rotation.from_quat(to_xyzw(keys))
    slerp = run_json("eval", {"rotations": {"quaternions": keys}, "kind": "slerp", "grid": times, "t": t})
    expect = Slerp(times, r)(t).as_quat()
    for got, e in zip(slerp["quaternions"], expect):
        assert same_rotation(got, [e[3], e[0], e[1], e[2]]) <= 1e-12, f"seed {seed}"
    c2 = run_json("eval", {"rotations": {"quaternions": keys}, "kind": "c2", "grid": times, "t": t,
                           "derivatives": [0, 1], "frame": "body"})
    spline = RotationSpline(times, r)
    expect_q = spline(t).as_quat()
    expect_w = spline(t, 1)
    scale = max(1.0, float(np.max(np.abs(expect_w))))
    for got, e in zip(c2["quaternions"], expect_q):
        assert same_rotation(got, [e[3], e[0], e[1], e[2]]) <= 1e-9, f"seed {seed}"
    assert float(np.max(np.abs(np.asarray(c2["angular_velocities"]) - expect_w))) <= 1e-8 * scale, f"seed {seed}"
    assert len(c2["quaternions"]) == 40 and len(slerp["quaternions"]) == 40


def test_every_input_form_gives_the_same_curve(seed):
    # The keys as quaternions, rotation vectors (radians and degrees),
    # axis-angle, Euler angles in an extrinsic and an intrinsic convention
    # (degrees) and matrices: the same curve to 1e-13 (each conversion is a
    # few roundings of unit-size numbers; the spline adds a few more).
    Rotation = scipy_rotation()
    rng = random.Random(seed)
    keys = random_keys(rng, 5)
    r = Rotation.from_quat(to_xyzw(keys))
    rv = r.as_rotvec()
    angles = np.linalg.norm(rv, axis=1)
    forms = {
        "quaternions": {"quaternions": keys},
        "rotation_vectors": {"rotation_vectors": rv.tolist()},
        "rotation_vectors in degrees": {"rotation_vectors": np.degrees(rv).tolist(), "degrees": True},
        # key 0 is the identity: any axis with angle 0 (here x).
        "axis_angle": {"axis_angle": [(list(v / a) if a > 0 else [1.0, 0.0, 0.0]) + [a] for v, a in zip(rv, angles)]},
        "euler xyz": {"euler": {"convention": "xyz", "degrees": True, "angles": r.as_euler("xyz", degrees=True).tolist()}},
        "euler ZYX": {"euler": {"convention": "ZYX", "angles": r.as_euler("ZYX").tolist()}},
        "matrices": {"matrices": r.as_matrix().tolist()},
    }
    t = [k * 4 / 16 for k in range(17)]
    ref = None
    for name, rotations in forms.items():
        out = run_json("eval", {"rotations": rotations, "t": t, "derivatives": [0, 1]})
        if ref is None:
            ref = out
            for i in range(5):
                assert same_rotation(out["quaternions"][4 * i], keys[i]) <= 1e-14
            continue
        for a, b in zip(out["quaternions"], ref["quaternions"]):
            assert same_rotation(a, b) <= 1e-13, f"seed {seed}, {name}"
        assert float(np.max(np.abs(np.asarray(out["angular_velocities"]) - ref["angular_velocities"]))) <= 1e-12, name
    assert ref is not None and len(ref["quaternions"]) == 17


def test_sample_counts_and_constant_angular_speed(seed):
    # sample: count samples at equal t (first and last t the domain's ends),
    # and at equal turned angle: a piecewise slerp turns at a constant rate
    # per segment, so at equal angle steps each |omega| dt is the same share.
    rng = random.Random(seed)
    keys = random_keys(rng, 5)
    out = run_json("sample", {"rotations": {"quaternions": keys}, "count": 9})
    assert out["t"][0] == 0 and out["t"][-1] == 4 and len(out["quaternions"]) == 9
    out = run_json("sample", {"rotations": {"quaternions": keys}, "kind": "slerp", "count": 41, "spacing": "angle",
                              "derivatives": [0, 1]})
    t = np.asarray(out["t"])
    w = np.linalg.norm(np.asarray(out["angular_velocities"]), axis=1)
    assert len(t) == 41
    # The total angle of a piecewise slerp is the sum of its key-to-key angles.
    total = sum(angle(a, b) for a, b in zip(keys, keys[1:]))
    # Between samples inside one segment, angle = |omega| dt = total / 40 (to
    # the angle table's 1e-12 relative accuracy, 1e-9 with the t rounding).
    inside = 0
    for k in range(40):
        if math.floor(t[k]) == math.floor(t[k + 1] - 1e-12) and w[k] > 0:
            assert abs(w[k] * (t[k + 1] - t[k]) - total / 40) <= 1e-9 * total, f"seed {seed}, step {k}"
            inside += 1
    assert inside >= 30


def test_pose_curve():
    # Points and rotations on one grid: eval at the knots gives both; the
    # velocity is the position curve's; sample by arc length gives equal
    # chord steps on a straight path.
    keys = random_keys(random.Random(SEED), 4)
    points = [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]
    out = run_json("eval", {"points": points, "rotations": {"quaternions": keys}, "t": [0, 1, 2, 3],
                            "derivatives": [0, 1]})
    for i in range(4):
        assert max(abs(a - b) for a, b in zip(out["positions"][i], points[i])) <= 1e-14
        assert same_rotation(out["quaternions"][i], keys[i]) <= 1e-14
        assert abs(out["velocities"][i][1]) <= 1e-14 and abs(out["velocities"][i][2]) <= 1e-14
    assert len(out["angular_velocities"]) == 4
    s = run_json("sample", {"points": points, "rotations": {"quaternions": keys}, "count": 7, "spacing": "arc_length"})
    x = [p[0] for p in s["positions"]]
    assert len(x) == 7
    for k in range(7):
        assert abs(x[k] - k * 0.5) <= 1e-10, k  # the arc-length table's 1e-12 relative, with margin


def test_csv_output_parses():
    keys = random_keys(random.Random(SEED), 4)
    doc = json.dumps({"rotations": {"quaternions": keys}, "t": [0, 0.5, 1, 3], "derivatives": [0, 1, 2]})
    p = run(["eval", "-", "--format", "csv"], doc)
    assert p.returncode == 0, p.stderr
    rows = list(csv.reader(io.StringIO(p.stdout)))
    assert rows[0] == ["t", "qw", "qx", "qy", "qz", "wx", "wy", "wz", "ax", "ay", "az"]
    assert len(rows) == 5
    ref = run_json("eval", json.loads(doc))
    for i, r in enumerate(rows[1:]):
        v = [float(x) for x in r]
        assert v[0] == ref["t"][i]
        assert v[1:5] == ref["quaternions"][i] and v[5:8] == ref["angular_velocities"][i]
        assert v[8:11] == ref["angular_accelerations"][i]
    pose = json.dumps({"points": [[0, 0, 0], [1, 0, 0], [1, 1, 0]], "rotations": {"quaternions": keys[:3]},
                       "count": 5, "derivatives": [0, 1]})
    p = run(["sample", "-", "--format", "tsv"], pose)
    assert p.returncode == 0, p.stderr
    rows = [line.split("\t") for line in p.stdout.splitlines()]
    assert rows[0] == ["t", "x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz"]
    assert len(rows) == 6 and all(len(r) == 14 for r in rows)


Q = [[1, 0, 0, 0], [0.8775825618903728, 0.479425538604203, 0, 0], [0.5403023058681398, 0, 0.8414709848078965, 0]]

ERRORS = [
    ({"rotations": [[1, 0, 0, 0]], "t": [0]}, "rotations: expected an object with one of"),
    ({"rotations": {"quaternion": Q}, "t": [0]}, "rotations: unknown field 'quaternion'"),
    ({"rotations": {"quaternions": Q, "rotation_vectors": [[0, 0, 0]]}, "t": [0]}, "rotations: give one form of rotations"),
    ({"rotations": {"quaternions": [Q[0], [1, 0, "a", 0], Q[2]]}, "t": [0]},
     'rotations.quaternions[1][2]: expected a finite number, got "a"'),
    ({"rotations": {"quaternions": [Q[0], Q[1], [0.9, 0, 0, 0]]}, "t": [0]},
     "rotations.quaternions[2]: not a unit quaternion (norm 0.9"),
    ({"rotations": {"quaternions": [Q[0], [1, 0, 0]]}, "t": [0]},
     "rotations.quaternions[1]: expected an array of 4 numbers, got [1,0,0]"),
    ({"rotations": {"rotation_vectors": [[0, 0, 0], [0, 1]]}, "t": [0]},
     "rotations.rotation_vectors[1]: expected an array of 3 numbers"),
    ({"rotations": {"axis_angle": [[1, 0, 0, 0], [0, 0, 0, 1]]}, "t": [0]}, "rotations.axis_angle[1]: the axis is zero"),
    ({"rotations": {"euler": {"convention": "xxy", "angles": [[0, 0, 0]]}}, "t": [0]},
     "rotations.euler.convention: euler convention \"xxy\": the same axis twice in a row"),
    ({"rotations": {"euler": {"convention": "xyz", "angles": [[0, 0, 0], [0, None, 0]]}}, "t": [0]},
     "rotations.euler.angles[1][1]: expected a finite number, got null"),
    ({"rotations": {"euler": {"angles": [[0, 0, 0]]}}, "t": [0]}, "rotations.euler: missing field 'convention'"),
    ({"rotations": {"matrices": [[[1, 0, 0], [0, 1, 0], [0, 0, 1]], [[1, 0, 0], [0, 1, 0], [0, 0, 2]]]}, "t": [0]},
     "rotations.matrices[1]: rotation matrix: not a rotation"),
    ({"rotations": {"quaternions": Q}, "kind": "spline", "t": [0]}, "kind: expected one of catmull_rom"),
    ({"rotations": {"quaternions": Q}, "t": [0, 2.5]}, "t[1]: t = 2.5 is outside the domain [0, 2]"),
    ({"rotations": {"quaternions": Q}, "t": [0], "derivatives": [0, 3]}, "derivatives[1]: expected 0, 1 or 2, got 3"),
    ({"rotations": {"quaternions": Q}, "t": [0], "frame": "local"}, 'frame: expected "world" or "body", got "local"'),
    ({"rotations": {"quaternions": Q}, "t": [0], "kind": "squad", "start": "natural"},
     "start: only used with kind catmull_rom, kochanek_bartels or c2"),
    ({"rotations": {"quaternions": Q}, "t": [0], "end": {"angular_velocity": [0, 1]}},
     "end.angular_velocity: expected an array of 3 numbers"),
    ({"rotations": {"quaternions": Q}, "t": [0], "tcb": [0, 0, 0]}, "tcb: only used with kind kochanek_bartels"),
    ({"rotations": {"quaternions": Q}, "t": [0], "alpha": 2}, "alpha must be in [0, 1], got 2"),
    ({"rotations": {"quaternions": Q}, "t": [0], "grid": [0, 2, 1]}, "grid is not increasing at index 2"),
    ({"rotations": {"quaternions": Q}, "t": [0], "tension": 0.5}, "tension: unknown field in a rotation curve file"),
    ({"rotations": {"quaternions": [Q[0], Q[0], Q[1]]}, "kind": "c2", "alpha": 0.5, "t": [0]},
     "alpha: keys 0 and 1 are the same rotation, so alpha's grid has a zero interval there"),
    ({"rotations": {"quaternions": [Q[0], Q[0], Q[1]]}, "alpha": 0.5, "strict": True, "t": [0]},
     "keys 0 and 1 are the same rotation"),
    ({"points": [[0, 0, 0], [1, 0, 0]], "rotations": {"quaternions": Q}, "t": [0]},
     "points: a pose curve needs one rotation per point: 2 points, 3 rotations in rotations.quaternions"),
    ({"points": [[0, 0], [1, 0], [2, 0]], "rotations": {"quaternions": Q}, "t": [0]}, "points: a pose curve needs 3-D points"),
    ({"points": [[0, 0, 0], [1, 0, 0], [2, 0, 0]], "rotations": {"quaternions": Q}, "t": [0], "derivatives": [2]},
     "derivatives[0]: expected 0 or 1"),
]


@pytest.mark.parametrize("doc,expected", ERRORS)
def test_errors_name_the_field_and_index(doc, expected):
    p = run(["eval", "-"], json.dumps(doc))
    assert p.returncode == 2, p.stdout
    assert p.stderr.startswith("crspline: "), p.stderr
    assert expected in p.stderr, p.stderr
    assert p.stdout == ""


def test_sample_errors_and_file_name(tmp_path):
    base = {"rotations": {"quaternions": Q}}
    for doc, expected in [(dict(base), "count: missing"), (dict(base, count=1), "count: expected an integer >= 2, got 1"),
                          (dict(base, count=5, spacing="arc_length"), 'spacing: expected "t", "angle", got "arc_length"'),
                          (dict(base, count=5, t=[0]), "t: unknown field in a rotation curve file for sample")]:
        p = run(["sample", "-"], json.dumps(doc))
        assert p.returncode == 2 and expected in p.stderr, (doc, p.stderr)
    path = tmp_path / "r.json"
    path.write_text(json.dumps({"rotations": {"quaternions": [Q[0], [2, 0, 0, 0]]}, "t": [0]}))
    p = run(["eval", str(path)])
    assert p.returncode == 2 and p.stderr.startswith(f"crspline: {path}: rotations.quaternions[1]: not a unit"), p.stderr
    p = run(["eval", "-", "--alpha", "0.5"], json.dumps(dict(base, t=[0])))
    assert p.returncode == 2 and "--alpha: not used with a rotation curve file" in p.stderr, p.stderr
    for command, fmt in (("sample", "geojson"), ("sample", "svg-path"), ("eval", "svg"), ("sample", "svg")):
        p = run([command, "-", "--format", fmt], json.dumps(dict(base, count=3)))
        assert p.returncode == 2 and f"--format {fmt}: a rotation curve file gives json, csv or tsv" in p.stderr, p.stderr
    p = run(["eval", "-", "--t", "0,1.5", "--derivatives", "1"], json.dumps(base))
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout)["t"] == [0, 1.5]
