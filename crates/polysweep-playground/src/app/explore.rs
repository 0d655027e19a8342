//! The sweep explorer in the app (its model is explorer.rs): key X or the panel's checkbox turns it on. The canvas
//! then shows, over the operands, the sweep line at the current event's x, the event, the edges of S in their order
//! (each in the colour of its place from the bottom, listed in the panel in the same colours), the points where
//! edges have been split so far, the result edges selected so far coloured by the reason of Fig. 10, and, after the
//! last event, the rings the connection step closes, filled as they close. Keys: → and ← step by event, Shift+→
//! and Shift+← by x, C to the next crossing, Space plays and pauses, Home and End.
//!
//! Drawing only what changed: the selected edges go to the GPU (gpu.rs) in chunks of `CHUNK`, uploaded once, and
//! only the last, unfinished chunk is drawn by egui each frame; S, a few hundred edges at most, is drawn by egui.

use super::{Playground, RESULT_FILL};
use crate::explorer::{Explorer, Selected};
use crate::fill::{Fill, Outline};
use crate::gpu::Layer;
use crate::operation::Op;
use crate::scene::Operand;
use eframe::egui::{self, Color32, Key, Modifiers, Pos2, Stroke};
use polysweep::{Error, FillRule, Meeting, MultiPolygon, Operation, Options, Point, Polygon};
use polysweep::{Reason, Step, TraceEdge};
use std::sync::Arc;

/// The colours of S's edges by their place from the bottom, in turn.
pub const STATUS_COLOURS: [Color32; 6] = [
    Color32::from_rgb(255, 80, 200),
    Color32::from_rgb(80, 220, 255),
    Color32::from_rgb(0, 200, 140),
    Color32::from_rgb(110, 255, 110),
    Color32::from_rgb(255, 140, 40),
    Color32::from_rgb(170, 130, 255),
];

/// The colour of a selected edge by the row of Fig. 10 that selected it.
pub fn reason_colour(reason: Reason) -> Color32 {
    match reason {
        Reason::InsideOther => RESULT_FILL,
        Reason::OutsideOther => Color32::from_rgb(255, 255, 255),
        Reason::SameTransition => Color32::from_rgb(255, 60, 60),
        Reason::DifferentTransition => Color32::from_rgb(60, 120, 255),
        _ => Color32::GRAY,
    }
}

/// Selected edges per GPU chunk.
const CHUNK: usize = 4096;

/// The explorer and what the app keeps for drawing it, for the inputs it was made from.
pub(super) struct Exploring {
    inputs: ([u64; 2], Op, FillRule),
    explorer: Result<Explorer, Error>,
    /// Whether the trace's operand 0 is Q (for Q − P, traced as a difference with the operands swapped).
    swapped: bool,
    /// The selected edges of each whole chunk, one outline per reason.
    chunks: Vec<Vec<(Reason, Outline)>>,
    /// Per polygon of the result, the fill of its rings closed so far, and how many those are.
    ring_fills: Vec<(usize, Fill)>,
}

impl Playground {
    /// The explorer, when it is on and the trace succeeded.
    pub fn explorer(&self) -> Option<&Explorer> {
        self.exploring
            .as_ref()
            .and_then(|e| e.explorer.as_ref().ok())
    }

    fn explorer_mut(&mut self) -> Option<&mut Explorer> {
        self.exploring
            .as_mut()
            .and_then(|e| e.explorer.as_mut().ok())
    }

    /// Turns the explorer on or off.
    pub fn set_exploring(&mut self, on: bool) {
        if !on {
            self.exploring = None;
        } else if self.exploring.is_none() {
            self.refresh_explorer();
        }
    }

    /// Traces again when the operands, operation or fill rule changed, keeping the position where it can.
    pub(super) fn refresh_explorer(&mut self) {
        let revisions = [Operand::Subject, Operand::Clipping].map(|w| self.scene.revision(w));
        let inputs = (revisions, self.operation, self.fill_rule);
        if self.exploring.as_ref().is_some_and(|e| e.inputs == inputs) {
            return;
        }
        let position = self.explorer().map_or(0, Explorer::position);
        let [p, q] = [Operand::Subject, Operand::Clipping].map(|w| self.scene.operand(w).clone());
        let (operation, operands, swapped) = match self.operation {
            Op::Intersection => (Operation::Intersection, [p, q], false),
            Op::Union => (Operation::Union, [p, q], false),
            Op::SubjectMinusClipping => (Operation::Difference, [p, q], false),
            Op::ClippingMinusSubject => (Operation::Difference, [q, p], true),
            Op::Xor => (Operation::Xor, [p, q], false),
        };
        let options = Options::default().with_fill_rule(self.fill_rule);
        let mut explorer = Explorer::new(operation, options, operands.map(Arc::new));
        if let Ok(explorer) = &mut explorer {
            explorer.go_to(position).ok();
        }
        self.exploring = Some(Exploring {
            inputs,
            explorer,
            swapped,
            chunks: Vec::new(),
            ring_fills: Vec::new(),
        });
    }

    /// The explorer's keys, and playing; only while it is on.
    pub(super) fn explorer_input(&mut self, ui: &egui::Ui) {
        if self.exploring.is_none() {
            return;
        }
        let (keys, dt) = ui.input_mut(|i| {
            let mut pressed = |modifiers, key| i.consume_key(modifiers, key);
            let keys = [
                pressed(Modifiers::NONE, Key::ArrowRight),
                pressed(Modifiers::NONE, Key::ArrowLeft),
                pressed(Modifiers::SHIFT, Key::ArrowRight),
                pressed(Modifiers::SHIFT, Key::ArrowLeft),
                pressed(Modifiers::NONE, Key::C),
                pressed(Modifiers::NONE, Key::Space),
                pressed(Modifiers::NONE, Key::Home),
                pressed(Modifiers::NONE, Key::End),
            ];
            (keys, f64::from(i.stable_dt))
        });
        let Some(explorer) = self.explorer_mut() else {
            return;
        };
        let [next, back, next_x, back_x, crossing, play, home, end] = keys;
        let moved = match () {
            _ if next => explorer.step(1),
            _ if back => explorer.step(-1),
            _ if next_x => explorer.step_x(true),
            _ if back_x => explorer.step_x(false),
            _ if crossing => explorer.next_crossing(),
            _ if home => explorer.go_to(0),
            _ if end => explorer.go_to(usize::MAX),
            _ => Ok(()),
        };
        if play {
            explorer.playing = !explorer.playing;
        }
        let played = if explorer.playing {
            ui.ctx().request_repaint();
            explorer.play(dt.min(0.25))
        } else {
            Ok(())
        };
        if let Err(e) = moved.and(played) {
            self.status = Some((e.to_string(), true));
        }
    }

    /// The panel's part: the switch, and while on the controls, the event, what it did, and S.
    pub(super) fn explorer_controls(&mut self, ui: &mut egui::Ui) {
        ui.strong("Sweep explorer");
        let mut on = self.exploring.is_some();
        if ui
            .checkbox(&mut on, "step through the sweep  [X]")
            .changed()
        {
            self.set_exploring(on);
        }
        let Some(exploring) = &mut self.exploring else {
            return;
        };
        let swapped = exploring.swapped;
        let explorer = match &mut exploring.explorer {
            Ok(explorer) => explorer,
            Err(e) => {
                ui.colored_label(super::ERROR_TEXT, e.to_string());
                return;
            }
        };
        if explorer.is_empty() {
            ui.label("Nothing to sweep: draw P and Q.");
            return;
        }
        let mut moved = Ok(());
        ui.horizontal(|ui| {
            let button = |ui: &mut egui::Ui, label: &str| ui.button(label).clicked();
            if button(ui, "|◀") {
                moved = explorer.go_to(0);
            }
            if button(ui, "◀ x") {
                moved = explorer.step_x(false);
            }
            if button(ui, "◀") {
                moved = explorer.step(-1);
            }
            if button(ui, if explorer.playing { "⏸" } else { "▶▶" }) {
                explorer.playing = !explorer.playing;
            }
            if button(ui, "▶") {
                moved = explorer.step(1);
            }
            if button(ui, "x ▶") {
                moved = explorer.step_x(true);
            }
            if button(ui, "▶|") {
                moved = explorer.go_to(usize::MAX);
            }
        });
        ui.horizontal(|ui| {
            if ui.button("next crossing [C]").clicked() {
                moved = explorer.next_crossing();
            }
            ui.add(
                egui::Slider::new(&mut explorer.speed, 1.0..=2000.0)
                    .logarithmic(true)
                    .text("steps/s"),
            );
        });
        let mut position = explorer.position();
        let last = explorer.len() - 1;
        if ui
            .add(egui::Slider::new(&mut position, 0..=last).text("step"))
            .changed()
        {
            moved = explorer.go_to(position);
        }
        if let Err(e) = moved {
            ui.colored_label(super::ERROR_TEXT, e.to_string());
        }
        let name = |operand: usize| ["P", "Q"][operand ^ usize::from(swapped)];
        let edge_text = |e: &TraceEdge| {
            format!(
                "{} ({}, {}) → ({}, {})",
                name(e.operand),
                e.left[0],
                e.left[1],
                e.right[0],
                e.right[1]
            )
        };
        match explorer.event() {
            Some((point, left, edge)) => {
                let end = if left { "left" } else { "right" };
                let text = format!(
                    "Event {} of {}: the {end} end, ({}, {}), of {}",
                    explorer.position() + 1,
                    explorer.event_count(),
                    point[0],
                    point[1],
                    edge_text(&edge)
                );
                ui.add(egui::Label::new(text).wrap());
            }
            None => {
                let rings = explorer.rings().len();
                ui.label(format!(
                    "Connection (§5): {rings} ring(s) of the result closed"
                ));
            }
        }
        for step in explorer.substeps() {
            let line = match step {
                Step::Meeting { meeting, at, .. } => {
                    let kind = match meeting {
                        Meeting::Crossing => "a crossing",
                        Meeting::VertexOnEdge => "a vertex on an edge",
                        Meeting::Overlap => "an overlap (§7.2)",
                        _ => "a meeting",
                    };
                    format!("possibleInter: {kind} at ({}, {})", at[0], at[1])
                }
                Step::Subdivision { edge, at } => {
                    format!("split {} at ({}, {})", edge_text(edge), at[0], at[1])
                }
                Step::Flags {
                    in_out,
                    inside_other,
                    in_result,
                    ..
                } => format!(
                    "Fig. 9: inOut {in_out}, inside the other {inside_other}, in the result {in_result}"
                ),
                Step::Selection {
                    in_result, reason, ..
                } => format!(
                    "Fig. 10: {} ({reason:?})",
                    if *in_result { "in the result" } else { "not in the result" }
                ),
                _ => continue,
            };
            ui.add(egui::Label::new(egui::RichText::new(line).small()).wrap());
        }
        let status = explorer.status();
        ui.label(format!("S, top to bottom ({} edges):", status.len()));
        let row_height = ui.text_style_height(&egui::TextStyle::Small);
        egui::ScrollArea::vertical()
            .id_salt("status")
            .max_height(180.0)
            .show_rows(ui, row_height, status.len(), |ui, rows| {
                for row in rows {
                    // Top first: row 0 is the highest edge.
                    let place = status.len() - 1 - row;
                    let colour = STATUS_COLOURS[place % STATUS_COLOURS.len()];
                    ui.horizontal(|ui| {
                        ui.colored_label(colour, "■");
                        ui.small(edge_text(&status[place]));
                    });
                }
            });
    }

    /// The GPU layers of the explorer: the selected edges of the whole chunks so far, and the rings closed so far.
    pub(super) fn explorer_layers(&mut self, layers: &mut Vec<Layer>) {
        let Some(exploring) = &mut self.exploring else {
            return;
        };
        let Ok(explorer) = &exploring.explorer else {
            return;
        };
        let selected = explorer.selected();
        let whole = selected.len() / CHUNK;
        while exploring.chunks.len() < whole {
            let chunk = &selected[exploring.chunks.len() * CHUNK..][..CHUNK];
            exploring.chunks.push(outlines_by_reason(chunk));
        }
        for (reason, outline) in exploring.chunks[..whole].iter().flatten() {
            layers.push(Layer::Outline(
                outline.clone(),
                Stroke::new(3.0, reason_colour(*reason)),
            ));
        }
        let rings = explorer.rings();
        let polygons = rings.iter().map(|r| r.polygon + 1).max().unwrap_or(0);
        let mut closed = vec![0; polygons];
        for ring in rings {
            closed[ring.polygon] += 1;
        }
        exploring.ring_fills.resize(polygons, (0, Fill::default()));
        for (polygon, (filled, fill)) in exploring.ring_fills.iter_mut().enumerate() {
            if *filled != closed[polygon] {
                let mut of_polygon = (rings.iter().filter(|r| r.polygon == polygon))
                    .map(|r| r.points.iter().map(|&p| Point::from(p)).collect::<Vec<_>>());
                let exterior = of_polygon.next().unwrap_or_default();
                let shape = MultiPolygon::new(vec![Polygon::new(exterior, of_polygon.collect())]);
                *fill = Fill::of(&shape);
                *filled = closed[polygon];
            }
            layers.push(Layer::Fill(fill.clone(), RESULT_FILL));
        }
    }

    /// The explorer's egui shapes over the polygons: the sweep line, S, the selected edges of the unfinished chunk,
    /// the subdivision points, the event.
    pub(super) fn paint_explorer(
        &self,
        painter: &egui::Painter,
        canvas: egui::Rect,
        to_screen: impl Fn(Point) -> Pos2,
    ) {
        let Some(explorer) = self.explorer() else {
            return;
        };
        let segment = |e: &TraceEdge| [e.left, e.right].map(|p| to_screen(Point::from(p)));
        if let Some((point, ..)) = explorer.event() {
            let x = to_screen(Point::from(point)).x;
            painter.vline(
                x,
                canvas.y_range(),
                Stroke::new(1.0, Color32::from_gray(170)),
            );
        }
        let event = explorer.event();
        // An edge that has just left S thin and white, under its colour if the selection took it.
        if let Some((_, false, edge)) = event {
            painter.line_segment(segment(&edge), Stroke::new(1.5, Color32::WHITE));
        }
        let selected = explorer.selected();
        for Selected { edge, reason, .. } in &selected[selected.len() / CHUNK * CHUNK..] {
            painter.line_segment(segment(edge), Stroke::new(3.0, reason_colour(*reason)));
        }
        // The event's edge wider, in its place's colour, if it is in S.
        let current = |e: &TraceEdge| {
            event.is_some_and(|(.., edge)| edge.left == e.left && edge.right == e.right)
        };
        for (place, edge) in explorer.status().iter().enumerate() {
            let colour = STATUS_COLOURS[place % STATUS_COLOURS.len()];
            let width = if current(edge) { 7.0 } else { 4.0 };
            painter.line_segment(segment(edge), Stroke::new(width, colour));
        }
        for at in explorer.subdivisions() {
            let at = to_screen(Point::from(at));
            painter.circle_stroke(at, 4.0, Stroke::new(1.5, Color32::WHITE));
        }
        if let Some((point, ..)) = event {
            painter.circle_stroke(
                to_screen(Point::from(point)),
                8.0,
                Stroke::new(2.5, Color32::WHITE),
            );
        }
    }
}

/// One outline per reason of the selected edges of a chunk.
fn outlines_by_reason(chunk: &[Selected]) -> Vec<(Reason, Outline)> {
    let reasons = [
        Reason::InsideOther,
        Reason::OutsideOther,
        Reason::SameTransition,
        Reason::DifferentTransition,
        Reason::NoTransition,
    ];
    (reasons.into_iter())
        .map(|reason| {
            let ends = (chunk.iter().filter(|s| s.reason == reason))
                .map(|s| [s.edge.left, s.edge.right].map(Point::from))
                .collect();
            (reason, Outline::of_segments(ends))
        })
        .collect()
}
