//! The trace of the sweep on the paper's Fig. 7 case (tests/fixtures/fig7-sweep-line.json), checked step by step
//! against the walk-through of §3 worked out by hand for these two triangles:
//!
//! P = (0, 4) (4, 0) (8, 4): edges a = (0,4)–(4,0), b = (4,0)–(8,4), c = (0,4)–(8,4).
//! Q = (0, −1) (12, −1) (6, 5): edges d = (0,−1)–(12,−1), e = (0,−1)–(6,5), f = (6,5)–(12,−1).
//!
//! At x = 0 the left events of d and e (bottom to top), then of a and c. Inserting a puts it above e, which it
//! crosses at i = (2.5, 1.5): both are subdivided there, so S holds d, e up to i, a up to i; c goes on top (the
//! paper: "S = {q2q3, iq2, p1i, p0p1}"). At i, e's and a's first parts leave S outside the other triangle; a's
//! second part enters S inside Q (its flags read from d), e's inside P (read from a's); e then crosses c at (5, 4).

mod common;

use common::*;
use polysweep::{trace, Meeting, MultiPolygon, Operation, Options, Reason, Step, TraceEdge};
use serde_json::Value;

fn fig7() -> (MultiPolygon, MultiPolygon) {
    let path = fixtures_dir().join("fig7-sweep-line.json");
    let v: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    (multipolygon(&v["subject"]), multipolygon(&v["clipping"]))
}

/// An edge by its ends and operand, winding aside.
fn ends(edge: &TraceEdge) -> ([f64; 2], [f64; 2], usize) {
    (edge.left, edge.right, edge.operand)
}

const I: [f64; 2] = [2.5, 1.5];
const D: ([f64; 2], [f64; 2], usize) = ([0.0, -1.0], [12.0, -1.0], 1);
const E_TO_I: ([f64; 2], [f64; 2], usize) = ([0.0, -1.0], I, 1);
const A_TO_I: ([f64; 2], [f64; 2], usize) = ([0.0, 4.0], I, 0);
const C: ([f64; 2], [f64; 2], usize) = ([0.0, 4.0], [8.0, 4.0], 0);

#[test]
fn fig7_status_and_subdivisions_follow_section_3() {
    let (p, q) = fig7();
    let steps = trace(Operation::Intersection, &p, &q, &Options::default()).unwrap();
    let events: Vec<usize> = (steps.iter().enumerate())
        .filter(|(_, s)| matches!(s, Step::Event { .. }))
        .map(|(i, _)| i)
        .collect();
    let event = |k: usize| match &steps[events[k]] {
        Step::Event { point, left, edge } => (*point, *left, ends(edge)),
        other => unreachable!("{other:?}"),
    };
    // The steps of event k, up to the next event.
    let during = |k: usize| &steps[events[k] + 1..*events.get(k + 1).unwrap_or(&steps.len())];
    let status_after = |k: usize| match during(k).last() {
        Some(Step::Status(s)) => s.iter().map(ends).collect::<Vec<_>>(),
        other => panic!("event {k} does not end with S: {other:?}"),
    };

    assert_eq!(event(0), ([0.0, -1.0], true, D));
    assert_eq!(status_after(0), [D]);
    assert_eq!(event(1).2 .1, [6.0, 5.0], "e, above d, second");
    assert_eq!(event(2), ([0.0, 4.0], true, ([0.0, 4.0], [4.0, 0.0], 0)));
    // Inserting a: it crosses its neighbour below, e, at i; both are subdivided there.
    let meetings: Vec<_> = (during(2).iter())
        .filter_map(|s| match s {
            Step::Meeting {
                lower,
                upper,
                meeting,
                at,
            } => Some((ends(lower).1, ends(upper).1, *meeting, *at)),
            _ => None,
        })
        .collect();
    assert_eq!(meetings, [([6.0, 5.0], [4.0, 0.0], Meeting::Crossing, I)]);
    let split: Vec<_> = (during(2).iter())
        .filter_map(|s| match s {
            Step::Subdivision { edge, at } => Some((edge.operand, *at)),
            _ => None,
        })
        .collect();
    assert_eq!(split, [(1, I), (0, I)]);
    assert_eq!(status_after(2), [D, E_TO_I, A_TO_I]);
    // Then c, on top: the four edges of the paper's last S.
    assert_eq!(event(3), ([0.0, 4.0], true, C));
    assert_eq!(status_after(3), [D, E_TO_I, A_TO_I, C]);

    // Fig. 9's flags as each entered S: d and e outside P; a outside Q, and an in-out transition of Q for e.
    let flags = |edge: ([f64; 2], [f64; 2], usize)| {
        steps.iter().find_map(|s| match s {
            Step::Flags {
                edge: e,
                in_out,
                inside_other,
                in_result,
                ..
            } if ends(e) == edge => Some((*in_out, *inside_other, *in_result)),
            _ => None,
        })
    };
    assert_eq!(flags(D), Some((false, false, false)));
    assert_eq!(
        flags(([0.0, -1.0], [6.0, 5.0], 1)),
        Some((true, false, false))
    );
    assert_eq!(flags(C), Some((true, false, false)));
    // At i, a's second part enters above d, inside Q; e's second part above it, inside P: both bound P ∩ Q.
    assert_eq!(flags((I, [4.0, 0.0], 0)), Some((false, true, true)));
    assert_eq!(flags((I, [6.0, 5.0], 1)), Some((true, true, true)));

    // Fig. 10's selection as edges leave S.
    let selected = |edge: ([f64; 2], [f64; 2], usize)| {
        steps.iter().find_map(|s| match s {
            Step::Selection {
                edge: e,
                in_result,
                reason,
            } if ends(e) == edge => Some((*in_result, *reason)),
            _ => None,
        })
    };
    assert_eq!(selected(E_TO_I), Some((false, Reason::OutsideOther)));
    assert_eq!(selected(A_TO_I), Some((false, Reason::OutsideOther)));
    assert_eq!(
        selected((I, [4.0, 0.0], 0)),
        Some((true, Reason::InsideOther))
    );
    assert_eq!(selected(D), Some((false, Reason::OutsideOther)));

    // The connection step closes the one ring of P ∩ Q, the fixture's expected intersection.
    let rings: Vec<_> = (steps.iter())
        .filter_map(|s| match s {
            Step::Ring {
                polygon,
                ring,
                points,
            } => Some((*polygon, *ring, points.clone())),
            _ => None,
        })
        .collect();
    assert_eq!(rings.len(), 1);
    let ring = MultiPolygon::from_coordinates(&[vec![rings[0].2.clone()]]);
    let expected = MultiPolygon::from_coordinates(&[vec![vec![
        [2.5, 1.5],
        [4.0, 0.0],
        [7.5, 3.5],
        [7.0, 4.0],
        [5.0, 4.0],
        [2.5, 1.5],
    ]]]);
    assert_eq!(normalise(&ring), normalise(&expected));
}

#[test]
fn every_event_ends_with_s_in_order_and_the_trace_agrees_with_the_operation() {
    let (p, q) = fig7();
    for operation in [
        Operation::Intersection,
        Operation::Union,
        Operation::Difference,
        Operation::Xor,
    ] {
        let steps = trace(operation, &p, &q, &Options::default()).unwrap();
        let events = steps
            .iter()
            .filter(|s| matches!(s, Step::Event { .. }))
            .count();
        let statuses = steps
            .iter()
            .filter(|s| matches!(s, Step::Status(_)))
            .count();
        assert_eq!(events, statuses);
        // 6 input edges and 4 crossings (e × a at (2.5, 1.5), e × c at (5, 4), f × c at (7, 4), f × b at
        // (7.5, 3.5)), each splitting two edges into two: 6 + 8 = 14 edges, 28 events.
        assert_eq!(events, 28, "{operation:?}");
        // S is empty at the end.
        assert!(
            matches!(steps.iter().rev().find(|s| matches!(s, Step::Status(_))), Some(Step::Status(s)) if s.is_empty())
        );
        let ring_points: usize = (steps.iter())
            .map(|s| match s {
                // (Closed rings: the first point again at the end.)
                Step::Ring { points, .. } => points.len() - 1,
                _ => 0,
            })
            .sum();
        let result = polysweep::overlay(operation, &p, &q, &Options::default()).unwrap();
        assert_eq!(ring_points, result.vertex_count(), "{operation:?}");
    }
}

#[test]
fn a_window_keeps_s_only_for_its_events_and_every_other_step() {
    let (p, q) = fig7();
    let options = Options::default();
    let all = trace(Operation::Union, &p, &q, &options).unwrap();
    let window =
        polysweep::trace_with_status_for(Operation::Union, &p, &q, &options, 2..4).unwrap();
    let without_status = |steps: &[Step]| -> Vec<Step> {
        (steps.iter())
            .filter(|s| !matches!(s, Step::Status(_)))
            .cloned()
            .collect()
    };
    assert_eq!(without_status(&all), without_status(&window));
    let statuses: Vec<_> = (window.iter())
        .filter_map(|s| match s {
            Step::Status(s) => Some(s.iter().map(ends).collect::<Vec<_>>()),
            _ => None,
        })
        .collect();
    assert_eq!(
        statuses,
        [vec![D, E_TO_I, A_TO_I], vec![D, E_TO_I, A_TO_I, C]]
    );
}

/// The polygons the trace's ring steps close.
fn rings_of(steps: &[Step]) -> MultiPolygon {
    let mut polygons: Vec<Vec<Vec<[f64; 2]>>> = Vec::new();
    for step in steps {
        if let Step::Ring {
            polygon, points, ..
        } = step
        {
            if polygons.len() <= *polygon {
                polygons.resize(polygon + 1, Vec::new());
            }
            polygons[*polygon].push(points.clone());
        }
    }
    MultiPolygon::from_coordinates(&polygons)
}

#[test]
fn on_every_fixture_the_trace_ends_in_the_result_of_the_paper_s_algorithm() {
    let mut paths: Vec<_> = std::fs::read_dir(fixtures_dir())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 30);
    for path in paths {
        let v: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let fill_rule = match v["fill_rule"].as_str() {
            Some("nonzero") => polysweep::FillRule::NonZero,
            Some("positive") => polysweep::FillRule::Positive,
            Some("negative") => polysweep::FillRule::Negative,
            _ => polysweep::FillRule::EvenOdd,
        };
        let options = Options::default().with_fill_rule(fill_rule);
        let (p, q) = (multipolygon(&v["subject"]), multipolygon(&v["clipping"]));
        for operation in [
            Operation::Intersection,
            Operation::Union,
            Operation::Difference,
            Operation::Xor,
        ] {
            let steps = trace(operation, &p, &q, &options).unwrap();
            let expected =
                polysweep::overlay(operation, &p, &q, &options.without_shortcuts()).unwrap();
            assert_eq!(
                normalise(&rings_of(&steps)),
                normalise(&expected),
                "{} {operation:?}",
                path.display()
            );
            let last_status = steps.iter().rev().find_map(|s| match s {
                Step::Status(s) => Some(s.len()),
                _ => None,
            });
            assert!(last_status.is_none_or(|n| n == 0), "S ends empty");
        }
    }
}
