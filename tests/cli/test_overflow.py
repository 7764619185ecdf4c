"""Issue 31 point 3: coordinates whose difference overflows.

Points (-1.5e308, 0) and (1.5e308, 0) are finite, their chord (3e308) is
not. The core refuses such a curve at construction, naming the points, so
every subcommand that builds it refuses it too (exit 2, one line), in every
alpha, open and closed: `length` used to print "total": 0.0 and `analyze`
to certify it. Standard library only."""
import json

from cli_support import run

LINE = "crspline: <stdin>: points[0]: points 0 and 1: the chord between them overflows (|P1 - P0| is not finite)\n"

COMMANDS = [
    (["length", "-"], {}),
    (["analyze", "-"], {}),
    (["eval", "-"], {"t": [0]}),
    (["sample", "-"], {"count": 3}),
    (["bezier", "-"], {}),
]


def test_every_subcommand_refuses_an_overflowing_chord():
    checked = 0
    for alpha in (0, 0.5, 1):
        for closed in (False, True):
            for args, extra in COMMANDS:
                doc = {"points": [[-1.5e308, 0], [1.5e308, 0]], "alpha": alpha, **extra}
                if closed:
                    doc["end"] = "closed"
                p = run(args, json.dumps(doc))
                where = f"{args[0]} alpha {alpha} closed {closed}"
                assert p.returncode == 2, (where, p.returncode, p.stdout[:200], p.stderr)
                assert p.stdout == "", (where, p.stdout[:200])
                assert p.stderr == LINE, (where, p.stderr)
                checked += 1
    assert checked == 3 * 2 * len(COMMANDS)


def test_a_wide_but_finite_curve_is_accepted():
    # Chords of 2e300: everything finite, the length is the polyline's sum
    # (a straight line), no refusal.
    doc = {"points": [[-1e300, 0], [0, 0], [1e300, 0]], "alpha": 0.5}
    p = run(["length", "-"], json.dumps(doc))
    assert p.returncode == 0, p.stderr
    total = json.loads(p.stdout)["total"]
    assert abs(total - 2e300) <= 1e-12 * 2e300, total
