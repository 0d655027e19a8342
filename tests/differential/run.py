#!/usr/bin/env python3
"""Differential test of the polysweep npm package (pkg/, built) against GEOS (shapely) and an exact reference.

    .venv/bin/python tests/differential/run.py [--seed S] [--cases N] [--case I ...] [--family F ...] [-v]

Cases are generated from (seed, index), so `--seed S --case I` replays case I of a run alone (the family is
chosen by the index, whatever --cases). Named cases (known regressions) run every time, unless --case selects
others; select one with --case NAME. See README.md.
"""

import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import time
import unittest
from fractions import Fraction

sys.dont_write_bytecode = True  # no __pycache__ left in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)

import exact  # noqa: E402

try:
    import shapely
    from shapely.geometry import GeometryCollection, LineString, MultiPolygon, Polygon
    from shapely.ops import polygonize, unary_union
except ImportError:  # pragma: no cover
    sys.exit("shapely is missing: python3 -m venv .venv && .venv/bin/pip install shapely==2.2.0, "
             "then run this with .venv/bin/python")

DEFAULT_SEED = 20091
DEFAULT_CASES = 15000
AREA_TOL = 1e-9       # |symmetric difference| / operands' area
COUNT_THRESHOLD = 1e-7  # components and holes count when their ring's |area| exceeds this share of operands' area
EXACT_MAX_SEGMENTS = 450
OPS = ("union", "intersection", "difference", "xor")
TAU = 2 * math.pi


# ==============================================================================================================
# case generation
# ==============================================================================================================

def closed(pts):
    pts = [[float(x), float(y)] for x, y in pts]
    return pts + [list(pts[0])]


def star(rng, cx, cy, r0, r1, n):
    """A star-shaped (so simple) ring, counter-clockwise, open."""
    angles = sorted(rng.uniform(0, TAU) for _ in range(n))
    return [(cx + rng.uniform(r0, r1) * math.cos(a), cy + rng.uniform(r0, r1) * math.sin(a)) for a in angles]


def oriented(rng, pts, ccw=None):
    if ccw is None:
        ccw = rng.random() < 0.5
    return closed(pts if ccw else pts[::-1])


def rand_op(rng):
    return rng.choice(OPS)


def rand_fill(rng, exotic=False):
    fills = ["evenodd", "nonzero", "structure", "default"]
    if exotic:
        fills += ["positive", "negative"]
    return rng.choice(fills)


def two(op, a, b, fill):
    return {"steps": [{"op": op, "operands": [a, b], "fill": fill}]}


def gen_random(rng):
    a = [[oriented(rng, star(rng, 0, 0, 0.3, 1.5, rng.randint(3, 10)))]]
    b = [[oriented(rng, star(rng, rng.uniform(-1, 1), rng.uniform(-1, 1), 0.3, 1.5, rng.randint(3, 10)))]]
    return two(rand_op(rng), a, b, rand_fill(rng))


def holed(rng, cx, cy, fill):
    shell_ccw = rng.random() < 0.5
    r = rng.uniform(2, 3)
    shell = oriented(rng, star(rng, cx, cy, r, r * 1.4, rng.randint(4, 9)), shell_ccw)
    rings = [shell]
    theta = rng.uniform(0, TAU)
    for k in range(rng.randint(1, 2)):
        d = rng.uniform(0.3, 0.5) * r
        hx, hy = cx + d * math.cos(theta + k * math.pi), cy + d * math.sin(theta + k * math.pi)
        hole = star(rng, hx, hy, 0.1 * r, 0.3 * r, rng.randint(3, 6))
        if fill in ("nonzero", "positive", "negative") and rng.random() < 0.85:
            rings.append(oriented(rng, hole, not shell_ccw))
        else:
            rings.append(oriented(rng, hole))
    return [rings]


def gen_holes(rng):
    fill = rand_fill(rng, exotic=True)
    a = holed(rng, 0, 0, fill)
    b = holed(rng, rng.uniform(-3, 3), rng.uniform(-3, 3), fill) if rng.random() < 0.7 else \
        [[oriented(rng, star(rng, rng.uniform(-2, 2), rng.uniform(-2, 2), 0.5, 2.5, rng.randint(3, 8)))]]
    return two(rand_op(rng), a, b, fill)


def gen_multi(rng):
    def operand():
        return [[oriented(rng, star(rng, rng.uniform(-2, 2), rng.uniform(-2, 2), 0.4, 1.2, rng.randint(3, 7)))]
                for _ in range(rng.randint(2, 3))]
    return two(rand_op(rng), operand(), operand(), rand_fill(rng, exotic=True))


def gen_shared(rng):
    """Pieces of one fan subdivision of a star (spokes from the origin): polygons sharing edges exactly, within an
    operand and between operands; some pieces carry the exact midpoint of a spoke (collinear partial overlaps)."""
    n = rng.randint(4, 9)
    outer = star(rng, 0, 0, 1, 2, n)
    pieces = []
    i = 0
    while i < n:
        k = rng.randint(1, 2)
        pts = [(0.0, 0.0)] + [outer[(i + j) % n] for j in range(k + 1)]
        if rng.random() < 0.4:  # the midpoint of the first spoke, exact (a halving)
            v = pts[1]
            pts.insert(1, (v[0] * 0.5, v[1] * 0.5))
        pieces.append(pts)
        i += k
    a, b = [], []
    for p in pieces:
        r = rng.random()
        if r < 0.45:
            a.append([oriented(rng, p)])
        elif r < 0.9:
            b.append([oriented(rng, p)])
        else:
            a.append([oriented(rng, p)])
            b.append([oriented(rng, p)])
    if rng.random() < 0.5:
        # a rectangle with an edge on a spoke's line through the origin (axis-aligned spoke: x axis)
        b.append([closed([(0, 0), (rng.uniform(0.5, 2), 0), (rng.uniform(0.5, 2), -1), (0, -1)])])
        a.append([closed([(0, 0), (-1.5, 0), (-1.5, 1), (0, 1)])])
    fill = rng.choice(["evenodd", "nonzero", "structure", "default"])
    if fill == "nonzero":  # pieces of one operand must not cancel: wind them alike
        a = [[closed(_ccw(p[0][:-1]))] for p in a]
        b = [[closed(_ccw(p[0][:-1]))] for p in b]
    return two(rand_op(rng), a, b, fill)


def _area2(pts):
    return sum(pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
               for i in range(len(pts)))


def _ccw(pts):
    return pts if _area2(pts) > 0 else pts[::-1]


def gen_grid(rng):
    m = rng.choice([3, 4, 6])

    def ring():
        return closed([(rng.randint(0, m), rng.randint(0, m)) for _ in range(rng.randint(3, 7))])

    def operand():
        out = [[ring()] for _ in range(rng.randint(1, 2))]
        if rng.random() < 0.3:
            x0, y0 = rng.randint(0, m - 1), rng.randint(0, m - 1)
            out.append([closed([(x0, y0), (rng.randint(x0 + 1, m), y0), (rng.randint(x0 + 1, m), rng.randint(y0 + 1, m)),
                                (x0, rng.randint(y0 + 1, m))])])
        return out
    return two(rand_op(rng), operand(), operand(), rand_fill(rng, exotic=True))


def gen_near_parallel(rng):
    a_pts = star(rng, 0, 0, 0.5, 1.5, rng.randint(3, 6))
    i = rng.randrange(len(a_pts))
    p, q = a_pts[i], a_pts[(i + 1) % len(a_pts)]
    ex, ey = q[0] - p[0], q[1] - p[1]
    nx, ny = -ey, ex
    d1 = rng.choice([0.0, 1.0, -1.0]) * 10 ** rng.uniform(-16, -8)
    d2 = rng.choice([1.0, -1.0]) * 10 ** rng.uniform(-16, -8)
    s0, s1 = rng.uniform(-0.3, 0.3), rng.uniform(0.7, 1.3)
    p2 = (p[0] + s0 * ex + d1 * nx, p[1] + s0 * ey + d1 * ny)
    q2 = (p[0] + s1 * ex + d2 * nx, p[1] + s1 * ey + d2 * ny)
    side = rng.choice([1, -1]) * rng.uniform(0.2, 1.5)
    t = rng.uniform(0.2, 0.8)
    r = (p[0] + t * ex + side * nx, p[1] + t * ey + side * ny)
    b_pts = [p2, q2, r]
    if rng.random() < 0.4:  # a second nearly parallel edge on the far side
        r2 = (p[0] + rng.uniform(0, 1) * ex + side * nx * 2, p[1] + rng.uniform(0, 1) * ey + side * ny * 2)
        b_pts = [p2, q2, r, r2]
        b_pts = star_sort(b_pts)
    return two(rand_op(rng), [[oriented(rng, a_pts)]], [[oriented(rng, b_pts)]], rand_fill(rng))


def star_sort(pts):
    cx = sum(p[0] for p in pts) / len(pts)
    cy = sum(p[1] for p in pts) / len(pts)
    return sorted(pts, key=lambda p: math.atan2(p[1] - cy, p[0] - cx))


def gen_sliver(rng):
    a = [[oriented(rng, star(rng, 0, 0, 0.5, 1.5, rng.randint(3, 8)))]]
    slivers = []
    for _ in range(rng.randint(1, 2)):
        th = rng.uniform(0, TAU)
        off = rng.uniform(-0.8, 0.8)
        length = rng.uniform(1.0, 4.0)
        ux, uy = math.cos(th), math.sin(th)
        nx, ny = -uy, ux
        cx, cy = off * nx + rng.uniform(-0.5, 0.5) * ux, off * ny + rng.uniform(-0.5, 0.5) * uy
        u = (cx - length / 2 * ux, cy - length / 2 * uy)
        v = (cx + length / 2 * ux, cy + length / 2 * uy)
        w = length * 10 ** rng.uniform(-12, -3)
        if rng.random() < 0.5:
            pts = [u, v, (v[0] + w * nx, v[1] + w * ny), (u[0] + w * nx, u[1] + w * ny)]
        else:  # a needle
            pts = [u, v, ((u[0] + v[0]) / 2 + w * nx, (u[1] + v[1]) / 2 + w * ny)]
        slivers.append([oriented(rng, pts)])
    ops = [a, slivers]
    rng.shuffle(ops)
    return two(rand_op(rng), ops[0], ops[1], rand_fill(rng))


def gen_fan(rng):
    """Triangles sharing a vertex, neighbouring spokes nearly collinear, coordinates with 6 decimals. Where one
    wedge ends and the next begins the two spokes are: at angles 1e-7..1e-2 rad apart; or collinear in decimal
    but of different lengths (p and 1.5 p written with 6 decimals), so only binary rounding, far below an ulp of
    the angle, separates or overlaps them (the three-wedge union polysweep got wrong was of this kind); or one
    spoke shared exactly."""
    k = rng.choice([2, 3, 3, 3, 4])
    c = (round(rng.uniform(-1, 1), 6), round(rng.uniform(-1, 1), 6)) if rng.random() < 0.3 else (0.0, 0.0)
    c_micro = (round(c[0] * 1e6), round(c[1] * 1e6))

    def dec(micro):  # a coordinate written with 6 decimals, read as the nearest double
        return float(f"{micro}e-6")

    def spoke_at(angle, r):
        return (round(c_micro[0] + r * 1e6 * math.cos(angle)), round(c_micro[1] + r * 1e6 * math.sin(angle)))

    a = rng.uniform(0, TAU)
    start = spoke_at(a, rng.uniform(3, 9))
    wedges = []
    for _ in range(k):
        b = a + rng.uniform(0.3, 1.2)
        end = spoke_at(b, rng.uniform(3, 9))
        mode = rng.random()
        if mode < 0.4:  # the next spoke collinear in decimal: c + (m / n) (end - c), on the 6-decimal grid
            n = rng.choice([1, 2, 3, 4, 5, 6])
            dx, dy = (end[0] - c_micro[0]) // 60 * 60, (end[1] - c_micro[1]) // 60 * 60
            end = (c_micro[0] + dx, c_micro[1] + dy)
            m = rng.choice([x for x in range(1, 3 * n) if x != n])
            nxt, a_next = (c_micro[0] + dx // n * m, c_micro[1] + dy // n * m), b
        elif mode < 0.55:  # the same spoke
            nxt, a_next = end, b
        else:  # another spoke 1e-7..1e-2 rad away, either side
            a_next = b + rng.choice([1, -1]) * 10 ** rng.uniform(-7, -2)
            nxt = spoke_at(a_next, rng.uniform(3, 9))
        pts = [(dec(c_micro[0]), dec(c_micro[1])), (dec(start[0]), dec(start[1])), (dec(end[0]), dec(end[1]))]
        wedges.append([[oriented(rng, pts, rng.random() < 0.8)]])
        start, a = nxt, a_next
    op = "union" if rng.random() < 0.5 else rand_op(rng)
    fill = rng.choice(["evenodd", "nonzero", "structure", "default"])
    return {"steps": [{"op": op, "operands": wedges, "fill": fill}]}


def bowtie_ring(rng, cx, cy, s):
    kind = rng.randrange(3)
    if kind == 0:  # a bow-tie quadrilateral
        pts = [(cx - s, cy - s), (cx + s, cy + s), (cx + s, cy - s), (cx - s, cy + s)]
        pts = [(x + rng.uniform(-0.4, 0.4) * s, y + rng.uniform(-0.4, 0.4) * s) for x, y in pts]
    elif kind == 1:  # a pentagram {5/2}, or {7/3}
        n, step = rng.choice([(5, 2), (7, 2), (7, 3)])
        rot = rng.uniform(0, TAU)
        pts = [(cx + s * math.cos(rot + TAU * (i * step % n) / n), cy + s * math.sin(rot + TAU * (i * step % n) / n))
               for i in range(n)]
    else:  # random vertex order: crossings anywhere
        pts = [(cx + rng.uniform(-s, s), cy + rng.uniform(-s, s)) for _ in range(rng.randint(4, 8))]
    return pts


def gen_bowtie(rng):
    a = [[oriented(rng, bowtie_ring(rng, 0, 0, 1.5))]]
    if rng.random() < 0.5:
        b = [[oriented(rng, bowtie_ring(rng, rng.uniform(-1, 1), rng.uniform(-1, 1), 1.5))]]
    else:
        b = [[oriented(rng, star(rng, rng.uniform(-1, 1), rng.uniform(-1, 1), 0.5, 1.5, rng.randint(3, 8)))]]
    if rng.random() < 0.2:
        a.append([oriented(rng, bowtie_ring(rng, rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0))])
    ops = [a, b]
    rng.shuffle(ops)
    return two(rand_op(rng), ops[0], ops[1], rand_fill(rng, exotic=True))


def _scaled(rng, scale, integral):
    def operand(cx, cy):
        pts = star(rng, cx, cy, 0.3 * scale, 1.5 * scale, rng.randint(3, 9))
        if integral:
            pts = [(float(round(x)), float(round(y))) for x, y in pts]
        return [[oriented(rng, pts)]]
    if integral:
        ox, oy = 0.0, 0.0
    else:
        ox, oy = rng.choice([(0.0, 0.0), (rng.uniform(-3, 3) * scale, rng.uniform(-3, 3) * scale)])
    a = operand(ox, oy)
    b = operand(ox + rng.uniform(-1, 1) * scale, oy + rng.uniform(-1, 1) * scale)
    return two(rand_op(rng), a, b, rand_fill(rng))


def gen_huge(rng):
    return _scaled(rng, 1e9, rng.random() < 0.5)


def gen_tiny(rng):
    if rng.random() < 0.25:  # tiny shapes far from the origin: coordinates near 1, features near 1e-9
        case = _scaled(rng, 1e-9, False)
        for o in case["steps"][0]["operands"]:
            for poly in o:
                for ring in poly:
                    for p in ring:
                        p[0] += 1.0
                        p[1] -= 1.0
        return case
    return _scaled(rng, 1e-9, False)


def gen_near_vertex(rng):
    """Vertices within ~1e-18 (relative) of an edge: the edge passes near the origin, where doubles are dense."""
    y0, y1 = rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)
    a_pts = [(-1.0, y0), (1.0, y1), (rng.uniform(0.3, 1.5), 1.5), (rng.uniform(-1.5, -0.3), 1.5)]
    if rng.random() < 0.5:
        a_pts = [(x, -y) for x, y in a_pts][::-1]  # the body below the edge
    fa, fb = (Fraction(-1), Fraction(y0)), (Fraction(1), Fraction(y1))

    def near(x):
        fx = Fraction(x)
        fy = fa[1] + (fb[1] - fa[1]) * (fx - fa[0]) / (fb[0] - fa[0])
        k = rng.choice([0, 0, 1, -1, 2, -3])
        return (x, float(fy + Fraction(k) * Fraction(10) ** -18))

    b_pts = []
    for _ in range(rng.randint(1, 2)):
        x = rng.choice([1, -1]) * 10 ** rng.uniform(-6, -2)
        b_pts.append(near(x))
    side = rng.choice([1, -1])
    b_pts.append((rng.uniform(-1, 1), rng.uniform(0.3, 1.2) * side))
    if rng.random() < 0.5:
        b_pts.append((rng.uniform(-1, 1), rng.uniform(0.3, 1.2) * -side))
    b_pts = star_sort(b_pts)
    return two(rand_op(rng), [[oriented(rng, a_pts)]], [[oriented(rng, b_pts)]], rand_fill(rng))


def gen_rotated(rng):
    a_pts = star(rng, 0, 0, 0.5, 1.5, rng.randint(3, 8))
    th = rng.choice([1, -1]) * 10 ** rng.uniform(-13, -5)
    kind = rng.randrange(3)
    if kind == 0:
        pv = a_pts[rng.randrange(len(a_pts))]
    elif kind == 1:
        pv = (sum(p[0] for p in a_pts) / len(a_pts), sum(p[1] for p in a_pts) / len(a_pts))
    else:
        pv = (rng.uniform(-3, 3), rng.uniform(-3, 3))
    c, s = math.cos(th), math.sin(th)
    b_pts = [(pv[0] + c * (x - pv[0]) - s * (y - pv[1]), pv[1] + s * (x - pv[0]) + c * (y - pv[1])) for x, y in a_pts]
    if rng.random() < 0.3:
        b_pts = b_pts[: max(3, len(b_pts) - 1)]
    return two(rand_op(rng), [[oriented(rng, a_pts)]], [[oriented(rng, b_pts)]], rand_fill(rng))


def gen_nary(rng):
    fill = rand_fill(rng)
    operands = []
    for _ in range(3):
        if rng.random() < 0.25:
            operands.append(holed(rng, rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), fill))
        else:
            operands.append([[oriented(rng, star(rng, rng.uniform(-1, 1), rng.uniform(-1, 1), 0.4, 2.0,
                                                 rng.randint(3, 8)))]])
    return {"steps": [{"op": rand_op(rng), "operands": operands, "fill": fill}]}


def gen_chained(rng):
    fill = rand_fill(rng)

    def operand():
        return [[oriented(rng, star(rng, rng.uniform(-1, 1), rng.uniform(-1, 1), 0.4, 1.8, rng.randint(3, 7)))]]
    steps = [{"op": rand_op(rng), "operands": [operand(), operand()], "fill": fill}]
    for k in range(rng.randint(1, 2)):
        ops = [{"ref": k}, operand()]
        if rng.random() < 0.3:
            ops.reverse()
        steps.append({"op": rand_op(rng), "operands": ops, "fill": fill})
    return {"steps": steps}


# family: (generator, exact reference always)
FAMILIES = {
    "random": (gen_random, False),
    "holes": (gen_holes, False),
    "multi": (gen_multi, False),
    "shared-edges": (gen_shared, False),
    "grid": (gen_grid, False),
    "bowtie": (gen_bowtie, False),
    "huge": (gen_huge, False),
    "tiny": (gen_tiny, False),
    "nary": (gen_nary, False),
    "chained": (gen_chained, False),
    "near-parallel": (gen_near_parallel, True),
    "sliver": (gen_sliver, True),
    "fan": (gen_fan, True),
    "near-vertex": (gen_near_vertex, True),
    "rotated": (gen_rotated, True),
}
FAMILY_ORDER = list(FAMILIES)

# Fixed cases: known bugs (they fail until polysweep is fixed), checked like generated ones, exact always.
NAMED = {
    # three wedges with nearly collinear spokes: polysweep returned 1 polygon; exactly 2, area 53.12985622384823
    "bug-three-wedges-union": {
        "family": "named",
        "steps": [{"op": "union", "fill": "default", "operands": [
            [[[0, 0], [-0.491463, 7.98489], [-6.543493, 4.602466]]],
            [[[0, 0], [-4.90762, 3.45185], [-3.05317, -2.584212]]],
            [[[0, 0], [-4.579755, -3.876318], [1.743494, -5.7411]]]]}],
        "expect": {"area": 53.12985622384823, "polygons": 2, "holes": 0},
    },
    # a self-crossing ring with a near-vertical spike: under 'evenodd' and 'nonzero' polysweep returned an invalid
    # zero-area spike; exactly 2 triangles (the default 'structure' reading got it right)
    "bug-spike-union": {
        "family": "named",
        "steps": [{"op": "union", "fill": fill, "operands": [
            [[[-0.24999999999999745, -0.24999999999999747], [11.500000000000002, -1.2499999999999976],
              [-4.249999999999998, 10.500000000000002], [-0.24999999999999747, 28.500000000000004],
              [-0.24999999999999745, -4.249999999999998]]],
            []]} for fill in ("evenodd", "nonzero", "default")],
        "expect": {"area": 87.59275793650794, "polygons": 2, "holes": 0},
    },
}


def generate(seed, index):
    family = FAMILY_ORDER[index % len(FAMILY_ORDER)]
    rng = random.Random(f"polysweep-differential:{seed}:{index}")
    case = FAMILIES[family][0](rng)
    case["family"] = family
    case["id"] = index
    return case


# ==============================================================================================================
# reading operands and results with shapely
# ==============================================================================================================

class GeosTrouble(Exception):
    pass


def polygons_of(geom):
    if geom is None or geom.is_empty:
        return []
    if isinstance(geom, Polygon):
        return [geom]
    if isinstance(geom, (MultiPolygon, GeometryCollection)):
        return [p for g in geom.geoms for p in polygons_of(g)]
    return []


def as_multi(polys):
    polys = [p for p in polys if not p.is_empty and p.area > 0]
    return MultiPolygon(polys) if polys else MultiPolygon()


def ring_area(ring):
    """Signed shoelace area of a ring given as (x, y) pairs (closed or open), float, relative to its first vertex
    (shapes far from the origin, tiny next to their coordinates, keep their precision)."""
    s = 0.0
    n = len(ring)
    x0, y0 = ring[0][0], ring[0][1]
    for i in range(1, n - 1):
        x1, y1 = ring[i][0] - x0, ring[i][1] - y0
        x2, y2 = ring[i + 1][0] - x0, ring[i + 1][1] - y0
        s += x1 * y2 - x2 * y1
    return s / 2


def exact_ring_area(ring):
    return exact.ring_area(ring)


def region(operand, fill):
    """The operand's point set under the fill rule as a shapely MultiPolygon: the faces of all its rings, noded
    and polygonized by GEOS, each kept by an exact winding test of an interior point against the original rings
    (as tests/fixtures/generate.py does). Valid polygon sets whose reading is plain take a shortcut."""
    polys = exact.normalize_operand(operand)
    rule = "structure" if fill == "default" else fill
    rings_ok = all(len(r) >= 3 for p in polys for r in p)
    if not polys:
        return MultiPolygon()
    if rings_ok:
        try:
            shp = [Polygon(p[0], p[1:]) for p in polys]
            mp = MultiPolygon(shp)
            if mp.is_valid:
                if rule in ("evenodd", "structure"):
                    return mp
                ccw = [[Polygon(r).exterior.is_ccw for r in p] for p in polys]
                if rule == "nonzero" and all(all(h != c[0] for h in c[1:]) for c in ccw):
                    return mp
                if rule == "positive" and all(c[0] and not any(c[1:]) for c in ccw):
                    return mp
                if rule == "negative" and all(not c[0] and all(c[1:]) for c in ccw):
                    return mp
        except Exception:
            pass
    lines = []
    for p in polys:
        for r in p:
            for i in range(len(r)):
                a, b = r[i], r[(i + 1) % len(r)]
                if a != b:
                    lines.append(LineString([a, b]))
    if not lines:
        return MultiPolygon()
    kept = []
    for face in polygonize(unary_union(lines)):
        rp = face.representative_point()
        try:
            if exact.inside(polys, (rp.x, rp.y), rule):
                kept.append(face)
        except ValueError:
            raise GeosTrouble("a face's representative point lies on an edge")
    return as_multi(polygons_of(unary_union(kept))) if kept else MultiPolygon()


def geos_op(op, regions):
    fn = {"union": shapely.union, "intersection": shapely.intersection, "difference": shapely.difference,
          "xor": shapely.symmetric_difference}[op]
    acc = regions[0]
    for r in regions[1:]:
        acc = fn(acc, r)
    return as_multi(polygons_of(acc))


def geom_of(result):
    return MultiPolygon([Polygon(p[0], p[1:]) for p in result]) if result else MultiPolygon()


def counts_of_coords(result, thr):
    """(polygons, holes) of polysweep's result whose ring's |area| (exact) exceeds thr."""
    thr = Fraction(thr)
    polys = sum(1 for p in result if p and len(p[0]) >= 3 and exact_ring_area(p[0]) > thr)
    holes = sum(1 for p in result for h in p[1:] if len(h) >= 3 and -exact_ring_area(h) > thr)
    return polys, holes


def counts_of_geom(g, thr):
    polys = holes = 0
    for p in polygons_of(g):
        if abs(ring_area(p.exterior.coords)) > thr:
            polys += 1
        holes += sum(1 for h in p.interiors if abs(ring_area(h.coords)) > thr)
    return polys, holes


def ring_cover_area(ring):
    """Area a ring winds around at all (make_valid's reading for a ring crossing itself), float."""
    if len(set(ring)) < 3:
        return 0.0
    a = abs(ring_area(ring))
    try:
        if not shapely.LinearRing(ring).is_simple:
            a = shapely.make_valid(Polygon(ring)).area
    except Exception:  # noqa: BLE001
        pass
    return a


def operand_scale(operands):
    """The operands' area, the scale of tolerances: sum of the areas their rings wind around (float)."""
    return sum(ring_cover_area(r) for o in operands for p in exact.normalize_operand(o) for r in p)


def rounding_allowance(operands, result):
    """Area that rounding computed vertices to doubles may move: 4 ulps of the largest coordinate along every edge
    of the operands and the result."""
    mx = 0.0
    perimeter = 0.0
    for o in list(operands) + [result]:
        for p in exact.normalize_operand(o):
            for r in p:
                for i in range(len(r)):
                    (x1, y1), (x2, y2) = r[i], r[(i + 1) % len(r)]
                    mx = max(mx, abs(x1), abs(y1))
                    perimeter += math.hypot(x2 - x1, y2 - y1)
    return 4 * 2.0 ** -52 * mx * perimeter


def validity_problems(result):
    """The output contract: closed rings of 4+ positions, exteriors counter-clockwise, holes clockwise (exactly),
    each polygon valid, polygons meeting only at points (the MultiPolygon valid)."""
    problems = []
    if not isinstance(result, list):
        return ["result is not MultiPolygon coordinates"]
    for i, p in enumerate(result):
        if not p:
            problems.append(f"polygon {i} has no rings")
            continue
        for j, r in enumerate(p):
            if len(r) < 4:
                problems.append(f"polygon {i} ring {j} has {len(r)} positions")
                continue
            if r[0] != r[-1]:
                problems.append(f"polygon {i} ring {j} is not closed")
            a = exact_ring_area(r[:-1])
            if j == 0 and a <= 0:
                problems.append(f"polygon {i} exterior is not counter-clockwise (area {float(a):.3g})")
            if j > 0 and a >= 0:
                problems.append(f"polygon {i} hole {j} is not clockwise (area {float(a):.3g})")
    if problems:
        return problems
    try:
        for i, p in enumerate(result):
            poly = Polygon(p[0], p[1:])
            if not poly.is_valid:
                problems.append(f"polygon {i}: {shapely.is_valid_reason(poly)}")
        if not problems:
            mp = geom_of(result)
            if not mp.is_valid:
                problems.append(f"multipolygon: {shapely.is_valid_reason(mp)}")
    except Exception as e:  # noqa: BLE001
        problems.append(f"shapely could not read the result: {e}")
    return problems


# ==============================================================================================================
# checking
# ==============================================================================================================

class StepOutcome:
    def __init__(self):
        self.errors = []         # failure messages
        self.geos = None         # True agree, False disagree, None not compared
        self.geos_note = ""
        self.exact = None        # 'right', 'wrong', 'unrepresentable' or 'operand rounded' (accepted), None not run
        self.exact_note = ""


def rounded_exact_is_valid(rings):
    """Is the exact result, its vertices rounded to the nearest doubles, still a valid MultiPolygon (each clockwise
    ring put in the smallest counter-clockwise ring that covers it)? If not, its topology (how its pieces touch,
    slivers thinner than an ulp) cannot be written in doubles as it is, and an output may differ from it in
    polygon and hole counts without being wrong."""
    shells, holes = [], []
    for a, pts in rings:
        r = [(float(x), float(y)) for x, y in pts]
        if len(set(r)) < 3:
            return False
        (shells if a > 0 else holes).append(r)
    try:
        sp = [Polygon(s) for s in shells]
        if not all(s.is_valid for s in sp):
            return False
        members = [[] for _ in shells]
        for h in holes:
            hp = Polygon(h)
            if not hp.is_valid:
                return False
            parents = [i for i, s in enumerate(sp) if s.covers(hp)]
            if not parents:
                return False
            members[min(parents, key=lambda i: sp[i].area)].append(h)
        mp = MultiPolygon([Polygon(s, hs) for s, hs in zip(shells, members)])
        return bool(mp.is_valid)
    except Exception:  # noqa: BLE001
        return False


def is_valid_polygon_set(operand):
    """Is the operand (MultiPolygon coordinates) a valid polygon set, which the structure rule reads as it is?"""
    try:
        return bool(MultiPolygon([Polygon(p[0], p[1:]) for p in operand if p]).is_valid)
    except Exception:  # noqa: BLE001  (a ring of fewer than 3 points, say)
        return False


def exact_check(op, operands, fill, result, thr, tol):
    """(verdict, note) for polysweep's result against the exact reference. verdict: 'right', 'wrong',
    'unrepresentable' (the point sets agree, the counts do not, and the exact result's topology does not survive
    rounding its vertices to doubles: accepted), 'operand rounded' (the point sets agree, the counts do not, and an
    operand read by its structure is not a valid polygon set: the library makes it one first and writes it in
    doubles, so the operation sees the rounded operand, a known limit in docs/robustness.md: accepted), or None (not
    run)."""
    nseg = sum(len(r) for o in operands + [result] for p in exact.normalize_operand(o) for r in p)
    if nseg > EXACT_MAX_SEGMENTS:
        return None, f"too large for the exact reference ({nseg} segments)"
    arr = exact.Arrangement(list(operands) + [result])
    n = len(operands)
    fills = [fill] * n + ["structure"]
    fn = exact.op_function(op)
    res_edges = arr.boundary(lambda ins: fn(ins[:n]), fills)
    rings = arr.rings(res_edges)
    area = arr.area(res_edges)
    sym = arr.area(arr.boundary(lambda ins: fn(ins[:n]) != ins[n], fills))
    ec = exact.ring_counts(rings, thr)
    pc = counts_of_coords(result, thr)
    pa = sum(float(exact_ring_area(r)) for p in result for r in p if len(r) >= 3)
    note = (f"exact: area {float(area):.17g}, {ec[0]} polygons, {ec[1]} holes; polysweep: area {pa:.17g}, "
            f"{pc[0]} polygons, {pc[1]} holes; |symmetric difference| {float(sym):.3g} (tolerance {tol:.3g})")
    if float(sym) > tol:
        return "wrong", note
    if ec == pc:
        return "right", note
    if fill in ("structure", "default") and not all(is_valid_polygon_set(o) for o in operands):
        return "operand rounded", note + "; an operand read by its structure was made valid and rounded first"
    if rounded_exact_is_valid(rings):
        return "wrong", note + "; the exact result rounded to doubles is valid with the exact counts"
    return "unrepresentable", note + "; the exact result's topology does not survive rounding to doubles"


def check_step(step, operands, out, family_exact, thr, tol):
    o = StepOutcome()
    if "error" in out:
        o.errors.append(f"threw {out['error']}")
        return o
    result = out["result"]
    if "flatMismatch" in out:
        o.errors.append("overlayFlat's result differs from the nested result")
    if "flatError" in out:
        o.errors.append(f"overlayFlat threw {out['flatError']} where the nested call did not")
    problems = validity_problems(result)
    if problems:
        o.errors.append("invalid result: " + "; ".join(problems[:4]))
    op, fill = step["op"], step["fill"]
    # GEOS
    try:
        regions = [region(x, fill) for x in operands]
        g = geos_op(op, regions)
        pc = counts_of_coords(result, thr)
        gc = counts_of_geom(g, thr)
        p_geom = geom_of(result) if not problems else shapely.make_valid(geom_of(result))
        sd = shapely.symmetric_difference(p_geom, g).area
        o.geos = sd <= tol and pc == gc
        if not o.geos:
            o.geos_note = (f"GEOS: area {g.area:.17g}, {gc[0]} polygons, {gc[1]} holes; polysweep: {pc[0]} "
                           f"polygons, {pc[1]} holes; |symmetric difference| {sd:.3g}")
    except Exception as e:  # noqa: BLE001  (GEOS topology errors, GeosTrouble)
        o.geos = False
        o.geos_note = f"GEOS failed: {type(e).__name__}: {e}"
    if family_exact or not o.geos or problems:
        try:
            o.exact, o.exact_note = exact_check(op, operands, fill, result, thr, tol)
        except Exception as e:  # noqa: BLE001
            o.exact, o.exact_note = None, f"exact reference failed: {type(e).__name__}: {e}"
        if o.exact == "wrong":
            o.errors.append("disagrees with the exact reference: " + o.exact_note)
        elif o.exact is None and not o.geos:
            o.errors.append("disagrees with GEOS, exact reference unavailable: " + o.exact_note + "; " + o.geos_note)
    return o


def check_case(case, res, exact_all=False):
    """List of (step index, StepOutcome)."""
    family_exact = exact_all or case["family"] == "named" or FAMILIES[case["family"]][1]
    outcomes = []
    for k, (step, out) in enumerate(zip(case["steps"], res["steps"])):
        if "error" in out and out["error"].startswith("not run"):
            continue
        operands = [res["steps"][x["ref"]]["result"] if isinstance(x, dict) else x for x in step["operands"]]
        scale = operand_scale(operands)
        thr = COUNT_THRESHOLD * scale
        tol = AREA_TOL * scale + rounding_allowance(operands, out.get("result", []))
        o = check_step(step, operands, out, family_exact, thr, tol)
        if "expect" in case and "result" in out:
            e = case["expect"]
            pc = counts_of_coords(out["result"], thr)
            if (pc != (e["polygons"], e["holes"])):
                o.errors.append(f"expected {e['polygons']} polygons and {e['holes']} holes (area {e['area']}), "
                                f"got {pc[0]} and {pc[1]}")
        outcomes.append((k, o))
    return outcomes


# ==============================================================================================================
# main
# ==============================================================================================================

def run_driver(cases, driver="polysweep-driver.mjs", payload=lambda c: {"steps": c["steps"]}):
    """Runs a Node driver of this folder on the cases (each sent as payload(case)) in one process; its output."""
    with tempfile.TemporaryDirectory(prefix="polysweep-differential-") as tmp:
        cin, cout = os.path.join(tmp, "cases.json"), os.path.join(tmp, "results.json")
        with open(cin, "w") as f:
            json.dump([payload(c) for c in cases], f)
        proc = subprocess.run(["node", os.path.join(HERE, driver), cin, cout],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            sys.exit(f"the Node driver failed (exit {proc.returncode}):\n{proc.stderr}")
        with open(cout) as f:
            return json.load(f)


def run_unit_tests():
    import test_exact
    suite = unittest.defaultTestLoader.loadTestsFromModule(test_exact)
    result = unittest.TextTestRunner(stream=open(os.devnull, "w"), verbosity=0).run(suite)
    if not result.wasSuccessful():
        for _, tb in result.failures + result.errors:
            print(tb)
        sys.exit("exact.py's unit tests failed")
    return result.testsRun


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seed", type=int, default=DEFAULT_SEED)
    ap.add_argument("--cases", type=int, default=DEFAULT_CASES, help="generated cases (default %(default)s)")
    ap.add_argument("--case", action="append", default=[], help="run only this case index or name (repeatable)")
    ap.add_argument("--family", action="append", default=[], help="run only generated cases of this family")
    ap.add_argument("--no-named", action="store_true", help="leave out the named (known-bug) cases")
    ap.add_argument("--exact-all", action="store_true",
                    help="apply the exact reference to every step, not only where GEOS disagrees (slower)")
    ap.add_argument("--show", action="store_true", help="print each failing case's input and polysweep's result")
    ap.add_argument("--print-all", action="store_true",
                    help="print every failure (by default the first %d of each family)" % 8)
    ap.add_argument("-v", "--verbose", action="store_true", help="also print GEOS disagreements that pass")
    args = ap.parse_args()

    t0 = time.time()
    ntests = run_unit_tests()
    if args.family:
        unknown = set(args.family) - set(FAMILIES)
        if unknown:
            sys.exit(f"unknown families {sorted(unknown)}; families: {', '.join(FAMILY_ORDER)}")
    cases = []
    if args.case:
        for c in args.case:
            if c in NAMED:
                cases.append(dict(NAMED[c], id=c))
            else:
                cases.append(generate(args.seed, int(c)))
    else:
        for i in range(args.cases):
            if args.family and FAMILY_ORDER[i % len(FAMILY_ORDER)] not in args.family:
                continue
            cases.append(generate(args.seed, i))
        if not args.no_named:
            cases += [dict(v, id=k) for k, v in NAMED.items()]
    print(f"polysweep differential test: seed {args.seed}, {len(cases)} cases "
          f"(exact.py unit tests: {ntests} passed)")
    t1 = time.time()
    out = run_driver(cases)
    t2 = time.time()

    table = {}
    failures = []
    py = os.path.relpath(sys.executable, os.getcwd()) if os.path.exists(sys.executable) else "python3"
    script = os.path.relpath(os.path.join(HERE, "run.py"), os.getcwd())
    keys = ["cases", "steps", "agree", "off_right", "off_unrepr", "off_rounded", "off_wrong", "off_undecided", "exact",
            "agree_wrong", "invalid", "threw", "failed"]
    for case, res in zip(cases, out["results"]):
        fam = case["family"]
        row = table.setdefault(fam, dict.fromkeys(keys, 0))
        row["cases"] += 1
        outcomes = check_case(case, res, args.exact_all)
        errs = []
        for k, o in outcomes:
            row["steps"] += 1
            if o.geos:
                row["agree"] += 1
            elif o.geos is not None:
                row[{"right": "off_right", "unrepresentable": "off_unrepr", "operand rounded": "off_rounded",
                     "wrong": "off_wrong",
                     None: "off_undecided"}[o.exact]] += 1
            if o.exact is not None:
                row["exact"] += 1
                if o.geos and o.exact == "wrong":
                    row["agree_wrong"] += 1
            row["invalid"] += any(m.startswith("invalid") for m in o.errors)
            row["threw"] += any(m.startswith("threw") for m in o.errors)
            tag = f"step {k}: " if len(case["steps"]) > 1 else ""
            errs += [tag + m for m in o.errors]
            if args.verbose and not o.geos and not o.errors:
                print(f"  [{fam} {case['id']}] {tag}GEOS disagrees, exact reference: {o.exact}: {o.exact_note}; "
                      f"{o.geos_note}")
        if errs:
            row["failed"] += 1
            failures.append((case, res, errs))
    t3 = time.time()

    head1 = ["", "", "", "GEOS", "GEOS disagrees; exact reference:", "", "", "", "", "exact", "exact wrong,", "", "", ""]
    head2 = ["family", "cases", "steps", "agrees", "ps right", "unrepr.", "op. rounded", "ps wrong", "n/a", "checked",
             "GEOS agreed", "invalid", "threw", "FAILED"]
    rows = []
    order = FAMILY_ORDER + ["named"]
    for fam in sorted(table, key=order.index):
        r = table[fam]
        rows.append([fam] + [r[k] for k in keys])
    total = ["total"] + [sum(r[i] for r in rows) for i in range(1, len(head2))]
    widths = [max(len(str(x)) for x in [c] + [r[i] for r in rows + [total]]) for i, c in enumerate(head2)]
    widths[4] = max(widths[4], 0)

    def fmt(r):
        return "  ".join(str(x).ljust(w) if i == 0 else str(x).rjust(w) for i, (x, w) in enumerate(zip(r, widths)))
    print()
    print("  ".join(h.ljust(w) for h, w in zip(head1, widths)).rstrip())
    print(fmt(head2))
    for r in rows:
        print(fmt(r))
    print(fmt(total))
    print("(unrepr.: polysweep's point set is right but its polygon/hole counts differ from the exact result's, whose "
          "topology cannot be kept in doubles; accepted. op. rounded: the same, where an operand read by its structure "
          "is not a valid polygon set and was made one and rounded first, a known limit; accepted)")
    print()
    printed = {}
    for case, res, errs in failures:
        cid = case["id"]
        printed[case["family"]] = printed.get(case["family"], 0) + 1
        if printed[case["family"]] > 8 and not args.print_all:
            continue
        what = "; ".join(f"{s['op']} ({s['fill']})" for s in case["steps"])
        if any(isinstance(o, dict) for s in case["steps"] for o in s["operands"]):
            what = "chain: " + what
        print(f"FAIL [{case['family']} {cid}] {what}:")
        for e in errs:
            print(f"    {e}")
        print(f"    replay: {py} {script} --seed {args.seed} --case {cid} --show")
        if args.show:
            print("    case: " + json.dumps({"steps": case["steps"]}))
            print("    polysweep: " + json.dumps(res["steps"]))
    hidden = {f: n - 8 for f, n in printed.items() if n > 8 and not args.print_all}
    if hidden:
        print("not printed (--print-all): " + ", ".join(f"{n} more {f}" for f, n in hidden.items()))
    print(f"{len(failures)} of {len(cases)} cases failed; seed {args.seed}. Time: generation {t1 - t0:.1f} s, "
          f"polysweep {t2 - t1:.1f} s (in Node {out['ms'] / 1000:.1f} s), checks {t3 - t2:.1f} s, "
          f"total {t3 - t0:.1f} s")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
