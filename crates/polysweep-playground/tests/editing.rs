//! The playground's logic without a window: drawing, editing, undo, the five operations, loading, errors, and
//! whole egui frames driven by synthetic mouse and keyboard events.

mod common;

use common::{click_at, frame, key, p, SCREEN};
use eframe::egui::{self, Key, PointerButton, Pos2, Vec2};
use polysweep::FillRule;
use polysweep_playground::operation::{self, Op};
use polysweep_playground::presets::Preset;
use polysweep_playground::scene::{Operand, VertexId};
use polysweep_playground::Playground;

/// Draws an axis-aligned square by clicks, closing it by clicking its first vertex again.
fn draw_square(app: &mut Playground, operand: Operand, x: f64, y: f64, size: f64) {
    app.active = operand;
    for corner in [
        p(x, y),
        p(x + size, y),
        p(x + size, y + size),
        p(x, y + size),
        p(x, y),
    ] {
        app.click(corner, 0.1);
    }
}

/// A vertex of the first polygon of an operand.
fn vertex_of(operand: Operand, ring: usize, vertex: usize) -> VertexId {
    VertexId {
        operand,
        polygon: 0,
        ring,
        vertex,
    }
}

fn result_area(app: &mut Playground) -> f64 {
    app.outcome().as_ref().expect("no error").result.area()
}

#[test]
fn two_drawn_squares_give_every_operation() {
    let mut app = Playground::default();
    draw_square(&mut app, Operand::Subject, 0.0, 0.0, 4.0);
    draw_square(&mut app, Operand::Clipping, 2.0, 2.0, 4.0);
    assert!(
        app.drawing.is_empty(),
        "clicking the first vertex closed each ring"
    );
    let expected = [
        (Op::Intersection, 4.0),
        (Op::Union, 28.0),
        (Op::SubjectMinusClipping, 12.0),
        (Op::ClippingMinusSubject, 12.0),
        (Op::Xor, 24.0),
    ];
    for (op, area) in expected {
        app.operation = op;
        assert_eq!(result_area(&mut app), area, "{op:?}");
    }
    app.operation = Op::Intersection;
    let outcome = app.outcome().as_ref().unwrap();
    assert_eq!(outcome.crossings, 2);
    assert_eq!(outcome.result.0[0].exterior.len(), 5, "a closed square");
}

#[test]
fn undo_and_redo_walk_the_history() {
    let mut app = Playground::default();
    draw_square(&mut app, Operand::Subject, 0.0, 0.0, 4.0);
    draw_square(&mut app, Operand::Clipping, 2.0, 2.0, 4.0);
    app.scene.undo();
    assert!(app.scene.operand(Operand::Clipping).is_empty());
    assert_eq!(result_area(&mut app), 0.0);
    app.scene.redo();
    assert_eq!(result_area(&mut app), 4.0);

    // A drag is one step, however many moves it makes.
    let corner = vertex_of(Operand::Clipping, 0, 0);
    app.scene.checkpoint();
    for step in 1..=10 {
        app.scene.move_vertex(
            corner,
            p(2.0 - 0.2 * f64::from(step), 2.0 - 0.2 * f64::from(step)),
        );
    }
    assert_eq!(app.scene.point(corner), Some(p(0.0, 0.0)));
    // Q is now (0,0) (6,2) (6,6) (2,6): P's square less the triangles under y = x/3 and left of y = 3x.
    assert!((result_area(&mut app) - (16.0 - 2.0 * 8.0 / 3.0)).abs() < 1e-12);
    app.scene.undo();
    assert_eq!(
        app.scene.point(corner),
        Some(p(2.0, 2.0)),
        "one undo reverts the whole drag"
    );
    assert!(app.scene.can_redo());
    let generation = app.scene.generation();
    app.scene.redo();
    assert_ne!(
        app.scene.generation(),
        generation,
        "a drag in progress can tell its vertex ids are stale"
    );
    app.scene.undo();
}

#[test]
fn deleting_vertices_shrinks_then_removes_rings() {
    let mut app = Playground::default();
    draw_square(&mut app, Operand::Subject, 0.0, 0.0, 4.0);
    app.click(p(1.0, 1.0), 0.1);
    app.click(p(3.0, 1.0), 0.1);
    app.click(p(3.0, 3.0), 0.1);
    app.close_ring();
    assert_eq!(
        app.scene.operand(Operand::Subject).0[0].holes.len(),
        1,
        "a ring drawn inside P is a hole of it"
    );
    let region = operation::region(
        app.scene.operand(Operand::Subject),
        Operand::Subject,
        FillRule::EvenOdd,
    )
    .unwrap();
    assert_eq!(region.area(), 16.0 - 2.0);
    // Drawn counter-clockwise like its shell, the hole was turned around: it is a hole under non-zero too.
    let non_zero = operation::region(
        app.scene.operand(Operand::Subject),
        Operand::Subject,
        FillRule::NonZero,
    )
    .unwrap();
    assert_eq!(non_zero.area(), 16.0 - 2.0);

    let vertex = |ring, vertex| vertex_of(Operand::Subject, ring, vertex);
    app.scene.delete_vertex(vertex(0, 3));
    assert_eq!(app.scene.operand(Operand::Subject).0[0].exterior.len(), 3);
    assert_eq!(
        operation::region(
            app.scene.operand(Operand::Subject),
            Operand::Subject,
            FillRule::EvenOdd
        )
        .unwrap()
        .area(),
        8.0 - 2.0
    );
    app.scene.delete_vertex(vertex(1, 0));
    assert!(
        app.scene.operand(Operand::Subject).0[0].holes.is_empty(),
        "a hole of 2 vertices is gone"
    );
    app.scene.delete_vertex(vertex(0, 0));
    assert!(
        app.scene.operand(Operand::Subject).is_empty(),
        "and so is an exterior"
    );
    app.scene.undo();
    app.scene.undo();
    assert_eq!(app.scene.operand(Operand::Subject).0[0].holes.len(), 1);
}

#[test]
fn snapping_and_the_ring_in_progress() {
    let mut app = Playground::default();
    assert!(app.snap);
    app.click(p(2.4, 3.6), 0.1);
    assert_eq!(app.drawing, [p(2.0, 4.0)]);
    app.snap = false;
    app.click(p(2.4, 3.6), 0.1);
    assert_eq!(app.drawing[1], p(2.4, 3.6));
    app.close_ring();
    assert!(
        app.scene.operand(Operand::Subject).is_empty(),
        "two vertices make no ring"
    );
    assert!(!app.scene.can_undo(), "and no undo step");
}

#[test]
fn errors_name_the_vertex_and_the_app_recovers() {
    let mut app = Playground::default();
    draw_square(&mut app, Operand::Subject, 0.0, 0.0, 4.0);
    draw_square(&mut app, Operand::Clipping, 2.0, 2.0, 4.0);
    let bad = vertex_of(Operand::Clipping, 0, 2);
    app.scene.checkpoint();
    app.scene.move_vertex(bad, p(f64::NAN, 1.0));
    for op in Op::ALL {
        app.operation = op;
        let error = app.outcome().as_ref().expect_err("NaN is refused").clone();
        assert_eq!(
            error.location().expect("a vertex is named").operand,
            1,
            "{op:?}: Q is operand 1, also when the core swaps it"
        );
        assert_eq!(
            VertexId::from_location(&app.scene, &error.location().unwrap()),
            Some(bad)
        );
        assert!(
            error
                .to_string()
                .contains("operand 1, polygon 0, ring 0, vertex 2"),
            "{error}"
        );
    }
    app.scene.undo();
    app.operation = Op::Union;
    assert_eq!(result_area(&mut app), 28.0);
}

#[test]
fn geojson_loads_into_the_active_operand_and_bad_text_changes_nothing() {
    let mut app = Playground::default();
    app.active = Operand::Clipping;
    app.load_text("t.geojson", r#"{"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[0,0],[3,0],[3,3],[0,3],[0,0]]]}}"#);
    let q = app.scene.operand(Operand::Clipping);
    assert_eq!(
        q.0[0].exterior.len(),
        4,
        "the closing point is dropped: every vertex is one handle"
    );
    app.load_text(
        "bad.geojson",
        r#"{"type":"Polygon","coordinates":[[[0,0],[1]]]}"#,
    );
    assert_eq!(app.scene.operand(Operand::Clipping).vertex_count(), 4);
    app.operation = Op::ClippingMinusSubject;
    assert_eq!(result_area(&mut app), 9.0);
}

#[test]
fn presets_load_and_compute() {
    let mut app = Playground::default();
    app.load_preset(Preset::Fig3);
    app.operation = Op::Intersection;
    // Fig. 3: the two notched squares of the fixture overlap in two triangles of area 4 each.
    assert_eq!(result_area(&mut app), 8.0);
    app.load_preset(Preset::Table1 { squares: 8 });
    let outcome = app.outcome().as_ref().unwrap();
    assert_eq!(
        outcome.crossings, 160,
        "the paper's Table 1 workload at 8 squares"
    );
    app.scene.undo();
    assert_eq!(
        app.scene.operand(Operand::Subject).0.len(),
        1,
        "back to Fig. 3"
    );
}

// ---- whole frames through egui ----

#[test]
fn the_mouse_draws_and_the_keys_switch_operations() {
    let ctx = egui::Context::default();
    let mut app = Playground::default();
    frame(&ctx, &mut app, vec![]);
    // The canvas is right of the 280-point panel; 30 points per unit around (5, 5) at its centre.
    let canvas_center = Pos2::new(280.0 + (SCREEN.x - 280.0) / 2.0, SCREEN.y / 2.0);
    let screen = |x: f32, y: f32| canvas_center + Vec2::new((x - 5.0) * 30.0, -(y - 5.0) * 30.0);
    for (x, y) in [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0), (0.0, 0.0)] {
        click_at(&ctx, &mut app, screen(x, y), PointerButton::Primary);
    }
    key(&ctx, &mut app, Key::Q);
    assert_eq!(app.active, Operand::Clipping);
    for (x, y) in [(2.0, 2.0), (6.0, 2.0), (6.0, 6.0), (2.0, 6.0)] {
        click_at(&ctx, &mut app, screen(x, y), PointerButton::Primary);
    }
    key(&ctx, &mut app, Key::Enter);
    assert_eq!(
        app.scene.operand(Operand::Subject).0[0].exterior,
        [p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)]
    );
    assert_eq!(app.scene.operand(Operand::Clipping).vertex_count(), 4);
    for (key_, op, area) in [
        (Key::Num2, Op::Union, 28.0),
        (Key::Num4, Op::ClippingMinusSubject, 12.0),
        (Key::Num1, Op::Intersection, 4.0),
    ] {
        key(&ctx, &mut app, key_);
        assert_eq!(app.operation, op);
        assert_eq!(result_area(&mut app), area);
    }
}

#[test]
fn history_on_large_data_is_bounded_by_its_size() {
    let mut app = Playground::default();
    app.load_preset(Preset::Table1 { squares: 8 });
    let step_vertices = 59_212 + 8 * 4;
    for _ in 0..100 {
        app.scene.checkpoint();
    }
    let mut undos = 0;
    while app.scene.can_undo() {
        app.scene.undo();
        undos += 1;
    }
    assert_eq!(
        undos,
        4_000_000 / step_vertices,
        "as many steps as fit in 4 million vertices"
    );
}

#[test]
fn an_edit_invalidates_only_what_derives_from_its_operand() {
    let mut app = Playground::default();
    draw_square(&mut app, Operand::Subject, 0.0, 0.0, 4.0);
    draw_square(&mut app, Operand::Clipping, 2.0, 2.0, 4.0);
    let revisions =
        |app: &Playground| [Operand::Subject, Operand::Clipping].map(|w| app.scene.revision(w));
    let before = revisions(&app);
    app.scene.checkpoint();
    app.scene
        .move_vertex(vertex_of(Operand::Subject, 0, 2), p(5.0, 5.0));
    let moved = revisions(&app);
    assert!(
        moved[0] != before[0] && moved[1] == before[1],
        "moving a vertex of P leaves Q's fill alone"
    );
    app.scene
        .move_vertex(vertex_of(Operand::Subject, 0, 2), p(5.0, 5.0));
    assert_eq!(
        revisions(&app),
        moved,
        "a drag held still asks for nothing new"
    );
    app.scene.undo();
    assert!(revisions(&app)[0] != moved[0] && revisions(&app)[1] == before[1]);
    assert_eq!(
        result_area(&mut app),
        4.0,
        "and the result follows the undo"
    );
}

#[test]
fn the_vertex_under_the_pointer_is_found_among_many_polygons_and_follows_edits() {
    let mut app = Playground::default();
    for k in 0..5 {
        draw_square(&mut app, Operand::Subject, 10.0 * k as f64, 0.0, 2.0);
    }
    draw_square(&mut app, Operand::Clipping, 21.0, 1.0, 2.0);
    let scene = &app.scene;
    let corner = |polygon, vertex| VertexId {
        operand: Operand::Subject,
        polygon,
        ring: 0,
        vertex,
    };
    // (22, 2) is the fourth polygon's corner (index 2); Q's corner (21, 1) is farther than the radius from it.
    assert_eq!(
        scene.vertex_near(p(22.05, 2.0), 0.3, Operand::Subject),
        Some(corner(2, 2))
    );
    assert_eq!(scene.vertex_near(p(5.0, 5.0), 0.3, Operand::Subject), None);
    let q = scene
        .vertex_near(p(21.1, 1.0), 0.3, Operand::Subject)
        .unwrap();
    assert_eq!(q.operand, Operand::Clipping);
    // Moved far away, the vertex is found where it went and no longer where it was.
    app.scene.move_vertex(corner(4, 0), p(100.0, 100.0));
    assert_eq!(
        app.scene
            .vertex_near(p(100.0, 100.1), 0.3, Operand::Subject),
        Some(corner(4, 0))
    );
    assert_eq!(
        app.scene.vertex_near(p(40.0, 0.0), 0.3, Operand::Subject),
        None
    );
}

#[test]
fn key_x_opens_the_sweep_explorer_and_the_arrows_step_through_it() {
    let ctx = egui::Context::default();
    let mut app = Playground::default();
    app.load_preset(Preset::Fig7);
    frame(&ctx, &mut app, vec![]);
    key(&ctx, &mut app, Key::X);
    assert_eq!(app.explorer().map(|e| e.position()), Some(0));
    for _ in 0..3 {
        key(&ctx, &mut app, Key::ArrowRight);
    }
    let explorer = app.explorer().expect("on");
    assert_eq!(explorer.position(), 3);
    assert_eq!(
        explorer.status().len(),
        4,
        "§3's S after p0p1 is inserted: four edges"
    );
    key(&ctx, &mut app, Key::ArrowLeft);
    assert_eq!(app.explorer().unwrap().position(), 2);
    // Editing traces again, at the same step.
    app.scene.checkpoint();
    let apex = VertexId {
        operand: Operand::Clipping,
        polygon: 0,
        ring: 0,
        vertex: 2,
    };
    app.scene.move_vertex(apex, p(6.0, 6.0));
    frame(&ctx, &mut app, vec![]);
    assert_eq!(app.explorer().unwrap().position(), 2);
    key(&ctx, &mut app, Key::X);
    assert!(app.explorer().is_none());
}
