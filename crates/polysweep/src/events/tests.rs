use super::*;
use crate::geometry::MultiPolygon;
use crate::input::add_edges;

#[test]
fn initial_events_come_in_event_order() {
    // Rings that share vertices and edges (two squares side by side, a third touching at a corner: points where
    // only vertical and horizontal edges meet, of both operands, ordered by key), a ring that passes twice through
    // one point, vertical edges, a column of points with one x, and a ring with two vertices only (its edges
    // cancel).
    let ring = |points: &[[f64; 2]]| {
        let mut ring = points.to_vec();
        ring.push(points[0]);
        vec![ring]
    };
    let subject = MultiPolygon::from_coordinates(&[
        ring(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
        ring(&[[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]),
        ring(&[[2.0, 1.0], [3.0, 1.0], [3.0, 2.0], [2.0, 2.0]]),
        ring(&[
            [0.0, 3.0],
            [2.0, 5.0],
            [2.0, 3.0],
            [0.0, 5.0],
            [1.0, 4.0],
            [-1.0, 4.0],
            [1.0, 4.0],
        ]),
        ring(&[[5.0, 0.0], [5.0, 9.0]]),
    ]);
    let clipping = MultiPolygon::from_coordinates(&[
        ring(&[[1.0, -1.0], [1.0, 3.0], [0.5, 3.0]]),
        ring(&[[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]),
    ]);
    // A column of 70 squares listed out of order, with 140 vertices at each of two x's: more than are sorted by
    // comparison (`SORTED_BY_VALUE`).
    let column = MultiPolygon::from_coordinates(
        &(0..70)
            .map(|i| {
                let y = f64::from((i * 37) % 70);
                ring(&[[10.0, y], [11.0, y], [11.0, y + 1.0], [10.0, y + 1.0]])
            })
            .collect::<Vec<_>>(),
    );
    let mut edges = Vec::new();
    add_edges(&mut edges, &subject, 0, 0..subject.0.len());
    add_edges(&mut edges, &clipping, 1, 0..clipping.0.len());
    add_edges(&mut edges, &column, 0, 0..column.0.len());
    let exact = Exact::default();
    let events = initial_events(&edges, &exact, &mut Default::default(), Vec::new(), false);
    assert_eq!(events.len(), 2 * edges.len());
    for i in 1..events.len() as EventId {
        assert_eq!(
            event_order(&events, &edges, &exact, i - 1, i),
            Ordering::Less,
            "events {} and {i}",
            i - 1
        );
    }
    for (i, event) in events.iter().enumerate() {
        let other = &events[event.other as usize];
        assert_eq!(other.other as usize, i);
        assert_ne!(other.left(), event.left());
        let far = far_point(&events, &edges, i as EventId);
        assert_eq!({ other.point.approx }, { far.approx });
    }
}

#[test]
fn an_event_is_small_and_finds_its_other_end() {
    // The events are the sweep's largest array (two or more per input edge): their size is its memory traffic.
    assert_eq!(std::mem::size_of::<SweepEvent>(), 40);
    let edge = InputEdge {
        line: Line {
            a: [0.0, 0.0],
            b: [1.0, 0.0],
        },
        operand: 1,
        winding: -1,
    };
    let split_point = SweepPoint::input([0.5, 0.0]);
    let largest = OTHER_AT_INPUT_END - 1;
    let edges = vec![edge; 8];
    for (segment, left) in [(0, true), (7, false), (largest, true), (largest, false)] {
        let event = SweepEvent::initial(&edge, segment, left, 5);
        assert_eq!((event.segment(), event.left()), (segment, left));
        assert_eq!(event.winding, [0, -1]);
        assert_eq!(
            { event.point.approx },
            if left { edge.line.a } else { edge.line.b }
        );
        let fragment = event.fragment(split_point, !left, 0);
        assert_eq!((fragment.segment(), fragment.left()), (segment, !left));
        if segment < 8 {
            // The other end: the input segment's end until a split makes it a new event.
            let mut events = vec![fragment, event];
            let at = |events: &[SweepEvent]| far_point(events, &edges, 1).approx;
            assert_eq!(at(&events), if left { edge.line.b } else { edge.line.a });
            events[1].set_other(0);
            assert_eq!(
                (at(&events), events[1].segment()),
                (split_point.approx, segment)
            );
        }
    }
}

#[test]
fn an_event_knows_its_node_in_s_then_its_result_edge() {
    let edge = InputEdge {
        line: Line {
            a: [0.0, 0.0],
            b: [1.0, 0.0],
        },
        operand: 0,
        winding: 1,
    };
    let mut event = SweepEvent::initial(&edge, 0, true, 1);
    assert_eq!((event.node(), event.result_edge()), (NONE, NONE));
    for (node, index) in [(0, 0), (RECORDED - 1, RECORDED - 2)] {
        event.enter_status(node);
        assert_eq!((event.node(), event.result_edge()), (node, NONE));
        event.record(index);
        assert_eq!((event.node(), event.result_edge()), (NONE, index));
        event.enter_status(node);
        event.leave_status();
        assert_eq!((event.node(), event.result_edge()), (NONE, NONE));
    }
}
