//! Results computed away from the UI thread: frames go on while a result is pending, a drag's many requests end in
//! the result for where the vertex was left, and what is shown then is what the operands give (worked by hand).

mod common;

use common::{frame, p};
use eframe::egui;
use polysweep_playground::operation::Op;
use polysweep_playground::scene::{Operand, VertexId};
use polysweep_playground::Playground;
use std::time::{Duration, Instant};

fn square(x: f64, y: f64, side: f64) -> polysweep::MultiPolygon {
    polysweep::MultiPolygon::from_coordinates(&[vec![vec![
        [x, y],
        [x + side, y],
        [x + side, y + side],
        [x, y + side],
    ]]])
}

/// Runs frames until nothing is pending, at most for `limit`; returns how many it took.
fn frames_until_settled(ctx: &egui::Context, app: &mut Playground, limit: Duration) -> usize {
    let start = Instant::now();
    let mut frames = 0;
    while app.pending() {
        assert!(start.elapsed() < limit, "no result after {limit:?}");
        frame(ctx, app, vec![]);
        frames += 1;
        std::thread::sleep(Duration::from_millis(1));
    }
    frames
}

#[test]
fn a_drag_ends_in_the_result_for_where_the_vertex_was_left() {
    let ctx = egui::Context::default();
    let mut app = Playground::default();
    app.scene
        .replace_both(square(0.0, 0.0, 4.0), square(2.0, 2.0, 4.0));
    app.operation = Op::Union;
    frames_until_settled(&ctx, &mut app, Duration::from_secs(20));
    let shown = app.shown().expect("a result after settling");
    assert_eq!(shown.outcome.as_ref().unwrap().result.area(), 28.0);
    assert!(app.results_received() >= 1);

    // P's corner (4, 0) is dragged right in 40 steps, a frame each, to (12, 0). P becomes the quadrilateral
    // (0,0) (12,0) (4,4) (0,4), of area 16 + 16 = 32. It overlaps Q = 2..6 × 2..6 in the square 2..4 × 2..4
    // (area 4) and, under its edge y = (12 − x)/2, in the trapezoid over 4 ≤ x ≤ 6 from y = 2 to that edge
    // (heights 2 and 1, area 3): the union is 32 + 16 − 7 = 41.
    let corner = VertexId {
        operand: Operand::Subject,
        polygon: 0,
        ring: 0,
        vertex: 1,
    };
    let before = app.results_received();
    app.scene.checkpoint();
    for step in 1..=40 {
        app.scene
            .move_vertex(corner, p(4.0 + 8.0 * step as f64 / 40.0, 0.0));
        frame(&ctx, &mut app, vec![]);
    }
    frames_until_settled(&ctx, &mut app, Duration::from_secs(20));
    let shown = app.shown().expect("a result");
    assert_eq!(shown.outcome.as_ref().unwrap().result.area(), 41.0);
    let delivered = app.results_received() - before;
    assert!(app.computes_off_thread());
    assert!(delivered >= 1, "the drag's results came from the thread");
    // Each of the 40 moves asked for a result; requests not started when a newer one came were dropped, so at
    // most that many were computed, and on a busy machine fewer.
    assert!(delivered <= 40, "{delivered} results for 40 moves");
    let (frames, while_pending) = app.frames();
    assert!(frames >= 42 && while_pending >= 1);

    // What is shown is what settling here computes, and nothing newer arrives later to replace it.
    let shown_area = shown.outcome.as_ref().unwrap().result.area();
    assert_eq!(app.outcome().as_ref().unwrap().result.area(), shown_area);
}
