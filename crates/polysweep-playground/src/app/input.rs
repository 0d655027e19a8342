//! What the keys and the pointer do: the shortcuts, and on the canvas drawing, dragging vertices (of rings and of
//! lines), deleting them, panning and zooming (snapping to the grid where a vertex is placed).

use super::{Playground, Tool, HANDLE_RADIUS};
use crate::operation::Op;
use crate::scene::{LineVertex, Operand, Scene, VertexId};
use eframe::egui::{self, Key, Modifiers};
use polysweep::{FillRule, Point};

/// What a drag on the canvas is doing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Drag {
    /// Moving a vertex, since the scene's generation given (an undo, delete or load meanwhile ends the drag).
    Vertex(Handle, u64),
    Pan,
}

/// A vertex the pointer can grab: of an operand's ring or of a line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Handle {
    Ring(VertexId),
    Line(LineVertex),
}

impl Handle {
    pub(super) fn point(self, scene: &Scene) -> Option<Point> {
        match self {
            Handle::Ring(id) => scene.point(id),
            Handle::Line(id) => scene.line_point(id),
        }
    }

    fn move_to(self, scene: &mut Scene, to: Point) {
        match self {
            Handle::Ring(id) => scene.move_vertex(id, to),
            Handle::Line(id) => scene.move_line_vertex(id, to),
        }
    }

    fn delete(self, scene: &mut Scene) {
        match self {
            Handle::Ring(id) => scene.delete_vertex(id),
            Handle::Line(id) => scene.delete_line_vertex(id),
        }
    }
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
        let mut exploring = None;
        ui.input_mut(|i| {
            let keys = [Key::Num1, Key::Num2, Key::Num3, Key::Num4, Key::Num5];
            for (key, op) in keys.into_iter().zip(Op::ALL) {
                if i.consume_key(Modifiers::NONE, key) {
                    self.operation = op;
                }
            }
            if i.consume_key(Modifiers::NONE, Key::E) {
                self.fill_rule = FillRule::EvenOdd;
            }
            if i.consume_key(Modifiers::NONE, Key::N) {
                self.fill_rule = FillRule::NonZero;
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
                self.tool = Tool::Ring;
            }
            if i.consume_key(Modifiers::NONE, Key::Q) {
                self.active = Operand::Clipping;
                self.tool = Tool::Ring;
            }
            if i.consume_key(Modifiers::NONE, Key::L) {
                self.tool = Tool::Line;
            }
            if i.consume_key(Modifiers::NONE, Key::G) {
                self.snap = !self.snap;
            }
            if i.consume_key(Modifiers::NONE, Key::F) {
                self.fit_pending = true;
            }
            if i.consume_key(Modifiers::NONE, Key::X) {
                exploring = Some(self.exploring.is_none());
            }
            if i.consume_key(Modifiers::NONE, Key::Enter) {
                self.finish_drawing();
            }
            if i.consume_key(Modifiers::NONE, Key::Escape) {
                self.drawing.clear();
            }
            if i.consume_key(Modifiers::NONE, Key::Backspace) {
                self.drawing.pop();
            }
        });
        if let Some(on) = exploring {
            self.set_exploring(on);
        }
    }

    /// The vertex under the pointer: the nearest of a ring or a line, and on a tie the kind the tool draws.
    pub(super) fn handle_under(&self, at: Point) -> Option<Handle> {
        let radius = f64::from(HANDLE_RADIUS) / self.view.scale;
        let ring = self
            .scene
            .vertex_near(at, radius, self.active)
            .map(Handle::Ring);
        let line = self.scene.line_vertex_near(at, radius).map(Handle::Line);
        let (preferred, other) = match self.tool {
            Tool::Ring => (ring, line),
            Tool::Line => (line, ring),
        };
        let distance = |h: Option<Handle>| {
            h.and_then(|h| h.point(&self.scene))
                .map_or(f64::INFINITY, |p| (p.x - at.x).hypot(p.y - at.y))
        };
        if distance(other) < distance(preferred) {
            other
        } else {
            preferred
        }
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
            let on_vertex = self.handle_under(self.view.to_world(canvas, origin));
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
                    id.move_to(
                        &mut self.scene,
                        if self.snap { self.view.snap(at) } else { at },
                    );
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
        // egui counts a double-click right after a quick click elsewhere as a triple-click: either way this click
        // repeats the one before on the same spot.
        if response.double_clicked() || response.triple_clicked() {
            // The double-click's first click added its vertex; the second finishes the ring or line.
            self.finish_drawing();
        } else if response.clicked() {
            self.click(at, grab);
        } else if response.secondary_clicked() {
            match self.handle_under(at) {
                Some(id) => id.delete(&mut self.scene),
                None => {
                    self.drawing.pop();
                }
            }
        }
        let delete =
            !ui.ctx().egui_wants_keyboard_input() && ui.input(|i| i.key_pressed(Key::Delete));
        if response.hovered() && self.drag.is_none() && delete {
            if let Some(id) = self.handle_under(at) {
                id.delete(&mut self.scene);
            }
        }
    }
}
