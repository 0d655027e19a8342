//! The playground window: a side panel with the operations, data and figures, and the canvas where the operands and
//! lines are drawn and edited, the result is filled live, and the lines clip it and split it into pieces.
//!
//! Mouse: click adds a vertex to the ring being drawn (of the active operand); click its first vertex, double-click
//! or press Enter to close it. With the line tool, click adds a vertex to the line being drawn; double-click or
//! Enter finishes it. Drag a vertex to move it, drag elsewhere to pan, scroll or pinch to zoom. Right-click a vertex
//! (or hover it and press Delete) to delete it. Keys: 1–5 operations, P/Q draw into that operand, L draw lines,
//! G grid snapping, F fit, Esc drops the ring or line being drawn, Backspace its last vertex, Ctrl+Z /
//! Ctrl+Shift+Z (or Ctrl+Y) undo and redo, Ctrl+V pastes GeoJSON into the active operand, X steps through the
//! sweep (see explore.rs for its keys).

mod canvas;
mod derived;
mod explore;
mod input;
mod panel;

use crate::io::{self, Files};
use crate::operation::Op;
use crate::presets::Preset;
use crate::scene::{Operand, Scene};
use crate::view::View;
use derived::Derived;
use eframe::egui::{self, Color32};
use eframe::egui_wgpu::wgpu;
use explore::Exploring;
use input::Drag;
use polysweep::{geojson, FillRule, Point};

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
/// The pieces the lines split the result into, in turn: the first is the result's own colour, so that a result no
/// line cuts looks as it does without lines. Opaque like the result.
pub const PIECE_FILLS: [Color32; 8] = [
    RESULT_FILL,
    Color32::from_rgb(70, 200, 170),
    Color32::from_rgb(175, 140, 250),
    Color32::from_rgb(150, 215, 90),
    Color32::from_rgb(245, 125, 185),
    Color32::from_rgb(110, 190, 245),
    Color32::from_rgb(240, 140, 70),
    Color32::from_rgb(215, 225, 120),
];
/// The parts of the lines inside the result stand out over any piece; the parts outside are dimmed (and dashed).
pub const LINE_INSIDE: Color32 = Color32::WHITE;
const LINE_OUTSIDE: Color32 = Color32::from_gray(150);
/// Errors in the side panel: red, and far enough from Q's salmon that a test can tell them apart.
pub const ERROR_TEXT: Color32 = Color32::from_rgb(255, 64, 64);
const BACKGROUND: Color32 = Color32::from_rgb(18, 20, 24);

/// Vertex handles are drawn (and grabbed) within this many screen points.
const HANDLE_RADIUS: f32 = 7.0;

/// What a click on the canvas draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tool {
    /// A ring of the active operand.
    Ring,
    /// A line.
    Line,
}

pub struct Playground {
    pub scene: Scene,
    pub operation: Op,
    pub fill_rule: FillRule,
    /// The operand new rings go to.
    pub active: Operand,
    pub tool: Tool,
    /// The ring or line being drawn, not yet finished: the tool at the finish decides which it becomes.
    pub drawing: Vec<Point>,
    pub snap: bool,
    pub view: View,
    /// Fit the view to the data on the next frame (the canvas size is known only then).
    fit_pending: bool,
    drag: Option<Drag>,
    derived: Derived,
    /// The sweep explorer, while it is on (key X).
    exploring: Option<Exploring>,
    files: Files,
    /// The last thing that happened that the user should know of (loads, saves, errors).
    status: Option<(String, bool)>,
    paste_text: Option<String>,
    /// The graphics API wgpu draws with ("WebGPU", "WebGL2", "Vulkan"…), once eframe has chosen it.
    pub renderer: Option<&'static str>,
    /// In the browser, the worker script results are computed in (background.rs); natively they are computed on
    /// a thread.
    pub worker_url: Option<String>,
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
            tool: Tool::Ring,
            drawing: Vec::new(),
            snap: true,
            view: View::default(),
            fit_pending: false,
            drag: None,
            derived: Derived::default(),
            exploring: None,
            files: Files::default(),
            status: None,
            paste_text: None,
            renderer: None,
            worker_url: None,
            #[cfg(not(target_arch = "wasm32"))]
            path: String::new(),
        };
        playground.status = Some((
            "Click to draw P; press Q to draw Q, L to draw lines. Or pick a preset.".into(),
            false,
        ));
        playground
    }
}

impl eframe::App for Playground {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }

    /// Lets the page ask the running app for its renderer (lib.rs, `WebHandle::renderer`).
    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(&mut *self)
    }
}

impl Playground {
    /// The app in eframe, in dark mode to match the canvas.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        cc.egui_ctx.set_theme(egui::Theme::Dark);
        let mut playground = Playground::default();
        if let Some(render_state) = &cc.wgpu_render_state {
            crate::gpu::FillPipeline::install(render_state);
            playground.renderer = Some(match render_state.adapter.get_info().backend {
                wgpu::Backend::BrowserWebGpu => "WebGPU",
                wgpu::Backend::Gl if cfg!(target_arch = "wasm32") => "WebGL2",
                wgpu::Backend::Gl => "OpenGL",
                wgpu::Backend::Vulkan => "Vulkan",
                wgpu::Backend::Metal => "Metal",
                wgpu::Backend::Dx12 => "DirectX 12",
                _ => "wgpu",
            });
        }
        playground
    }

    /// Loads a preset as one undoable step and fits the view to it.
    pub fn load_preset(&mut self, preset: Preset) {
        let (p, q) = preset.operands();
        self.scene.replace_both(p, q);
        self.drawing.clear();
        self.fit_pending = true;
        self.status = Some((format!("{} loaded", preset.label()), false));
    }

    /// Loads the preset of that name in links (`land-8`), or says there is none.
    pub fn load_preset_named(&mut self, name: &str) {
        match Preset::named(name) {
            Some(preset) => self.load_preset(preset),
            None => {
                let names: Vec<_> = Preset::ALL.iter().map(|p| p.name()).collect();
                let known = names.join(", ");
                self.status = Some((
                    format!("No preset is named {name:?}; there are {known}."),
                    true,
                ));
            }
        }
    }

    /// Adds a vertex to the ring or line being drawn, or closes the ring when `at` is on its first vertex (a line
    /// may come back to its start).
    pub fn click(&mut self, at: Point, grab_radius: f64) {
        if let (Tool::Ring, Some(first)) = (self.tool, self.drawing.first()) {
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

    /// Finishes what is being drawn: closes the ring, or adds the line to the scene.
    pub fn finish_drawing(&mut self) {
        match self.tool {
            Tool::Ring => self.close_ring(),
            Tool::Line => self.scene.add_line(std::mem::take(&mut self.drawing)),
        }
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
        self.explorer_input(ui);
        if self.exploring.is_some() {
            self.refresh_explorer();
        }
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
}
