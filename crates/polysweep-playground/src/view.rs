//! The camera: where the world (y up, f64) lands on the screen (y down, f32 points), with pan, zoom about the
//! pointer, fit-to-data and the grid that snapping uses.
//!
//! Positions are transformed in f64 on every frame rather than baked into f32 meshes once, so that zooming deep
//! into longitude/latitude data does not shake vertices by f32 rounding.

use eframe::egui::{Pos2, Rect, Vec2};
use polysweep::Point;

/// Zoom limits, in screen points per world unit.
const MIN_SCALE: f64 = 1e-12;
const MAX_SCALE: f64 = 1e12;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// The world point at the centre of the canvas.
    pub center: Point,
    /// Screen points per world unit.
    pub scale: f64,
}

impl Default for View {
    fn default() -> Self {
        View {
            center: Point::new(5.0, 5.0),
            scale: 30.0,
        }
    }
}

impl View {
    pub fn to_screen(&self, canvas: Rect, p: Point) -> Pos2 {
        let c = canvas.center();
        Pos2::new(
            c.x + ((p.x - self.center.x) * self.scale) as f32,
            c.y - ((p.y - self.center.y) * self.scale) as f32,
        )
    }

    pub fn to_world(&self, canvas: Rect, pos: Pos2) -> Point {
        let c = canvas.center();
        Point::new(
            self.center.x + f64::from(pos.x - c.x) / self.scale,
            self.center.y - f64::from(pos.y - c.y) / self.scale,
        )
    }

    /// Moves the world with the pointer by `delta` screen points.
    pub fn pan(&mut self, delta: Vec2) {
        self.center.x -= f64::from(delta.x) / self.scale;
        self.center.y += f64::from(delta.y) / self.scale;
    }

    /// Zooms by `factor`, keeping the world point under `pointer` where it is.
    pub fn zoom_at(&mut self, canvas: Rect, pointer: Pos2, factor: f64) {
        let anchor = self.to_world(canvas, pointer);
        self.scale = (self.scale * factor).clamp(MIN_SCALE, MAX_SCALE);
        let moved = self.to_world(canvas, pointer);
        self.center.x += anchor.x - moved.x;
        self.center.y += anchor.y - moved.y;
    }

    /// Shows the box `[min, max]` whole, with a margin.
    pub fn fit(&mut self, canvas: Rect, min: Point, max: Point) {
        let (w, h) = ((max.x - min.x).max(1e-9), (max.y - min.y).max(1e-9));
        self.center = Point::new((min.x + max.x) / 2.0, (min.y + max.y) / 2.0);
        let scale = 0.9 * (f64::from(canvas.width()) / w).min(f64::from(canvas.height()) / h);
        self.scale = scale.clamp(MIN_SCALE, MAX_SCALE);
    }

    /// World spacing of the grid: 1, 2 or 5 times a power of ten, at least 24 screen points apart.
    pub fn grid_step(&self) -> f64 {
        let min_step = 24.0 / self.scale;
        let decade = 10f64.powf(min_step.log10().floor());
        [1.0, 2.0, 5.0, 10.0]
            .iter()
            .map(|m| m * decade)
            .find(|s| *s >= min_step)
            .unwrap_or(10.0 * decade)
    }

    /// The world coordinates of the grid lines between `lo` and `hi` along one axis: at most `max` of them, and
    /// computed as multiples of the step, not by adding it up, which stalls once the step is below an ulp of the
    /// coordinate (deep zoom into projected data).
    pub fn grid_lines(&self, lo: f64, hi: f64, max: usize) -> impl Iterator<Item = f64> {
        let step = self.grid_step();
        let first = (lo / step).floor();
        let count = ((hi / step).ceil() - first).clamp(0.0, max as f64) as usize;
        (0..=count).map(move |k| (first + k as f64) * step)
    }

    /// `p` moved to the nearest grid point.
    pub fn snap(&self, p: Point) -> Point {
        let step = self.grid_step();
        Point::new((p.x / step).round() * step, (p.y / step).round() * step)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn canvas() -> Rect {
        Rect::from_min_size(Pos2::new(100.0, 0.0), Vec2::new(800.0, 600.0))
    }

    #[test]
    fn screen_and_world_round_trip_with_y_up() {
        let view = View {
            center: Point::new(10.0, 20.0),
            scale: 4.0,
        };
        assert_eq!(
            view.to_screen(canvas(), Point::new(10.0, 20.0)),
            Pos2::new(500.0, 300.0)
        );
        assert_eq!(
            view.to_screen(canvas(), Point::new(11.0, 21.0)),
            Pos2::new(504.0, 296.0)
        );
        assert_eq!(
            view.to_world(canvas(), Pos2::new(504.0, 296.0)),
            Point::new(11.0, 21.0)
        );
    }

    #[test]
    fn zoom_keeps_the_point_under_the_pointer() {
        let mut view = View::default();
        let pointer = Pos2::new(700.0, 100.0);
        let before = view.to_world(canvas(), pointer);
        view.zoom_at(canvas(), pointer, 2.5);
        let after = view.to_world(canvas(), pointer);
        assert!((before.x - after.x).abs() < 1e-9 && (before.y - after.y).abs() < 1e-9);
        assert_eq!(view.scale, 75.0);
    }

    #[test]
    fn grid_steps_are_round_and_snap_to_them() {
        let view = View {
            center: Point::new(0.0, 0.0),
            scale: 30.0,
        };
        assert_eq!(view.grid_step(), 1.0);
        assert_eq!(View { scale: 3.0, ..view }.grid_step(), 10.0);
        assert_eq!(
            View {
                scale: 100.0,
                ..view
            }
            .grid_step(),
            0.5
        );
        assert_eq!(view.snap(Point::new(2.4, -3.6)), Point::new(2.0, -4.0));
        assert_eq!(
            view.grid_lines(-1.5, 1.5, 100).collect::<Vec<_>>(),
            [-2.0, -1.0, 0.0, 1.0, 2.0]
        );
    }

    #[test]
    fn grid_lines_end_at_deep_zoom_far_from_the_origin() {
        let view = View {
            center: Point::new(6e5, 5e6),
            scale: 1e12,
        };
        let lines: Vec<f64> = view.grid_lines(6e5, 6e5 + 1e-9, 500).collect();
        assert!(!lines.is_empty() && lines.len() <= 501);
    }

    #[test]
    fn fit_shows_the_whole_box() {
        let mut view = View::default();
        view.fit(canvas(), Point::new(-180.0, -90.0), Point::new(180.0, 90.0));
        let corner = view.to_screen(canvas(), Point::new(-180.0, 90.0));
        assert!(canvas().contains(corner));
        assert_eq!(view.center, Point::new(0.0, 0.0));
    }
}
