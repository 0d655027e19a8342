//! What the playground's integration tests share: whole frames of the app through egui, and input events.
#![allow(dead_code)] // each test binary uses part of it

use eframe::egui::{self, Event, Key, Modifiers, PointerButton, Pos2, RawInput, Rect, Vec2};
use polysweep::Point;
use polysweep_playground::Playground;

pub fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

pub const SCREEN: Vec2 = Vec2::new(1200.0, 800.0);

pub fn frame(ctx: &egui::Context, app: &mut Playground, events: Vec<Event>) {
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, SCREEN)),
        events,
        ..Default::default()
    };
    let mut output = ctx.run_ui(input, |ui| app.show(ui));
    // Tessellate as a renderer would, so that the meshes the app paints (pieces, dashed parts) are checked too.
    for primitive in ctx.tessellate(std::mem::take(&mut output.shapes), output.pixels_per_point) {
        if let egui::epaint::Primitive::Mesh(mesh) = primitive.primitive {
            assert!(mesh.is_valid(), "a mesh indexes past its vertices");
        }
    }
    output.textures_delta.clear();
}

pub fn button(at: Pos2, button: PointerButton, pressed: bool) -> Event {
    Event::PointerButton {
        pos: at,
        button,
        pressed,
        modifiers: Modifiers::NONE,
    }
}

pub fn click_at(ctx: &egui::Context, app: &mut Playground, at: Pos2, which: PointerButton) {
    frame(ctx, app, vec![Event::PointerMoved(at)]);
    frame(ctx, app, vec![button(at, which, true)]);
    frame(ctx, app, vec![button(at, which, false)]);
}

pub fn key(ctx: &egui::Context, app: &mut Playground, key: Key) {
    let event = |pressed| Event::Key {
        key,
        physical_key: None,
        pressed,
        repeat: false,
        modifiers: Modifiers::NONE,
    };
    frame(ctx, app, vec![event(true), event(false)]);
}
