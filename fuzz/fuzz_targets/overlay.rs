//! Coverage-guided fuzzing of the overlay (issue 24): arbitrary operands whose coordinates are drawn from a few
//! values and the floats next to them, so that near-coincidences (vertices a few ulps off an edge, nearly collinear
//! edges, crossings a few ulps apart) are common. Every fill rule, every operation, two operands or three, and a
//! result fed into a second operation. Each result must validate, and be right at sample points away from every
//! edge: membership there is decided exactly (orient2d on the input's float vertices) from the operands alone.
//!
//! Lines and layers too (issue 26), on the same operands: the second operand's rings as lines splitting the first,
//! and the two as layers of one feature each. They are not snap-rounded (docs/robustness.md, known limit), so only
//! their membership at the sample points is checked, not the output contract.
//!
//! Run: `RUSTC_BOOTSTRAP=1 cargo fuzz run -O -a overlay` in `fuzz/` (`-a`: with debug assertions, among them that
//! snap rounding's last sweep constructs no point; see docs/robustness.md for the figures).
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use polysweep::{
    overlay, overlay_all, overlay_layers, split, validate, FillRule, LayerMode, MultiPolygon,
    Operation, Options, Point,
};

/// A coordinate: `value` (−8..7) times the case's scale, moved by `nudge` (−4..3) floats.
#[derive(Arbitrary, Debug, Clone, Copy)]
struct Coordinate(u8);

#[derive(Arbitrary, Debug)]
struct Case {
    operation: u8,
    rule: u8,
    scale: u8,
    operands: Vec<Vec<Vec<Vec<(Coordinate, Coordinate)>>>>,
    second: Option<(u8, Vec<Vec<Vec<(Coordinate, Coordinate)>>>)>,
    samples: Vec<(Coordinate, Coordinate)>,
}

const SCALES: [f64; 8] = [1.0, 0.1, 0.3, 1e-9, 1e9, 0.7, 3.0e-7, 1.0 / 3.0];
const OPERATIONS: [Operation; 4] = [
    Operation::Intersection,
    Operation::Union,
    Operation::Difference,
    Operation::Xor,
];
const RULES: [FillRule; 5] = [
    FillRule::EvenOdd,
    FillRule::NonZero,
    FillRule::Positive,
    FillRule::Negative,
    FillRule::Structure,
];

fn value(c: Coordinate, scale: f64) -> f64 {
    let v = f64::from((c.0 >> 4) as i8 - 8) * scale;
    let nudge = i64::from(c.0 & 7) - 4;
    if v == 0.0 {
        return 0.0; // (its neighbours are subnormal: out of range)
    }
    // The next floats away from or towards zero, by the bits.
    f64::from_bits((v.to_bits() as i64 + nudge) as u64)
}

fn operand(raw: &[Vec<Vec<(Coordinate, Coordinate)>>], scale: f64) -> MultiPolygon {
    let coordinates: Vec<Vec<Vec<[f64; 2]>>> = (raw.iter().take(3))
        .map(|polygon| {
            (polygon.iter().take(3))
                .map(|ring| {
                    (ring.iter().take(12))
                        .map(|&(x, y)| [value(x, scale), value(y, scale)])
                        .collect()
                })
                .collect()
        })
        .collect();
    MultiPolygon::from_coordinates(&coordinates)
}

/// The winding number of `ring` around `p` (exact: orient2d on floats).
fn winding(ring: &[Point], p: Point) -> i32 {
    let n = ring.len();
    let mut w = 0;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        let side = robust::orient2d(
            robust::Coord { x: a.x, y: a.y },
            robust::Coord { x: b.x, y: b.y },
            robust::Coord { x: p.x, y: p.y },
        );
        if a.y <= p.y && b.y > p.y && side > 0.0 {
            w += 1;
        } else if a.y > p.y && b.y <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

/// Is `p` inside `m` as `rule` reads it?
fn inside(m: &MultiPolygon, rule: FillRule, p: Point) -> bool {
    if rule == FillRule::Structure {
        return m.0.iter().any(|polygon| {
            winding(&polygon.exterior, p) != 0
                && polygon.holes.iter().all(|hole| winding(hole, p) == 0)
        });
    }
    let w: i32 =
        m.0.iter()
            .flat_map(|polygon| polygon.rings())
            .map(|ring| winding(ring, p))
            .sum();
    match rule {
        FillRule::EvenOdd | FillRule::Structure => w % 2 != 0,
        FillRule::NonZero => w != 0,
        FillRule::Positive => w > 0,
        FillRule::Negative => w < 0,
    }
}

fn combine(operation: Operation, inside: &[bool]) -> bool {
    match operation {
        Operation::Intersection => inside.iter().all(|&i| i),
        Operation::Union => inside.iter().any(|&i| i),
        Operation::Difference => inside[0] && !inside[1..].iter().any(|&i| i),
        Operation::Xor => inside.iter().filter(|&&i| i).count() % 2 == 1,
    }
}

/// Is `p` within a few ulps of an edge of `m` (where rounding the result may legitimately move the boundary)?
fn near_an_edge(m: &MultiPolygon, p: Point, margin: f64) -> bool {
    m.0.iter().flat_map(|polygon| polygon.rings()).any(|ring| {
        let n = ring.len();
        (0..n).any(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let (lo_x, hi_x) = (a.x.min(b.x) - margin, a.x.max(b.x) + margin);
            let (lo_y, hi_y) = (a.y.min(b.y) - margin, a.y.max(b.y) + margin);
            if p.x < lo_x || p.x > hi_x || p.y < lo_y || p.y > hi_y {
                return false;
            }
            let cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
            let length = (b.x - a.x).abs().max((b.y - a.y).abs());
            cross.abs() <= margin * length * 4.0
        })
    })
}

/// Checks `result` of `operation` over `operands` read by `rule`: valid, and right at the sample points.
fn check(
    result: &MultiPolygon,
    operation: Operation,
    operands: &[&MultiPolygon],
    rule: FillRule,
    samples: &[Point],
    margin: f64,
) {
    if let Err(problem) = validate(result) {
        panic!("invalid result: {problem:?}\n{result:?}");
    }
    for &p in samples {
        if operands.iter().any(|m| near_an_edge(m, p, margin)) || near_an_edge(result, p, margin) {
            continue;
        }
        let each: Vec<bool> = operands.iter().map(|m| inside(m, rule, p)).collect();
        let want = combine(operation, &each);
        let got = inside(result, FillRule::EvenOdd, p);
        assert_eq!(got, want, "wrong at {p:?}\n{result:?}");
    }
}

fuzz_target!(|case: Case| {
    let scale = SCALES[usize::from(case.scale) % SCALES.len()];
    let operation = OPERATIONS[usize::from(case.operation) % 4];
    let rule = RULES[usize::from(case.rule) % RULES.len()];
    let options = Options::default().with_fill_rule(rule);
    let operands: Vec<MultiPolygon> = case
        .operands
        .iter()
        .take(3)
        .map(|raw| operand(raw, scale))
        .collect();
    if operands.len() < 2 {
        return;
    }
    // Ulps of the largest coordinate, with room for rounding at crossings and the float test above.
    let margin = 16.0 * scale * 8.0 * f64::EPSILON;
    let samples: Vec<Point> = (case.samples.iter().take(64))
        .map(|&(x, y)| Point::new(value(x, scale), value(y, scale)))
        .collect();
    let result = if operands.len() == 2 {
        overlay(operation, &operands[0], &operands[1], &options)
    } else {
        overlay_all(operation, &operands, &options)
    }
    .expect("coordinates in range");
    let refs: Vec<&MultiPolygon> = operands.iter().collect();
    check(&result, operation, &refs, rule, &samples, margin);
    check_lines_and_layers(&operands[0], &operands[1], rule, &samples, margin);
    // A result fed into a second operation. The result is a valid polygon set, which every rule but the
    // negative one reads as it is (that one reads it as empty): there the chained operation reads both by even-odd.
    if let Some((second_operation, raw)) = &case.second {
        let third = operand(raw, scale);
        let second_operation = OPERATIONS[usize::from(*second_operation) % 4];
        let chained_rule = if rule == FillRule::Negative {
            FillRule::EvenOdd
        } else {
            rule
        };
        let chained_options = Options::default().with_fill_rule(chained_rule);
        let chained = overlay(second_operation, &result, &third, &chained_options)
            .expect("coordinates in range");
        if let Err(problem) = validate(&chained) {
            panic!("invalid chained result: {problem:?}\n{chained:?}");
        }
        for &p in &samples {
            if refs.iter().any(|m| near_an_edge(m, p, margin))
                || near_an_edge(&result, p, margin)
                || near_an_edge(&third, p, margin)
                || near_an_edge(&chained, p, margin)
            {
                continue;
            }
            let first = combine(
                operation,
                &refs.iter().map(|m| inside(m, rule, p)).collect::<Vec<_>>(),
            );
            let want = combine(second_operation, &[first, inside(&third, chained_rule, p)]);
            assert_eq!(
                inside(&chained, FillRule::EvenOdd, p),
                want,
                "chained wrong at {p:?}\n{chained:?}"
            );
        }
    }
});

/// Splits `polygon` along `other`'s rings (as open lines), and overlays the two as layers of one feature each:
/// away from every edge, a point of the polygon lies in exactly one piece, and a point lies in the face whose
/// features are those around it.
fn check_lines_and_layers(
    polygon: &MultiPolygon,
    other: &MultiPolygon,
    rule: FillRule,
    samples: &[Point],
    margin: f64,
) {
    let options = Options::default().with_fill_rule(rule);
    let lines: Vec<Vec<Point>> = other.0.iter().flat_map(|p| p.rings().cloned()).collect();
    let pieces: Vec<MultiPolygon> = split(polygon, &lines, &options)
        .expect("coordinates in range")
        .into_iter()
        .map(|piece| MultiPolygon(vec![piece]))
        .collect();
    let faces = overlay_layers(
        std::slice::from_ref(polygon),
        std::slice::from_ref(other),
        LayerMode::Union,
        &options,
    )
    .expect("coordinates in range");
    let near = |m: &MultiPolygon, p| near_an_edge(m, p, margin);
    for &p in samples {
        if near(polygon, p)
            || near(other, p)
            || pieces.iter().any(|m| near(m, p))
            || faces.iter().any(|f| near(&f.polygons, p))
        {
            continue;
        }
        let in_pieces = pieces
            .iter()
            .filter(|m| inside(m, FillRule::EvenOdd, p))
            .count();
        assert_eq!(
            in_pieces,
            usize::from(inside(polygon, rule, p)),
            "split at {p:?}\n{pieces:?}"
        );
        let covered: Vec<_> = faces
            .iter()
            .filter(|f| inside(&f.polygons, FillRule::EvenOdd, p))
            .map(|f| (f.a.len(), f.b.len()))
            .collect();
        let want = (
            usize::from(inside(polygon, rule, p)),
            usize::from(inside(other, rule, p)),
        );
        if want == (0, 0) {
            assert!(covered.is_empty(), "a face where no feature is, at {p:?}");
        } else {
            assert_eq!(covered, vec![want], "layers at {p:?}");
        }
    }
}
