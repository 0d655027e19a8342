//! Filling polygons that egui's painter cannot: egui fills only convex paths, so every region is triangulated
//! (earcut, the algorithm MapLibre and Mapbox fill with) into a mesh.
//!
//! Earcut needs simple rings with holes inside their shell. Results of polysweep are exactly that by its output
//! contract; an operand, which may cross itself, is first passed through polysweep (its union with nothing), which
//! yields the region the fill rule gives it — so the picture shows the operand as the operations read it.

use earcut::Earcut;
use eframe::egui::{epaint::Vertex, Color32, Mesh, Pos2};
use polysweep::{MultiPolygon, Point};

/// A triangulated region in world coordinates.
#[derive(Clone, Debug, Default)]
pub struct Fill {
    points: Vec<Point>,
    triangles: Vec<u32>,
}

impl Fill {
    /// Triangulates a valid polygon set (simple rings, holes inside their shells).
    pub fn of(m: &MultiPolygon) -> Fill {
        let mut fill = Fill::default();
        let mut earcut = Earcut::new();
        let (mut data, mut holes, mut triangles) =
            (Vec::new(), Vec::<u32>::new(), Vec::<u32>::new());
        for polygon in &m.0 {
            data.clear();
            holes.clear();
            for (r, ring) in polygon.rings().enumerate() {
                if r > 0 {
                    holes.push(data.len() as u32);
                }
                // Closed or open alike: earcut drops a repeated closing point itself.
                data.extend(ring.iter().map(|p| [p.x, p.y]));
            }
            earcut.earcut(data.iter().copied(), &holes, &mut triangles);
            let base = fill.points.len() as u32;
            fill.triangles.extend(triangles.iter().map(|t| t + base));
            fill.points
                .extend(data.iter().map(|&[x, y]| Point::new(x, y)));
        }
        fill
    }

    pub fn triangle_count(&self) -> usize {
        self.triangles.len() / 3
    }

    /// Total area of the triangles, to check the triangulation against the polygons' own area.
    pub fn area(&self) -> f64 {
        self.triangles
            .chunks_exact(3)
            .map(|t| {
                let [a, b, c] = [0, 1, 2].map(|i| self.points[t[i] as usize]);
                ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).abs() / 2.0
            })
            .sum()
    }

    /// The screen mesh, placing every world point with `to_screen`.
    pub fn mesh(&self, to_screen: impl Fn(Point) -> Pos2, color: Color32) -> Mesh {
        let vertices = (self.points.iter())
            .map(|&p| Vertex {
                pos: to_screen(p),
                uv: Pos2::ZERO,
                color,
            })
            .collect();
        Mesh {
            vertices,
            indices: self.triangles.clone(),
            ..Mesh::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn covers_concave_polygons_with_holes_exactly() {
        let comb = MultiPolygon::from_coordinates(&[
            vec![
                vec![
                    [0.0, 0.0],
                    [10.0, 0.0],
                    [10.0, 10.0],
                    [8.0, 10.0],
                    [8.0, 3.0],
                    [2.0, 3.0],
                    [2.0, 10.0],
                    [0.0, 10.0],
                    [0.0, 0.0],
                ],
                vec![[1.0, 1.0], [1.0, 2.0], [9.0, 2.0], [9.0, 1.0], [1.0, 1.0]],
            ],
            vec![vec![[20.0, 0.0], [21.0, 0.0], [21.0, 1.0]]],
        ]);
        let fill = Fill::of(&comb);
        assert_eq!(fill.area(), comb.area());
        assert_eq!(fill.area(), 100.0 - 6.0 * 7.0 - 8.0 + 0.5);
        assert!(fill.triangle_count() >= 10);
    }

    #[test]
    fn meshes_follow_the_view() {
        let fill = Fill::of(&MultiPolygon::from_coordinates(&[vec![vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
        ]]]));
        let mesh = fill.mesh(
            |p| Pos2::new(p.x as f32 * 10.0, -p.y as f32 * 10.0),
            Color32::RED,
        );
        assert_eq!(mesh.indices.len(), 3);
        assert!(mesh
            .vertices
            .iter()
            .any(|v| v.pos == Pos2::new(10.0, -10.0)));
        assert!(mesh.is_valid());
    }
}
