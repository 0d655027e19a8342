//! CPU time of playground frames on the paper's Table 1 data (land, 59,212 vertices, × 8 squares), without a GPU:
//! the app's frame plus egui's tessellation, as the renderer would receive it (the fills are not in it: the GPU
//! pipeline of gpu.rs uploads them once and only moves them per frame). Prints medians in milliseconds.
//!
//! ```text
//! cargo run --release -p polysweep-playground --example frame_time
//! ```

use eframe::egui::{self, Event, Modifiers, PointerButton, Pos2, RawInput, Rect, Vec2};
use polysweep_playground::operation::Op;
use polysweep_playground::presets::Preset;
use polysweep_playground::Playground;
use std::time::Instant;

const SCREEN: Vec2 = Vec2::new(1600.0, 1000.0);

fn frame(ctx: &egui::Context, app: &mut Playground, time: &mut f64, events: Vec<Event>) -> f64 {
    *time += 1.0 / 60.0;
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, SCREEN)),
        time: Some(*time),
        events,
        ..Default::default()
    };
    let start = Instant::now();
    let mut output = ctx.run_ui(input, |ui| app.show(ui));
    let primitives = ctx.tessellate(std::mem::take(&mut output.shapes), output.pixels_per_point);
    std::hint::black_box(primitives);
    output.textures_delta.clear();
    start.elapsed().as_secs_f64() * 1e3
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let ctx = egui::Context::default();
    let mut app = Playground::default();
    let mut time = 0.0;
    app.load_preset(Preset::Table1 { squares: 8 });
    for op in [Op::Intersection, Op::Union] {
        app.operation = op;
        frame(&ctx, &mut app, &mut time, vec![]);
        let idle: Vec<f64> = (0..20)
            .map(|_| frame(&ctx, &mut app, &mut time, vec![]))
            .collect();
        // Pan: drag across empty canvas space (no vertex under the press).
        let start = Pos2::new(1590.0, 990.0);
        frame(&ctx, &mut app, &mut time, vec![Event::PointerMoved(start)]);
        let press = Event::PointerButton {
            pos: start,
            button: PointerButton::Primary,
            pressed: true,
            modifiers: Modifiers::NONE,
        };
        frame(&ctx, &mut app, &mut time, vec![press]);
        let pan: Vec<f64> = (1..=30)
            .map(|i| {
                frame(
                    &ctx,
                    &mut app,
                    &mut time,
                    vec![Event::PointerMoved(start - Vec2::splat(i as f32 * 3.0))],
                )
            })
            .collect();
        let release = Event::PointerButton {
            pos: start,
            button: PointerButton::Primary,
            pressed: false,
            modifiers: Modifiers::NONE,
        };
        frame(&ctx, &mut app, &mut time, vec![release]);
        let outcome = app
            .outcome()
            .as_ref()
            .map(|o| o.milliseconds)
            .unwrap_or(f64::NAN);
        println!(
            "{op:?}: idle frame {:.2} ms, panning frame {:.2} ms, the operation itself {:.2} ms",
            median(idle),
            median(pan),
            outcome
        );
    }
}
