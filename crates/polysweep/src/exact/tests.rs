//! Tests of the exact predicates against rational arithmetic and float formulas.

use super::*;

#[test]
fn crossing_is_exact_and_predicates_see_it_on_both_lines() {
    let mut exact = Exact::default();
    // Lines whose crossing (1/3, 1/3) is not representable in binary floating point.
    let l = Line {
        a: [0.0, 0.0],
        b: [1.0, 1.0],
    };
    let m = Line {
        a: [0.0, 1.0],
        b: [0.5, 0.0],
    };
    let x = exact.crossing(&l, &m);
    assert_eq!(exact.orient(&l, &x), Ordering::Equal);
    assert_eq!(exact.orient(&m, &x), Ordering::Equal);
    let rounded = SweepPoint::input(x.approx);
    assert_ne!(
        exact.cmp_points(&x, &rounded),
        Ordering::Equal,
        "1/3 is not a float"
    );
    assert_eq!({ x.approx }, [1.0 / 3.0, 1.0 / 3.0]);
}

#[test]
fn a_point_knows_its_crossing_and_which_coordinates_are_exact() {
    assert_eq!(std::mem::size_of::<SweepPoint>(), 20);
    assert_eq!(std::mem::size_of::<Crossing>(), 72);
    let input = SweepPoint::input([0.25, -3.0]);
    assert!(input.is_input() && input.is_exact(0) && input.is_exact(1));
    let mut exact = Exact::default();
    let diagonal = Line {
        a: [0.0, 0.0],
        b: [3.0, 1.0],
    };
    let lines = [
        // (1/2, 1/6): x exact, y rounded.
        Line {
            a: [0.5, -1.0],
            b: [0.5, 1.0],
        },
        // (3/7, 1/7): both rounded.
        Line {
            a: [0.0, 1.0],
            b: [1.0, -1.0],
        },
        // (3/2, 1/2): both exact.
        Line {
            a: [0.0, 0.5],
            b: [2.0, 0.5],
        },
    ];
    for (index, (line, exact_axes)) in lines
        .iter()
        .zip([[true, false], [false, false], [true, true]])
        .enumerate()
    {
        let p = exact.crossing(&diagonal, line);
        // A crossing with both coordinates floats is a point like an input vertex, without a record.
        let recorded = exact_axes != [true, true];
        assert_eq!(p.is_input(), !recorded, "crossing {index}");
        if recorded {
            assert_eq!(p.crossing(), index as u32);
        }
        assert_eq!(exact.crossing_count(), index + 1);
        assert_eq!(
            [p.is_exact(0), p.is_exact(1)],
            exact_axes,
            "crossing {index}"
        );
    }
}

#[test]
fn coordinates_compare_exactly_around_crossings() {
    // Crossings of random lines, each coordinate compared, against the exact fractions, with its own rounding
    // and the floats next to it (as input points), and with the other crossings.
    let mut exact = Exact::default();
    let mut random = crate::test_random::unit(41);
    let mut crossings = Vec::new();
    for _ in 0..200 {
        let mut point = || [random() * 8.0 - 4.0, random() * 8.0 - 4.0];
        let (l, m) = (
            Line {
                a: point(),
                b: point(),
            },
            Line {
                a: point(),
                b: point(),
            },
        );
        if exact.orient(&l, &SweepPoint::input(m.a)) != exact.orient(&l, &SweepPoint::input(m.b)) {
            crossings.push(exact.crossing(&l, &m));
        }
    }
    assert!(crossings.len() > 50);
    // Input coordinates compare as numbers: -0 equals 0.
    for (u, v, order) in [
        (-0.0, 0.0, Ordering::Equal),
        (-1.0, 0.0, Ordering::Less),
        (2.0, -0.0, Ordering::Greater),
        (f64::MIN_POSITIVE, 0.0, Ordering::Greater),
    ] {
        let (p, q) = (SweepPoint::input([u, v]), SweepPoint::input([v, u]));
        assert_eq!(exact.cmp_coordinate(&p, &q, 0), order, "{u} against {v}");
        assert_eq!(exact.cmp_coordinate(&p, &q, 1), order.reverse());
    }
    let exactly = |exact: &Exact, p: &SweepPoint, q: &SweepPoint, axis: usize| {
        let ((pn, pd), (qn, qd)) = (exact.fraction(p, axis), exact.fraction(q, axis));
        (&(&pn * &qd) - &(&qn * &pd)).sign()
    };
    for p in &crossings {
        for axis in 0..2 {
            let v = p.approx[axis];
            for f in [
                v.next_down().next_down(),
                v.next_down(),
                v,
                v.next_up(),
                v.next_up().next_up(),
            ] {
                let mut q = p.approx;
                q[axis] = f;
                let q = SweepPoint::input(q);
                assert_eq!(
                    exact.cmp_coordinate(p, &q, axis),
                    exactly(&exact, p, &q, axis)
                );
                assert_eq!(
                    exact.cmp_coordinate(&q, p, axis),
                    exactly(&exact, &q, p, axis)
                );
            }
            for q in &crossings {
                assert_eq!(
                    exact.cmp_coordinate(p, q, axis),
                    exactly(&exact, p, q, axis)
                );
            }
        }
    }
}

#[test]
fn float_rounding_of_crossings_agrees_with_exact_rounding() {
    // Crossings of many kinds of lines: real-looking coordinates with short edges (which the float estimate
    // must nearly always round), and integer, tiny, huge, axis-parallel and nearly parallel ones, whose
    // crossings are often exactly on floats or on midpoints between them (which it must leave alone).
    let mut random = crate::test_random::unit(0x9e37_79b9_7f4a_7c15);
    let mut estimated = [0usize; 6];
    let mut tried = [0usize; 6];
    for i in 0..60_000 {
        let kind = i % 6;
        let snap = |p: [f64; 2]| match kind {
            1 => p.map(|v| (v * 16.0).floor()),
            2 => p.map(|v| (v * 1024.0).floor() * 2f64.powi(-40)),
            3 => p.map(|v| (v * 1e9).floor() + 1e9),
            _ => p,
        };
        let mut point =
            |scale: f64, offset: f64| snap([offset + random() * scale, offset + random() * scale]);
        let (scale, offset) = if kind == 0 {
            (360.0, -180.0)
        } else {
            (1.0, 0.0)
        };
        let [a1, b1, a2, b2, short] = [(); 5].map(|_| point(scale, offset));
        let mut l = Line { a: a1, b: b1 };
        let mut m = Line { a: a2, b: b2 };
        if kind == 0 || kind == 4 {
            // A short edge near the first one, as a coastline's against a grid's or its own.
            m.a = [
                a1[0] + (short[0] - offset) / scale - 0.5,
                a1[1] + (short[1] - offset) / scale - 0.5,
            ];
            l.b = [
                a1[0] + (b2[0] - offset) / scale * 0.5,
                a1[1] + (b2[1] - offset) / scale - 0.5,
            ];
        }
        if kind == 4 {
            m.b[0] = m.a[0]; // vertical
        }
        if kind == 5 {
            // Nearly parallel: crossing the first one in its middle at an angle of about 1e-12 or less.
            let (mid, dir) = (
                [(a1[0] + b1[0]) / 2.0, (a1[1] + b1[1]) / 2.0],
                [b1[0] - a1[0], b1[1] - a1[1]],
            );
            let tilt = 1e-12 * random().powi(8);
            m.a = [
                mid[0] - 0.3 * dir[0] - tilt * dir[1],
                mid[1] - 0.3 * dir[1] + tilt * dir[0],
            ];
            m.b = [
                mid[0] + 0.3 * dir[0] + tilt * dir[1],
                mid[1] + 0.3 * dir[1] - tilt * dir[0],
            ];
        }
        if l.a == l.b || m.a == m.b || Exact::default().cross_directions(&l, &m) == Ordering::Equal
        {
            continue;
        }
        // As in the sweep, only segments that properly cross.
        let exact_predicates = Exact::default();
        let side = |line: &Line, p: [f64; 2]| exact_predicates.orient(line, &SweepPoint::input(p));
        if side(&l, m.a) == side(&l, m.b) || side(&m, l.a) == side(&m, l.b) {
            continue;
        }
        tried[kind] += 1;
        let (exact, exactly) = Fraction::crossing(&l, &m).rounded();
        if let Some((approx, representable)) = estimate::rounded_crossing(&l, &m) {
            estimated[kind] += 1;
            assert_eq!(approx, exact, "kind {kind}: {l:?} × {m:?}");
            for axis in 0..2 {
                assert!(
                    !representable[axis] || exactly[axis],
                    "kind {kind}: {l:?} × {m:?}"
                );
            }
        }
    }
    assert!(
        estimated[0] * 100 >= tried[0] * 99,
        "real-looking crossings rounded by floats: {} of {}",
        estimated[0],
        tried[0]
    );
    assert!(
        estimated[4] * 10 >= tried[4] * 9,
        "{estimated:?} of {tried:?}"
    );
}

#[test]
fn crossing_against_axis_parallel_lines() {
    let mut exact = Exact::default();
    let diagonal = Line {
        a: [0.0, 0.0],
        b: [3.0, 1.0],
    };
    let steep = Line {
        a: [0.0, 1.0],
        b: [1.0, 0.0],
    };
    let x = exact.crossing(&diagonal, &steep); // (3/4, 1/4)
    let horizontal = |y: f64, forward: bool| {
        let (a, b) = ([-5.0, y], [5.0, y]);
        if forward {
            Line { a, b }
        } else {
            Line { a: b, b: a }
        }
    };
    let vertical = |x: f64, up: bool| {
        let (a, b) = ([x, -5.0], [x, 5.0]);
        if up {
            Line { a, b }
        } else {
            Line { a: b, b: a }
        }
    };
    assert_eq!(exact.orient(&horizontal(0.25, true), &x), Ordering::Equal);
    assert_eq!(exact.orient(&horizontal(0.2, true), &x), Ordering::Greater);
    assert_eq!(exact.orient(&horizontal(0.2, false), &x), Ordering::Less);
    assert_eq!(exact.orient(&vertical(0.75, true), &x), Ordering::Equal);
    assert_eq!(exact.orient(&vertical(0.8, true), &x), Ordering::Greater);
    assert_eq!(exact.orient(&vertical(0.8, false), &x), Ordering::Less);
    assert_eq!(exact.orient(&vertical(0.7, true), &x), Ordering::Less);
}

#[test]
fn orientation_of_nearly_collinear_points_is_exact() {
    let exact = Exact::default();
    let line = Line {
        a: [0.5, 0.5],
        b: [12.0, 12.0],
    };
    // 24 · (1 + 2^-52) is the float right after 24: one ulp above the diagonal.
    let p = SweepPoint::input([24.0, 24.0 + 24.0 * 2f64.powi(-52)]);
    assert_eq!(exact.orient(&line, &p), Ordering::Greater);
    assert_eq!(
        exact.orient(&line, &SweepPoint::input([24.0, 24.0])),
        Ordering::Equal
    );
}

#[test]
fn orientation_agrees_with_the_adaptive_predicate_on_and_next_to_lines() {
    // Points on axis-parallel lines, at lines' endpoints, on their extensions, and one float off each: the
    // shortcut for points exactly on a line must answer as the adaptive predicate does, and only for them.
    let exact = Exact::default();
    let lines = [
        ([0.25, 3.0], [7.5, 3.0]),
        ([-2.0, -1.0], [-2.0, 6.0]),
        ([0.1, 0.2], [0.7, 1.9]),
        ([1e-50, -3e40], [5e30, -3e40]),
    ];
    let mut on_a_line = 0;
    for (a, b) in lines {
        let line = Line { a, b };
        // Far along the line, rounded: nearly on it, where the float filter cannot decide.
        let far = [a[0] + 40.0 * (b[0] - a[0]), a[1] + 40.0 * (b[1] - a[1])];
        for base in [a, b, [a[0], b[1]], [b[0], a[1]], [a[0] * 3.0, a[1]], far] {
            for dx in [f64::next_down, |v: f64| v, f64::next_up] {
                for dy in [f64::next_down, |v: f64| v, f64::next_up] {
                    let p = [dx(base[0]), dy(base[1])];
                    let side = exact.orient(&line, &SweepPoint::input(p));
                    assert_eq!(
                        side,
                        Exact::orient_adaptive(&line, p),
                        "{p:?} against {line:?}"
                    );
                    on_a_line += usize::from(side == Ordering::Equal);
                }
            }
        }
    }
    assert!(on_a_line > 10);
}

#[test]
fn direction_cross_product() {
    let exact = Exact::default();
    let east = Line {
        a: [0.0, 0.0],
        b: [1.0, 0.0],
    };
    let north = Line {
        a: [5.0, 5.0],
        b: [5.0, 9.0],
    };
    assert_eq!(exact.cross_directions(&east, &north), Ordering::Greater);
    assert_eq!(exact.cross_directions(&north, &east), Ordering::Less);
    assert_eq!(exact.cross_directions(&east, &east), Ordering::Equal);
}

#[test]
fn crossing_matches_float_formula_on_real_coordinates() {
    let mut exact = Exact::default();
    let cases = [
        (
            [-179.5, 10.25],
            [-170.125, 12.0],
            [-178.0, 15.0],
            [-172.0, 9.0],
        ),
        (
            [12.3456789, -45.6789],
            [13.1, -44.2],
            [12.5, -44.0],
            [12.9, -46.0],
        ),
    ];
    for (a1, b1, a2, b2) in cases {
        let l = Line { a: a1, b: b1 };
        let m = Line { a: a2, b: b2 };
        let p = exact.crossing(&l, &m);
        let d1 = [b1[0] - a1[0], b1[1] - a1[1]];
        let d2 = [b2[0] - a2[0], b2[1] - a2[1]];
        let t =
            ((a2[0] - a1[0]) * d2[1] - (a2[1] - a1[1]) * d2[0]) / (d1[0] * d2[1] - d1[1] * d2[0]);
        let f = [a1[0] + t * d1[0], a1[1] + t * d1[1]];
        assert!(
            (p.approx[0] - f[0]).abs() < 2f64.powi(-30)
                && (p.approx[1] - f[1]).abs() < 2f64.powi(-30),
            "{:?} vs {:?}",
            { p.approx },
            f
        );
        assert_eq!(exact.orient(&l, &p), Ordering::Equal);
        assert_eq!(exact.orient(&m, &p), Ordering::Equal);
    }
}
