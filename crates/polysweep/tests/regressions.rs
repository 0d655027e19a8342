//! Cases found by review, each with its expectation worked out by hand.

use polysweep::{
    difference, intersection, overlay, overlay_all, overlay_with_stats, union, union_all, xor_all,
    FillRule, MultiPolygon, Operation, Options,
};

/// Intersection and difference skip polygons outside the box where the result can lie. A hole ring may reach
/// outside its own exterior (under even-odd its outer part is filled), so that box must be of all the rings.
#[test]
fn a_hole_reaching_outside_its_shell_still_counts() {
    let square =
        |x0: f64, y0: f64, x1: f64, y1: f64| vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]];
    let p = MultiPolygon::from_coordinates(&[vec![
        square(0.0, 0.0, 4.0, 4.0),
        square(3.0, 3.0, 8.0, 8.0),
    ]]);
    let q = MultiPolygon::from_coordinates(&[vec![square(5.0, 5.0, 7.0, 7.0)]]);
    // Q lies inside the "hole" ring and outside the exterior: covered once, so inside P.
    assert_eq!(intersection(&p, &q).unwrap().area(), 4.0);
    assert_eq!(intersection(&q, &p).unwrap().area(), 4.0);
    assert_eq!(difference(&q, &p).unwrap().area(), 0.0);
    assert_eq!(
        difference(&p, &q).unwrap().area(),
        16.0 + 25.0 - 2.0 * 1.0 - 4.0
    );
}

/// Found by the property test of n-ary operations (with a seed other than CI's): a vertex of one operand that is a
/// rounded crossing point, (5/3, 13/3) to the nearest floats, lies within an ulp of the other operand's edge from
/// (1, 5) to (2, 4), and an edge of the first operand passes within an ulp of (2, 4). The result's ring then has a
/// hairpin there whose two sides round onto each other, and the ring was dropped as if rounding had inverted it.
/// Expected: the pentagon (2, 2), (16/7, 12/7), (4, 3), (2, 4), (3, 3), area 10/7, plus a sliver thinner than an
/// ulp along (5/3, 13/3) to (2, 4).
#[test]
fn a_ring_with_a_hairpin_at_merged_vertices_is_kept() {
    let a = MultiPolygon::from_coordinates(&[vec![vec![
        [0.0, 0.0],
        [4.0, 3.0],
        [2.0, 4.0],
        [1.0, 5.0],
    ]]]);
    let b = MultiPolygon::from_coordinates(&[vec![vec![
        [5.0 / 3.0, 13.0 / 3.0],
        [3.0, 3.0],
        [2.0, 2.0],
        [4.0, 0.0],
        [4.0, 3.0],
        [2.0, 5.0],
    ]]]);
    for result in [intersection(&a, &b).unwrap(), intersection(&b, &a).unwrap()] {
        assert!(polysweep::validate(&result).is_ok());
        assert!(
            (result.area() - 10.0 / 7.0).abs() < 1e-12,
            "area {}",
            result.area()
        );
    }
}

/// Found by the property test of n-ary operations (with a seed other than CI's). Operand 1's two triangles cross at
/// (16/5, 9/5), which its own sweep rounds to the nearest floats; operand 0's edge from (0, 1) to (4, 2) and operand
/// 2's from (3, 1) to (4, 5) cross exactly there too. In the final sweep these make distinct exact points within an
/// ulp of each other, and one that comes later in sweep order rounds onto an earlier one. A result ring of area
/// 3/5 was then checked at the rounded vertex that comes first, where it turns the other way (that vertex is not
/// its exact extreme), and was dropped as a sliver. Expected: the xor of all three, which is the even-odd fill of
/// the five triangles together, area 6577/990 (integrated exactly by hand, slab by slab between the x of every
/// vertex and crossing, over the odd intervals of each slab).
#[test]
fn a_ring_is_checked_at_its_exact_extreme_vertex() {
    let triangles = |rings: &[[[f64; 2]; 3]]| {
        MultiPolygon::from_coordinates(
            &(rings.iter())
                .map(|r| vec![vec![r[0], r[1], r[2], r[0]]])
                .collect::<Vec<_>>(),
        )
    };
    let operands = [
        triangles(&[[[0.0, 2.0], [0.0, 1.0], [4.0, 2.0]]]),
        triangles(&[
            [[0.0, 2.0], [0.0, 1.0], [4.0, 2.0]],
            [[0.0, 0.0], [4.0, 1.0], [1.0, 4.0]],
        ]),
        triangles(&[
            [[3.0, 0.0], [4.0, 3.0], [0.0, 3.0]],
            [[0.0, 0.0], [3.0, 1.0], [4.0, 5.0]],
        ]),
    ];
    let result = xor_all(&operands).unwrap();
    assert!(polysweep::validate(&result).is_ok());
    let expected = 6577.0 / 990.0;
    assert!(
        (result.area() - expected).abs() < 1e-12,
        "area {} instead of {expected}",
        result.area()
    );
}

/// Found by a scratch run of random operands on a grid of spacing 0.1 (decimal coordinates, which floats do not
/// represent, so vertices lie within ulps of other edges without being on them). Near (0.7, 0.2) the union
/// has a cluster of crossings a few ulps apart; rounding them moved edges across each other, and the repair passes
/// (sweeps of the rounded result, before snap rounding) cycled on the same rounding without converging, leaving
/// edges that cross. Expected: a valid result, of area
/// 0.145545618597089... (the union integrated exactly in rationals from the floats given, slab by slab between the x
/// of every vertex and crossing).
#[test]
fn rounding_a_cluster_of_crossings_leaves_no_edges_crossing() {
    let a = MultiPolygon::from_coordinates(&[vec![vec![
        [0.4, 0.7000000000000001],
        [0.1, 0.2],
        [0.2, 0.30000000000000004],
        [0.4, 0.7000000000000001],
    ]]]);
    let b = MultiPolygon::from_coordinates(&[
        vec![vec![
            [0.4, 0.7000000000000001],
            [0.4, 0.2],
            [0.6000000000000001, 0.4],
            [0.2, 0.0],
            [0.8, 0.1],
            [0.4, 0.5],
            [0.30000000000000004, 0.4],
            [0.4, 0.5],
            [0.4, 0.7000000000000001],
        ]],
        vec![vec![
            [0.7000000000000001, 0.2],
            [0.2, 0.5],
            [0.30000000000000004, 0.6000000000000001],
            [0.7000000000000001, 0.1],
            [0.4, 0.30000000000000004],
            [0.7000000000000001, 0.2],
        ]],
        vec![vec![
            [0.1, 0.30000000000000004],
            [0.2, 0.5],
            [0.30000000000000004, 0.1],
            [0.1, 0.30000000000000004],
        ]],
    ]);
    let (result, stats) =
        overlay_with_stats(Operation::Union, &a, &b, &Options::default()).unwrap();
    assert_eq!(polysweep::validate(&result), Ok(()));
    assert!((result.area() - 0.145_545_618_597_089_2).abs() < 1e-12);
    // Rounded plainly, edges cross: the result is snap-rounded and read back (see docs/robustness.md, §3).
    assert_eq!(stats.snap_rounding_sweeps, 2);
}

/// Issue 24: three triangles fanned around the origin. W2's vertex (-3.05317, -2.584212) lies 7e-17 rad off W3's
/// edge from the origin to (-4.579755, -3.876318), exactly on W2's side, so W3 meets W1 and W2 only at the origin.
/// W2's vertex (-4.90762, 3.45185) lies inside W1, so the final sweep constructs a crossing and rounds; the snapping
/// of close calls (before snap rounding replaced it) bent W3's edge through W2's vertex, and the union came out as
/// one polygon. Expected: two
/// polygons, W1 ∪ W2 and W3, of area 53.12985622384823 (in rationals from the floats given: the pentagon of W1 ∪ W2
/// through the crossing, plus W3).
#[test]
fn triangles_fanned_around_a_point_stay_apart() {
    let triangle = |points: [[f64; 2]; 3]| {
        MultiPolygon::from_coordinates(&[vec![vec![points[0], points[1], points[2], points[0]]]])
    };
    let w1 = triangle([[0.0, 0.0], [-0.491463, 7.98489], [-6.543493, 4.602466]]);
    let w2 = triangle([[0.0, 0.0], [-4.90762, 3.45185], [-3.05317, -2.584212]]);
    let w3 = triangle([[0.0, 0.0], [-4.579755, -3.876318], [1.743494, -5.7411]]);
    let result = union_all(&[w1, w2, w3]).unwrap();
    assert_eq!(polysweep::validate(&result), Ok(()));
    assert_eq!(result.0.len(), 2);
    assert!((result.area() - 53.129_856_223_848_23).abs() < 1e-12);
}

/// Issue 24: a ring whose last two edges run down x = -0.24999999999999745 from an ulp to its left, to
/// (-0.25, -4.25), and back up it to (-0.25, -0.25). The first edge crosses another 1e-17 left of the line, and that
/// crossing rounds onto it: the edge from it down to (-0.25, -4.25) became vertical and ran back along the other, a
/// spike. The sweep noted no close call there: the edge passes 3e-18 from (-0.25, -0.25) but leaves the sweep line
/// at its lower end, before that point is met at the same x. Expected: two triangles, of area 87.59275793650794
/// (in rationals from the floats given).
#[test]
fn an_edge_that_rounding_makes_vertical_is_noticed() {
    let ring = MultiPolygon::from_coordinates(&[vec![vec![
        [-0.24999999999999745, -0.24999999999999747],
        [11.500000000000002, -1.2499999999999976],
        [-4.249999999999998, 10.500000000000002],
        [-0.24999999999999747, 28.500000000000004],
        [-0.24999999999999745, -4.249999999999998],
    ]]]);
    for fill_rule in [FillRule::EvenOdd, FillRule::NonZero] {
        let options = Options::default().with_fill_rule(fill_rule);
        let result = overlay(Operation::Union, &ring, &MultiPolygon::default(), &options).unwrap();
        assert_eq!(polysweep::validate(&result), Ok(()), "{fill_rule:?}");
        assert_eq!(result.0.len(), 2, "{fill_rule:?}");
        assert!((result.area() - 87.592_757_936_507_94).abs() < 1e-12);
    }
}

/// Found by the decimal-grid property test with another seed: the union of A ∪ B (two triangles that touch) with C
/// (three rings, one crossing itself) has a hole whose ring had a point inserted by snapping. The ring's
/// lowest-leftmost vertex was looked for among its written points by edge index, which that point shifts: the
/// edges found there were not the ones at that vertex, and the edge below them was the hole's own, so the hole was
/// placed by testing its vertices, the first off the shell's boundary an ulp outside it. The hole was dropped, and
/// the union filled it. Expected: area 0.22168925142942347 (the union integrated exactly in rationals, slab by slab).
#[test]
fn a_hole_with_snapped_points_finds_its_shell() {
    let grid = |rings: &[&[(i32, i32)]]| {
        let ring = |r: &[(i32, i32)]| -> Vec<[f64; 2]> {
            r.iter()
                .map(|&(x, y)| [x as f64 * 0.1, y as f64 * 0.1])
                .collect()
        };
        MultiPolygon::from_coordinates(&rings.iter().map(|r| vec![ring(r)]).collect::<Vec<_>>())
    };
    let a = grid(&[&[(7, 6), (4, 3), (0, 0), (3, 2)]]);
    let b = grid(&[&[(3, 6), (0, 0), (0, 6)]]);
    let c = grid(&[
        &[(0, 1), (1, 0), (0, 0)],
        &[(0, 3), (8, 6), (1, 2), (3, 0), (8, 7)],
        &[(5, 4), (6, 5), (5, 0)],
    ]);
    let result = union(&union(&a, &b).unwrap(), &c).unwrap();
    assert_eq!(polysweep::validate(&result), Ok(()));
    assert!((result.area() - 0.221_689_251_429_423_47).abs() < 1e-12);
}

/// Issue 24, found by the differential test (tests/differential, seed 20091, case 148): B's vertex
/// (-1.2002201991730366e-06, 0.0261872278596968) lies within 1e-18 of A's lower edge, and B's two edges cross that
/// edge a few ulps from it. The snapping of close calls (before snap rounding replaced it) bent an edge through a
/// crossing's rounded point, and the xor came out as one polygon with a hole. Rounded plainly, the result is valid,
/// and has the exact topology:
/// two polygons, no hole, of area 2.9342839989984237 (the exact reference, `exact.py`, in rationals).
#[test]
fn a_vertex_an_ulp_from_an_edge_keeps_the_xor_in_two() {
    let a = MultiPolygon::from_coordinates(&[vec![vec![
        [-1.0, -0.1007313058064152],
        [1.0, 0.15310606618654998],
        [1.116240068529813, 1.5],
        [-0.9679151014053681, 1.5],
    ]]]);
    let b = MultiPolygon::from_coordinates(&[vec![vec![
        [-0.9424646166933064, -0.7454047433698368],
        [-1.2002201991730366e-06, 0.0261872278596968],
        [-0.8360882769044637, 0.7194599399211659],
    ]]]);
    let result = polysweep::xor(&a, &b).unwrap();
    assert_eq!(polysweep::validate(&result), Ok(()));
    assert_eq!(result.0.len(), 2);
    assert!(result.0.iter().all(|p| p.holes.is_empty()));
    assert!((result.area() - 2.934_283_998_998_423_7).abs() < 1e-12);
}

/// Issue 24, found by the fuzzer (`fuzz/`, with debug assertions): the xor of three operands on a grid of spacing
/// 0.7, nudged by a few ulps, needs snap rounding. On the floats' own cells, two long snapped edges from x < 0 to
/// x ≈ 0.37, whose ends lie in neighbouring cells, crossed: the cells shrink towards zero, and the argument for snap
/// rounding holds on uniform grids only. Snapped on the uniform grid, the result is valid. Expected: its area,
/// 47.36406256690653 (the exact reference, `tests/differential/exact.py`, in rationals).
#[test]
fn snap_rounding_across_powers_of_two_uses_a_uniform_grid() {
    let operands = [
        MultiPolygon::from_coordinates(&[
            vec![vec![
                [4.900000000000002, -4.199999999999997],
                [-5.599999999999998, -4.2],
                [3.4999999999999987, -0.6999999999999997],
                [-2.7999999999999994, -5.599999999999999],
                [-4.199999999999998, 3.4999999999999996],
                [4.900000000000002, -2.799999999999998],
                [-4.199999999999997, -5.599999999999997],
                [-5.599999999999998, 3.4999999999999987],
                [-2.1, -2.1],
                [-5.599999999999996, -5.599999999999996],
            ]],
            vec![vec![
                [-5.599999999999999, -4.2],
                [-2.799999999999998, 2.100000000000001],
                [4.900000000000002, -5.599999999999999],
                [-5.599999999999998, -2.1],
                [3.5000000000000013, -5.599999999999996],
                [-4.2, 3.4999999999999987],
                [-2.100000000000001, -2.1],
                [-5.599999999999996, -5.599999999999996],
            ]],
            vec![vec![
                [-5.599999999999998, -4.2],
                [4.899999999999999, -2.1],
                [3.5000000000000013, -5.599999999999996],
            ]],
        ]),
        MultiPolygon::from_coordinates(&[vec![
            vec![[-4.2, 3.4999999999999987]],
            vec![
                [4.900000000000001, -5.599999999999999],
                [-5.599999999999998, -2.1],
                [3.5000000000000013, -5.599999999999996],
                [-4.2, 3.4999999999999987],
            ],
            vec![
                [4.900000000000002, 4.900000000000002],
                [-5.599999999999997, -5.599999999999998],
                [-2.7999999999999985, 3.4999999999999987],
            ],
        ]]),
        MultiPolygon::from_coordinates(&[
            vec![
                vec![[-4.2, 3.4999999999999987]],
                vec![
                    [4.900000000000002, -5.599999999999999],
                    [-5.599999999999998, -2.1],
                    [3.5000000000000013, -5.599999999999996],
                    [-4.2, 3.4999999999999987],
                    [-2.100000000000001, -2.1],
                    [3.5000000000000013, -5.599999999999996],
                ],
            ],
            vec![vec![
                [-5.599999999999999, -4.2],
                [4.900000000000002, 4.900000000000002],
                [-5.599999999999996, -2.1],
                [-5.599999999999996, 4.900000000000002],
            ]],
        ]),
    ];
    let options = Options::default().with_fill_rule(FillRule::EvenOdd);
    let result = overlay_all(Operation::Xor, &operands, &options).unwrap();
    assert_eq!(polysweep::validate(&result), Ok(()));
    assert!((result.area() - 47.364_062_566_906_53).abs() < 1e-12);
}

/// Issue 24, found by the fuzzer: the xor of three operands on a grid of spacing 0.7, nudged by a few ulps, is
/// snap-rounded, and the sweep back, which rounds nothing, has a hole thin enough that its float area came out with
/// the wrong sign. The ring walk took that for a sliver turned inside out by rounding and dropped it, leaving the
/// island inside it overlapping its shell. A ring none of whose vertices is rounded has its exact turn as its
/// orientation. Expected: a valid result of area 40.93319410326232 (the exact reference, `exact.py`).
#[test]
fn a_ring_written_exactly_has_its_exact_orientation() {
    let operands = [
        MultiPolygon::from_coordinates(&[
            vec![vec![
                [4.900000000000002, -4.199999999999997],
                [-5.599999999999998, -4.2],
                [3.4999999999999987, -3.499999999999999],
                [-2.7999999999999994, -5.599999999999999],
                [-2.799999999999998, 2.100000000000001],
                [4.900000000000002, 4.900000000000002],
                [4.900000000000002, 4.900000000000002],
                [4.900000000000002, -5.599999999999996],
                [-4.2, 3.4999999999999987],
                [-2.100000000000001, -2.1],
                [-5.599999999999996, -5.599999999999996],
            ]],
            vec![vec![
                [-5.599999999999998, -4.2],
                [4.899999999999999, -2.1],
                [3.5000000000000013, -5.6],
            ]],
        ]),
        MultiPolygon::from_coordinates(&[
            vec![
                vec![[-4.2, 3.4999999999999987]],
                vec![
                    [4.900000000000001, -5.599999999999999],
                    [-5.599999999999998, -2.1],
                    [2.800000000000001, 4.900000000000002],
                    [-5.599999999999997, 4.899999999999999],
                ],
                vec![
                    [3.4999999999999987, -0.6999999999999997],
                    [-2.7999999999999994, -5.599999999999999],
                    [-4.199999999999998, 3.4999999999999996],
                    [4.900000000000002, -2.799999999999998],
                    [-4.199999999999997, -5.599999999999997],
                    [-5.599999999999998, 3.4999999999999987],
                    [-2.1, -2.1],
                    [-5.599999999999996, 4.900000000000002],
                ],
            ],
            vec![
                vec![[2.800000000000001, -4.2], [-2.1, 3.5000000000000013]],
                vec![
                    [3.4999999999999996, -3.4999999999999996],
                    [-5.599999999999996, 4.900000000000002],
                ],
                vec![
                    [4.899999999999999, -5.599999999999998],
                    [-2.7999999999999985, -5.599999999999999],
                    [-4.199999999999998, 3.4999999999999996],
                    [4.900000000000002, -2.799999999999998],
                    [-4.199999999999997, -5.599999999999997],
                    [-5.599999999999998, 3.4999999999999987],
                    [-2.1, -2.1],
                    [-5.599999999999996, -5.599999999999996],
                ],
            ],
            vec![vec![
                [-5.599999999999999, -4.2],
                [-2.799999999999998, 2.100000000000001],
                [4.900000000000002, 4.900000000000002],
                [4.900000000000002, 4.900000000000002],
                [4.900000000000002, -5.599999999999996],
                [-4.2, 3.4999999999999987],
                [-2.100000000000001, -2.1],
                [-5.599999999999996, -5.599999999999996],
            ]],
        ]),
        MultiPolygon::from_coordinates(&[
            vec![
                vec![[-4.2, 3.4999999999999987]],
                vec![
                    [4.900000000000001, -5.599999999999999],
                    [-5.599999999999998, -2.1],
                    [2.800000000000001, 4.900000000000002],
                    [-5.599999999999997, 4.899999999999999],
                ],
                vec![
                    [3.4999999999999987, -0.6999999999999997],
                    [-2.7999999999999994, -5.599999999999999],
                    [-4.199999999999998, 3.4999999999999996],
                    [4.900000000000002, -2.799999999999998],
                    [-4.199999999999997, -5.599999999999997],
                    [-5.599999999999998, 3.4999999999999987],
                    [-2.1, -2.1],
                    [-5.599999999999996, 4.900000000000002],
                ],
            ],
            vec![vec![[2.800000000000001, -4.2], [-2.1, 3.5000000000000013]]],
        ]),
    ];
    let options = Options::default().with_fill_rule(FillRule::EvenOdd);
    let result = overlay_all(Operation::Xor, &operands, &options).unwrap();
    assert_eq!(polysweep::validate(&result), Ok(()));
    assert!((result.area() - 40.933_194_103_262_32).abs() < 1e-12);
}
