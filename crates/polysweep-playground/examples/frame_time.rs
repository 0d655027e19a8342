//! CPU time of playground frames, without a GPU: the app's frame plus egui's tessellation, as the renderer would
//! receive it (the polygons are not in it: the GPU pipeline of gpu.rs uploads them once per change and only moves
//! them per frame). On the paper's Table 1 data (land, 59,212 vertices, × 8 squares) and on 1M and 4M vertices (a
//! grid of 64-gons against a few squares): frames while the result is computed on a thread, idle and panning
//! frames, and how many results a second follow a dragged vertex. Prints milliseconds.
//!
//! ```text
//! cargo run --release -p polysweep-playground --example frame_time
//! ```

use eframe::egui::{self, Event, Modifiers, PointerButton, Pos2, RawInput, Rect, Vec2};
use polysweep::{MultiPolygon, Point};
use polysweep_playground::operation::Op;
use polysweep_playground::presets::Preset;
use polysweep_playground::scene::{Operand, VertexId};
use polysweep_playground::view::View;
use polysweep_playground::Playground;
use std::time::{Duration, Instant};

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

/// `n` × `n` 64-gons of radius 0.4 on the unit grid (64·n² vertices), and four squares over parts of it.
fn polygon_grid(n: usize) -> (MultiPolygon, MultiPolygon) {
    let gon = |cx: f64, cy: f64| {
        vec![(0..64)
            .map(|k| {
                let angle = k as f64 * std::f64::consts::TAU / 64.0;
                [cx + 0.4 * angle.cos(), cy + 0.4 * angle.sin()]
            })
            .collect::<Vec<_>>()]
    };
    let gons: Vec<_> = (0..n * n)
        .map(|k| gon((k % n) as f64, (k / n) as f64))
        .collect();
    let side = n as f64 / 3.0;
    let squares: Vec<_> = [(0.1, 0.1), (0.6, 0.1), (0.1, 0.6), (0.6, 0.6)]
        .iter()
        .map(|&(x, y)| {
            let (x, y) = (x * n as f64, y * n as f64);
            vec![vec![
                [x, y],
                [x + side, y],
                [x + side, y + side],
                [x, y + side],
            ]]
        })
        .collect();
    (
        MultiPolygon::from_coordinates(&gons),
        MultiPolygon::from_coordinates(&squares),
    )
}

/// Loads a data set into the app.
type Load = fn(&mut Playground);

fn main() {
    let ctx = egui::Context::default();
    let mut time = 0.0;
    let datasets: [(&str, Load); 3] = [
        ("land × 8 squares (59,212 + 32 vertices)", |app| {
            app.load_preset(Preset::Table1 { squares: 8 })
        }),
        ("1M vertices", |app| load_grid(app, 125)),
        ("4M vertices", |app| load_grid(app, 250)),
    ];
    for (name, load) in datasets {
        let mut app = Playground::default();
        load(&mut app);
        for op in [Op::Intersection, Op::Union] {
            app.operation = op;
            let (wait, frames) = paced_frames(&ctx, &mut app, &mut time, |app, _| app.pending());
            let (idle, pan) = idle_and_pan(&ctx, &mut app, &mut time);
            let outcome = app
                .outcome()
                .as_ref()
                .map(|o| o.milliseconds)
                .unwrap_or(f64::NAN);
            println!(
                "{name}, {op:?}: the result and its fills came {wait:.0} ms after the change, computed on a \
                 thread while {} frames were drawn (median {:.2} ms, longest {:.2} ms); the operation itself \
                 {outcome:.1} ms; idle frame {idle:.2} ms, panning frame {pan:.2} ms",
                frames.len(),
                median(frames.clone()),
                frames.iter().copied().fold(0.0, f64::max),
            );
        }
        // A vertex of Q dragged for two seconds, moved on every frame: how often the shown result follows it.
        let corner = VertexId {
            operand: Operand::Clipping,
            polygon: 0,
            ring: 0,
            vertex: 1,
        };
        let start = app.scene.point(corner).expect("Q has a polygon");
        let results = app.results_received();
        let (_, frames) = paced_frames(&ctx, &mut app, &mut time, |app, i| {
            let to = Point::new(start.x + i as f64 * 0.01, start.y);
            app.scene.move_vertex(corner, to);
            i < 120
        });
        let results = app.results_received() - results;
        println!(
            "{name}, a vertex of Q dragged for 2 s at 60 frames a second: {:.1} results a second shown, frames \
             median {:.2} ms, longest {:.2} ms",
            results as f64 / 2.0,
            median(frames.clone()),
            frames.iter().copied().fold(0.0, f64::max),
        );
    }
}

/// Frames at 60 a second (sleeping out the rest of each 1/60 s) for as long as `go_on(app, frame number)` says, at
/// most a minute; returns the milliseconds it took and each frame's time.
fn paced_frames(
    ctx: &egui::Context,
    app: &mut Playground,
    time: &mut f64,
    mut go_on: impl FnMut(&mut Playground, usize) -> bool,
) -> (f64, Vec<f64>) {
    let start = Instant::now();
    let mut frames = Vec::new();
    while go_on(app, frames.len()) && start.elapsed().as_secs() < 60 {
        let took = frame(ctx, app, time, vec![]);
        frames.push(took);
        std::thread::sleep(Duration::from_secs_f64((1.0 / 60.0 - took / 1e3).max(0.0)));
    }
    (start.elapsed().as_secs_f64() * 1e3, frames)
}

/// Loads `polygon_grid(n)` as P and Q, in view.
fn load_grid(app: &mut Playground, n: usize) {
    let (p, q) = polygon_grid(n);
    app.scene.replace_both(p, q);
    let middle = (n as f64 - 1.0) / 2.0;
    app.view = View {
        center: polysweep::Point::new(middle, middle),
        scale: f64::from(SCREEN.y) / (n as f64 + 1.0),
    };
}

/// Median frames: idle, then panning (a drag across empty canvas space, no vertex under the press).
fn idle_and_pan(ctx: &egui::Context, app: &mut Playground, time: &mut f64) -> (f64, f64) {
    let idle: Vec<f64> = (0..20).map(|_| frame(ctx, app, time, vec![])).collect();
    let start = Pos2::new(1590.0, 990.0);
    frame(ctx, app, time, vec![Event::PointerMoved(start)]);
    let button = |pressed| Event::PointerButton {
        pos: start,
        button: PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    };
    frame(ctx, app, time, vec![button(true)]);
    let pan: Vec<f64> = (1..=30)
        .map(|i| {
            let to = start - Vec2::splat(i as f32 * 3.0);
            frame(ctx, app, time, vec![Event::PointerMoved(to)])
        })
        .collect();
    frame(ctx, app, time, vec![button(false)]);
    (median(idle), median(pan))
}
