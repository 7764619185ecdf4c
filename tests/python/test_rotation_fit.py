"""crspline.rotation.fit (issue 40 point 4): keyframe reduction of an
orientation stream, proved at the samples. Checked here with NumPy alone,
independently of the core's bound: every sample's angle to the returned
curve (4 asin(|q - r| / 2) on the nearer sign) is within the tolerance, on a
seeded corpus of motion-capture-like streams (the seed is printed on
failure); the result agrees with itself; bad input is a ValueError naming
what is wrong; docs/rotation.md's "Keyframe reduction" examples run as
shown."""
import doctest
import pathlib
import re
import threading

import numpy as np
import pytest

from crspline import rotation

ROOT = pathlib.Path(__file__).resolve().parents[2]
DEG = np.pi / 180


def quat_mul(a, b):
    w = a[..., 0] * b[..., 0] - np.sum(a[..., 1:] * b[..., 1:], axis=-1)
    v = a[..., :1] * b[..., 1:] + b[..., :1] * a[..., 1:] + np.cross(a[..., 1:], b[..., 1:])
    return np.concatenate([w[..., None], v], axis=-1)


def from_rotvec(r):
    a = np.linalg.norm(r, axis=-1, keepdims=True)
    s = np.where(a > 0, np.sin(a / 2) / np.where(a > 0, a, 1), 0.5)
    return np.concatenate([np.cos(a / 2), s * r], axis=-1)


def angles(q, r):
    """The rotation angle between rows of q and r (unit-normalized first), the short way."""
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    r = r / np.linalg.norm(r, axis=1, keepdims=True)
    r = np.where(np.sum(q * r, axis=1, keepdims=True) < 0, -r, r)
    return 4 * np.arcsin(np.minimum(1.0, np.linalg.norm(q - r, axis=1) / 2))


def mocap(rng, n, hz=120.0, noise=0.05 * DEG):
    """Sums of sinusoids of the rotation vector (0.2-2 Hz), sensor noise, random signs."""
    t = np.arange(n) / hz
    amp, freq, phase = rng.uniform(size=(3, 3, 3))
    r = np.zeros((n, 3))
    for c in range(3):
        for k in range(3):
            r[:, c] += 0.8 * amp[c, k] * np.sin(2 * np.pi * (0.2 + 1.8 * freq[c, k]) * t + 6.3 * phase[c, k]) / 3
    base = rng.normal(size=4)
    q = quat_mul(from_rotvec(rng.normal(size=(n, 3)) * noise), quat_mul(from_rotvec(r), base / np.linalg.norm(base)))
    return t, q * rng.choice([-1.0, 1.0], size=(n, 1))


def spin(rng, n, hz=120.0, rate=4 * np.pi, noise=0.05 * DEG):
    t = np.arange(n) / hz
    axis = np.stack([np.cos(0.5 * t), np.sin(0.5 * t), np.ones(n)], axis=1)
    axis /= np.linalg.norm(axis, axis=1, keepdims=True)
    return t, quat_mul(from_rotvec(rng.normal(size=(n, 3)) * noise), from_rotvec(axis * (rate * t)[:, None]))


def big_steps(rng, n):
    """Sparse samples 150-179 degrees apart about random axes, at uneven times."""
    q = [np.array([1.0, 0, 0, 0])]
    for _ in range(n - 1):
        axis = rng.normal(size=3)
        q.append(quat_mul(from_rotvec(axis / np.linalg.norm(axis) * rng.uniform(150, 179) * DEG), q[-1]))
    return np.cumsum(rng.uniform(0.5, 1.5, size=n)), np.array(q)


def corpus(rng):
    yield "mocap", *mocap(rng, 900)
    yield "spin", *spin(rng, 900)
    yield "near-180 steps", *big_steps(rng, 40)
    t, q = mocap(rng, 900, noise=0.0)
    q[300:600] = q[300] * rng.choice([-1.0, 1.0], size=(300, 1))  # a still stretch, signs free
    yield "still stretch", t, q


@pytest.mark.parametrize("tol_deg", [0.2, 1.0, 4.0])
def test_proved_at_every_sample(seed, tol_deg):
    rng = np.random.default_rng(seed)
    tol = tol_deg * DEG
    samples = kept = streams = 0
    for name, t, q in corpus(rng):
        r = rotation.fit(t, q, angle_tolerance=tol)
        assert r.indices[0] == 0 and r.indices[-1] == len(t) - 1, name
        assert np.all(np.diff(r.indices) > 0), name
        assert r.count == len(r.indices) == len(r.times) == len(r.keys)
        assert np.array_equal(r.times, t[r.indices])
        assert np.array_equal(r.curve.grid, r.times)
        # The samples' rotations: both sides normalized in double (here and
        # in the core) differ by a few ulps per component, |q - r| < 1e-15,
        # and the angle 4 asin(|q - r| / 2) is at most twice that.
        assert angles(r.keys, q[r.indices]).max() <= 2e-15, name
        e = angles(r.curve.evaluate(t), q)
        # The proof is at the samples: the independent angle stays within the
        # tolerance, and the reported bound is above it by its rounding slack
        # only (16 eps relative + 4 |norm - 1| + 32 eps: below 1e-13 rad).
        assert e.max() <= tol, f"{name}: sample {int(e.argmax())} at {e.max()} > {tol}"
        assert e.max() <= r.max_angle <= min(tol, e.max() + 1e-13), name
        samples, kept, streams = samples + len(t), kept + r.count, streams + 1
    assert streams == 4
    # At 120 Hz the reduction is large even at 0.2 degrees.
    assert kept * 4 < samples, f"{kept} keys of {samples} samples"


def test_fewer_keys_at_larger_tolerance(seed):
    t, q = mocap(np.random.default_rng(seed), 1200)
    counts = [rotation.fit(t, q, angle_tolerance=a * DEG).count for a in (0.1, 0.5, 2.0)]
    assert counts[0] > counts[1] > counts[2] >= 2, counts


def test_still_stream_and_two_samples():
    q = np.tile([0.5, 0.5, -0.5, 0.5], (300, 1)) * np.where(np.arange(300) % 2, -1.0, 1.0)[:, None]
    r = rotation.fit(np.arange(300.0), q, angle_tolerance=1e-9)
    assert list(r.indices) == [0, 299] and r.max_angle <= 1e-13
    r = rotation.fit([0.0, 1.0], [[1, 0, 0, 0], [0, 1, 0, 0]], angle_tolerance=0.1)
    assert list(r.indices) == [0, 1]


def test_runs_beside_other_threads(seed):
    """The fit releases the GIL: two threads fit at once and give what one does."""
    t, q = mocap(np.random.default_rng(seed), 3000)
    alone = rotation.fit(t, q, angle_tolerance=0.3 * DEG)
    out = [None, None]

    def work(k):
        out[k] = rotation.fit(t, q, angle_tolerance=0.3 * DEG)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    for r in out:
        assert np.array_equal(r.indices, alone.indices) and r.max_angle == alone.max_angle


@pytest.mark.parametrize("kwargs, quats, times, message", [
    ({"angle_tolerance": 0.0}, None, None, "angle_tolerance must be a positive finite angle in radians, got 0"),
    ({"angle_tolerance": -0.1}, None, None, "angle_tolerance must be a positive finite angle in radians, got -0.1"),
    ({"angle_tolerance": float("nan")}, None, None, "angle_tolerance must be a positive finite angle in radians, got nan"),
    ({"angle_tolerance": 1e-15}, None, None, "below what rounding lets the proof resolve"),
    ({"angle_tolerance": 0.1}, [[1, 0, 0, 0]], [0.0], "a rotation fit needs at least 2 samples, got 1"),
    ({"angle_tolerance": 0.1}, None, [0.0, 1.0, 1.0], "times is not increasing at index 2 (1 then 1)"),
    ({"angle_tolerance": 0.1}, None, [0.0, float("nan"), 2.0], "times 1 is not finite (nan)"),
    ({"angle_tolerance": 0.1}, None, [0.0, 1.0], "times has 2 values and quaternions 3 rows"),
    ({"angle_tolerance": 0.1}, [[1, 0, 0, 0], [0, 0, 0, 0], [1, 0, 0, 0]], None,
     "sample 1 [0, 0, 0, 0] has norm 0: not a rotation"),
    ({"angle_tolerance": 0.1}, [[1, 0, 0, 0], [1, float("nan"), 0, 0], [1, 0, 0, 0]], None,
     "sample 1: component 1 (x) is not finite (nan)"),
    ({"angle_tolerance": 0.1}, [[1, 0, 0], [1, 0, 0], [1, 0, 0]], None, "quaternions must have shape (n, 4)"),
])
def test_bad_input_is_named(kwargs, quats, times, message):
    q = [[1, 0, 0, 0], [0.9689124217106447, 0.24740395925452294, 0, 0], [0.8775825618903728, 0.479425538604203, 0, 0]]
    with pytest.raises(ValueError) as e:
        rotation.fit([0.0, 1.0, 2.0] if times is None else times, q if quats is None else quats, **kwargs)
    assert message in str(e.value)


def section_blocks():
    """The ```pycon blocks of docs/rotation.md's "Keyframe reduction" section."""
    text = (ROOT / "docs" / "rotation.md").read_text()
    section = re.search(r"^## Keyframe reduction\n(.*?)(?=^## )", text, re.S | re.M).group(1)
    return re.findall(r"^```pycon\n(.*?)^```", section, re.S | re.M)


def test_docs_section_runs_as_shown(tmp_path, monkeypatch):
    blocks = section_blocks()
    assert len(blocks) == 1
    monkeypatch.chdir(tmp_path)
    parser, runner = doctest.DocTestParser(), doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    globs = {}
    for k, block in enumerate(blocks):
        test = parser.get_doctest(block, globs, f"docs/rotation.md keyframe block {k}", "docs/rotation.md", 0)
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.attempted >= 6 and result.failed == 0
