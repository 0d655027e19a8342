//! The playground window: a side panel with the operations, data and figures, and the canvas where the operands are
//! drawn and edited and the result is filled live.
//!
//! Mouse: click adds a vertex to the ring being drawn (of the active operand); click its first vertex, double-click
//! or press Enter to close it. Drag a vertex to move it, drag elsewhere to pan, scroll or pinch to zoom.
//! Right-click a vertex (or hover it and press Delete) to delete it. Keys: 1–5 operations, P/Q active operand,
//! G grid snapping, F fit, Esc drops the ring being drawn, Backspace its last vertex, Ctrl+Z / Ctrl+Shift+Z (or
//! Ctrl+Y) undo and redo, Ctrl+V pastes GeoJSON into the active operand.

use crate::fill::Fill;
use crate::io::{self, Files};
use crate::operation::{self, Op, Outcome};
use crate::presets::Preset;
use crate::scene::{Operand, Scene, VertexId};
use crate::view::View;
use eframe::egui::{self, Color32, Key, Mesh, Modifiers, Pos2, Rect, Sense, Shape, Stroke};
use polysweep::{geojson, Error, FillRule, MultiPolygon, Point};
use web_time::Instant;

/// Fill colours; the result is opaque so that it reads (and tests) the same over any operand.
pub const RESULT_FILL: Color32 = Color32::from_rgb(250, 190, 40);
const RESULT_EDGE: Color32 = Color32::from_rgb(120, 80, 0);
const OPERAND_FILL: [Color32; 2] = [
    Color32::from_rgba_premultiplied(30, 60, 110, 110),
    Color32::from_rgba_premultiplied(110, 35, 30, 110),
];
const OPERAND_EDGE: [Color32; 2] = [
    Color32::from_rgb(90, 150, 255),
    Color32::from_rgb(255, 110, 90),
];
/// Errors in the side panel: red, and far enough from Q's salmon that a test can tell them apart.
pub const ERROR_TEXT: Color32 = Color32::from_rgb(255, 64, 64);
const BACKGROUND: Color32 = Color32::from_rgb(18, 20, 24);

/// Vertex handles are drawn (and grabbed) within this many screen points.
const HANDLE_RADIUS: f32 = 7.0;
/// A computation slower than this (in milliseconds) is not repeated on every move of a drag.
const FRAME_BUDGET_MS: f64 = 12.0;
/// Above this many vertices an operand's handles are not drawn: they would cover the picture.
const MAX_HANDLES: usize = 5000;

/// What a drag on the canvas is doing.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Drag {
    /// Moving a vertex, since the scene's generation given (an undo, delete or load meanwhile ends the drag).
    Vertex(VertexId, u64),
    Pan,
}

/// What is derived from the operands, recomputed only when its inputs change.
#[derive(Default)]
struct Derived {
    /// The operand revision and fill rule each region fill was computed from.
    region_inputs: [Option<(u64, FillRule)>; 2],
    region_fills: [Fill; 2],
    /// The operand revisions, operation and fill rule the result was computed from.
    result_inputs: Option<([u64; 2], Op, FillRule)>,
    outcome: Option<Result<Outcome, Error>>,
    result_fill: Fill,
    /// How long the last computation of each took (sweep and triangulation), to decide what can run mid-drag.
    region_milliseconds: [f64; 2],
    result_milliseconds: f64,
}

pub struct Playground {
    pub scene: Scene,
    pub operation: Op,
    pub fill_rule: FillRule,
    /// The operand new rings go to.
    pub active: Operand,
    /// The ring being drawn, not yet closed.
    pub drawing: Vec<Point>,
    pub snap: bool,
    pub view: View,
    /// Fit the view to the data on the next frame (the canvas size is known only then).
    fit_pending: bool,
    drag: Option<Drag>,
    derived: Derived,
    files: Files,
    /// The last thing that happened that the user should know of (loads, saves, errors).
    status: Option<(String, bool)>,
    paste_text: Option<String>,
    #[cfg(not(target_arch = "wasm32"))]
    path: String,
}

impl Default for Playground {
    fn default() -> Self {
        let mut playground = Playground {
            scene: Scene::default(),
            operation: Op::Intersection,
            fill_rule: FillRule::EvenOdd,
            active: Operand::Subject,
            drawing: Vec::new(),
            snap: true,
            view: View::default(),
            fit_pending: false,
            drag: None,
            derived: Derived::default(),
            files: Files::default(),
            status: None,
            paste_text: None,
            #[cfg(not(target_arch = "wasm32"))]
            path: String::new(),
        };
        playground.status = Some((
            "Click to draw P; press Q to draw Q. Or pick a preset.".into(),
            false,
        ));
        playground
    }
}

impl eframe::App for Playground {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }
}

impl Playground {
    /// The app in eframe, in dark mode to match the canvas.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        cc.egui_ctx.set_theme(egui::Theme::Dark);
        Playground::default()
    }

    /// Loads a preset as one undoable step and fits the view to it.
    pub fn load_preset(&mut self, preset: Preset) {
        let (p, q) = preset.operands();
        self.scene.replace_both(p, q);
        self.drawing.clear();
        self.fit_pending = true;
        self.status = Some((format!("{} loaded", preset.label()), false));
    }

    /// Adds a vertex to the ring being drawn, or closes the ring when `at` is on its first vertex.
    pub fn click(&mut self, at: Point, grab_radius: f64) {
        if let Some(first) = self.drawing.first() {
            if self.drawing.len() >= 3 && (first.x - at.x).hypot(first.y - at.y) <= grab_radius {
                return self.close_ring();
            }
        }
        self.drawing
            .push(if self.snap { self.view.snap(at) } else { at });
    }

    /// Closes the ring being drawn into the active operand (a ring of fewer than 3 vertices is dropped).
    pub fn close_ring(&mut self) {
        let ring = std::mem::take(&mut self.drawing);
        self.scene.add_ring(self.active, ring);
    }

    /// The result of the current operation, computing it if the operands, operation or fill rule changed.
    pub fn outcome(&mut self) -> &Result<Outcome, Error> {
        self.refresh(true);
        self.derived.outcome.as_ref().expect("refreshed above")
    }

    /// Brings the fills and the result up to date with the operands. With `allow_slow` false (mid-drag), whatever
    /// took longer than a frame last time is left as it is, so that dragging stays smooth on large data; the canvas
    /// refreshes it when the pointer rests or is released. Returns whether everything is up to date.
    fn refresh(&mut self, allow_slow: bool) -> bool {
        let timed = |work: &mut dyn FnMut()| {
            let start = Instant::now();
            work();
            start.elapsed().as_secs_f64() * 1e3
        };
        let mut up_to_date = true;
        for which in [Operand::Subject, Operand::Clipping] {
            let i = which.index();
            let inputs = Some((self.scene.revision(which), self.fill_rule));
            if self.derived.region_inputs[i] == inputs {
                continue;
            }
            if !allow_slow && self.derived.region_milliseconds[i] > FRAME_BUDGET_MS {
                up_to_date = false;
                continue;
            }
            let (scene, fill_rule, derived) = (&self.scene, self.fill_rule, &mut self.derived);
            derived.region_milliseconds[i] = timed(&mut || {
                let region = operation::region(scene, which, fill_rule).unwrap_or_default();
                derived.region_fills[i] = Fill::of(&region);
            });
            derived.region_inputs[i] = inputs;
        }
        let revisions = [Operand::Subject, Operand::Clipping].map(|w| self.scene.revision(w));
        let inputs = Some((revisions, self.operation, self.fill_rule));
        let fresh = self.derived.result_inputs == inputs;
        if !fresh && !allow_slow && self.derived.result_milliseconds > FRAME_BUDGET_MS {
            return false;
        }
        if !fresh {
            let (scene, operation, fill_rule, derived) = (
                &self.scene,
                self.operation,
                self.fill_rule,
                &mut self.derived,
            );
            derived.result_milliseconds = timed(&mut || {
                let outcome = operation::run(operation, scene, fill_rule);
                derived.result_fill = outcome
                    .as_ref()
                    .map(|o| Fill::of(&o.result))
                    .unwrap_or_default();
                derived.outcome = Some(outcome);
            });
            derived.result_inputs = inputs;
        }
        up_to_date
    }

    /// Loads GeoJSON text into the active operand.
    pub fn load_text(&mut self, name: &str, text: &str) {
        match geojson::parse(text) {
            Ok(m) if m.is_empty() => {
                self.status = Some((format!("{name}: no polygons in it"), true))
            }
            Ok(m) => {
                let (polygons, vertices) = (m.0.len(), m.vertex_count());
                self.scene.replace(self.active, m);
                self.fit_pending = true;
                self.status = Some((
                    format!(
                        "{name}: {polygons} polygons, {vertices} vertices into {}",
                        self.active.name()
                    ),
                    false,
                ));
            }
            Err(e) => self.status = Some((format!("{name}: {e}"), true)),
        }
    }

    fn save(&mut self, name: &str, m: &MultiPolygon) {
        self.status = Some(
            match self.files.save(name, &geojson::to_geometry(m).to_string()) {
                Ok(done) => (done, false),
                Err(e) => (e, true),
            },
        );
    }

    /// One frame of the whole window.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        for (name, bytes) in self.files.take() {
            match bytes.and_then(|b| io::text_of(&b)) {
                Ok(text) => self.load_text(&name, &text),
                Err(e) => self.status = Some((format!("{name}: {e}"), true)),
            }
        }
        let dropped = ui.input_mut(|i| std::mem::take(&mut i.raw.dropped_files));
        for file in dropped {
            self.files.receive_dropped(ui.ctx(), file);
        }
        self.keyboard(ui);
        egui::Panel::left("controls")
            .resizable(false)
            .exact_size(280.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.controls(ui));
            });
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| self.canvas(ui));
        self.paste_window(ui.ctx());
    }

    fn keyboard(&mut self, ui: &egui::Ui) {
        if ui.ctx().egui_wants_keyboard_input() {
            return;
        }
        let pasted: Vec<String> = ui.input(|i| {
            i.events
                .iter()
                .filter_map(|e| {
                    if let egui::Event::Paste(t) = e {
                        Some(t.clone())
                    } else {
                        None
                    }
                })
                .collect()
        });
        for text in pasted {
            self.load_text("pasted text", &text);
        }
        ui.input_mut(|i| {
            let keys = [Key::Num1, Key::Num2, Key::Num3, Key::Num4, Key::Num5];
            for (key, op) in keys.into_iter().zip(Op::ALL) {
                if i.consume_key(Modifiers::NONE, key) {
                    self.operation = op;
                }
            }
            if i.consume_key(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z)
                || i.consume_key(Modifiers::COMMAND, Key::Y)
            {
                self.scene.redo();
            }
            if i.consume_key(Modifiers::COMMAND, Key::Z) {
                self.scene.undo();
            }
            if i.consume_key(Modifiers::NONE, Key::P) {
                self.active = Operand::Subject;
            }
            if i.consume_key(Modifiers::NONE, Key::Q) {
                self.active = Operand::Clipping;
            }
            if i.consume_key(Modifiers::NONE, Key::G) {
                self.snap = !self.snap;
            }
            if i.consume_key(Modifiers::NONE, Key::F) {
                self.fit_pending = true;
            }
            if i.consume_key(Modifiers::NONE, Key::Enter) {
                self.close_ring();
            }
            if i.consume_key(Modifiers::NONE, Key::Escape) {
                self.drawing.clear();
            }
            if i.consume_key(Modifiers::NONE, Key::Backspace) {
                self.drawing.pop();
            }
        });
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("polysweep playground");
        ui.label("Martínez–Rueda–Feito plane sweep, exact predicates.");
        ui.separator();

        ui.strong("Operation");
        for (n, op) in Op::ALL.into_iter().enumerate() {
            ui.radio_value(
                &mut self.operation,
                op,
                format!("{}   [{}]", op.label(), n + 1),
            );
        }
        ui.horizontal(|ui| {
            ui.label("Fill rule:");
            ui.radio_value(&mut self.fill_rule, FillRule::EvenOdd, "even-odd");
            ui.radio_value(&mut self.fill_rule, FillRule::NonZero, "non-zero");
        });
        ui.separator();

        ui.strong("Drawing");
        ui.horizontal(|ui| {
            ui.label("into");
            for which in [Operand::Subject, Operand::Clipping] {
                let label = egui::RichText::new(which.name()).color(OPERAND_EDGE[which.index()]);
                ui.radio_value(&mut self.active, which, label);
            }
        });
        ui.checkbox(&mut self.snap, "snap to grid  [G]");
        ui.horizontal(|ui| {
            if ui
                .add_enabled(self.scene.can_undo(), egui::Button::new("Undo"))
                .clicked()
            {
                self.scene.undo();
            }
            if ui
                .add_enabled(self.scene.can_redo(), egui::Button::new("Redo"))
                .clicked()
            {
                self.scene.redo();
            }
            if ui.button("Fit view [F]").clicked() {
                self.fit_pending = true;
            }
        });
        ui.horizontal(|ui| {
            for which in [Operand::Subject, Operand::Clipping] {
                let name = if which == Operand::Subject {
                    "Clear P"
                } else {
                    "Clear Q"
                };
                if ui.button(name).clicked() {
                    self.scene.replace(which, MultiPolygon::default());
                }
            }
        });
        ui.separator();

        ui.strong("Presets");
        let mut chosen = None;
        egui::ComboBox::from_id_salt("preset")
            .selected_text("load a preset…")
            .width(240.0)
            .show_ui(ui, |ui| {
                for preset in Preset::ALL {
                    if ui.selectable_label(false, preset.label()).clicked() {
                        chosen = Some(preset);
                    }
                }
            });
        if let Some(preset) = chosen {
            self.load_preset(preset);
        }
        ui.separator();

        self.data_controls(ui);
        ui.separator();
        self.figures(ui);
        if let Some((message, is_error)) = &self.status {
            ui.separator();
            let color = if *is_error {
                ERROR_TEXT
            } else {
                ui.visuals().text_color()
            };
            ui.label(egui::RichText::new(message).color(color));
        }
        ui.separator();
        ui.small(
            "Click: add vertex · click first vertex / double-click / Enter: close ring · drag vertex: move · \
             right-click vertex or Delete: remove · drag: pan · scroll: zoom · Esc: drop ring · Ctrl+Z / Ctrl+Y",
        );
    }

    fn data_controls(&mut self, ui: &mut egui::Ui) {
        ui.strong("GeoJSON");
        ui.label(format!("Open, drop or paste into {}", self.active.name()));
        ui.horizontal(|ui| {
            #[cfg(target_arch = "wasm32")]
            if ui.button("Open file…").clicked() {
                self.files.open_picker(ui.ctx());
            }
            if ui.button("Paste…").clicked() {
                self.paste_text = Some(String::new());
            }
        });
        #[cfg(not(target_arch = "wasm32"))]
        ui.horizontal(|ui| {
            ui.add(
                egui::TextEdit::singleline(&mut self.path)
                    .hint_text("path/to/file.geojson")
                    .desired_width(170.0),
            );
            if ui.button("Open").clicked() {
                self.files.open_path(&self.path.clone());
            }
        });
        ui.horizontal(|ui| {
            if ui.button("Save P").clicked() {
                self.save(
                    "subject.geojson",
                    &self.scene.operand(Operand::Subject).clone(),
                );
            }
            if ui.button("Save Q").clicked() {
                self.save(
                    "clipping.geojson",
                    &self.scene.operand(Operand::Clipping).clone(),
                );
            }
            if ui.button("Save result").clicked() {
                if let Ok(outcome) = self.outcome() {
                    let result = outcome.result.clone();
                    self.save(&format!("{}.geojson", self.operation.slug()), &result);
                }
            }
        });
    }

    fn figures(&mut self, ui: &mut egui::Ui) {
        let vertices =
            [Operand::Subject, Operand::Clipping].map(|w| self.scene.operand(w).vertex_count());
        let mut rows = vec![(
            "vertices in P / Q",
            format!("{} / {}", vertices[0], vertices[1]),
        )];
        match &self.derived.outcome {
            Some(Ok(o)) => rows.extend([
                ("vertices out", o.result.vertex_count().to_string()),
                ("polygons out", o.result.0.len().to_string()),
                ("edge intersections", o.crossings.to_string()),
                ("result area", format!("{:.6}", o.result.area())),
                ("operation time", format!("{:.2} ms", o.milliseconds)),
                (
                    "fill triangles",
                    self.derived.result_fill.triangle_count().to_string(),
                ),
            ]),
            Some(Err(e)) => rows.push(("error", e.to_string())),
            None => {}
        }
        rows.push((
            "last frame",
            format!("{:.1} ms", ui.input(|i| i.unstable_dt) * 1e3),
        ));
        egui::Grid::new("figures")
            .num_columns(2)
            .striped(true)
            .show(ui, |ui| {
                for (name, value) in rows {
                    ui.label(name);
                    let value = egui::RichText::new(value);
                    ui.label(if name == "error" {
                        value.color(ERROR_TEXT)
                    } else {
                        value
                    });
                    ui.end_row();
                }
            });
    }

    fn paste_window(&mut self, ctx: &egui::Context) {
        let Some(mut text) = self.paste_text.take() else {
            return;
        };
        let mut open = true;
        let mut load = false;
        egui::Window::new("Paste GeoJSON")
            .open(&mut open)
            .default_width(420.0)
            .show(ctx, |ui| {
                ui.label(format!(
                    "A Polygon, MultiPolygon, Feature or FeatureCollection, into {}",
                    self.active.name()
                ));
                egui::ScrollArea::vertical()
                    .max_height(300.0)
                    .show(ui, |ui| {
                        ui.add(
                            egui::TextEdit::multiline(&mut text)
                                .code_editor()
                                .desired_rows(12)
                                .desired_width(f32::INFINITY),
                        );
                    });
                load = ui.button("Load").clicked();
            });
        if load {
            self.load_text("pasted text", &text);
        } else if open {
            self.paste_text = Some(text);
        }
    }

    fn data_bounds(&self) -> Option<(Point, Point)> {
        let points = [Operand::Subject, Operand::Clipping]
            .into_iter()
            .flat_map(|w| {
                self.scene
                    .operand(w)
                    .0
                    .iter()
                    .flat_map(|p| p.rings().flatten())
            })
            .chain(&self.drawing);
        points.fold(None, |b, p| {
            let (lo, hi) = b.unwrap_or((*p, *p));
            Some((
                Point::new(lo.x.min(p.x), lo.y.min(p.y)),
                Point::new(hi.x.max(p.x), hi.y.max(p.y)),
            ))
        })
    }

    fn canvas(&mut self, ui: &mut egui::Ui) {
        let (response, painter) = ui.allocate_painter(ui.available_size(), Sense::click_and_drag());
        let canvas = response.rect;
        if std::mem::take(&mut self.fit_pending) {
            if let Some((lo, hi)) = self.data_bounds() {
                self.view.fit(canvas, lo, hi);
            }
        }
        self.interact(ui, &response);
        let settled =
            self.drag.is_none() || ui.input(|i| i.pointer.time_since_last_movement() > 0.15);
        let up_to_date = self.refresh(settled);
        if !up_to_date {
            ui.ctx()
                .request_repaint_after(std::time::Duration::from_millis(160));
        }
        let error_at = match &self.derived.outcome {
            Some(Err(e)) => e.location(),
            _ => None,
        };
        let error_vertex = error_at.and_then(|at| VertexId::from_location(&self.scene, &at));
        let view = self.view;
        let to_screen = |p: Point| view.to_screen(canvas, p);

        painter.rect_filled(canvas, 0.0, BACKGROUND);
        if self.snap {
            self.paint_grid(&painter, canvas);
        }
        for i in 0..2 {
            painter.add(Shape::mesh(
                self.derived.region_fills[i].mesh(to_screen, OPERAND_FILL[i]),
            ));
        }
        painter.add(Shape::mesh(
            self.derived.result_fill.mesh(to_screen, RESULT_FILL),
        ));
        if let Some(Ok(outcome)) = &self.derived.outcome {
            paint_outline(
                &painter,
                canvas,
                &outcome.result,
                to_screen,
                Stroke::new(1.0, RESULT_EDGE),
            );
        }
        for which in [Operand::Subject, Operand::Clipping] {
            let operand = self.scene.operand(which);
            let edge = OPERAND_EDGE[which.index()];
            paint_outline(&painter, canvas, operand, to_screen, Stroke::new(1.5, edge));
            if operand.vertex_count() <= MAX_HANDLES {
                let radius = if which == self.active { 3.5 } else { 2.5 };
                for p in operand.0.iter().flat_map(|p| p.rings().flatten()) {
                    painter.circle_filled(to_screen(*p), radius, edge);
                }
            }
        }
        self.paint_drawing(&painter, &response, to_screen);
        let pointer_world = response.hover_pos().map(|p| self.view.to_world(canvas, p));
        let hovered = pointer_world.and_then(|p| self.vertex_under(p));
        if let Some(id) = hovered.or(match self.drag {
            Some(Drag::Vertex(id, _)) => Some(id),
            _ => None,
        }) {
            if let Some(p) = self.scene.point(id) {
                painter.circle_stroke(
                    to_screen(p),
                    HANDLE_RADIUS,
                    Stroke::new(2.0, Color32::WHITE),
                );
            }
        }
        if let Some(p) = error_vertex.and_then(|id| self.scene.point(id)) {
            painter.circle_stroke(to_screen(p), 10.0, Stroke::new(3.0, Color32::RED));
        }
        if !up_to_date {
            let text = "large data: the result follows when the pointer rests";
            painter.text(
                canvas.left_top() + egui::vec2(8.0, 6.0),
                egui::Align2::LEFT_TOP,
                text,
                egui::FontId::proportional(13.0),
                Color32::LIGHT_GRAY,
            );
        }
        if let Some(p) = pointer_world {
            let text = format!("{:.6}, {:.6}", p.x, p.y);
            painter.text(
                canvas.right_bottom() - egui::vec2(8.0, 6.0),
                egui::Align2::RIGHT_BOTTOM,
                text,
                egui::FontId::monospace(12.0),
                Color32::GRAY,
            );
        }
    }

    fn vertex_under(&self, at: Point) -> Option<VertexId> {
        self.scene
            .vertex_near(at, f64::from(HANDLE_RADIUS) / self.view.scale, self.active)
    }

    fn interact(&mut self, ui: &egui::Ui, response: &egui::Response) {
        let canvas = response.rect;
        if response.hovered() {
            let (scroll, zoom, pointer) = ui.input(|i| {
                (
                    i.smooth_scroll_delta.y,
                    i.zoom_delta(),
                    i.pointer.hover_pos(),
                )
            });
            let factor = f64::from(zoom) * (f64::from(scroll) / 300.0).exp();
            if let (Some(pointer), true) = (pointer, factor != 1.0) {
                self.view.zoom_at(canvas, pointer, factor);
            }
        }
        let grab = f64::from(HANDLE_RADIUS) / self.view.scale;
        if response.drag_started() {
            let origin = ui
                .input(|i| i.pointer.press_origin())
                .unwrap_or(canvas.center());
            let on_vertex = self.vertex_under(self.view.to_world(canvas, origin));
            self.drag = match on_vertex {
                Some(id) if response.drag_started_by(egui::PointerButton::Primary) => {
                    self.scene.checkpoint();
                    Some(Drag::Vertex(id, self.scene.generation()))
                }
                _ => Some(Drag::Pan),
            };
        }
        if response.dragged() {
            match (self.drag, response.interact_pointer_pos()) {
                (Some(Drag::Vertex(_, generation)), _) if generation != self.scene.generation() => {
                    self.drag = None;
                }
                (Some(Drag::Vertex(id, _)), Some(pos)) => {
                    let at = self.view.to_world(canvas, pos);
                    self.scene
                        .move_vertex(id, if self.snap { self.view.snap(at) } else { at });
                }
                (Some(Drag::Pan), _) => self.view.pan(response.drag_delta()),
                _ => {}
            }
        }
        if response.drag_stopped() {
            self.drag = None;
        }
        let pointer = response.interact_pointer_pos().or(response.hover_pos());
        let Some(pointer) = pointer else { return };
        let at = self.view.to_world(canvas, pointer);
        if response.double_clicked() {
            // The double-click's first click added its vertex; the second closes the ring.
            self.close_ring();
        } else if response.clicked() {
            self.click(at, grab);
        } else if response.secondary_clicked() {
            match self.vertex_under(at) {
                Some(id) => self.scene.delete_vertex(id),
                None => {
                    self.drawing.pop();
                }
            }
        }
        let delete =
            !ui.ctx().egui_wants_keyboard_input() && ui.input(|i| i.key_pressed(Key::Delete));
        if response.hovered() && self.drag.is_none() && delete {
            if let Some(id) = self.vertex_under(at) {
                self.scene.delete_vertex(id);
            }
        }
    }

    fn paint_grid(&self, painter: &egui::Painter, canvas: Rect) {
        let (lo, hi) = (
            self.view.to_world(canvas, canvas.left_bottom()),
            self.view.to_world(canvas, canvas.right_top()),
        );
        let stroke = Stroke::new(1.0, Color32::from_gray(38));
        for x in self.view.grid_lines(lo.x, hi.x, 500) {
            let sx = self.view.to_screen(canvas, Point::new(x, 0.0)).x;
            painter.vline(sx, canvas.y_range(), stroke);
        }
        for y in self.view.grid_lines(lo.y, hi.y, 500) {
            let sy = self.view.to_screen(canvas, Point::new(0.0, y)).y;
            painter.hline(canvas.x_range(), sy, stroke);
        }
    }

    fn paint_drawing(
        &self,
        painter: &egui::Painter,
        response: &egui::Response,
        to_screen: impl Fn(Point) -> Pos2,
    ) {
        if self.drawing.is_empty() {
            return;
        }
        let edge = OPERAND_EDGE[self.active.index()];
        let mut points: Vec<Pos2> = self.drawing.iter().map(|p| to_screen(*p)).collect();
        if let Some(pointer) = response.hover_pos() {
            points.push(pointer);
        }
        painter.add(Shape::line(points, Stroke::new(1.5, edge)));
        for p in &self.drawing {
            painter.circle_filled(to_screen(*p), 3.5, edge);
        }
        painter.circle_stroke(
            to_screen(self.drawing[0]),
            HANDLE_RADIUS,
            Stroke::new(1.5, edge),
        );
    }
}

/// Draws every ring of `m` that is on screen, as one mesh of a thin quad per edge. egui's own path stroke joins
/// edges with miters, which shoot far out at the hairpin turns of real coastlines; separate quads have no joins.
/// Vertices closer than a pixel to the last one drawn are skipped: zoomed out, a coastline has many per pixel.
fn paint_outline(
    painter: &egui::Painter,
    canvas: Rect,
    m: &MultiPolygon,
    to_screen: impl Fn(Point) -> Pos2,
    stroke: Stroke,
) {
    let mut mesh = Mesh::default();
    let mut points: Vec<Pos2> = Vec::new();
    for ring in m.0.iter().flat_map(|p| p.rings()) {
        points.clear();
        for p in ring.iter().chain(ring.first()) {
            let q = to_screen(*p);
            if points.last().is_none_or(|last| last.distance_sq(q) >= 1.0) {
                points.push(q);
            }
        }
        if points.len() < 3 || !Rect::from_points(&points).intersects(canvas) {
            continue;
        }
        for edge in points.windows(2) {
            let (a, b) = (edge[0], edge[1]);
            let half = (b - a).normalized().rot90() * (stroke.width / 2.0);
            let base = mesh.vertices.len() as u32;
            for corner in [a + half, b + half, b - half, a - half] {
                mesh.colored_vertex(corner, stroke.color);
            }
            mesh.add_triangle(base, base + 1, base + 2);
            mesh.add_triangle(base, base + 2, base + 3);
        }
    }
    painter.add(Shape::mesh(mesh));
}
