"""The Python module: hand-derived values, a brute-force envelope, and agreement with the CLI."""
import csv as csv_module
import io
import itertools
import json
import math
import os
import random
import re
import subprocess
import sys
from decimal import Decimal
from fractions import Fraction as F
from pathlib import Path

import numpy as np
import pytest

import scalecert

SRC = Path(os.environ.get("SCALECERT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("SCALECERT_BIN", "scalecert")
CHECK = os.environ.get("SCALECERT_CHECK_BIN", "scalecert-check")


def box(x0, y0, z0, x1, y1, z1):
    return [[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]


def stacked():
    # [0,2]^3 below [0,2]^2 x [3,5], seeds the centres: P1(r1) reaches z = 1 + r1, P2(r2) starts
    # at z = 4 - r2, so they touch on r1 + r2 = 3 (face on face) and the growth distance is 3/2.
    return scalecert.Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), ("1/2", "5/2"), (F(1, 2), 2.5))


def test_stacked_cubes_by_hand():
    c = stacked().curve()
    assert len(c["pieces"]) == 1
    p = c["pieces"][0]
    assert (p["slope"], p["intercept"], p["rho1"]) == (-1, 3, (F(1, 2), F(5, 2)))
    assert p["contact"] == "FF"
    assert c["switch_points"] == []
    assert c["growth_distance"] == F(3, 2) and c["growth_distance_in_rectangle"]


def test_queries_carry_their_certificates():
    s = stacked()
    q = s.query(1, F(3, 2))
    assert q["verdict"] == scalecert.Verdict.Separated
    k = q["plane"]["normal"][2]  # (0, 0, k): P1 up to z = 2, P2 from z = 5/2
    assert q["plane"]["c1"] == 2 * k and q["plane"]["c2"] == F(5, 2) * k
    assert q["certificate"]["verdict"] == "separated"
    q = s.query("0.5", Decimal("2.5"))
    assert q["verdict"] == scalecert.Verdict.Touching
    assert q["common_point"]["point"][2] == F(3, 2)
    q = s.query(2, 2)
    assert q["verdict"] == scalecert.Verdict.Overlapping
    assert q["common_point"]["rho1"] + q["common_point"]["rho2"] == 3


def test_tetrahedron_on_box_by_hand():
    # The tetrahedron's lowest vertex v = (2,0,2), about the seed (0,0,9/2), sits at
    # (2 r1, 0, 9/2 - 5/2 r1); the box [-1,1]^3 scaled by r2 has its top at z = r2. Vertex on face
    # (VF) while v is over the top face: r2 = 9/2 - 5/2 r1, until x = 2 r1 reaches the edge
    # x = r2 at r1 = 1, r2 = 2, where v touches the edge (a VE switch).
    s = scalecert.Scene.load(str(SRC / "certificates/scenes/tetra_box_switch.json"))
    c = s.curve()
    p = c["pieces"][0]
    assert (p["slope"], p["intercept"], p["contact"]) == (F(-5, 2), F(9, 2), "VF")
    assert p["rho1"] == (F(1, 2), 1)
    sw = c["switch_points"][0]
    assert (sw["rho1"], sw["rho2"], sw["contact"]) == (1, 2, "VE")
    assert sw["features"] == ([0], [5, 7])


def test_classify_takes_doubles_at_their_exact_values():
    s = stacked()
    r1 = np.array([1.0, 1.5, 1.5, 2.0, 0.1])
    r2 = np.array([1.0, 1.5, np.nextafter(1.5, 2.0), 2.0, 2.9])
    v = s.classify(r1, r2)
    assert v.dtype == np.int8
    S, T, O = (int(x) for x in (scalecert.Verdict.Separated, scalecert.Verdict.Touching, scalecert.Verdict.Overlapping))
    # 0.1 + 2.9 in doubles: 0.1 is above 1/10 and 2.9 below 29/10 by different amounts.
    exact = F(0.1) + F(2.9)
    assert list(v) == [S, T, O, O, S if exact < 3 else T if exact == 3 else O]
    big = np.random.default_rng(1).uniform(0.5, 2.5, size=(2, 20000))
    v = s.classify(big[0], big[1])
    want = [S if F(a) + F(b) < 3 else T if F(a) + F(b) == 3 else O for a, b in zip(big[0], big[1])]
    assert v.tolist() == want


def test_check_plane_is_exact():
    s = stacked()
    assert s.check_plane(1, 1, [0, 0, 1], "2.5")["separates"]
    assert not s.check_plane(1, 1, [0, 0, 1], 3)["separates"]  # touches P2's bottom face
    # A plane that misses P1's top (z = 2) by 10^-17: rejected.
    assert not s.check_plane(1, 1, [0, 0, 1], Decimal("1.99999999999999999"))["separates"]
    r = s.check_plane(1, 1, [1, 0, 1])
    assert (r["c1"], r["c2"], r["separates"]) == (4, 3, False)


def test_bad_input_is_one_line():
    with pytest.raises(ValueError, match="I1: lo > hi"):
        scalecert.Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), (3, 1), (1, 2))
    with pytest.raises(ValueError, match="flat"):
        scalecert.Scene(box(0, 0, 0, 2, 2, 0), box(0, 0, 3, 2, 2, 5), (1, 2), (1, 2))
    with pytest.raises(ValueError, match="not strictly inside"):
        scalecert.Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), (1, 2), (1, 2), seeds=([2, 1, 1], None))
    with pytest.raises(ValueError, match="not a number"):
        scalecert.Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), (1, 2), (1, [2]))
    with pytest.raises(ValueError, match="finite"):
        scalecert.Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), (1, float("inf")), (1, 2))
    with pytest.raises(ValueError, match="> 0"):
        stacked().query(0, 1)
    with pytest.raises(ValueError, match="finite"):
        stacked().classify(np.array([1.0]), np.array([np.nan]))


# ---- a brute-force envelope: every cross product of two difference vectors is a candidate normal
def brute_f(P1, P2, s1, s2, r1):
    diffs = [np.subtract(a, b) for P in (P1, P2) for a, b in itertools.combinations(P, 2)]
    d = [s2[i] - s1[i] for i in range(3)]
    best = None
    for a, b in itertools.combinations(diffs, 2):
        n0 = [int(a[1] * b[2] - a[2] * b[1]), int(a[2] * b[0] - a[0] * b[2]), int(a[0] * b[1] - a[1] * b[0])]
        if n0 == [0, 0, 0]:
            continue
        for n in (n0, [-x for x in n0]):
            h1 = max(sum(n[i] * (v[i] - s1[i]) for i in range(3)) for v in P1)
            h2 = max(-sum(n[i] * (w[i] - s2[i]) for i in range(3)) for w in P2)
            val = (sum(n[i] * d[i] for i in range(3)) - r1 * h1) / h2
            best = val if best is None or val > best else best
    return best


def random_scene(rng, n1, n2):
    P1 = [[rng.randint(-4, 4) for _ in range(3)] for _ in range(n1)]
    P2 = [[rng.randint(-4, 4) + 7 * (k == 0) for k in range(3)] for _ in range(n2)]
    return P1, P2


def test_random_scenes_match_brute_force_and_the_cli(tmp_path):
    rng = random.Random(7)
    done = 0
    while done < 6:
        P1, P2 = random_scene(rng, 5 + done % 3, 6)
        try:
            s = scalecert.Scene(P1, P2, ("1/3", 3), (F(1, 2), "2.75"))
        except ValueError:
            continue  # flat point sets: drawn again
        s1, s2 = s.seeds()
        c = s.curve()
        for p in c["pieces"]:
            for r1 in (p["rho1"][0], (p["rho1"][0] + p["rho1"][1]) / 2, p["rho1"][1]):
                assert p["slope"] * r1 + p["intercept"] == brute_f(
                    [[F(x) for x in v] for v in P1], [[F(x) for x in v] for v in P2], s1, s2, r1)
        scene = tmp_path / f"s{done}.json"
        scene.write_text(s.json())
        for cmd, mine in (("curve", json.dumps(s.curve_json(), indent=2)), ("partition", s.partition_json())):
            out = subprocess.run([CLI, cmd, str(scene)], capture_output=True, text=True, check=True).stdout
            if cmd == "partition":
                assert out == mine  # byte for byte
            else:
                assert json.loads(out)["pieces"] == json.loads(mine)["pieces"]
        cert = tmp_path / f"s{done}.partition.json"
        cert.write_text(s.partition_json())
        assert subprocess.run([CHECK, str(cert)], capture_output=True).returncode == 0
        done += 1


def test_numpy_and_exact_inputs_agree():
    P1 = np.array(box(0, 0, 0, 2, 2, 2), dtype=np.int64)
    a = scalecert.Scene(P1, np.array(box(0, 0, 3, 2, 2, 5), dtype=np.float64), (0.5, 2.5), (0.5, 2.5))
    b = scalecert.Scene([[F(x) for x in v] for v in box(0, 0, 0, 2, 2, 2)],
                        [[str(x) for x in v] for v in box(0, 0, 3, 2, 2, 5)], ("1/2", "5/2"), ("0.5", "2.5"))
    assert a.json() == b.json()
    assert a.partition_json() == b.partition_json()
    c = scalecert.Scene([[0.1, 0, 0]] + box(0, 0, 0, 2, 2, 2)[1:], box(0, 0, 3, 2, 2, 5), (1, 2), (1, 2))
    assert json.loads(c.json())["P1"]["vertices"][0][0] == str(F(0.1))  # the double's exact value


def test_golden_and_claims(tmp_path):
    # An unknown family is refused before the directory is made (as by scalecert golden).
    with pytest.raises(ValueError, match="unknown family 'bogus'"):
        scalecert.golden("bogus", 1, 5, "1/1024", str(tmp_path / "never-made"))
    assert not (tmp_path / "never-made").exists()
    scalecert.golden("random", 2, 5, "1/1024", str(tmp_path / "g"))
    names = sorted(p.name for p in (tmp_path / "g").iterdir())
    assert names == ["random-0.golden.csv", "random-0.golden.json", "random-0.golden.rational.csv",
                     "random-0.scene.json", "random-1.golden.csv", "random-1.golden.json",
                     "random-1.golden.rational.csv", "random-1.scene.json"]
    out = subprocess.run([CLI, "golden", "--family", "random", "--count", "2", "--seed", "5", "--eps", "1/1024",
                          "--dir", str(tmp_path / "h")], capture_output=True, check=True)
    for n in names:
        assert (tmp_path / "g" / n).read_bytes() == (tmp_path / "h" / n).read_bytes()
    # Stacked cubes: (1, 1) separated, (3/2, 3/2) touching, growth 3/2; a false claim is caught.
    r = stacked().certify_fp("1 1 separated\n1.5 1.5 touching\ngrowth 1.5\n2 2 separated\n")
    assert r["wrong"] == 1
    # JSON claims: the distance at (1, 1/2) is 3/2 (P1 reaches z = 2, P2(1/2) starts at 3.5).
    claims = {"format": "scalecert-claims-1", "claims": [{"kind": "distance", "rho1": 1, "rho2": "1/2", "value": "1.5000001"}]}
    assert stacked().certify_fp(json.dumps(claims))["wrong"] == 1
    assert stacked().certify_fp(json.dumps(claims), tolerance="1e-6")["wrong"] == 0
    # The library's words, not the command's; one number, not an array; a KeyboardInterrupt raised
    # while a number is read goes on as itself.
    with pytest.raises(scalecert.InputError, match="tolerance: must be >= 0"):
        stacked().certify_fp(json.dumps(claims), tolerance=-1)
    with pytest.raises(scalecert.InputError, match="not an array"):
        stacked().certify_fp(json.dumps(claims), tolerance=np.array([1e-3]))

    class Interrupting:
        @property
        def dtype(self):
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        stacked().certify_fp(json.dumps(claims), tolerance=Interrupting())
    # Claims as dicts: a float means the double it is. The doubles 0.1 and 2.9 sum to just under 3,
    # so the cubes (touching on rho1 + rho2 = 3) are separated there; as decimals they touch.
    assert F(0.1) + F(2.9) < 3
    c = [{"kind": "verdict", "rho1": 0.1, "rho2": 2.9, "verdict": "separated"},
         {"kind": "verdict", "rho1": F(1, 10), "rho2": Decimal("2.9"), "verdict": "touching"},
         {"kind": "verdict", "rho1": np.float64(0.1), "rho2": np.float32(2.5), "verdict": "separated"},
         {"kind": "witness_point", "rho1": 2, "rho2": 2, "point": np.array([1, 1, 2.5])}]
    r = stacked().certify_fp(c)
    assert r["wrong"] == 0 and [x["right"] for x in r["claims"]] == [True] * 4
    assert stacked().certify_fp({"format": "scalecert-claims-1", "claims": c[:1]})["wrong"] == 0
    assert stacked().certify_fp(json.dumps({"format": "scalecert-claims-1", "claims": c[:1]}), exact_decimals=True)["wrong"] == 1
    with pytest.raises(scalecert.InputError, match="claims: .*NaN|claims: .*nan|Out of range"):
        stacked().certify_fp([{"kind": "verdict", "rho1": float("nan"), "rho2": 1, "verdict": "separated"}])
    with pytest.raises(scalecert.InputError, match="not a number, string, list or dict"):
        stacked().certify_fp([{"kind": "verdict", "rho1": object(), "rho2": 1, "verdict": "separated"}])
    with pytest.raises(scalecert.InputError, match="expected a str"):
        stacked().certify_fp(3)
    # With the judgements certificate, which the independent checker verifies.
    r, cert = stacked().certify_fp(c, certificate=True)
    assert r["wrong"] == 0 and json.loads(cert)["kind"] == "judgements"
    (tmp_path / "j.json").write_text(cert)
    out = subprocess.run([CHECK, str(tmp_path / "j.json")], capture_output=True, text=True)
    assert out.returncode == 0 and out.stdout.startswith("valid:")
    # A scene's golden data: 7 values of rho1 across [1/2, 5/2] (the curve rho2 = 3 - rho1 runs from
    # corner to corner), 25 pairs each (on it, and 2^-k above, below, right and left of it), 13 where
    # it enters and 13 where it leaves the rectangle, 4 corners; rho1 = 3/4 has rho2 = 9/4 on it.
    g, csv, rational = stacked().golden()
    rows = csv.splitlines()
    assert len(rows) == 1 + 7 * 25 + 2 * 13 + 4 == len(rational.splitlines())
    assert "0.75,2.25,on,touching,touching,0,vertical" in csv
    # 2^-4 of 9/4 above the curve they overlap by 9/64 in z, and as far below they are 9/64 apart,
    # the closest points 9/64 apart in z and the plane z = their midpoint between them.
    assert "\n0.75,2.390625,above 2^-4,overlapping,depth,0.140625,vertical,,,,,,,0,0,1,,,\n" in csv
    below = next(q for q in g["queries"] if q["rho1"] == "3/4" and q["where"] == "below 2^-4")
    m = below["measure_at_doubles"]
    assert m["kind"] == "distance" and m["squared"] == "81/4096" and m["value_double"] == 0.140625
    p1, p2 = [F(v) for v in m["closest_P1"]], [F(v) for v in m["closest_P2"]]
    assert p1[2] == F(7, 4) and p2[2] - p1[2] == F(9, 64)  # P1's top 1 + 3/4
    assert m["plane"] == {"normal": ["0", "0", "1"], "offset": str(F(7, 4) + F(9, 128))}
    # The rational CSV, read with Fraction: each row's squared distance is (3 - rho1 - rho2)^2.
    for r in csv_module.DictReader(io.StringIO(rational)):
        s = F(int(r["rho1_num"]), int(r["rho1_den"])) + F(int(r["rho2_num"]), int(r["rho2_den"]))
        assert F(int(r["squared_num"]), int(r["squared_den"])) == (3 - s) ** 2
    # Fewer pairs when asked: one vertical (rho1 = 3/2), one offset: 5 + 3 + 3 + 4.
    g, _, _ = stacked().golden(verticals=1, offsets=[8])
    assert len(g["queries"]) == 15 and g["query_points"] == {"verticals": 1, "offsets": [8]}
    for bad in ({"verticals": -1}, {"offsets": [0]}, {"offsets": "4"}, {"offsets": [4, 4]}):
        with pytest.raises(scalecert.InputError):
            stacked().golden(**bad)


def test_readme_example_runs(tmp_path):
    text = (SRC / "README.md").read_text()
    m = re.search(r"<!-- python-example -->\s*```python\n(.*?)```", text, re.S)
    assert m, "README has no python example"
    code = m.group(1)
    assert len(code.strip().splitlines()) <= 12
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=SRC)
    assert out.returncode == 0, out.stderr
    assert "touching" in out.stdout.lower()


# ---- numbers past CPython's 4,300-digit int <-> str limit (3.11: a bare ValueError) -----------
def no_str_limit(f):
    """f() with CPython's int <-> str digit limit lifted (the test's own text only)."""
    old = getattr(sys, "get_int_max_str_digits", lambda: None)()
    if old is not None:
        sys.set_int_max_str_digits(0)
    try:
        return f()
    finally:
        if old is not None:
            sys.set_int_max_str_digits(old)


def test_exact_results_past_4300_digits_come_back_as_fractions():
    # P1 = [-a, a]^3 about the origin, P2 = [-1, 1]^2 x [c - 1, c + 1] about (0, 0, c). P1(r1)
    # reaches z = a r1 and P2(r2) starts at z = c - r2: they touch on a r1 + r2 = c, face on face
    # (slope -a, intercept c), and the growth distance is rho* = c / (a + 1). With a = 1 + 5^-6000
    # and c = 3 + 3^-9100 the common denominators are 13,932 and 14,423 bits (README "Limits":
    # 16,384), and rho* has about 8,540 digits above and below.
    a, c = 1 + F(1, 5**3100), 3 + F(1, 3**4600)  # within 16,384 bits each, as is rho
    rho = c / (a + 1)  # derived here, in Python's own Fractions
    assert min(rho.numerator.bit_length(), rho.denominator.bit_length()) > 4300 * 3.33
    P1 = [[x, y, z] for x in (-a, a) for y in (-a, a) for z in (-a, a)]
    P2 = [[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (c - 1, c + 1)]
    text = lambda q: no_str_limit(lambda: f"{q.numerator}/{q.denominator}")
    # Fractions in (their ints read through bytes), and the same numbers as "p/q" strings.
    for p1, p2 in ((P1, P2), ([[text(v) for v in p] for p in P1], [[text(v) for v in p] for p in P2])):
        s = scalecert.Scene(p1, p2, (F(1, 2), 3), ("1/2", 3))
        cv = s.curve()
        g = cv["growth_distance"]
        assert isinstance(g, F) and g == rho
        assert len(cv["pieces"]) == 1
        assert (cv["pieces"][0]["slope"], cv["pieces"][0]["intercept"]) == (-a, c)
        assert s.seeds()[1] == (0, 0, c)
        q = s.query(rho, rho)
        assert q["verdict"] == scalecert.Verdict.Touching
        assert (q["common_point"]["rho1"], q["common_point"]["rho2"]) == (rho, rho)
        r = s.check_plane(1, 1, [0, 0, 1])  # P1(1) up to z = a, P2(1) from z = c - 1
        assert (r["c1"], r["c2"], r["separates"]) == (a, c - 1, True)


def test_too_large_numbers_are_input_errors():
    # Past 16,384 bits in a numerator or denominator (docs/manual.md "Limits", as for text), an int
    # or Fraction is refused as scalecert.InputError, never a bare ValueError.
    s = stacked()
    for bad in (2**16384, -(2**16384), F(1, 2**16384), F(2**16384 + 1, 3)):
        with pytest.raises(scalecert.InputError, match="16384"):
            s.query(bad, 1)
    with pytest.raises(scalecert.InputError, match="16384 bits"):
        s.query("1e-99990", 1)
    with pytest.raises(scalecert.InputError, match="longer than 100000"):
        s.query("9" * 200000, 1)
    # Within the limit: read exactly, however many digits (the touching line is r1 + r2 = 3).
    assert s.query(2**16383, 1)["verdict"] == scalecert.Verdict.Overlapping
    t = F(1, 3**10000)
    assert s.query(3 - t, t)["verdict"] == scalecert.Verdict.Touching
    assert s.query(3 - t, t / 2)["verdict"] == scalecert.Verdict.Separated


def test_a_fifo_is_refused_not_waited_on(tmp_path):
    # A named pipe with no writer as a scene or mesh file: InputError at once (the read used to
    # wait for a writer forever). In a child process with a timeout, so a regression fails.
    fifo = tmp_path / "p.json"
    os.mkfifo(fifo)
    os.mkfifo(tmp_path / "p.off")
    code = (
        "import scalecert, sys\n"
        "for f in (lambda: scalecert.Scene.load(sys.argv[1] + '/p.json'),\n"
        "          lambda: scalecert.Scene.from_meshes(sys.argv[1] + '/p.off', sys.argv[2], (1, 2), (1, 2))):\n"
        "    try:\n"
        "        f()\n"
        "    except scalecert.InputError as e:\n"
        "        print(e)\n"
    )
    mesh = SRC / "examples" / "tetra.obj"
    out = subprocess.run([sys.executable, "-c", code, str(tmp_path), str(mesh)], capture_output=True, text=True, timeout=30)
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()
    assert lines == [f"{tmp_path}/p.json: is a named pipe (FIFO), not a scene file (only regular files are read)",
                     f"{tmp_path}/p.off: is a named pipe (FIFO), not a mesh file (only regular files are read)"]


def test_certify_arrays_by_hand_and_brute_force(tmp_path):
    # Stacked cubes: P1(r1) = 1 + r1[-1, 1]^3 and P2(r2) = (1, 1, 4) + r2[-1, 1]^3 are axis-aligned
    # boxes: their distance is the norm of the per-axis gaps, and when they overlap the depth is
    # the smallest per-axis overlap (the difference is a box). The arrays as doubles.
    s = stacked()
    r1 = np.array([1.0, 2.0, 1.5, 0.75, 3.0])
    r2 = np.array([0.5, 2.0, 1.5, 0.5, 0.25])

    def brute(a, b):
        lo1, hi1 = [1 - a] * 3, [1 + a] * 3
        lo2, hi2 = [1 - b, 1 - b, 4 - b], [1 + b, 1 + b, 4 + b]
        gaps = [max(0, lo2[c] - hi1[c], lo1[c] - hi2[c]) for c in range(3)]
        over = [min(hi1[c] - lo2[c], hi2[c] - lo1[c]) for c in range(3)]
        return (sum(g * g for g in gaps), min(over) if min(over) > 0 else None)

    truth = [brute(F(a), F(b)) for a, b in zip(r1, r2)]
    d = s.certify("distance", r1, r2, value=[math.sqrt(t[0]) for t in truth], fractions=True)
    assert [x == t[0] for x, t in zip(d["exact_squared"], truth)] == [True] * 5
    assert d["right"].dtype == bool and d["exact"].dtype == np.float64
    assert list(d["exact"]) == [math.sqrt(t[0]) for t in truth]  # sqrt of these exact squares is exact or correctly rounded
    # Depths where they overlap: (2, 2) overlaps by 1 in z; a separated pair's depth claim is wrong.
    p = s.certify("penetration_depth", [2.0, 1.0], [2.0, 1.0], value=[1.0, 0.0], direction=[[0, 0, 1], [0, 0, 1]])
    assert list(p["right"]) == [True, False] and list(p["direction_right"]) == [True, False]
    assert p["exact"][0] == 1.0 and math.isnan(p["exact"][1])
    # One rounded closest point fails only the closest points, not the value.
    c = s.certify("distance", [1.0], [0.5], value=[1.5], closest=np.array([[[1, 1, 2.0000000001], [1, 1, 3.5]]]))
    assert list(c["value_right"]) == [True] and list(c["closest_right"]) == [False] and list(c["right"]) == [False]
    v = s.certify("verdict", r1, r2, verdict="separated")
    assert list(v["right"]) == [a + b < 3 for a, b in zip(r1, r2)]
    # With the judgements certificate, which the independent checker verifies.
    w = s.certify("witness_point", [1.5], [1.5], point=[[1, 1, 2.5]], certificate=True)
    (tmp_path / "w.json").write_text(w["certificate"])
    out = subprocess.run([CHECK, str(tmp_path / "w.json")], capture_output=True, text=True)
    assert w["right"][0] and out.returncode == 0
    # Bad input: one line, InputError.
    with pytest.raises(scalecert.InputError, match="value has 2 rows, rho1 has 5"):
        s.certify("distance", r1, r2, value=[1.0, 2.0])
    with pytest.raises(scalecert.InputError, match="not a finite number"):
        s.certify("distance", [float("nan")], [1.0], value=[1.0])
    with pytest.raises(scalecert.InputError, match="unknown kind"):
        s.certify("area", r1, r2)
    with pytest.raises(scalecert.InputError, match="does not use"):
        s.certify("verdict", r1, r2, verdict="touching", value=r1)


def test_certify_values_beyond_the_doubles():
    # A claimed distance of 10^400 between the stacked cubes at (1, 1) (exactly 1 apart): wrong,
    # with an infinite relative error, not an exception (the report's doubles overflow to null).
    s = stacked()
    r = s.certify("distance", [1], [1], value=["1e400"])
    assert not r["right"][0]
    assert np.isinf(r["rel_error"][0])
    # A depth claimed as 1 where it is about 10^300 (the cubes at (10^300, 1)): relative error 1.
    d = s.certify("penetration_depth", ["1e300"], [1], value=[1])
    assert not d["right"][0]
    assert d["rel_error"][0] == 1.0


def test_region_of_parts_by_hand_and_the_cli(tmp_path):
    # The U and the peg (tests/data/compound_u_peg.json, derived by hand in tests/test_compound.cpp):
    # the bottom meets the peg from r1 + 3 r2 = 6 on, each wall from r2 = 2 r1; the two lines cross
    # at (6/7, 12/7), where the peg touches the bottom and both walls at once.
    U = [box(-3, -1, 0, 3, 1, 1), box(-3, -1, 1, -2, 1, 4), box(2, -1, 1, 3, 1, 4)]
    peg = [box(-1, F(-1, 2), 2, 1, F(1, 2), 5)]
    r = scalecert.Scene.from_parts(U, peg, ("1/2", 2), (F(1, 2), 3), seeds=((0, 0, F(1, 2)), (0, 0, "7/2")))
    assert r.verdict(1, 3) == scalecert.Verdict.Overlapping
    assert r.verdict(F(1, 2), 1) == scalecert.Verdict.Touching          # on the wall's line
    assert r.verdict(F(6, 7), F(12, 7) - F(1, 100)) == scalecert.Verdict.Separated  # below the reflex corner
    assert r.verdict(F(3, 2), F(3, 2)) == scalecert.Verdict.Touching    # the growth set starts at 4 rho = 6
    assert list(r.classify([1.0, 0.5, 2.0], [3.0, 1.0, 1.0])) == [2, 1, 0]
    # Either seed may be None (the mean of that object's points), as for Scene: the peg's mean is its centre.
    assert scalecert.Scene.from_parts(U, peg, ("1/2", 2), (F(1, 2), 3), seeds=((0, 0, F(1, 2)), None)).verdict(F(1, 2), 1) == scalecert.Verdict.Touching
    d = r.region()
    assert [(s["rho1"], s["rho2"], s["change"]) for s in d["switch_points"]] == [("6/7", "12/7", "pair")]
    # The growth set starts where the peg's bottom face (z = 2: its points 0, 2, 4, 6, as box() lists
    # them, z fastest) reaches the bottom's top (z = 1: points 1, 3, 5, 7 of part 0): 4 rho = 6.
    assert [(g["from"], g["to"], g["first_contact"]["contact"]) for g in d["growth_set"]] == [("3/2", "2", "FF")]
    assert d["growth_set"][0]["first_contact"]["features"] == {"P1": [1, 3, 5, 7], "P2": [0, 2, 4, 6]}
    # The band (tests/test_compound.cpp) from rho = 3/2 on: its pair meets on rho1 = rho2 from 9/7, so
    # the growth set starts on the rectangle's edge, already overlapping: no contact there.
    band = scalecert.Scene.from_parts([box(2, -1, -1, 3, 1, 1), box(-3, -1, -1, -2, 1, 1)], [box(4, -1, -1, 5, 1, 1)], ("3/2", 4), (1, 3),
                            seeds=((0, 0, 0), (F(9, 2), 0, 0)))
    g = band.region()["growth_set"]
    assert [(x["from"], x["to"], x["first_contact"]["contact"]) for x in g] == [("3/2", "3", None)]
    # Outside I1 x I2 too: at (3, 1) the bottom, z in [1/2 - 3/2, 1/2 + 3/2], reaches z = 2, the peg's
    # bottom, over x in [-1, 1] (the walls, x in [-9, -6] and [6, 9], stay clear): touching.
    assert r.verdict(3, 1) == scalecert.Verdict.Touching
    assert r.verdict(3, F(99, 100)) == scalecert.Verdict.Separated
    # classify too: pairs outside I1 x I2 are judged one by one, beside those located on the grid
    # (line 410's); the double 0.99 lies below 99/100.
    assert list(r.classify([3.0, 1.0, 3.0], [1.0, 3.0, 0.99])) == [1, 2, 0]
    with pytest.raises(ValueError, match="pair 1 .numbered from 0.: two finite numbers > 0 are required"):
        r.classify([3.0, 3.0], [1.0, 0.0])
    for bad in (["a"], [1 + 2j], [object()]):  # InputError (a ValueError) with one line, not pybind's TypeError
        with pytest.raises(ValueError, match="expected real numbers"):
            r.classify(bad, [1.0])
    with pytest.raises(ValueError, match="flat"):
        scalecert.Scene.from_parts([[[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]], peg, (1, 2), (1, 2)).verdict(1, 1)  # built on first use
    # Golden data on parts (the band, derived by hand in tests/test_cli.cpp): 25 pairs around
    # (23/8, 5/2), the first touching there, and 4 corners; the same bytes as scalecert golden writes.
    g, csv, _ = scalecert.Scene.load(str(SRC / "tests" / "data" / "compound_band.json")).golden()
    assert len(g["queries"]) == 29 and g["queries"][0]["rho2"] == "5/2" and g["queries"][0]["verdict"] == "touching"
    assert csv.count("\n") == 30
    subprocess.run([CLI, "golden", str(SRC / "tests" / "data" / "compound_band.json"), "--dir", str(tmp_path / "g")], check=True)
    assert (tmp_path / "g" / "compound_band.golden.csv").read_text() == csv
    # The scene file through Scene.load and through the command: the same bytes.
    scene = SRC / "tests" / "data" / "compound_u_peg.json"
    loaded = scalecert.Scene.load(str(scene))
    cert = tmp_path / "u.cert.json"
    out = subprocess.run([CLI, "region", str(scene), "--certificate", str(cert)], capture_output=True, text=True, check=True).stdout
    assert json.loads(out) == loaded.region()
    assert cert.read_text() == loaded.partition_json()
    assert subprocess.run([CHECK, str(cert)], capture_output=True).returncode == 0


def test_region_certify_fp_by_hand_and_the_cli(tmp_path):
    # The U and the peg (tests/test_compound.cpp, u_and_peg_claims_judged_by_hand): at (1, 1) the peg
    # is 1 above the bottom and 1 from each wall (separated, distance 1, no plane: the walls rise past
    # the peg's bottom); at (1, 2) its bottom sinks into the U's bottom; at (6/7, 12/7) all three touch.
    scene = SRC / "tests" / "data" / "compound_u_peg.json"
    r = scalecert.Scene.load(str(scene))
    claims = {"format": "scalecert-claims-1", "claims": [
        {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"},
        {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.0},
        {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 1]},
        {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "touching"},
        {"kind": "verdict", "rho1": "6/7", "rho2": "12/7", "verdict": "touching"}]}
    report, cert = r.certify_fp(claims, certificate=True)
    assert [c["right"] for c in report["claims"]] == [True, True, False, False, True]
    assert report["claims"][3]["exact"] == "overlapping"
    # The command gives the same certificate, and scalecert-check accepts it.
    path, out = tmp_path / "claims.json", tmp_path / "cert.json"
    path.write_text(json.dumps(claims))
    p = subprocess.run([CLI, "certify-fp", str(scene), str(path), "--certificate", str(out)], capture_output=True, text=True)
    assert p.returncode == 1  # two claims are wrong
    assert out.read_text() == cert
    assert subprocess.run([CHECK, str(out)], capture_output=True).returncode == 0
    # Claims on convex objects only are refused with one line.
    with pytest.raises(ValueError, match="claim on two convex objects"):
        r.certify_fp({"format": "scalecert-claims-1", "claims": [{"kind": "growth_distance", "value": 1}]})
    # Verdict lines work; curve lines are refused.
    assert r.certify_fp("1 1 separated\n1 2 overlapping\n")["wrong"] == 0
    with pytest.raises(ValueError, match="verdict lines only"):
        r.certify_fp("curve 1 2\n")


def test_a_big_int_is_one_exact_value_through_every_entry_point():
    # Two unit cubes along x, D = 2^53 + 1 apart (seeds their centres): at (1, 1) the distance is D,
    # by hand. As a double, 2^53 + 1 is 2^53: a claim of the int must be judged at the int.
    D = 2**53 + 1
    a, b = box(0, 0, 0, 1, 1, 1), box(1 + D, 0, 0, 2 + D, 1, 1)
    s = scalecert.Scene(a, b, (1, 2), (1, 2))
    r = scalecert.Scene.from_parts([a], [b], (1, 2), (1, 2))
    claim = [{"kind": "distance", "rho1": 1, "rho2": 1, "value": D}]
    assert s.certify("distance", [1], [1], value=[D])["right"].tolist() == [True]
    assert s.certify_fp(claim)["wrong"] == 0
    assert r.certify_fp(claim)["wrong"] == 0
    assert s.certify_fp({"format": "scalecert-claims-1", "claims": claim})["wrong"] == 0
    assert s.certify_fp([{"kind": "distance", "rho1": 1, "rho2": 1, "value": np.int64(2**62)}])["wrong"] == 1
    # The double 2^53 is 1 short of D: wrong through every entry point.
    assert s.certify("distance", [1], [1], value=[float(D)])["right"].tolist() == [False]
    assert s.certify_fp([{"kind": "distance", "rho1": 1, "rho2": 1, "value": float(D)}])["wrong"] == 1
    assert r.certify_fp([{"kind": "distance", "rho1": 1, "rho2": 1, "value": float(D)}])["wrong"] == 1


class BadIndex:
    def __index__(self):
        raise ValueError("no index here")


class BadPath:
    def __fspath__(self):
        raise RuntimeError("no path here")


def test_every_bad_argument_is_an_input_error(tmp_path):
    s, r = stacked(), scalecert.Scene.from_parts([box(0, 0, 0, 2, 2, 2)], [box(0, 0, 3, 2, 2, 5)], (F(1, 2), 2), (F(1, 2), 2))
    bad = [
        lambda: s.classify([2**2000], [1.0]),           # too large for a double (was OverflowError)
        lambda: r.classify([2**2000], [1.0]),
        lambda: s.classify([2**53 + 1], [1]),            # an int that is no double
        lambda: r.classify(np.array([2**53 + 1]), np.array([1])),
        lambda: s.classify([F(1, 3)], [1.0]),            # a Fraction that is no double
        lambda: scalecert.golden("random", 2**70, 1, "1/8", str(tmp_path)),  # (was TypeError)
        lambda: scalecert.golden("random", "3", 1, "1/8", str(tmp_path)),
        lambda: scalecert.golden("random", 1, -1, "1/8", str(tmp_path)),
        lambda: scalecert.golden("random", 1, 2**64, "1/8", str(tmp_path)),
        lambda: scalecert.golden(5, 1, 1, "1/8", str(tmp_path)),
        lambda: scalecert.golden("random", True, 1, "1/8", str(tmp_path)),
        lambda: s.certify(5, [1], [1], verdict="separated"),
        lambda: s.certify("verdict", [1], [1], verdict="separated", certificate="yes"),
        lambda: s.certify_fp("1 1 separated\n", exact_decimals=1),
        lambda: r.certify_fp("1 1 separated\n", certificate=None),
        lambda: scalecert.Scene.load(5),
        lambda: scalecert.Scene.load(None),
        lambda: scalecert.Scene.from_meshes(1, 2, (1, 2), (1, 2)),
        lambda: s.certify_fp([{"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"}] + [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]),
        # text that is not UTF-8 (a lone surrogate), a NUL in a path, an __index__ or __fspath__ that raises
        lambda: scalecert.Scene.load("\udc80x.json"),
        lambda: scalecert.Scene.load("\udc80x.json"),
        lambda: s.certify_fp("1 1 separated\udc80"),
        lambda: s.certify("\udc80", [1], [1]),
        lambda: s.certify("verdict", ["\udc80"], [1], verdict=["separated"]),
        lambda: scalecert.golden("\udc80", 1, 1, "1/10", str(tmp_path)),
        lambda: scalecert.Scene.load(str(SRC / "certificates" / "scenes" / "stacked_cubes.json") + "\0junk"),
        lambda: scalecert.golden("random", BadIndex(), 1, "1/10", str(tmp_path)),
        lambda: scalecert.golden("random", 1, BadIndex(), "1/10", str(tmp_path)),
        lambda: scalecert.Scene.load(BadPath()),
    ]
    for i, f in enumerate(bad):
        with pytest.raises(scalecert.InputError) as e:
            f()
        assert "\n" not in str(e.value), i
    assert not any(tmp_path.iterdir())
    # A path may be an os.PathLike.
    assert scalecert.Scene.load(SRC / "certificates" / "scenes" / "stacked_cubes.json").curve()["growth_distance"] == F(3, 2)


def test_pairs_are_numbered_from_0_in_every_classify():
    s, r = stacked(), scalecert.Scene.from_parts([box(0, 0, 0, 2, 2, 2)], [box(0, 0, 3, 2, 2, 5)], (F(1, 2), 2), (F(1, 2), 2))
    with pytest.raises(scalecert.InputError, match=r"pair 1 \(numbered from 0\)"):
        s.classify([1.0, -1.0], [1.0, 1.0])
    with pytest.raises(scalecert.InputError, match=r"pair 1 \(numbered from 0\)"):
        r.classify([1.0, -1.0], [1.0, 1.0])


def test_region_from_meshes_reads_groups_as_parts(tmp_path):
    # An L of two boxes (foot [0,3]x[0,1]x[0,1], leg [0,1]x[0,1]x[1,3]) and the box [2,3]x[0,1]x[2,3]
    # in its notch: at (1, 1) the box is 1 from each part (separated), but on the L's hull, whose
    # face x + z = 4 holds the box's corner (2, ., 2) (touching). By hand.
    L, B = tmp_path / "L.obj", tmp_path / "B.obj"
    foot, leg = box(0, 0, 0, 3, 1, 1), box(0, 0, 1, 1, 1, 3)
    L.write_text("".join("v %d %d %d\n" % tuple(v) for v in foot + leg) +
                 "g foot\nf 1 2 4 3\nf 5 6 8 7\ng leg\nf 9 10 12 11\nf 13 14 16 15\n")
    B.write_text("".join("v %d %d %d\n" % tuple(v) for v in box(2, 0, 2, 3, 1, 3)) + "f 1 2 4 3\nf 5 6 8 7\n")
    r = scalecert.Scene.from_meshes(L, str(B), ("1/2", 2), ("1/2", 2), parts_from_groups=True)
    assert r.verdict(1, 1) == scalecert.Verdict.Separated
    assert [r.part_name(0, 0), r.part_name(0, 1), r.part_name(1, 0)] == ["foot", "leg", ""]
    with pytest.warns(UserWarning, match="2 groups with faces, read as one convex object"):
        hull = scalecert.Scene.from_meshes(L, B, ("1/2", 2), ("1/2", 2), parts_from_groups=False)
    assert hull.verdict(1, 1) == scalecert.Verdict.Touching
    assert len(hull.notes()) == 1 and hull.notes()[0].startswith(str(L) + ": 2 groups with faces")
    # A mesh of another format has no groups: one convex object under parts_from_groups as without.
    stl = SRC / "examples" / "box.stl"
    plain = scalecert.Scene.from_meshes(stl, stl, (1, 2), (1, 2))
    assert plain.convex and scalecert.Scene.from_meshes(stl, stl, (1, 2), (1, 2), parts_from_groups=True).json() == \
        plain.json()


def test_parts_named_by_groups_and_in_scenes(tmp_path):
    # tests/data/compound_band.obj has the groups `right` and `left`, in that order; read whole it
    # is one hull, with a warning. In a scene file a part's "name" names it; an empty or repeated
    # name, or one that is no string, is refused naming the field. The band's right part is the
    # one that meets P2's box (tests/test_compound.cpp), so the region names it "right".
    obj = SRC / "tests" / "data" / "compound_band.obj"
    s = scalecert.Scene.from_meshes(obj, obj, (1, 2), (1, 2), parts_from_groups=True)
    assert [s.part_name(i, k) for i in (0, 1) for k in (0, 1)] == ["right", "left", "right", "left"]
    assert s.notes() == []
    with pytest.raises(scalecert.InputError, match="has no part 2"):
        s.part_name(0, 2)
    with pytest.raises(scalecert.InputError, match="i: expected an int from 0 to 1"):
        s.part_name(2, 0)
    with pytest.warns(UserWarning) as said:
        whole = scalecert.Scene.from_meshes(obj, obj, (1, 2), (1, 2))
    assert [str(w.message) for w in said] == whole.notes() and len(whole.notes()) == 2
    assert whole.convex and whole.part_name(0, 0) == ""
    g = scalecert.Scene.load(SRC / "tests" / "data" / "compound_band_groups.json")
    assert g.region()["pair_regions"][0]["P1_part_name"] == "right"
    sc = json.loads((SRC / "tests" / "data" / "compound_band.json").read_text())
    sc["P1"]["parts"][0]["name"] = "right"
    named = tmp_path / "named.json"
    named.write_text(json.dumps(sc))
    n = scalecert.Scene.load(named)
    assert (n.part_name(0, 0), n.part_name(0, 1)) == ("right", "")
    assert json.loads(n.json())["P1"]["parts"][0]["name"] == "right"
    assert "name" not in json.loads(n.json())["P1"]["parts"][1]
    # Judgements name the part pair they rest on: at (1, 2) the right part [2, 3] is 1/2 from the
    # box [7/2, 11/2] (the left part, [-3, -2], is 11/2 away); at (2, 2) the right part [4, 6] meets
    # the box [7/2, 11/2]; at (1, 1), [2, 3] and [4, 5], nothing meets.
    d = n.certify("distance", [1.0], [2.0], value=[0.5])
    assert d["right"].tolist() == [True] and d["exact_parts"].tolist() == [[0, 0]]
    assert d["exact_part_names"] == [("right", "")]
    v = n.certify("verdict", [2.0, 1.0], [2.0, 1.0], verdict="overlapping")
    assert v["right"].tolist() == [True, False] and v["exact_parts"].tolist() == [[0, 0], [-1, -1]]
    assert "exact_parts" not in scalecert.Scene.load(SRC / "certificates" / "scenes" / "stacked_cubes.json").certify(
        "verdict", [1.0], [1.0], verdict="separated")
    for name, msg in ((" ", None), ("", "an empty name"), (3, "expected a string"), ("right", "names P1.parts.0. too")):
        sc["P1"]["parts"][1]["name"] = name
        named.write_text(json.dumps(sc))
        if msg is None:
            assert scalecert.Scene.load(named).part_name(0, 1) == " "
        else:
            with pytest.raises(scalecert.InputError, match="P1.parts.1..name: .*" + msg):
                scalecert.Scene.load(named)


def test_region_certify_over_arrays_by_hand():
    # The band (tests/test_compound.cpp): at (1, 2) its right part spans x in [2, 3] and the box
    # [7/2, 11/2], 1/2 apart along x; at (2, 2) the right part spans [4, 6] and holds (5, 0, 0).
    band = scalecert.Scene.from_parts([box(2, -1, -1, 3, 1, 1), box(-3, -1, -1, -2, 1, 1)], [box(4, -1, -1, 5, 1, 1)], (1, 4), (1, 3),
                            seeds=((0, 0, 0), (F(9, 2), 0, 0)))
    d = band.certify("distance", [1.0, 1.0], [2.0, 2.0], value=[0.5, 0.25],
                     closest=[[[3, 0, 0], [3.5, 0, 0]], [[3, 0, 0], [3.5, 1, 0]]], fractions=True)
    assert list(d["right"]) == [True, False]
    assert list(d["value_right"]) == [True, False]
    assert list(d["closest_right"]) == [True, False]  # the second pair is 1/2 apart in x and 1 in y
    assert list(d["exact"]) == [0.5, 0.5] and d["exact_squared"] == [F(1, 4), F(1, 4)]
    v = band.certify("verdict", [F(7, 6), 2, 3, F(7, 6)], [2, 2, 2, 2], verdict=["touching", "overlapping", "overlapping", "intersecting"])
    assert list(v["right"]) == [True, True, False, True]  # intersecting: overlapping or touching
    assert v["exact_verdict"] == ["touching", "overlapping", "separated", "touching"]
    w = band.certify("witness_point", [2, 1], [2, 2], point=[[5, 0, 0], [5, 0, 0]])
    assert list(w["right"]) == [True, False]  # at rho1 = 1 the right part ends at x = 3
    p = band.certify("separating_plane", [1, 1], [2, 2], normal=[[1, 0, 0], [1, 0, 0]], offset=["13/4", 4], certificate=True)
    assert list(p["right"]) == [True, False] and p["wrong"] == 1
    assert json.loads(p["certificate"])["kind"] == "compound_judgements"
    # A numpy scalar or 0-d array where a list is expected: an InputError like a float's.
    for scalar in (1.0, np.float64(1.0), np.array(1.0)):
        with pytest.raises(scalecert.InputError, match="rho1: expected a list"):
            band.certify("verdict", scalar, np.float64(1.0), verdict="separated")
    with pytest.raises(scalecert.InputError, match="parts: missing: a penetration depth on objects made of parts"):
        band.certify("penetration_depth", [2], [2], value=[1])


def test_outputs_that_are_no_answer_are_wrong_claims(tmp_path):
    # CLAIMS.md, "Outputs that are no answer", by hand on the stacked cubes: at (1, 1/2) they are
    # 3/2 apart. A NaN distance, an infinite coordinate, a zero normal: each wrong with its reason,
    # the right claim beside them judged as usual; a certificate the checker accepts.
    s = stacked()
    d = s.certify("distance", [1.0, 1.0, 1.0], [0.5, 0.5, 0.5], value=[1.5, float("nan"), 1.5],
                  closest=[[[1, 1, 2], [1, 1, 3.5]], [[1, 1, 2], [1, 1, 3.5]], [[1, 1, 2], [1, 1, float("inf")]]],
                  certificate=True)
    assert list(d["right"]) == [True, False, False] and d["wrong"] == 2
    assert d["reason"] == ["", "value: not a number", "closest: not a number"]
    (tmp_path / "d.json").write_text(d["certificate"])
    assert subprocess.run([CHECK, str(tmp_path / "d.json")], capture_output=True).returncode == 0
    p = s.certify("separating_plane", [1.0], [0.5], normal=[[0, 0, 0]])
    assert not p["right"][0] and p["reason"] == ["normal: the zero vector"]
    # Through certify_fp: json.dumps writes NaN, which is read as no answer.
    r = s.certify_fp([{"kind": "distance", "rho1": 1, "rho2": 0.5, "value": float("nan")},
                      {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5}])
    assert [c["right"] for c in r["claims"]] == [False, True] and r["claims"][0]["no_answer"] == "value"
    # An empty batch is judged: 0 claims.
    assert s.certify_fp([])["wrong"] == 0 and len(s.certify("verdict", [], [], verdict="separated")["right"]) == 0


def test_absolute_tolerance_on_points_and_values():
    # CLAIMS.md, "Tolerances": on the stacked cubes P1(1) = [0, 2]^3 and P2(1/2) = [0, 2]^2 x
    # [7/2, 9/2] are 3/2 apart. Closest points 0.9e-9 outside their faces (as doubles, within
    # 1e-9 of them), 1.5 - 1.8e-9 apart: wrong exactly, right within 1e-9; 2e-9 outside: wrong
    # within 1e-9 too. The same through the typed arrays on the band of parts: at (4/3, 1) P1's
    # right box is [8/3, 4] x [-4/3, 4/3]^2 and P2 is [4, 5] x [-1, 1]^2, touching at x = 4.
    from fractions import Fraction as F
    closest = np.array([[[1, 1, 2 + 0.9e-9], [1, 1, 3.5 - 0.9e-9]], [[1, 1, 2 + 2e-9], [1, 1, 3.5]]])
    for abs_tol, want in [(0, [False, False]), (F(1, 10**9), [True, False])]:
        r = stacked().certify("distance", [1, 1], [0.5, 0.5], value=[1.5, 1.5], closest=closest,
                              abs_tolerance=abs_tol)
        assert list(r["right"]) == want
    band = scalecert.Scene.load(str(SRC / "tests" / "data" / "compound_band.json"))
    r = band.certify("witness_point", [F(4, 3), F(4, 3)], [1, 1],
                     point=np.array([[4 + 0.9e-9, 0, 0], [4 + 3e-9, 0, 0]]), abs_tolerance="1e-9")
    assert list(r["right"]) == [True, False]
    r = band.certify("distance", [1, 1], [1, 1], value=[1 - 0.9e-9, 1 - 3e-9], abs_tolerance="1e-9")
    assert list(r["right"]) == [True, False]
    with pytest.raises(scalecert.InputError, match="abs_tolerance: must be >= 0"):
        stacked().certify_fp('{"format": "scalecert-claims-1", "claims": []}', abs_tolerance=-1)


def test_numbers_mean_what_the_program_held(tmp_path):
    # 0.1 as a double is 3602879701896397/2^55; as a float32 13421773/2^27 (0.1 * 2^27 =
    # 13421772.8 rounds up); as written 1/10. On the stacked cubes (touching on rho1 + rho2 = 3),
    # (0.1, 2.9) is separated as doubles, overlapping as floats (2.9f = 12163482/2^22, the sum
    # 3 + 13/2^27) and touching as decimals.
    assert F(0.1) == F(3602879701896397, 2**55)
    want = {"double": "separated", "float32": "overlapping", "exact": "touching"}
    for numbers, verdict in want.items():
        r = stacked().certify("verdict", [0.1], [2.9], verdict=verdict, numbers=numbers)
        assert r["right"].tolist() == [True], numbers
        text = stacked().certify_fp("0.1 2.9 " + verdict + "\n", numbers=numbers)
        assert text["wrong"] == 0, numbers
    assert stacked().certify_fp("0.1 2.9 touching\n", exact_decimals=True)["wrong"] == 0  # the earlier name
    # A scene made under a reading reads the rho it is asked about the same way, unless a call says
    # otherwise; classify takes doubles (or floats), so a scene of exact decimals refuses it.
    code = {"separated": scalecert.Verdict.Separated, "overlapping": scalecert.Verdict.Overlapping,
            "touching": scalecert.Verdict.Touching}
    for numbers, verdict in want.items():
        s = scalecert.Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), ("1/2", "5/2"), (F(1, 2), 2.5),
                            numbers=numbers)
        assert s.verdict(0.1, 2.9) == code[verdict], numbers
        assert s.query(0.1, 2.9)["verdict"] == code[verdict], numbers
        assert s.certify("verdict", [0.1], [2.9], verdict=verdict)["right"].tolist() == [True], numbers
        assert s.certify_fp("0.1 2.9 " + verdict + "\n")["wrong"] == 0, numbers
        assert s.certify("verdict", [0.1], [2.9], verdict="separated", numbers="double")["right"].tolist() == [True]
        if numbers == "exact":
            with pytest.raises(scalecert.InputError, match="classify: takes the doubles"):
                s.classify(np.array([0.1]), np.array([2.9]))
        else:
            assert s.classify(np.array([0.1]), np.array([2.9])).tolist() == [int(code[verdict])], numbers
    with pytest.raises(scalecert.InputError, match="numbers: expected 'double', 'float32' or 'exact'"):
        stacked().certify("verdict", [1], [1], verdict="separated", numbers="half")
    # Meshes and scenes: a decimal is read the same way, and the scene says how many were not
    # read as written (a UserWarning).
    (tmp_path / "t.off").write_text("OFF\n4 0 0\n0.1 0 0\n1 0 0\n0 1 0\n0 0 1\n")
    (tmp_path / "c.off").write_text("OFF\n8 0 0\n5 0 0\n6 0 0\n5 1 0\n6 1 0\n5 0 1\n6 0 1\n5 1 1\n6 1 1\n")
    tenth = {"double": F(0.1), "float32": F(13421773, 2**27), "exact": F(1, 10)}
    for numbers, x in tenth.items():
        import warnings
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            s = scalecert.Scene.from_meshes(str(tmp_path / "t.off"), str(tmp_path / "c.off"), ("1/2", 2), ("1/2", 2),
                                            numbers=numbers)
        assert s.json().count('"' + str(x.numerator) + "/" + str(x.denominator) + '"') == 1
        assert len([m for m in w if "1 number written as decimals" in str(m.message)]) == (numbers != "exact")
        # A float given in Python is read the same way.
        p = scalecert.Scene([[0.1, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [[5, 0, 0], [6, 0, 0], [5, 1, 0], [5, 0, 1]],
                            ("1/2", 2), ("1/2", 2), numbers=numbers)
        assert p.json() == scalecert.Scene([[x, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                                           [[5, 0, 0], [6, 0, 0], [5, 1, 0], [5, 0, 1]], ("1/2", 2), ("1/2", 2)).json()


def test_hex_floats_and_scenes_without_ranges():
    # Without I1, I2 the objects are as they are: [0,2]^3 and [0,2]^2 x [2,4] touch at (1, 1), on
    # rho1 + rho2 = 2. A hex float string is exact: "0x1.8p-1" = 3/4, so (3/4, 5/4) touches too, and
    # (3/4, 0x1.4000000000001p0) = (3/4, 5/4 + 2^-52) overlaps.
    s = scalecert.Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 2, 2, 2, 4))
    assert s.verdict(1, 1) == scalecert.Verdict.Touching
    assert s.verdict("0x1.8p-1", "0x1.4p0") == scalecert.Verdict.Touching
    assert s.verdict("0x1.8p-1", "0x1.4000000000001p0") == scalecert.Verdict.Overlapping
    assert json.loads(s.json())["I1"] == ["1", "1"]
    with pytest.raises(scalecert.InputError, match="'0x1.8q0' is not an exact number"):
        s.verdict("0x1.8q0", 1)


def test_float32_overflow_is_no_answer():
    # 1e39 is beyond the float32 range (about 3.4e38): a float32 program held an infinity, so the
    # claim is no answer (wrong), and the rest of the batch is judged.
    r = stacked().certify("distance", [1, 1], [1, "1/2"], value=[1e39, 1.5], numbers="float32")
    assert r["right"].tolist() == [False, True]


def test_meshes_at_poses(tmp_path):
    # The tall box [0,2]^2 x [3,7] turned a quarter about y and moved by (-3, 0, 5) is
    # [0,4] x [0,2] x [3,5]: touching the cube [0,2]^3 on rho1 + rho2 = 3 (unposed: rho1 + 2 rho2 = 4).
    (tmp_path / "cube.obj").write_text("".join(f"v {x} {y} {z}\n" for x in (0, 2) for y in (0, 2) for z in (0, 2)))
    (tmp_path / "tall.obj").write_text("".join(f"v {x} {y} {z}\n" for x in (0, 2) for y in (0, 2) for z in (3, 7)))
    pose = np.array([[0, 0, 1, -3], [0, 1, 0, 0], [-1, 0, 0, 5]], dtype=float)
    args = (str(tmp_path / "cube.obj"), str(tmp_path / "tall.obj"), ("1/2", 2), ("1/2", 2))
    assert scalecert.Scene.from_meshes(*args).verdict(1, F(3, 2)) == scalecert.Verdict.Touching
    posed = scalecert.Scene.from_meshes(*args, poses=(None, pose))
    assert posed.verdict(1, F(3, 2)) == scalecert.Verdict.Separated
    assert posed.verdict(1, 2) == scalecert.Verdict.Touching
    assert posed.seeds()[1] == (2, 1, 4)
    # A seed given in the mesh's frame moves with it: (1/2, 1, 5) inside the tall box goes to
    # (2, 1, 9/2) inside the moved box, so P2(rho2) reaches down to z = 9/2 - 3 rho2 / 2 and meets
    # P1's top 1 + rho1 on 2 rho1 + 3 rho2 = 7: touching at (1/2, 2) (apart about the default seed).
    seeded = scalecert.Scene.from_meshes(*args, poses=(None, pose), seeds=(None, (F(1, 2), 1, 5)))
    assert seeded.seeds()[1] == (2, 1, F(9, 2)) and seeded.seeds()[0] == (1, 1, 1)
    assert seeded.verdict(F(1, 2), 2) == scalecert.Verdict.Touching
    assert posed.verdict(F(1, 2), 2) == scalecert.Verdict.Separated
    with pytest.raises(scalecert.InputError, match=r"seeds\[1\]"):
        scalecert.Scene.from_meshes(*args, seeds=(None, (0, 1)))
    with pytest.raises(scalecert.InputError, match=r"poses\[1\]\[0\]: expected 4 numbers"):
        scalecert.Scene.from_meshes(*args, poses=(None, [[1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]))


def test_contacts_on_parts():
    # The U and peg (tests/data/compound_u_peg.json): at (1, 2) the peg [-2,2] x [-1,1] x [1/2,13/2]
    # sinks 1/2 into the U's bottom part 0 ([-3,3] x [-1,1] x [0,1]; along +z) and touches the arm
    # part 1 ([-3,-2] in x; depth 0); at (3/2, 2) that arm is apart and the bottom reaches z = 5/4
    # (depth 3/4). A contact is a penetration depth with its part pair.
    s = scalecert.Scene.load(str(SRC / "tests" / "data" / "compound_u_peg.json"))
    r = s.certify("penetration_depth", [1, 1, 1.5, 1.5], [2, 2, 2, 2], value=[0.5, 0, 0, 0.75],
                  parts=np.array([[0, 0], [1, 0], [1, 0], [0, 0]]), certificate=True)
    assert r["right"].tolist() == [True, True, False, True]
    assert r["exact"][[0, 1, 3]].tolist() == [0.5, 0.0, 0.75]
    assert np.isnan(r["exact"][2])  # apart: no depth
    r = s.certify("penetration_depth", [1], [2], value=[0.5], parts=[[0, 0]], direction=[[1, 0, 0]])
    assert r["right"].tolist() == [False] and r["value_right"].tolist() == [True]  # along x it is 5
    with pytest.raises(scalecert.InputError, match=r"parts: missing"):
        s.certify("penetration_depth", [1], [2], value=[0.5])
    with pytest.raises(scalecert.InputError, match=r"parts\[0\]: P1 has 3 parts"):
        s.certify("penetration_depth", [1], [2], value=[0.5], parts=[[3, 0]])
    text = s.certify_fp({"format": "scalecert-claims-1", "claims": [
        {"kind": "penetration_depth", "rho1": 1.5, "rho2": 2, "parts": [0, 0], "value": 0.75}]})
    assert text["wrong"] == 0


def test_claims_at_poses(tmp_path):
    # The stacked cubes (touching on rho1 + rho2 = 3) with P2 turned a quarter about the vertical
    # line through (1, 1): [R | t] = [[0,-1,0,2],[1,0,0,0],[0,0,1,0]] maps P2 onto itself, so each
    # claim is judged as unposed; lifted by 1 more (t3 = 1), (1, 2) is separated and (1, 1) is 2
    # apart. A pose of doubles: P1 turned 30 degrees about z keeps its z extent (R's third row is
    # exactly (0, 0, 1)), so it still touches P2 on rho1 + rho2 = 3.
    s = stacked()
    quarter = np.array([[0, -1, 0, 2], [1, 0, 0, 0], [0, 0, 1, 0]], dtype=float)
    lifted = quarter.copy()
    lifted[2, 3] = 1
    r = s.certify("verdict", [1, 1], [2, 2], verdict="touching", pose2=np.stack([quarter, lifted]),
                  certificate=True)
    assert r["right"].tolist() == [True, False] and r["exact_verdict"] == ["touching", "separated"]
    (tmp_path / "posed.json").write_text(r["certificate"])
    out = subprocess.run([CHECK, str(tmp_path / "posed.json")], capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    d = s.certify("distance", [1, 1], [1, 1], value=[1, 2], pose2=np.stack([quarter, lifted]))
    assert d["right"].tolist() == [True, True]
    c, n = math.cos(math.pi / 6), math.sin(math.pi / 6)
    turned = np.array([[c, -n, 0, 1 - c + n], [n, c, 0, 1 - n - c], [0, 0, 1, 0]])  # about (1, 1)
    t = s.certify("verdict", [1, 1.5], [2, 1.5], verdict="touching", pose1=np.stack([turned, turned]))
    assert t["right"].tolist() == [True, True]
    with pytest.raises(scalecert.InputError, match=r"pose1: its 3x3 part R is singular"):
        s.certify("verdict", [1], [2], verdict="touching", pose1=np.zeros((1, 3, 4)))


def test_claims_at_poses_on_parts():
    # The U and peg lifted by 10 (CLAIMS.md, "Poses"): at (1, 2) the peg starts at z = 21/2, 13/2
    # above the arms' tops; lowered by 1/4 it sinks 3/4 into the bottom part.
    s = scalecert.Scene.load(str(SRC / "tests" / "data" / "compound_u_peg.json"))
    up = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 10]], dtype=float)
    down = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -0.25]])
    assert s.certify("distance", [1], [2], value=[6.5], pose2=[up])["right"].tolist() == [True]
    d = s.certify("penetration_depth", [1], [2], value=[0.75], parts=[[0, 0]], pose2=[down])
    assert d["right"].tolist() == [True]


def test_audit_your_own_collision_test():
    # The stacked cubes' gap along z is 3 - r1 - r2: a test that answers from it exactly is never
    # wrong; one that adds the doubles (r1 + r2 < 3: separated, else intersecting) is wrong where
    # the rounded sum and the exact one fall on different sides of 3, counted here by hand.
    s = stacked()

    def by_gap(r1, r2):
        gaps = [3 - F(a) - F(b) for a, b in zip(r1, r2)]
        return ["separated" if g > 0 else "touching" if g == 0 else "overlapping" for g in gaps]

    def by_sum(r1, r2):
        return ["separated" if a + b < 3 else "intersecting" for a, b in zip(r1, r2)]

    exact = s.audit(by_gap)
    assert exact["wrong"] == 0 and exact["failures"] == [] and exact["right"].all()
    pairs = {(q["rho1_double"], q["rho2_double"]) for q in s.golden()[0]["queries"]}
    assert exact["queries"] == len(pairs)
    rounded = s.audit(by_sum)
    hand = [(a, b) for a, b in pairs if (a + b < 3) != (3 - F(a) - F(b) > 0)]
    assert hand and rounded["wrong"] == len(hand)
    # Each is a separated pair whose rounded sum reached 3: said intersecting.
    assert rounded["false_overlapping"] == len(hand) and rounded["false_separated"] == 0
    assert {(f["rho1"], f["rho2"]) for f in rounded["failures"]} == set(hand)
    assert all(f["said"] == "intersecting" and f["exact"] == "separated" for f in rounded["failures"])
    # Pairs of one's own; "overlapping" at a touching pair is wrong, "intersecting" right (CLAIMS.md).
    mine = s.audit(lambda r1, r2: ["overlapping", "intersecting"], rho1=[1.0, 1.0], rho2=[2.0, 2.0])
    assert list(mine["right"]) == [False, True] and mine["exact_verdict"] == ["touching", "touching"]
    assert mine["false_overlapping"] == 1 and mine["wrong"] == 1
    # "touching" where the gap 3 - r1 - r2 is 1 (apart) and -1 (overlapping): both wrong, counted as such.
    touch = s.audit(lambda r1, r2: ["touching"] * 3, rho1=[1.0, 2.0, 1.0], rho2=[1.0, 2.0, 2.0])
    assert list(touch["right"]) == [False, False, True] and touch["false_touching"] == 2 == touch["wrong"]
    # Answers that are no answer are wrong and counted; a wrong number of answers is bad input.
    none = s.audit(lambda r1, r2: [None, float("nan"), "yes"], rho1=[1.0, 1.0, 1.0], rho2=[1.0, 2.0, 3.0])
    assert none["wrong"] == none["no_answer"] == 3 and none["failures"][1]["said"] == "no answer: nan"
    odd = s.audit(lambda r1, r2: ["\udcff"], rho1=[1.0], rho2=[1.0])  # not UTF-8: no answer, not an error
    assert odd["no_answer"] == 1 and odd["failures"][0]["said"] == "no answer: '\\udcff'"
    with pytest.raises(scalecert.InputError, match="^audit: rho1"):
        s.audit(by_sum, rho1=["a"], rho2=[1.0])
    with pytest.raises(scalecert.InputError, match="returned 1 answers for 3 pairs"):
        s.audit(lambda r1, r2: ["separated"], rho1=[1.0, 1.0, 1.0], rho2=[1.0, 2.0, 3.0])
    with pytest.raises(scalecert.InputError, match="finite numbers > 0"):
        s.audit(by_sum, rho1=[1.0], rho2=[float("nan")])
    # A dict or a set of the right length is no sequence of answers: bad input, as a generator is.
    for shaped in (lambda r1, r2: {0: "separated"}, lambda r1, r2: {"separated"}, lambda r1, r2: (w for w in "a")):
        with pytest.raises(scalecert.InputError, match="returned no sequence for 1 pairs"):
            s.audit(shaped, rho1=[1.0], rho2=[1.0])
    # A long double that is not a double (0.1 as a long double) is refused as a Fraction is; one
    # that is a double exactly (0.5) is that double.
    if np.finfo(np.longdouble).nmant > 52:
        with pytest.raises(scalecert.InputError, match=r"rho1\[0\]: .* is not a double"):
            s.audit(by_sum, rho1=np.array([np.longdouble(1) / 10]), rho2=[1.0])
        half = s.audit(by_sum, rho1=np.array([0.5], dtype=np.longdouble), rho2=[1.0])
        assert half["queries"] == 1 and half["wrong"] == 0
    # The user's own exception is theirs, unchanged.
    with pytest.raises(ZeroDivisionError):
        s.audit(lambda r1, r2: 1 / 0)


def test_judge_mujoco_and_the_testing_helpers(tmp_path):
    # boxes.xml (tests/test_mujoco.cpp works it out by hand): the floor [-1,1]^2 x [-1,0] and a cube
    # of half-extent 1/2; at z = 2 they are 3/2 apart, at z = 1/2 touching, at (1/4, 0, 3/8) 1/8 deep.
    model = str(SRC / "tests/data/mujoco/boxes.xml")
    rows = [r.split() for r in (SRC / "tests/data/mujoco/boxes.qpos").read_text().splitlines()
            if r.strip() and not r.startswith("#")]
    qpos = np.array([[float(x) for x in r] for r in rows])
    r = scalecert.judge_mujoco(model, qpos)
    exact = [next(p for p in f["pairs"] if p["names"] == ["floor", "cube"])["signed_distance"].get("exact")
             for f in r["frames"]]
    assert exact == [None, "0", "-0.125"]  # 3/2 apart: decided by the boxes, with no exact distance
    # The same report as the command's, from the same MuJoCo.
    out = subprocess.run([CLI, "mujoco", model, "--qpos", str(SRC / "tests/data/mujoco/boxes.qpos"), "--json"],
                         capture_output=True, text=True)
    cli = json.loads(out.stdout)
    assert [f["pairs"] for f in cli["frames"]] == [f["pairs"] for f in r["frames"]]
    assert r["summary"]["wrong_pairs"] == cli["summary"]["wrong_pairs"] > 0
    # The pytest gate: an AssertionError naming each wrong judgement, with its state.
    import scalecert.testing as sct  # the submodule imports by its dotted name too
    with pytest.raises(AssertionError, match="MuJoCo was wrong at .* pair state") as e:
        sct.assert_mujoco(model, qpos, failures=str(tmp_path / "repro"))
    assert "WRONG  state 2 (qpos[2])" in str(e.value)  # MuJoCo's dist -1/16 where the depth is 1/8
    assert "reproducers" in str(e.value) and any((tmp_path / "repro").iterdir())
    sct.assert_mujoco(model, qpos[:1])  # 3/2 apart, no contact: right
    with pytest.raises(scalecert.InputError, match=r"qpos\[0\]: 2 numbers; the model's qpos has 21"):
        scalecert.judge_mujoco(model, [[0, 0]])
    with pytest.raises(scalecert.InputError, match="keyframe 0: the model has 0 keyframes"):
        scalecert.judge_mujoco(model, key=0)
    # Bad rows are input errors, not a crash or a wrong cast: past the doubles, bytes, complex.
    g = [0, 0, 2, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0]
    for bad, why in [([g[:-1] + [10**400]], "not rows of numbers a double holds"), ([bytes(21)], "not bytes"),
                     ([g[:-1] + [np.complex128(1)]], "expected real numbers"), ([g[:-1] + [True]], "expected real")]:
        with pytest.raises(scalecert.InputError, match=why):
            scalecert.judge_mujoco(model, bad)
    with pytest.raises(scalecert.InputError, match="failures: an empty path"):
        scalecert.judge_mujoco(model, failures="")
    with pytest.raises(scalecert.InputError, match="scene: expected a scalecert.Scene"):
        sct.assert_claims(None, "1 1 separated\n")
    # A gate that judged nothing fails: a model of two cylinders (not judged), no claims.
    spheres = tmp_path / "cylinders.xml"
    spheres.write_text('<mujoco><worldbody><geom type="cylinder" size="1 1"/><body><freejoint/>'
                       '<geom type="cylinder" size="1 1"/></body></worldbody></mujoco>')
    with pytest.raises(AssertionError, match="nothing of the model was judged"):
        sct.assert_mujoco(str(spheres))
    with pytest.raises(AssertionError, match="no claims to judge"):
        sct.assert_claims(stacked(), "")
    # Claims: on the stacked cubes (touching on rho1 + rho2 = 3), (2, 2) overlaps.
    sct.assert_claims(stacked(), "1 1 separated\n")
    with pytest.raises(AssertionError, match="1 of 2 claims wrong") as e:
        sct.assert_claims(stacked(), "1 1 separated\n2 2 not_overlapping\n")
    assert "WRONG  (2, 2) claimed not_overlapping: exact overlapping" in str(e.value)


def mujoco_arrays(model, qpos_file):
    """MuJoCo's arrays for a model at each qpos line, produced by Debian's libmujoco
    (tests/adapters/mujoco_arrays.cpp), as objects with the attributes and dtypes of MuJoCo's Python
    bindings' MjModel and MjData (mesh_vert float32, ids int32, names bytes)."""
    from types import SimpleNamespace as NS
    tool = Path(CLI).parent / "tests" / "mujoco_arrays"
    if not tool.exists():
        pytest.skip("built without MuJoCo")
    j = json.loads(subprocess.run([str(tool), model, qpos_file], capture_output=True, text=True, check=True).stdout)
    m = j["model"]
    ints = {k for k, v in m.items() if isinstance(v, list) and all(isinstance(x, int) for x in v)} - {
        "geom_size", "geom_margin", "geom_gap", "pair_margin", "pair_gap"}
    fields = {k: (np.array(v, dtype=np.int32) if k in ints else np.array(v, dtype=np.float64))
              for k, v in m.items() if isinstance(v, list)}
    fields["mesh_vert"] = np.array(m["mesh_vert"], dtype=np.float32).reshape(-1, 3)
    fields["geom_size"] = fields["geom_size"].reshape(-1, 3)
    model_obj = NS(nq=m["nq"], names=m["names"].encode("latin-1"), opt=NS(**m["opt"]), **fields)
    datas = []
    for d in j["data"]:
        c = d["contact"]
        contact = NS(geom1=np.array(c["geom1"], dtype=np.int32), geom2=np.array(c["geom2"], dtype=np.int32),
                     exclude=np.array(c["exclude"], dtype=np.int32), dist=np.array(c["dist"]),
                     includemargin=np.array(c["includemargin"]), pos=np.array(c["pos"]).reshape(-1, 3),
                     frame=np.array(c["frame"]).reshape(-1, 9))
        datas.append(NS(qpos=np.array(d["qpos"]), geom_xpos=np.array(d["geom_xpos"]).reshape(-1, 3),
                        geom_xmat=np.array(d["geom_xmat"]).reshape(-1, 9), ncon=d["ncon"], contact=contact))
    return model_obj, datas


def test_judge_mujoco_held_reads_mujocos_own_arrays():
    # The arrays a program holds in MuJoCo's Python bindings, read by their attribute names, judge
    # as the model file does at the same qpos: on boxes.xml (worked by hand in tests/test_mujoco.cpp:
    # 3/2 apart, touching with a contact at S = 0 = the margin, 1/8 deep) and the finger.
    for name in ["boxes", "panda_finger_cube"]:
        xml, qpos = str(SRC / f"tests/data/mujoco/{name}.xml"), str(SRC / f"tests/data/mujoco/{name}.qpos")
        model, datas = mujoco_arrays(xml, qpos)
        held = scalecert.judge_mujoco_held(model, datas, abs_tolerance="1e-9" if name != "boxes" else 0)
        rows = np.loadtxt(qpos, ndmin=2)
        fromfile = scalecert.judge_mujoco(xml, rows, abs_tolerance="1e-9" if name != "boxes" else 0)
        assert held["summary"] == fromfile["summary"]
        assert [f["pairs"] for f in held["frames"]] == [f["pairs"] for f in fromfile["frames"]]
        assert held["summary"]["judgements"] > 0
    # On boxes the 1/8-deep state is the one wrong pair state (MuJoCo's dist is -1/16), named by its
    # data index; the touching state's contact, at S = 0 = the margin, is right.
    model, datas = mujoco_arrays(str(SRC / "tests/data/mujoco/boxes.xml"), str(SRC / "tests/data/mujoco/boxes.qpos"))
    assert scalecert.judge_mujoco_held(model, datas[1])["summary"]["wrong_pairs"] == 0
    r = scalecert.judge_mujoco_held(model, datas[2])
    assert r["summary"]["wrong_pairs"] == 1
    names = [p["names"] for p in r["frames"][0]["pairs"]]
    assert ["floor", "cube"] in names  # names from MjModel.names and name_geomadr
    # The pytest gate on held arrays: right at 3/2 apart and touching, wrong (naming the state) 1/8 deep.
    import scalecert.testing as sct
    sct.assert_mujoco_held(model, datas[0])
    sct.assert_mujoco_held(model, datas[1])
    with pytest.raises(AssertionError, match=r"WRONG  state 0 \(data\[0\]\): 'floor' and 'cube'"):
        sct.assert_mujoco_held(model, datas[2])
    # What does not fit MuJoCo's fields is an InputError naming the field.
    bad = lambda **kw: type(model)(**{**vars(model), **kw})
    for m, why in [(bad(geom_size=model.geom_size[:-1]), "geom_size"),
                   (bad(mesh_vert=model.mesh_vert.astype(np.float64) + 1e-12), "not a float32"),
                   (bad(geom_bodyid=model.geom_bodyid + 50), r"geom_bodyid\[0\]"),
                   (bad(geom_type=np.array(["box"] * len(model.geom_type))), "expected numbers")]:
        with pytest.raises(scalecert.InputError, match=why):
            scalecert.judge_mujoco_held(m, datas[0])
    nodata = type(datas[0])(**{k: v for k, v in vars(datas[0]).items() if k != "geom_xmat"})
    with pytest.raises(scalecert.InputError, match="data.geom_xmat: missing"):
        scalecert.judge_mujoco_held(model, nodata)


def test_the_pytest_gate_example_in_the_docs(tmp_path):
    # docs/library.md, "Gates in pytest and GoogleTest": its two tests, as written there.
    text = (SRC / "docs/library.md").read_text()
    code = text.split("```python\n", 1)[1].split("```", 1)[0]
    namespace = {}
    cwd = os.getcwd()
    os.chdir(SRC)
    try:
        exec(code, namespace)
        namespace["test_gripper_contacts"](tmp_path)
        namespace["test_my_claims"]()
    finally:
        os.chdir(cwd)


def test_objects_with_a_radius(tmp_path):
    # CLAIMS.md, "Objects with a radius": a sphere of radius 1 at 0 and one of radius 2 at
    # (5, 0, 0); at (ρ1, ρ2) the signed distance is 5 − ρ1 − 2ρ2 (exact here, so no tolerance).
    s = scalecert.Scene(np.zeros((1, 3)), np.array([[5.0, 0, 0]]), radii=np.array([1.0, 2.0]))
    assert s.radii() == (F(1), F(2))
    assert s.verdict(1, 1) == scalecert.Verdict.Separated
    assert s.verdict(1, 2) == scalecert.Verdict.Touching
    assert s.verdict(2, 2) == scalecert.Verdict.Overlapping
    assert list(s.classify(np.array([1.0, 1, 2]), np.array([1.0, 2, 2]))) == [0, 1, 2]
    r = s.certify("signed_distance", [1.0, 1, 2, 2], [1.0, 2, 2, 2], value=[2.0, 0, -1, -1.5], fractions=True)
    assert list(r["right"]) == [True, True, True, False]
    assert r["radius_sum"] == [F(3), F(5), F(6), F(6)]
    assert r["exact_squared"][0] == F(25)  # the hulls' (the centres'), squared
    assert list(r["exact"]) == [2.0, 0.0, -1.0, -1.0]
    d = s.certify("penetration_depth", [2.0, 2.0], [2.0, 2.0], value=[1.0, 1.0], direction=[[1, 0, 0], [1, 1, 0]])
    assert list(d["direction_right"]) == [True, False]  # 45° off, the balls part after 6 − 5/√2
    # A capsule (two points, radius 1/4) crossing another at the origin: the hulls touch, depth 1/2.
    c = scalecert.Scene([[0, 0, -1], [0, 0, 1]], [[-1, 0, 0], [1, 0, 0]], radii=("1/4", "1/4"))
    assert list(c.certify("penetration_depth", [1.0], [1.0], value=[0.5])["right"]) == [True]
    with pytest.raises(scalecert.InputError, match="the touching curve is not built for objects with a radius"):
        s.curve()
    with pytest.raises(scalecert.InputError, match="radius: a radius is >= 0"):
        scalecert.Scene(np.zeros((1, 3)), [[5, 0, 0]], radii=(-1, 2))
    with pytest.raises(scalecert.InputError, match="radii\\[0\\]: not a finite number"):
        scalecert.Scene(np.zeros((1, 3)), [[5, 0, 0]], radii=(float("nan"), 2))
    with pytest.raises(scalecert.InputError, match="radii: expected"):
        scalecert.Scene(np.zeros((1, 3)), [[5, 0, 0]], radii=(1,))
    with pytest.raises(scalecert.InputError, match="the seed is not within less than the radius"):
        scalecert.Scene(np.zeros((1, 3)), [[5, 0, 0]], seeds=([1, 0, 0], None), radii=(1, 2))
    # The scene file keeps the radii; read back, it is the same scene.
    (tmp_path / "spheres.json").write_text(s.json())
    assert scalecert.Scene.load(str(tmp_path / "spheres.json")).radii() == (F(1), F(2))


def test_sphere_sets(tmp_path):
    # CLAIMS.md, "Parts with radii": spheres of radius 1 at 0 and 1/2 at (3, 0, 0) (seed 0) against
    # the box [5, 7] x [-1, 1]^2 (seed its centre): along x the second sphere reaches 7ρ1/2 and the
    # box starts at 6 − ρ2, so they touch at (10/7, 1) and are 3/2 apart at (1, 1).
    box = [[x, y, z] for x in (5, 7) for y in (-1, 1) for z in (-1, 1)]
    s = scalecert.Scene.sphere_set(np.array([[0.0, 0, 0], [3, 0, 0]]), np.array([1.0, 0.5]), box,
                                   seeds=([0, 0, 0], [6, 0, 0]))
    assert s.part_radii(0) == [F(1), F(1, 2)]
    assert s.part_radii(1) == [F(0)]
    assert s.verdict(1, 1) == scalecert.Verdict.Separated
    assert s.verdict(F(10, 7), 1) == scalecert.Verdict.Touching
    assert s.query(2, 1)["certificate"]["kind"] == "compound_judgements"  # its one verdict, proved
    r = s.certify("distance", [1.0, 1.0], [1.0, 1.0], value=[1.5, 4.0])
    assert list(r["right"]) == [True, False]
    # The same scene from parts, a radius a part; its file reads back the same.
    t = scalecert.Scene.from_parts([[[0, 0, 0]], [[3, 0, 0]]], [box], seeds=([0, 0, 0], [6, 0, 0]),
                                   radii=([1, "1/2"], None))
    (tmp_path / "set.json").write_text(t.json())
    assert scalecert.Scene.load(str(tmp_path / "set.json")).part_radii(0) == [F(1), F(1, 2)]
    with pytest.raises(scalecert.InputError, match="2 radii for 1 parts"):
        scalecert.Scene.sphere_set([[0, 0, 0]], [1, 2], box)
    with pytest.raises(scalecert.InputError, match="fewer than 4 vertices \\(1\\) and no radius > 0"):
        scalecert.Scene.sphere_set([[0, 0, 0]], [0], box)


def test_sphere_set_signed_distances_of_part_pairs():
    # The second sphere (radius 1/2 at (3, 0, 0)) is 3/2 from the box [5, 7] x [-1, 1]^2 at (1, 1),
    # the first (radius 1 at 0) 4: a signed distance is one part pair's (CLAIMS.md, "Parts with radii").
    box = [[x, y, z] for x in (5, 7) for y in (-1, 1) for z in (-1, 1)]
    s = scalecert.Scene.sphere_set([[0, 0, 0], [3, 0, 0]], [1, 0.5], box, seeds=([0, 0, 0], [6, 0, 0]))
    r = s.certify("signed_distance", [1.0, 1.0], [1.0, 1.0], value=[1.5, 4.0], parts=[[1, 0], [1, 0]])
    assert list(r["right"]) == [True, False]
    with pytest.raises(scalecert.InputError, match="parts: missing"):
        s.certify("signed_distance", [1.0], [1.0], value=[1.5])
    with pytest.raises(scalecert.InputError, match="certify: parts: kind 'distance' does not use it"):
        s.certify("distance", [1.0], [1.0], value=[1.5], parts=[[1, 0]])
