//! The side panel: the operation and fill rule, what to draw and drawing options, undo and redo, presets, GeoJSON
//! in and out, the figures of the result and of the lines against it, and the status line; and the window GeoJSON
//! is pasted into.

use super::{Playground, Tool, ERROR_TEXT, LINE_INSIDE, OPERAND_EDGE};
use crate::fill::Fill;
use crate::operation::Op;
use crate::presets::Preset;
use crate::scene::Operand;
use eframe::egui;
use polysweep::{geojson, FillRule, MultiPolygon};

impl Playground {
    fn save(&mut self, name: &str, m: &MultiPolygon) {
        self.status = Some(
            match self.files.save(name, &geojson::to_geometry(m).to_string()) {
                Ok(done) => (done, false),
                Err(e) => (e, true),
            },
        );
    }

    pub(super) fn controls(&mut self, ui: &mut egui::Ui) {
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
        ui.horizontal_wrapped(|ui| {
            ui.label("Fill rule:");
            ui.radio_value(&mut self.fill_rule, FillRule::EvenOdd, "even-odd [E]");
            ui.radio_value(&mut self.fill_rule, FillRule::NonZero, "non-zero [N]");
            ui.radio_value(&mut self.fill_rule, FillRule::Positive, "positive");
            ui.radio_value(&mut self.fill_rule, FillRule::Negative, "negative");
            ui.radio_value(&mut self.fill_rule, FillRule::Structure, "structure");
        });
        ui.separator();

        ui.strong("Drawing");
        ui.horizontal_wrapped(|ui| {
            ui.label("into");
            for which in [Operand::Subject, Operand::Clipping] {
                let label = egui::RichText::new(which.name()).color(OPERAND_EDGE[which.index()]);
                let selected = self.tool == Tool::Ring && self.active == which;
                if ui.radio(selected, label).clicked() {
                    self.active = which;
                    self.tool = Tool::Ring;
                }
            }
            let label = egui::RichText::new("lines  [L]").color(LINE_INSIDE);
            if ui.radio(self.tool == Tool::Line, label).clicked() {
                self.tool = Tool::Line;
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
            if ui
                .add_enabled(
                    !self.scene.lines().is_empty(),
                    egui::Button::new("Clear lines"),
                )
                .clicked()
            {
                self.scene.clear_lines();
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

        self.explorer_controls(ui);
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
            "Click: add vertex · click first vertex / double-click / Enter: close ring (finish line) · drag vertex: \
             move · right-click vertex or Delete: remove · drag: pan · scroll: zoom · Esc: drop ring or line · \
             L: draw lines, P / Q: draw rings · Ctrl+Z / Ctrl+Y",
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
        let computed = self.derived.computed.as_ref();
        match computed.map(|c| &c.outcome) {
            Some(Ok(o)) => rows.extend([
                ("vertices out", o.result.vertex_count().to_string()),
                ("polygons out", o.result.0.len().to_string()),
                ("edge intersections", o.crossings.to_string()),
                ("result area", format!("{:.6}", o.result.area())),
                ("operation time", format!("{:.2} ms", o.milliseconds)),
            ]),
            Some(Err(e)) => rows.push(("error", e.to_string())),
            None => {}
        }
        match computed.and_then(|c| c.cut.as_ref()) {
            Some(Ok(cut)) => rows.extend([
                ("lines", self.scene.lines().len().to_string()),
                ("pieces", cut.pieces.len().to_string()),
                (
                    "line parts in / out",
                    format!("{} / {}", cut.inside.len(), cut.outside.len()),
                ),
            ]),
            Some(Err(e)) => rows.push(("error", e.to_string())),
            None => {}
        }
        if let Some(c) = computed {
            let triangles = (c.piece_fills.iter().chain([&c.fill])).map(Fill::triangle_count);
            rows.push(("fill triangles", triangles.sum::<usize>().to_string()));
        }
        rows.push((
            "last frame",
            format!("{:.1} ms", ui.input(|i| i.unstable_dt) * 1e3),
        ));
        if let Some(renderer) = self.renderer {
            rows.push(("renderer", renderer.to_string()));
        }
        if self.pending() {
            // The figures and the canvas show the last result until the one being computed arrives.
            ui.horizontal(|ui| {
                ui.spinner();
                ui.label("computing the result…");
            });
        }
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

    pub(super) fn paste_window(&mut self, ctx: &egui::Context) {
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
}
