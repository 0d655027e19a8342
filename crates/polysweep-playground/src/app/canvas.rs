//! The canvas: fitting the view to the data, then painting the grid, the operands' fills and outlines, the result
//! (or its pieces, when lines cut it), the lines' parts inside and outside it, the ring or line being drawn, the
//! vertex handles and the vertex an error names.

use super::input::{Drag, Handle};
use super::{
    Playground, Tool, BACKGROUND, HANDLE_RADIUS, LINE_INSIDE, LINE_OUTSIDE, OPERAND_EDGE,
    OPERAND_FILL, PIECE_FILLS, RESULT_EDGE, RESULT_FILL,
};
use crate::gpu::{Layer, Polygons};
use crate::scene::{LineVertex, Operand, VertexId};
use eframe::egui::{self, Color32, Pos2, Rect, Sense, Shape, Stroke};
use polysweep::Point;

/// Above this many vertices an operand's handles are not drawn: they would cover the picture.
const MAX_HANDLES: usize = 5000;

impl Playground {
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
            .chain(self.scene.lines().iter().flatten())
            .chain(&self.drawing);
        points.fold(None, |b, p| {
            let (lo, hi) = b.unwrap_or((*p, *p));
            Some((
                Point::new(lo.x.min(p.x), lo.y.min(p.y)),
                Point::new(hi.x.max(p.x), hi.y.max(p.y)),
            ))
        })
    }

    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let (response, painter) = ui.allocate_painter(ui.available_size(), Sense::click_and_drag());
        let canvas = response.rect;
        if std::mem::take(&mut self.fit_pending) {
            if let Some((lo, hi)) = self.data_bounds() {
                self.view.fit(canvas, lo, hi);
            }
        }
        self.interact(ui, &response);
        let pending = self.derive_in_background(ui.ctx());
        if pending {
            // Keep drawing at the display's rate while a result is computed: the pending sign animates.
            ui.ctx().request_repaint();
        }
        // The operation's errors name an operand's vertex; the cut's (the result being valid) a line's.
        let computed = self.derived.computed.as_ref();
        let error_vertex = match (
            computed.map(|c| &c.outcome),
            computed.and_then(|c| c.cut.as_ref()),
        ) {
            (Some(Err(e)), _) => e
                .location()
                .and_then(|at| VertexId::from_location(&self.scene, &at))
                .map(Handle::Ring),
            (_, Some(Err(e))) => e
                .location()
                .and_then(|at| LineVertex::from_location(&self.scene, &at))
                .map(Handle::Line),
            _ => None,
        };
        let view = self.view;
        let to_screen = |p: Point| view.to_screen(canvas, p);

        painter.rect_filled(canvas, 0.0, BACKGROUND);
        if self.snap {
            self.paint_grid(&painter, canvas);
        }
        // The polygons on the GPU (gpu.rs), in one paint callback: the operands' fills, the result's (or its
        // pieces'), the result's outline, then the operands' outlines over them.
        let derived = &self.derived;
        let mut layers: Vec<_> = (derived.region_fills.iter().cloned())
            .zip(OPERAND_FILL)
            .map(|(fill, colour)| Layer::Fill(fill, colour))
            .collect();
        let result_edge = Stroke::new(1.0, RESULT_EDGE);
        let result = derived
            .computed
            .as_ref()
            .filter(|_| self.exploring.is_none());
        match result.map(|c| (c, &c.cut, &c.outcome)) {
            Some((computed, Some(Ok(_)), _)) => {
                let colours = PIECE_FILLS.iter().copied().cycle();
                layers.extend(
                    (computed.piece_fills.iter().cloned())
                        .zip(colours)
                        .map(|(fill, colour)| Layer::Fill(fill, colour)),
                );
                layers.push(Layer::Outline(computed.piece_outline.clone(), result_edge));
            }
            Some((computed, _, Ok(_))) => {
                layers.push(Layer::Fill(computed.fill.clone(), RESULT_FILL));
                layers.push(Layer::Outline(computed.outline.clone(), result_edge));
            }
            _ => {}
        }
        for (which, (_, outline)) in [Operand::Subject, Operand::Clipping]
            .into_iter()
            .zip(&derived.operand_outlines)
        {
            let edge = Stroke::new(1.5, OPERAND_EDGE[which.index()]);
            layers.push(Layer::Outline(outline.clone(), edge));
        }
        self.explorer_layers(&mut layers);
        Polygons {
            layers,
            view,
            canvas,
        }
        .paint(&painter);
        self.paint_explorer(&painter, canvas, to_screen);
        for which in [Operand::Subject, Operand::Clipping] {
            let operand = self.scene.operand(which);
            let edge = OPERAND_EDGE[which.index()];
            if operand.vertex_count() <= MAX_HANDLES {
                let radius = if which == self.active { 3.5 } else { 2.5 };
                for p in operand.0.iter().flat_map(|p| p.rings().flatten()) {
                    painter.circle_filled(to_screen(*p), radius, edge);
                }
            }
        }
        self.paint_lines(&painter, to_screen);
        self.paint_drawing(&painter, &response, to_screen);
        let pointer_world = response.hover_pos().map(|p| self.view.to_world(canvas, p));
        let hovered = pointer_world.and_then(|p| self.handle_under(p));
        if let Some(id) = hovered.or(match self.drag {
            Some(Drag::Vertex(id, _)) => Some(id),
            _ => None,
        }) {
            if let Some(p) = id.point(&self.scene) {
                painter.circle_stroke(
                    to_screen(p),
                    HANDLE_RADIUS,
                    Stroke::new(2.0, Color32::WHITE),
                );
            }
        }
        if let Some(p) = error_vertex.and_then(|id| id.point(&self.scene)) {
            painter.circle_stroke(to_screen(p), 10.0, Stroke::new(3.0, Color32::RED));
        }
        if pending {
            let dots = ".".repeat(1 + (ui.input(|i| i.time) * 3.0) as usize % 3);
            let text = format!("computing the result{dots}");
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

    /// The lines' parts inside the result solid and bright, the parts outside dashed and dim, and their vertices.
    fn paint_lines(&self, painter: &egui::Painter, to_screen: impl Fn(Point) -> Pos2) {
        let on_screen = |line: &[Point]| line.iter().map(|p| to_screen(*p)).collect::<Vec<_>>();
        let outside = Stroke::new(1.5, LINE_OUTSIDE);
        match self.derived.computed.as_ref().and_then(|c| c.cut.as_ref()) {
            Some(Ok(cut)) => {
                for part in &cut.outside {
                    painter.extend(Shape::dashed_line(&on_screen(part), outside, 6.0, 4.0));
                }
                for part in &cut.inside {
                    painter.add(Shape::line(on_screen(part), Stroke::new(2.5, LINE_INSIDE)));
                }
            }
            // No result to clip by (or an error): the lines as drawn, dimmed.
            _ => {
                for line in self.scene.lines() {
                    painter.extend(Shape::dashed_line(&on_screen(line), outside, 6.0, 4.0));
                }
            }
        }
        let radius = if self.tool == Tool::Line { 3.5 } else { 2.5 };
        for p in self.scene.lines().iter().flatten() {
            painter.circle_filled(to_screen(*p), radius, LINE_INSIDE);
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
        let edge = match self.tool {
            Tool::Ring => OPERAND_EDGE[self.active.index()],
            Tool::Line => LINE_INSIDE,
        };
        let mut points: Vec<Pos2> = self.drawing.iter().map(|p| to_screen(*p)).collect();
        if let Some(pointer) = response.hover_pos() {
            points.push(pointer);
        }
        painter.add(Shape::line(points, Stroke::new(1.5, edge)));
        for p in &self.drawing {
            painter.circle_filled(to_screen(*p), 3.5, edge);
        }
        // A click on the first vertex closes a ring.
        if self.tool == Tool::Ring {
            painter.circle_stroke(
                to_screen(self.drawing[0]),
                HANDLE_RADIUS,
                Stroke::new(1.5, edge),
            );
        }
    }
}
