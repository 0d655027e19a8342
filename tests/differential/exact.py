"""Exact overlay reference for small polygon sets, independent of polysweep and of GEOS.

An operand is a polygon set: a list of polygons, each a list of rings of [x, y] floats (GeoJSON MultiPolygon
coordinates; Polygon coordinates and open rings are accepted too). Its interior is read by a fill rule over all its
rings: 'evenodd', 'nonzero', 'positive', 'negative', or 'structure' (polysweep's default and GEOS's
make_valid(method='structure'): a polygon is where its exterior ring alone winds (non-zero) less where any of its
holes alone winds; an operand is the union of its polygons). 'default' is read as 'structure'.

Method (all arithmetic exact):
  * Every float is a dyadic rational, so all coordinates are scaled by one power of two, L, to integers.
  * Noding: every pair of segments of all rings of all operands is intersected exactly (proper crossings, an
    endpoint touching the other segment, collinear overlaps). Crossing points are rational and kept in homogeneous
    integer coordinates (X, Y, D), D > 0, reduced by their gcd, so equal points compare equal. Each segment is split
    at all the nodes on it; collinear overlapping pieces of different segments become the same sub-edge (deduped).
  * Classification: for a sub-edge p->q with midpoint m and left normal n, the winding number of every ring at a
    point infinitesimally to the left of m is the signed count of crossings of the ray from m in direction +n with
    the ring's segments, leaving out the segments that contain m (they are exactly the segments collinear with the
    sub-edge and covering it: any other segment through m would cross the sub-edge at m, which would be a node).
    The ray from m + eps*n in direction +n lies on the same line as the ray from m, and for eps small enough
    crosses exactly the same segments, except those through m, which it leaves behind it; so this is exact.
    Crossings use the half-open rule of Sunday's winding algorithm in the ray's frame (a rotation and a positive
    scale of the plane, which keeps orientation signs), which is correct for any point on no counted segment.
    Right side: the ray in direction -n. Self-check: left minus right winding of each ring equals the signed count
    of its segments covering the sub-edge (+1 along p->q, -1 against).
  * A sub-edge is on the result's boundary when the result covers exactly one side; it is kept oriented with the
    result on its left. Area = shoelace over these edges.
  * Rings: at each vertex, an incoming boundary edge continues with the outgoing edge that turns most to the left
    (the first outgoing edge clockwise from the way back). Around a vertex boundary edges alternate out/in, with
    the result just counter-clockwise of each outgoing edge, so this pairs each incoming edge with the outgoing edge
    across the same sector of the result: a walk never switches between two pieces of the result that meet at a
    point, so pieces touching at a point are separate rings (separate polygons). A walk can still come back to a
    vertex (a hole touching its shell, two holes touching): every walk is split at repeated vertices into simple
    rings, so such a hole is a ring of its own. Counter-clockwise rings (area > 0) are polygons' exteriors,
    clockwise rings holes: the OGC/GeoJSON reading of the output contract (polygons meet only at points, a hole
    touching its shell at a point is a separate ring, no ring touches itself).

O(n^2) in the number of segments, pure Python: meant for cases of up to a few hundred segments.
"""

from fractions import Fraction
from math import gcd, isfinite, lcm

__all__ = ["normalize_operand", "Arrangement", "overlay", "covers", "inside", "op_function", "ring_counts",
           "ring_area", "RULES"]

RULES = ("evenodd", "nonzero", "positive", "negative", "structure", "default")


# --------------------------------------------------------------------------------------------------------------
# input
# --------------------------------------------------------------------------------------------------------------

def _is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def normalize_operand(operand):
    """MultiPolygon or Polygon coordinates -> list of polygons, each a list of rings, each a list of (x, y) floats
    without the closing repeat and without consecutive duplicates."""
    if not operand:
        return []
    if _is_number(operand[0][0][0]):  # Polygon coordinates
        operand = [operand]
    out = []
    for polygon in operand:
        rings = []
        for ring in polygon:
            pts = []
            for p in ring:
                q = (float(p[0]), float(p[1]))
                if not (isfinite(q[0]) and isfinite(q[1])):
                    raise ValueError("non-finite coordinate")
                if not pts or pts[-1] != q:
                    pts.append(q)
            while len(pts) > 1 and pts[0] == pts[-1]:
                pts.pop()
            rings.append(pts)
        out.append(rings)
    return out


def op_function(op):
    """Membership of the result of an n-ary operation, from the memberships of its operands (polysweep's n-ary
    semantics: difference is the first operand minus all others, xor is 'in an odd number of operands')."""
    if op == "union":
        return any
    if op == "intersection":
        return lambda ins: all(ins) if ins else False
    if op == "difference":
        return lambda ins: bool(ins) and ins[0] and not any(ins[1:])
    if op == "xor":
        return lambda ins: sum(1 for v in ins if v) % 2 == 1
    raise ValueError(op)


def _read(rule, windings, rings_of_polygons):
    """Membership of one operand from the winding numbers of its rings.
    rings_of_polygons: list of lists of ring ids (exterior first)."""
    if rule in ("structure", "default"):
        for ids in rings_of_polygons:
            if ids and windings[ids[0]] != 0 and not any(windings[h] != 0 for h in ids[1:]):
                return True
        return False
    total = sum(windings[r] for ids in rings_of_polygons for r in ids)
    if rule == "evenodd":
        return total % 2 != 0
    if rule == "nonzero":
        return total != 0
    if rule == "positive":
        return total > 0
    if rule == "negative":
        return total < 0
    raise ValueError(rule)


# --------------------------------------------------------------------------------------------------------------
# homogeneous integer points
# --------------------------------------------------------------------------------------------------------------

def _canon(X, Y, D):
    if D < 0:
        X, Y, D = -X, -Y, -D
    g = gcd(gcd(X, Y), D)
    if g > 1:
        X, Y, D = X // g, Y // g, D // g
    return (X, Y, D)


def _add_inside(nodes, a, b, points):
    """Append to `nodes` each of `points` (on the line of segment a b) that lies strictly inside a b."""
    ex, ey = b[0] - a[0], b[1] - a[1]
    length2 = ex * ex + ey * ey
    for px, py in points:
        t = (px - a[0]) * ex + (py - a[1]) * ey
        if 0 < t < length2:
            nodes.append((px, py, 1))


def _orient(ax, ay, bx, by, cx, cy):
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


class Arrangement:
    """All rings of all operands, noded exactly. operands: list of operands (any form normalize_operand takes)."""

    def __init__(self, operands):
        self.operands = [normalize_operand(o) for o in operands]
        # scale to integers
        L = 1
        for op in self.operands:
            for polygon in op:
                for ring in polygon:
                    for x, y in ring:
                        for v in (x, y):
                            d = v.as_integer_ratio()[1]
                            if d > L:
                                L = d
        self.L = L
        self.ring_info = []  # ring id -> operand index
        self.structure = []  # operand -> list of polygons -> list of ring ids
        segs = []  # (ax, ay, bx, by, ring id)
        for k, op in enumerate(self.operands):
            pols = []
            for polygon in op:
                ids = []
                for ring in polygon:
                    rid = len(self.ring_info)
                    self.ring_info.append(k)
                    ids.append(rid)
                    pts = [(self._int(x), self._int(y)) for x, y in ring]
                    if len(pts) >= 2:
                        for i in range(len(pts)):
                            a, b = pts[i], pts[(i + 1) % len(pts)]
                            if a != b:
                                segs.append((a[0], a[1], b[0], b[1], rid))
                pols.append(ids)
            self.structure.append(pols)
        self.segs = segs
        self._node()
        self._windings = None

    def _int(self, v):
        n, d = v.as_integer_ratio()
        return n * (self.L // d)

    # ---- noding ----------------------------------------------------------------------------------------------
    def _node(self):
        segs = self.segs
        n = len(segs)
        nodes = [[(s[0], s[1], 1), (s[2], s[3], 1)] for s in segs]
        boxes = [(min(s[0], s[2]), max(s[0], s[2]), min(s[1], s[3]), max(s[1], s[3])) for s in segs]
        for i in range(n):
            ax, ay, bx, by, _ = segs[i]
            bi = boxes[i]
            for j in range(i + 1, n):
                bj = boxes[j]
                if bj[0] > bi[1] or bj[1] < bi[0] or bj[2] > bi[3] or bj[3] < bi[2]:
                    continue
                cx, cy, dx, dy, _ = segs[j]
                o1 = _orient(ax, ay, bx, by, cx, cy)
                o2 = _orient(ax, ay, bx, by, dx, dy)
                if o1 == 0 and o2 == 0:
                    # collinear: each endpoint strictly inside the other segment is a node of it
                    _add_inside(nodes[i], (ax, ay), (bx, by), ((cx, cy), (dx, dy)))
                    _add_inside(nodes[j], (cx, cy), (dx, dy), ((ax, ay), (bx, by)))
                    continue
                if (o1 > 0 and o2 > 0) or (o1 < 0 and o2 < 0):
                    continue
                o3 = _orient(cx, cy, dx, dy, ax, ay)
                o4 = _orient(cx, cy, dx, dy, bx, by)
                if (o3 > 0 and o4 > 0) or (o3 < 0 and o4 < 0):
                    continue
                # exactly one common point
                if o1 == 0:
                    nodes[i].append((cx, cy, 1))
                elif o2 == 0:
                    nodes[i].append((dx, dy, 1))
                elif o3 == 0:
                    nodes[j].append((ax, ay, 1))
                elif o4 == 0:
                    nodes[j].append((bx, by, 1))
                else:
                    D = o3 - o4
                    p = _canon(ax * D + o3 * (bx - ax), ay * D + o3 * (by - ay), D)
                    nodes[i].append(p)
                    nodes[j].append(p)
        sub = {}
        for i in range(n):
            ax, ay, bx, by, _ = segs[i]
            ex, ey = bx - ax, by - ay
            pts = set(nodes[i])
            keyed = sorted(pts, key=lambda P: Fraction((P[0] - ax * P[2]) * ex + (P[1] - ay * P[2]) * ey, P[2]))
            for p, q in zip(keyed, keyed[1:]):
                key = (p, q) if p < q else (q, p)
                sub[key] = True
        self.subedges = list(sub)

    # ---- classification --------------------------------------------------------------------------------------
    def _compute_windings(self):
        """For each sub-edge (p, q) of self.subedges (direction p->q): winding numbers of every ring just left and
        just right of it."""
        nr = len(self.ring_info)
        segs = self.segs
        out = []
        for p, q in self.subedges:
            X1, Y1, D1 = p
            X2, Y2, D2 = q
            # midpoint m = (MX, MY) / MD
            MX, MY, MD = X1 * D2 + X2 * D1, Y1 * D2 + Y2 * D1, 2 * D1 * D2
            dx, dy = X2 * D1 - X1 * D2, Y2 * D1 - Y1 * D2
            g = gcd(dx, dy)
            dx, dy = dx // g, dy // g
            nx, ny = -dy, dx  # left normal
            left = [0] * nr
            right = [0] * nr
            jump = [0] * nr
            for ax, ay, bx, by, rid in segs:
                # a - m, b - m, scaled by MD > 0
                ux, uy = ax * MD - MX, ay * MD - MY
                vx, vy = bx * MD - MX, by * MD - MY
                # o = cross(b - a, m - a), sign only
                o = (bx - ax) * (-uy) - (by - ay) * (-ux)
                if o == 0 and ux * vx + uy * vy < 0:
                    # segment contains m: collinear with the sub-edge and covering it
                    jump[rid] += 1 if (bx - ax) * dx + (by - ay) * dy > 0 else -1
                    continue
                sa = nx * uy - ny * ux  # cross(n, a - m)
                sb = nx * vy - ny * vx
                # ray from m along +n (left side)
                if sa <= 0 < sb:
                    if o > 0:
                        left[rid] += 1
                elif sb <= 0 < sa:
                    if o < 0:
                        left[rid] -= 1
                # ray from m along -n (right side): side values negated
                if sb < 0 <= sa:
                    if o > 0:
                        right[rid] += 1
                elif sa < 0 <= sb:
                    if o < 0:
                        right[rid] -= 1
            for r in range(nr):
                if left[r] - right[r] != jump[r]:
                    raise AssertionError("exact.py self-check failed: winding jump across a sub-edge")
            out.append((left, right))
        self._windings = out

    def memberships(self, fills):
        """For each sub-edge: (tuple of operand memberships on the left, same on the right)."""
        if self._windings is None:
            self._compute_windings()
        if isinstance(fills, str):
            fills = [fills] * len(self.operands)
        res = []
        for left, right in self._windings:
            res.append((tuple(_read(f, left, s) for f, s in zip(fills, self.structure)),
                        tuple(_read(f, right, s) for f, s in zip(fills, self.structure))))
        return res

    def boundary(self, fn, fills):
        """Directed boundary edges (p, q), homogeneous integer points, the region {fn(memberships)} on the left."""
        edges = []
        for (p, q), (ml, mr) in zip(self.subedges, self.memberships(fills)):
            cl, cr = bool(fn(list(ml))), bool(fn(list(mr)))
            if cl and not cr:
                edges.append((p, q))
            elif cr and not cl:
                edges.append((q, p))
        return edges

    def area(self, edges):
        """Exact area (Fraction, in input units) enclosed by directed boundary edges."""
        s = Fraction(0)
        for (X1, Y1, D1), (X2, Y2, D2) in edges:
            s += Fraction(X1 * Y2 - X2 * Y1, D1 * D2)
        return s / (2 * self.L * self.L)

    def rings(self, edges):
        """Simple rings from directed boundary edges: list of (signed area Fraction, [vertex (x, y) Fractions])."""
        out_edges = {}
        for p, q in edges:
            out_edges.setdefault(p, []).append(q)

        def direction(p, q):
            return (q[0] * p[2] - p[0] * q[2], q[1] * p[2] - p[1] * q[2])

        def half(r, v):
            c = r[0] * v[1] - r[1] * v[0]
            d = r[0] * v[0] + r[1] * v[1]
            return 0 if (c > 0 or (c == 0 and d > 0)) else 1

        def ccw_greater(r, v, w):
            """CCW angle from r to v greater than to w?"""
            hv, hw = half(r, v), half(r, w)
            if hv != hw:
                return hv > hw
            return v[0] * w[1] - v[1] * w[0] < 0

        # successor of each directed edge
        succ = {}
        for p, q in edges:
            cands = out_edges[q]
            back = direction(q, p)
            best = None
            for c in cands:
                v = direction(q, c)
                if best is None or ccw_greater(back, v, bestv):
                    best, bestv = c, v
            succ[(p, q)] = (q, best)
        used = set()
        result = []
        for e in edges:
            if e in used:
                continue
            walk = []
            cur = e
            while cur not in used:
                used.add(cur)
                walk.append(cur[0])
                cur = succ[cur]
            if cur != e:
                raise AssertionError("exact.py: boundary walk did not close")
            # split at repeated vertices
            stack, pos = [], {}
            for v in walk + [walk[0]]:
                if v in pos:
                    k = pos[v]
                    loop = stack[k:]
                    for w in loop[1:]:
                        del pos[w]
                    del stack[k + 1:]
                    if len(loop) >= 3:
                        result.append(loop)
                    elif len(loop) > 0 and len(loop) != 1:
                        raise AssertionError("exact.py: degenerate loop")
                else:
                    pos[v] = len(stack)
                    stack.append(v)
            if len(stack) > 1:
                raise AssertionError("exact.py: walk split left a remainder")
        L2 = 2 * self.L * self.L
        rings = []
        for loop in result:
            s = Fraction(0)
            for i in range(len(loop)):
                (X1, Y1, D1), (X2, Y2, D2) = loop[i], loop[(i + 1) % len(loop)]
                s += Fraction(X1 * Y2 - X2 * Y1, D1 * D2)
            pts = [(Fraction(X, D * self.L), Fraction(Y, D * self.L)) for X, Y, D in loop]
            rings.append((s / L2, pts))
        return rings


def ring_counts(rings, threshold):
    """(polygons, holes): counter-clockwise and clockwise rings whose |area| exceeds threshold."""
    thr = Fraction(threshold)
    return (sum(1 for a, _ in rings if a > thr), sum(1 for a, _ in rings if -a > thr))


class Overlay:
    def __init__(self, area, rings):
        self.area = area
        self.rings = rings

    def counts(self, threshold):
        return ring_counts(self.rings, threshold)


def overlay(op, operands, fill):
    """Exact result of op (union/intersection/difference/xor, n-ary) on operands read by fill (a rule, or one rule
    per operand): an Overlay with .area (Fraction), .rings [(signed area, vertices)], .counts(threshold)."""
    arr = Arrangement(operands)
    edges = arr.boundary(op_function(op), fill)
    return Overlay(arr.area(edges), arr.rings(edges))


def _ratio(v):
    return v.as_integer_ratio() if isinstance(v, float) else (v.numerator, v.denominator)


def _winding_at(point, operands):
    """Winding number of every ring at a rational point (x, y) (floats, ints or Fractions); raises ValueError if
    the point is on an edge. Integer arithmetic after scaling every coordinate by the lcm of their denominators."""
    ops = [normalize_operand(o) for o in operands]
    pr = [_ratio(point[0]) if not isinstance(point[0], int) else (point[0], 1),
          _ratio(point[1]) if not isinstance(point[1], int) else (point[1], 1)]
    L = lcm(pr[0][1], pr[1][1])
    for op in ops:
        for polygon in op:
            for ring in polygon:
                for x, y in ring:
                    L = lcm(L, x.as_integer_ratio()[1], y.as_integer_ratio()[1])
    px, py = pr[0][0] * (L // pr[0][1]), pr[1][0] * (L // pr[1][1])

    def scaled(v):
        n, d = v.as_integer_ratio()
        return n * (L // d)
    ws = []
    structure = []
    rid = 0
    for op in ops:
        pols = []
        for polygon in op:
            ids = []
            for ring in polygon:
                w = 0
                pts = [(scaled(x), scaled(y)) for x, y in ring]
                for i in range(len(pts) if len(pts) >= 2 else 0):
                    a, b = pts[i], pts[(i + 1) % len(pts)]
                    o = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
                    if o == 0 and min(a[0], b[0]) <= px <= max(a[0], b[0]) and min(a[1], b[1]) <= py <= max(a[1], b[1]):
                        raise ValueError("point on an edge")
                    if a[1] <= py < b[1] and o > 0:
                        w += 1
                    elif b[1] <= py < a[1] and o < 0:
                        w -= 1
                ws.append(w)
                ids.append(rid)
                rid += 1
            pols.append(ids)
        structure.append(pols)
    return ws, structure


def ring_area(ring):
    """Exact signed shoelace area (Fraction) of a ring of float (or int) coordinates, closed or open."""
    L = 1
    for x, y in ring:
        L = max(L, float(x).as_integer_ratio()[1], float(y).as_integer_ratio()[1])
    pts = []
    for x, y in ring:
        nx, dx = float(x).as_integer_ratio()
        ny, dy = float(y).as_integer_ratio()
        pts.append((nx * (L // dx), ny * (L // dy)))
    s = 0
    for i in range(len(pts)):
        (x1, y1), (x2, y2) = pts[i], pts[(i + 1) % len(pts)]
        s += x1 * y2 - x2 * y1
    return Fraction(s, 2 * L * L)


def inside(operand, point, fill):
    """Exact membership of a rational point (on no edge) in one operand read by fill."""
    ws, structure = _winding_at(point, [operand])
    return _read(fill, ws, structure[0])


def covers(op, A, B, point, fill):
    """Exact membership of a rational point (not on any edge) in op(A, B), both operands read by fill."""
    ws, structure = _winding_at(point, [A, B])
    return bool(op_function(op)([_read(fill, ws, s) for s in structure]))
