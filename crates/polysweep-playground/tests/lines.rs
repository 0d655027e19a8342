//! The line tool without a window: drawing lines, the result clipping them and split along them, undo, errors, and
//! whole egui frames driven by synthetic mouse and keyboard events.
//!
//! P is the square (0, 0)–(4, 4) and Q the square (2, 2)–(6, 6) throughout, so that their intersection is the
//! square (2, 2)–(4, 4) and their union has area 28; every expectation follows from that by hand.

mod common;

use common::{button, click_at, frame, key, p, SCREEN};
use eframe::egui::{self, Event, Key, PointerButton, Pos2, Vec2};
use polysweep::{Error, Point};
use polysweep_playground::app::Tool;
use polysweep_playground::operation::{Cut, Op};
use polysweep_playground::scene::{LineVertex, Operand};
use polysweep_playground::Playground;

/// P and Q drawn as in the module's comment, and the line tool chosen.
fn squares() -> Playground {
    let mut app = Playground::default();
    for (operand, x) in [(Operand::Subject, 0.0), (Operand::Clipping, 2.0)] {
        app.active = operand;
        for (dx, dy) in [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0), (0.0, 0.0)] {
            app.click(p(x + dx, x + dy), 0.1);
        }
    }
    app.tool = Tool::Line;
    app
}

fn draw_line(app: &mut Playground, vertices: &[Point]) {
    for &v in vertices {
        app.click(v, 0.1);
    }
    app.finish_drawing();
}

fn cut(app: &mut Playground) -> Cut {
    app.cut()
        .expect("there are lines and a result")
        .clone()
        .expect("no error")
}

fn areas(cut: &Cut) -> Vec<f64> {
    let mut areas: Vec<f64> = cut.pieces.iter().map(|piece| piece.area()).collect();
    areas.sort_by(f64::total_cmp);
    areas
}

#[test]
fn a_line_across_the_intersection_clips_and_splits_it() {
    let mut app = squares();
    assert!(app.cut().is_none(), "no lines, nothing to cut");
    draw_line(&mut app, &[p(1.0, 3.0), p(7.0, 3.0)]);
    assert_eq!(app.scene.lines(), [vec![p(1.0, 3.0), p(7.0, 3.0)]]);
    let cut = cut(&mut app);
    assert_eq!(cut.inside, [vec![p(2.0, 3.0), p(4.0, 3.0)]]);
    assert_eq!(
        cut.outside,
        [
            vec![p(1.0, 3.0), p(2.0, 3.0)],
            vec![p(4.0, 3.0), p(7.0, 3.0)]
        ]
    );
    assert_eq!(areas(&cut), [2.0, 2.0], "two halves of the 2 × 2 square");
}

#[test]
fn a_bent_line_cuts_a_corner_off_and_survives_operation_changes() {
    let mut app = squares();
    // Clicks snap to the grid: (1.2, 2.9) is drawn at (1, 3).
    draw_line(&mut app, &[p(1.2, 2.9), p(3.0, 3.0), p(3.0, 1.0)]);
    let intersection = cut(&mut app);
    assert_eq!(
        intersection.inside,
        [vec![p(2.0, 3.0), p(3.0, 3.0), p(3.0, 2.0)]],
        "the inside part keeps the line's bend"
    );
    assert_eq!(
        intersection.outside,
        [
            vec![p(1.0, 3.0), p(2.0, 3.0)],
            vec![p(3.0, 2.0), p(3.0, 1.0)]
        ]
    );
    assert_eq!(
        areas(&intersection),
        [1.0, 3.0],
        "the unit square at (2, 2) is cut off"
    );

    // The union holds all of the line, and its ends dangle: it cuts nothing.
    app.operation = Op::Union;
    let union = cut(&mut app);
    assert_eq!(union.inside, [vec![p(1.0, 3.0), p(3.0, 3.0), p(3.0, 1.0)]]);
    assert!(union.outside.is_empty());
    assert_eq!(areas(&union), [28.0]);

    // P − Q is P less the square (2, 2)–(4, 4): the line leaves it at (2, 3), runs through that square and comes
    // back in at (3, 2). Both parts inside end in the middle of P − Q, so nothing is cut off.
    app.operation = Op::SubjectMinusClipping;
    let difference = cut(&mut app);
    assert_eq!(
        difference.inside,
        [
            vec![p(1.0, 3.0), p(2.0, 3.0)],
            vec![p(3.0, 2.0), p(3.0, 1.0)]
        ]
    );
    assert_eq!(
        difference.outside,
        [vec![p(2.0, 3.0), p(3.0, 3.0), p(3.0, 2.0)]]
    );
    assert_eq!(areas(&difference), [12.0]);
}

#[test]
fn lines_are_undone_redone_cleared_and_edited_without_touching_the_operands() {
    let mut app = squares();
    let revisions =
        |app: &Playground| [Operand::Subject, Operand::Clipping].map(|w| app.scene.revision(w));
    let operands = revisions(&app);
    draw_line(&mut app, &[p(1.0, 3.0), p(7.0, 3.0)]);
    draw_line(&mut app, &[p(3.0, 1.0), p(3.0, 7.0)]);
    assert_eq!(cut(&mut app).pieces.len(), 4, "a cross quarters the square");
    app.scene.undo();
    assert_eq!(app.scene.lines().len(), 1);
    assert_eq!(cut(&mut app).pieces.len(), 2);
    app.scene.redo();
    assert_eq!(cut(&mut app).pieces.len(), 4);

    // Moving the cross's centre-line vertex off the square; deleting a vertex of a 2-vertex line removes the line.
    let end = LineVertex { line: 1, vertex: 0 };
    app.scene.checkpoint();
    app.scene.move_line_vertex(end, p(3.0, 5.0));
    assert_eq!(
        cut(&mut app).pieces.len(),
        2,
        "a line from (3, 5) up crosses nothing"
    );
    app.scene.delete_line_vertex(end);
    assert_eq!(app.scene.lines().len(), 1);
    app.scene.clear_lines();
    assert!(app.scene.lines().is_empty() && app.cut().is_none());
    app.scene.undo();
    assert_eq!(app.scene.lines().len(), 1, "a clear is one step");
    assert_eq!(
        revisions(&app),
        operands,
        "the result of P and Q was never recomputed"
    );

    // A line without two distinct vertices is dropped, and the drawing with it.
    draw_line(&mut app, &[p(5.0, 5.0), p(5.0, 5.0)]);
    draw_line(&mut app, &[p(5.0, 5.0)]);
    assert_eq!(app.scene.lines().len(), 1);
    assert!(app.drawing.is_empty());
}

#[test]
fn a_bad_line_vertex_is_named_and_the_app_recovers() {
    let mut app = squares();
    draw_line(&mut app, &[p(1.0, 3.0), p(7.0, 3.0)]);
    draw_line(&mut app, &[p(3.0, 1.0), p(3.0, 2.0), p(3.0, 7.0)]);
    let bad = LineVertex { line: 1, vertex: 2 };
    app.scene.checkpoint();
    app.scene.move_line_vertex(bad, p(3.0, f64::INFINITY));
    let error: Error = app
        .cut()
        .expect("lines and a result")
        .clone()
        .expect_err("infinity is refused");
    let at = error.location().expect("a vertex is named");
    assert_eq!(LineVertex::from_location(&app.scene, &at), Some(bad));
    assert!(
        error
            .to_string()
            .contains("operand 1, polygon 1, ring 0, vertex 2"),
        "{error}"
    );
    assert!(app.outcome().is_ok(), "the operation itself is unaffected");
    app.scene.undo();
    assert_eq!(cut(&mut app).pieces.len(), 4);
}

// ---- whole frames through egui ----

/// The first frame's view: 30 points per unit around (5, 5), at the centre of the canvas right of the 280-point
/// panel.
fn screen(x: f32, y: f32) -> Pos2 {
    let canvas_center = Pos2::new(280.0 + (SCREEN.x - 280.0) / 2.0, SCREEN.y / 2.0);
    canvas_center + Vec2::new((x - 5.0) * 30.0, -(y - 5.0) * 30.0)
}

#[test]
fn the_mouse_draws_lines_and_edits_them() {
    let ctx = egui::Context::default();
    let mut app = squares();
    app.tool = Tool::Ring;
    frame(&ctx, &mut app, vec![]);
    key(&ctx, &mut app, Key::L);
    assert_eq!(app.tool, Tool::Line);

    // Two clicks and Esc draw nothing; two clicks and a double-click on the last vertex draw a 3-vertex line. The
    // clicks come 50 ms apart, so egui counts the double-click as a triple-click with the one before.
    click_at(&ctx, &mut app, screen(1.0, 3.0), PointerButton::Primary);
    click_at(&ctx, &mut app, screen(3.0, 3.0), PointerButton::Primary);
    key(&ctx, &mut app, Key::Escape);
    assert!(app.drawing.is_empty() && app.scene.lines().is_empty());
    click_at(&ctx, &mut app, screen(1.0, 3.0), PointerButton::Primary);
    click_at(&ctx, &mut app, screen(3.0, 3.0), PointerButton::Primary);
    click_at(&ctx, &mut app, screen(5.0, 3.0), PointerButton::Primary);
    click_at(&ctx, &mut app, screen(5.0, 3.0), PointerButton::Primary);
    assert_eq!(
        app.scene.lines(),
        [vec![p(1.0, 3.0), p(3.0, 3.0), p(5.0, 3.0)]]
    );
    let halved = cut(&mut app);
    assert_eq!(halved.inside, [vec![p(2.0, 3.0), p(3.0, 3.0), p(4.0, 3.0)]]);
    assert_eq!(areas(&halved), [2.0, 2.0]);

    // Dragging the middle vertex from (3, 3) up to (3, 6): the line passes over the square and cuts nothing.
    let (from, to) = (screen(3.0, 3.0), screen(3.0, 6.0));
    frame(&ctx, &mut app, vec![Event::PointerMoved(from)]);
    frame(
        &ctx,
        &mut app,
        vec![button(from, PointerButton::Primary, true)],
    );
    for step in 1..=9 {
        let at = from + (to - from) * (step as f32 / 9.0);
        frame(&ctx, &mut app, vec![Event::PointerMoved(at)]);
    }
    frame(
        &ctx,
        &mut app,
        vec![button(to, PointerButton::Primary, false)],
    );
    assert_eq!(
        app.scene.lines(),
        [vec![p(1.0, 3.0), p(3.0, 6.0), p(5.0, 3.0)]]
    );
    let missed = cut(&mut app);
    assert!(missed.inside.is_empty());
    assert_eq!(missed.outside.len(), 1, "the line whole");
    assert_eq!(areas(&missed), [4.0]);

    // Right-click deletes the bend, and the line halves the square again. Enter finishes a line as a double-click
    // does; this one, along x = 8, misses the square: the first line is in three parts, the second in one.
    click_at(&ctx, &mut app, screen(3.0, 6.0), PointerButton::Secondary);
    assert_eq!(app.scene.lines()[0], [p(1.0, 3.0), p(5.0, 3.0)]);
    click_at(&ctx, &mut app, screen(8.0, 1.0), PointerButton::Primary);
    click_at(&ctx, &mut app, screen(8.0, 8.0), PointerButton::Primary);
    key(&ctx, &mut app, Key::Enter);
    assert_eq!(app.scene.lines().len(), 2);
    let halved = cut(&mut app);
    assert_eq!((halved.inside.len(), halved.outside.len()), (1, 3));
    assert_eq!(areas(&halved), [2.0, 2.0]);

    // P switches back to drawing rings; the lines stay.
    key(&ctx, &mut app, Key::P);
    assert_eq!((app.tool, app.active), (Tool::Ring, Operand::Subject));
    assert_eq!(app.scene.lines().len(), 2);
}
