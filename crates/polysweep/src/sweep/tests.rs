//! The sweep's own steps: the crossing step, and the limit on events.

use super::*;
use crate::geometry::MultiPolygon;
use crate::input::add_edges;
use crate::select::{FillRule, Operation};

#[test]
fn a_crossing_is_one_step_where_nothing_else_happens_and_four_events_where_it_does() {
    // The squares [0, 2]² and [1, 3]² cross properly at (2, 1) and (1, 2), with nothing else there: each
    // crossing is one step. With a triangle in the clipping operand whose long edge, on y = x - 1, passes
    // through (2, 1) too, the subject's vertical edge is split there as well: that crossing has other events at
    // its point, and goes back to four events.
    let square =
        |x: f64, y: f64| vec![vec![[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]]];
    let triangle = vec![vec![[0.0, -1.0], [4.0, -1.0], [4.0, 3.0]]];
    let p = MultiPolygon::from_coordinates(&[square(0.0, 0.0)]);
    let q = MultiPolygon::from_coordinates(&[square(1.0, 1.0)]);
    let q_and_t = MultiPolygon::from_coordinates(&[square(1.0, 1.0), triangle]);
    let area = |operation, a: &MultiPolygon, b: &MultiPolygon| {
        let options = crate::Options::default().with_fill_rule(FillRule::EvenOdd);
        crate::overlay(operation, a, b, &options).unwrap().area()
    };
    use Operation::*;
    assert_eq!(
        [Intersection, Union, Difference, Xor].map(|o| area(o, &p, &q)),
        [1.0, 7.0, 3.0, 6.0]
    );
    // Under even-odd the clipping operand is Q ⊕ T, of area 4 + 8 - 2 · 1/2 = 11 (Q ∩ T: x from 2 to 3 below
    // the line); P ∩ (Q ⊕ T) = P ∩ Q, 1, plus P ∩ T, 1/2 (x from 1 to 2 below the line), less twice P ∩ Q ∩ T,
    // which has no area.
    assert_eq!(
        [Intersection, Union, Difference, Xor].map(|o| area(o, &p, &q_and_t)),
        [1.5, 4.0 + 11.0 - 1.5, 4.0 - 1.5, 4.0 + 11.0 - 3.0]
    );
}

#[test]
fn a_sweep_that_outgrows_its_limit_stops_with_an_error() {
    // Five thin bars across five others: 4 crossings per pair of bars, 100 in all, each adding 4 events to
    // the 80 initial ones.
    let bar =
        |x: f64, y: f64, w: f64, h: f64| vec![vec![[x, y], [x + w, y], [x + w, y + h], [x, y + h]]];
    let across = MultiPolygon::from_coordinates(
        &(0..5)
            .map(|i| bar(0.0, 2.0 * i as f64, 10.0, 1.0))
            .collect::<Vec<_>>(),
    );
    let up = MultiPolygon::from_coordinates(
        &(0..5)
            .map(|i| bar(2.0 * i as f64 + 0.5, -1.0, 1.0, 12.0))
            .collect::<Vec<_>>(),
    );
    let mut edges = Vec::new();
    add_edges(&mut edges, &across, 0, 0..across.0.len());
    add_edges(&mut edges, &up, 1, 0..up.0.len());
    let selection = Selection::Pair {
        operation: Operation::Intersection,
        fill_rule: FillRule::EvenOdd,
    };
    let sweep = || {
        Sweep::new(
            &edges,
            selection,
            f64::INFINITY,
            12.0,
            Shortcuts::ALL,
            &mut Default::default(),
            Silent,
        )
    };
    let mut whole = sweep();
    assert_eq!(whole.run(), Ok(()));
    assert_eq!(
        (whole.events.len(), whole.exact.crossing_count()),
        (480, 100)
    );
    for limit in [80, 200, 479] {
        let mut limited = sweep();
        limited.max_events = limit;
        let error = limited.run().expect_err("more events than the limit");
        assert!(limited.events.len() <= limit);
        assert_eq!(error, Error::TooLarge { limit });
        assert_eq!(error.location(), None);
        assert!(
            error
                .to_string()
                .contains(&format!("more than {limit} sweep events")),
            "{error}"
        );
    }
}
