//! What the keys and the pointer do: the shortcuts, and on the canvas drawing, dragging vertices, deleting them,
//! panning and zooming (snapping to the grid where a vertex is placed).

use super::{Playground, HANDLE_RADIUS};
use crate::operation::Op;
use crate::scene::{Operand, VertexId};
use eframe::egui::{self, Key, Modifiers};
use polysweep::Point;

/// What a drag on the canvas is doing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Drag {
    /// Moving a vertex, since the scene's generation given (an undo, delete or load meanwhile ends the drag).
    Vertex(VertexId, u64),
    Pan,
}

impl Playground {
    pub(super) fn keyboard(&mut self, ui: &egui::Ui) {
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

    pub(super) fn vertex_under(&self, at: Point) -> Option<VertexId> {
        self.scene
            .vertex_near(at, f64::from(HANDLE_RADIUS) / self.view.scale, self.active)
    }

    pub(super) fn interact(&mut self, ui: &egui::Ui, response: &egui::Response) {
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
}
