//! What the GPU draws of polygons (gpu.rs), made once per change and uploaded once: fills, every region
//! triangulated (earcut, the algorithm MapLibre and Mapbox fill with), and outlines, every ring's edges.
//!
//! Earcut needs simple rings with holes inside their shell. Results of polysweep are exactly that by its output
//! contract; an operand, which may cross itself, is first passed through polysweep (its union with nothing), which
//! yields the region the fill rule gives it — so the picture shows the operand as the operations read it.

use earcut::Earcut;
use polysweep::{MultiPolygon, Point, Polygon};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// A new id for a fill or outline: the GPU keeps its buffers by it (0 is the empty default's).
fn next_id() -> u64 {
    static NEXT_ID: AtomicU64 = AtomicU64::new(1);
    NEXT_ID.fetch_add(1, Ordering::Relaxed)
}

/// A triangulated region in world coordinates. Cloning shares it: the frame's paint callback holds the fills
/// without copying them.
#[derive(Clone, Debug, Default)]
pub struct Fill(Arc<Triangles>);

#[derive(Debug, Default)]
struct Triangles {
    id: u64,
    points: Vec<Point>,
    triangles: Vec<u32>,
}

impl Fill {
    /// Triangulates a valid polygon set (simple rings, holes inside their shells).
    pub fn of(m: &MultiPolygon) -> Fill {
        let mut fill = Triangles {
            id: next_id(),
            ..Triangles::default()
        };
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
        Fill(Arc::new(fill))
    }

    /// A fill of triangles made elsewhere (in a worker, background.rs), with an id of this thread's.
    pub fn from_triangles(points: Vec<Point>, triangles: Vec<u32>) -> Fill {
        Fill(Arc::new(Triangles {
            id: next_id(),
            points,
            triangles,
        }))
    }

    pub fn id(&self) -> u64 {
        self.0.id
    }

    pub fn points(&self) -> &[Point] {
        &self.0.points
    }

    /// Indices into `points`, three per triangle.
    pub fn triangles(&self) -> &[u32] {
        &self.0.triangles
    }

    pub fn triangle_count(&self) -> usize {
        self.0.triangles.len() / 3
    }

    /// Total area of the triangles, to check the triangulation against the polygons' own area.
    pub fn area(&self) -> f64 {
        self.triangles()
            .chunks_exact(3)
            .map(|t| {
                let [a, b, c] = [0, 1, 2].map(|i| self.points()[t[i] as usize]);
                ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).abs() / 2.0
            })
            .sum()
    }
}

/// The edges of rings, as segments (start and end points, in world coordinates). Cloning shares them.
#[derive(Clone, Debug, Default)]
pub struct Outline(Arc<Segments>);

#[derive(Debug, Default)]
struct Segments {
    id: u64,
    ends: Vec<[Point; 2]>,
}

impl Outline {
    /// Every edge of every ring of `polygons`, closing edge included.
    pub fn of(polygons: &[Polygon]) -> Outline {
        let ends = (polygons.iter().flat_map(|p| p.rings()))
            .flat_map(|ring| ring.iter().zip(ring.iter().cycle().skip(1)))
            .filter(|(a, b)| a != b)
            .map(|(a, b)| [*a, *b])
            .collect();
        Outline::of_segments(ends)
    }

    /// Segments given as their two ends.
    pub fn of_segments(ends: Vec<[Point; 2]>) -> Outline {
        Outline(Arc::new(Segments {
            id: next_id(),
            ends,
        }))
    }

    pub fn id(&self) -> u64 {
        self.0.id
    }

    pub fn segments(&self) -> &[[Point; 2]] {
        &self.0.ends
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
    fn each_triangulation_has_its_own_id() {
        let triangle =
            MultiPolygon::from_coordinates(&[vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]]]);
        let (a, b) = (Fill::of(&triangle), Fill::of(&triangle));
        assert_ne!(a.id(), b.id());
        assert_eq!(a.clone().id(), a.id());
        assert_eq!(Fill::default().id(), 0);
        assert_eq!(a.triangles(), b.triangles());
    }

    #[test]
    fn outlines_hold_every_edge_once() {
        let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let holed = MultiPolygon::from_coordinates(&[vec![
            square.iter().chain(&square[..1]).copied().collect(),
            vec![[0.5, 0.5], [0.5, 1.0], [1.0, 1.0], [0.5, 0.5]],
        ]]);
        let outline = Outline::of(&holed.0);
        // The square's four edges, closed or not, and the triangular hole's three.
        assert_eq!(outline.segments().len(), 7);
        assert!(outline
            .segments()
            .contains(&[Point::new(0.0, 2.0), Point::new(0.0, 0.0)]));
        assert_ne!(outline.id(), Outline::of(&holed.0).id());
    }
}
