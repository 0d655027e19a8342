"""Hand-worked cases for exact.py (run by run.py first; alone: python3 tests/differential/test_exact.py)."""

import os
import sys
import unittest
from fractions import Fraction

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import exact  # noqa: E402


def sq(x0, y0, x1, y1, cw=False):
    r = [[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]]
    return r[::-1] if cw else r


class ExactTests(unittest.TestCase):
    def check(self, op, operands, fill, area, counts):
        res = exact.overlay(op, operands, fill)
        self.assertEqual(res.area, Fraction(area), f"{op} area")
        self.assertEqual(res.counts(0), counts, f"{op} counts")
        self.assertEqual(sum(a for a, _ in res.rings), res.area, "ring areas add up")
        return res

    def test_two_overlapping_squares(self):
        a, b = [[sq(0, 0, 2, 2)]], [[sq(1, 1, 3, 3)]]
        for fill in ("evenodd", "nonzero", "structure"):
            self.check("intersection", [a, b], fill, 1, (1, 0))
            self.check("union", [a, b], fill, 7, (1, 0))
            self.check("difference", [a, b], fill, 3, (1, 0))
            # two L shapes meeting at (2, 1) and (1, 2): two polygons, no hole
            self.check("xor", [a, b], fill, 6, (2, 0))

    def test_clockwise_input(self):
        a, b = [[sq(0, 0, 2, 2, cw=True)]], [[sq(1, 1, 3, 3)]]
        self.check("union", [a, b], "nonzero", 7, (1, 0))
        self.check("union", [a, b], "positive", 4, (1, 0))
        self.check("union", [a, b], "negative", 4, (1, 0))

    def test_square_with_hole(self):
        holed = [[sq(0, 0, 4, 4), sq(1, 1, 3, 3, cw=True)]]
        self.check("union", [holed, []], "evenodd", 12, (1, 1))
        self.check("union", [holed, []], "nonzero", 12, (1, 1))
        self.check("union", [holed, []], "structure", 12, (1, 1))
        same_way = [[sq(0, 0, 4, 4), sq(1, 1, 3, 3)]]
        self.check("union", [same_way, []], "evenodd", 12, (1, 1))
        self.check("union", [same_way, []], "nonzero", 16, (1, 0))
        self.check("union", [same_way, []], "structure", 12, (1, 1))
        # a bar across the hole: the hole is cut in two
        bar = [[sq(-1, 1.5, 5, 2.5)]]
        self.check("union", [holed, bar], "evenodd", 12 + 6 - 2, (1, 2))
        self.check("intersection", [holed, bar], "evenodd", 2, (2, 0))
        self.check("difference", [holed, bar], "evenodd", 12 - 2, (2, 0))

    def test_pinch_points(self):
        # two squares meeting at a corner: two polygons
        self.check("union", [[[sq(0, 0, 1, 1)]], [[sq(1, 1, 2, 2)]]], "evenodd", 2, (2, 0))
        # a hole touching its shell at one point (paper Fig. 2): one polygon and one hole
        diamond = [[[[4, 0], [6, 4], [4, 6], [2, 4], [4, 0]]]]
        res = self.check("difference", [[[sq(0, 0, 8, 8)]], diamond], "evenodd", 64 - 12, (1, 1))
        self.assertTrue(all(len(set(p)) == len(p) for _, p in res.rings), "rings are simple")
        # diamond touching two opposite sides: two polygons meeting at two points
        diamond2 = [[[[4, 0], [6, 4], [4, 8], [2, 4], [4, 0]]]]
        self.check("difference", [[[sq(0, 0, 8, 8)]], diamond2], "evenodd", 64 - 16, (2, 0))
        # C shape whose tips touch: one polygon with a hole touching its shell
        c_shape = [[[[0, 0], [3, 0], [3, 1], [1, 1], [1, 2], [3, 2], [3, 3], [0, 3], [0, 0]]]]
        tip = [[sq(2, 1, 3, 2)]]
        self.check("union", [c_shape, tip], "evenodd", 8, (1, 1))  # the notch's left half is a hole
        c_touch = [[[[0, 0], [3, 0], [2, 1.5], [3, 3], [0, 3], [0, 0]]]]
        self.check("union", [c_touch, []], "evenodd", Fraction(9) - Fraction(3, 2), (1, 0))
        # a hole touching its shell at (4, 2), given as a hole
        shell_with_hole = [[sq(0, 0, 4, 4), [[4, 2], [2, 1], [2, 3], [4, 2]]]]
        self.check("union", [shell_with_hole, []], "evenodd", 16 - 2, (1, 1))
        # the same as one ring that comes back to (4, 2)
        self_touching = [[[[0, 0], [4, 0], [4, 2], [2, 1], [2, 3], [4, 2], [4, 4], [0, 4]]]]
        for fill in ("evenodd", "nonzero", "structure"):
            self.check("union", [self_touching, []], fill, 16 - 2, (1, 1))
        # two holes touching each other at a point
        two_holes = [[sq(0, 0, 6, 6), sq(1, 1, 3, 3, cw=True), sq(3, 3, 5, 5, cw=True)]]
        self.check("union", [two_holes, []], "evenodd", 36 - 8, (1, 2))

    def test_bowtie(self):
        bowtie = [[[[0, 0], [2, 0], [0, 2], [2, 2], [0, 0]]]]
        for fill in ("evenodd", "nonzero", "structure"):
            self.check("union", [bowtie, []], fill, 2, (2, 0))
        self.check("union", [bowtie, []], "positive", 1, (1, 0))
        self.check("union", [bowtie, []], "negative", 1, (1, 0))
        self.check("intersection", [bowtie, [[sq(0, 0, 2, 1)]]], "evenodd", 1, (1, 0))
        self.check("xor", [bowtie, [[sq(0, 0, 2, 2)]]], "evenodd", 2, (2, 0))

    def test_overlapping_polygons_in_one_operand(self):
        two = [[sq(0, 0, 2, 2)], [sq(1, 0, 3, 2)]]
        self.check("union", [two, []], "evenodd", 4, (2, 0))
        self.check("union", [two, []], "nonzero", 6, (1, 0))
        self.check("union", [two, []], "structure", 6, (1, 0))

    def test_collinear_and_shared_edges(self):
        a, b = [[sq(0, 0, 4, 4)]], [[sq(2, 0, 6, 3)]]
        self.check("union", [a, b], "evenodd", 16 + 6, (1, 0))
        self.check("intersection", [a, b], "evenodd", 6, (1, 0))
        a, b = [[sq(0, 0, 4, 4)]], [[sq(1, -2, 3, 0)]]
        self.check("union", [a, b], "evenodd", 20, (1, 0))
        self.check("intersection", [a, b], "evenodd", 0, (0, 0))
        self.check("xor", [a, a], "evenodd", 0, (0, 0))

    def test_nary(self):
        a, b, c = [[sq(0, 0, 2, 2)]], [[sq(1, 0, 3, 2)]], [[sq(2, 0, 4, 2)]]
        self.check("union", [a, b, c], "evenodd", 8, (1, 0))
        self.check("xor", [a, b, c], "evenodd", 4, (2, 0))  # covered once: x in [0,1] and [3,4]
        self.check("intersection", [a, b, c], "evenodd", 0, (0, 0))
        self.check("difference", [b, a, c], "evenodd", 0, (0, 0))

    def test_rational_crossings(self):
        tri = [[[[0, 0], [3, 0], [0, 3], [0, 0]]]]
        tri2 = [[[[1, 1], [1, -1], [4, 1], [1, 1]]]]
        res = exact.overlay("intersection", [tri, tri2], "evenodd")
        # (1,0) (2.5,0) (2.8,0.2) (2,1) (1,1): 2.8 and 0.2 are crossings, not floats
        self.assertEqual(res.area, Fraction(29, 20))
        self.assertIn((Fraction(14, 5), Fraction(1, 5)), res.rings[0][1])
        self.assertEqual(res.counts(0), (1, 0))

    def test_known_polysweep_bugs(self):
        w1 = [[[0, 0], [-0.491463, 7.98489], [-6.543493, 4.602466]]]
        w2 = [[[0, 0], [-4.90762, 3.45185], [-3.05317, -2.584212]]]
        w3 = [[[0, 0], [-4.579755, -3.876318], [1.743494, -5.7411]]]
        res = exact.overlay("union", [w1, w2, w3], "structure")
        self.assertEqual(float(res.area), 53.12985622384823)
        self.assertEqual(res.counts(0), (2, 0))
        spike = [[[-0.24999999999999745, -0.24999999999999747], [11.500000000000002, -1.2499999999999976],
                  [-4.249999999999998, 10.500000000000002], [-0.24999999999999747, 28.500000000000004],
                  [-0.24999999999999745, -4.249999999999998]]]
        res = exact.overlay("union", [spike, []], "structure")
        self.assertAlmostEqual(float(res.area), 87.59275793650794, delta=1e-12)
        self.assertEqual(res.counts(1e-7 * 87), (2, 0))

    def test_covers(self):
        a, b = [[sq(0, 0, 2, 2)]], [[sq(1, 1, 3, 3)]]
        self.assertTrue(exact.covers("intersection", a, b, (Fraction(3, 2), Fraction(3, 2)), "evenodd"))
        self.assertFalse(exact.covers("intersection", a, b, (Fraction(1, 2), Fraction(3, 2)), "evenodd"))
        self.assertTrue(exact.covers("difference", a, b, (Fraction(1, 2), Fraction(3, 2)), "evenodd"))
        self.assertTrue(exact.covers("xor", a, b, (Fraction(5, 2), Fraction(5, 2)), "nonzero"))
        self.assertFalse(exact.covers("union", a, b, (Fraction(5, 2), Fraction(1, 2)), "nonzero"))
        with self.assertRaises(ValueError):
            exact.covers("union", a, b, (Fraction(2), Fraction(1, 2)), "evenodd")

    def test_float_scales(self):
        for s in (1e-9, 3.0e9, 0.1):
            a = [[[[0, 0], [2 * s, 0], [2 * s, 2 * s], [0, 2 * s]]]]
            b = [[[[s, s], [3 * s, s], [3 * s, 3 * s], [s, 3 * s]]]]
            res = exact.overlay("union", [a, b], "evenodd")
            # exact area of the union of the float squares
            s1, s2, s3 = Fraction(s), Fraction(2 * s), Fraction(3 * s)
            self.assertEqual(res.area, s2 * s2 + (s3 - s1) ** 2 - (s2 - s1) ** 2)
            self.assertEqual(res.counts(0), (1, 0))
            self.assertAlmostEqual(float(res.area), 7 * s * s, delta=1e-12 * s * s)


if __name__ == "__main__":
    unittest.main()
