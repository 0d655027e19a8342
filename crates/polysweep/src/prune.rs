//! Polygons that lie wholly inside or outside the other operand, away from its boundary (not in the paper).
//!
//! Where no edge of an operand passes, its winding number cannot change: a clipping polygon whose box lies in such
//! a place and outside the subject cannot change an intersection or a difference, and one inside it cannot change
//! a union, so it is left out of the sweep (see `overlay_pair`). This is what makes clipping a coastline
//! with a grid of tiles cost little more than the tiles that meet the coast: at land × 32,768 squares, most
//! squares are out at sea.
//!
//! [`KnownWinding`] finds the winding number of all the places at once, on a grid (see [`Grid`]):
//! - a cell that no edge's box touches has no edge in it, so one winding number holds in all of it, and in all of a
//!   block of such cells;
//! - each row has a line `y = yᵣ` inside it. An edge that crosses the line touches every cell of the row between
//!   the columns of its two ends, so every untouched cell of the row lies wholly to its left or wholly to its
//!   right. The winding number of a cell is then the sum over the edges crossing the row's line to its left
//!   (counted towards the line's left end, the usual half-open rule), read off a running sum along the row.
//!
//! It decides nothing by rounding: the cells are chosen by a monotone float function, and every comparison is
//! between input coordinates. Leaving out only polygons of the clipping operand, judged by the whole subject, keeps
//! it exact together with the pruning by boxes: a subject polygon that pruning leaves out meets no clipping
//! polygon's box.

use crate::geometry::{open_len, MultiPolygon, Point};
use crate::input::{running_sums, Bounds, Grid};

/// The winding number of an operand's rings, known on the cells of a grid that no edge of theirs touches.
pub(crate) struct KnownWinding {
    grid: Grid,
    /// Each cell's winding number (row by row), where known.
    winding: Vec<i32>,
    /// The rectangle sums (see [`Grid::rectangle_sums`]) of the cells where it is not known.
    unknown: Vec<u32>,
}

impl KnownWinding {
    /// The winding number of `operand`'s rings, all within `region`, on a grid of `cells` × `cells`.
    pub fn new(operand: &MultiPolygon, region: Bounds, cells: usize) -> Self {
        let grid = Grid::new(region, cells);
        let n = grid.cells;
        // Each row's line, where one lies strictly inside the row (a row of a degenerate grid may have none).
        let lines: Vec<Option<f64>> = (0..n)
            .map(|r| {
                let y = region.min(1) + (r as f64 + 0.5) / grid.scale(1);
                (y.is_finite() && grid.cell(y, 1) == r).then_some(y)
            })
            .collect();
        let (mut touches, mut winding) = (grid.difference_table(), vec![0i32; n * n]);
        // Each edge takes a step per row it spans. Edges spanning many rows (a comb's long teeth) could make that
        // up to 1,024 steps each: past a few per vertex the grid gives up and knows nothing, so the pass stays
        // linear in the subject's vertices and cells.
        let (budget, mut steps) = (4 * operand.vertex_count() + n, 0);
        for ring in operand.0.iter().flat_map(|p| p.rings()) {
            let ring = &ring[..open_len(ring)];
            let Some(&last) = ring.last() else { continue };
            // Each vertex's cell is worked out once; an edge's box touches the cells between its ends' (the cell
            // of a coordinate is monotone in it).
            let cell = |p: Point| [grid.cell(p.x, 0), grid.cell(p.y, 1)];
            let (mut a, [mut ca, mut ra]) = (last, cell(last));
            let mut counted = None;
            for &b in ring {
                let [cb, rb] = cell(b);
                let ([c0, c1], [r0, r1]) = ([ca.min(cb), ca.max(cb)], [ra.min(rb), ra.max(rb)]);
                // (Most edges are short: one after another in one cell, which is counted once.)
                if counted != Some([[c0, c1], [r0, r1]]) {
                    grid.count_range(&mut touches, [[c0, c1], [r0, r1]]);
                    counted = Some([[c0, c1], [r0, r1]]);
                }
                steps += r1 - r0 + 1;
                if steps > budget {
                    return KnownWinding {
                        grid,
                        winding: Vec::new(),
                        unknown: grid.rectangle_sums(|_, _| true),
                    };
                }
                // Where the edge crosses a row's line, it adds its direction to the cells right of its right
                // end's column: differences along each row, summed below.
                for (r, line) in lines.iter().enumerate().take(r1 + 1).skip(r0) {
                    let Some(y) = *line else { continue };
                    if (a.y < y) != (b.y < y) && c1 + 1 < n {
                        winding[r * n + c1 + 1] += if b.y < a.y { 1 } else { -1 };
                    }
                }
                (a, ca, ra) = (b, cb, rb);
            }
        }
        let touches = grid.counts(touches);
        winding.chunks_exact_mut(n).for_each(running_sums);
        let unknown = grid.rectangle_sums(|r, c| lines[r].is_none() || touches[r * n + c] > 0);
        KnownWinding {
            grid,
            winding,
            unknown,
        }
    }

    /// The winding number everywhere in box `b`, if it is one number there that the grid knows.
    pub fn throughout(&self, b: &Bounds) -> Option<i32> {
        let region = &self.grid.region;
        if !b.meets(region) {
            return Some(0); // every ring lies within the region
        }
        if !b.within(region) || self.grid.marked_in(&self.unknown, b) > 0 {
            return None;
        }
        let [[c, _], [r, _]] = self.grid.range(b);
        Some(self.winding[r * self.grid.cells + c])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Point;
    use crate::test_random::unit;

    /// The winding number of `operand`'s rings at `p`, by counting every edge that crosses the ray to its left.
    fn winding_at(operand: &MultiPolygon, p: Point) -> i32 {
        let mut winding = 0;
        for ring in operand.0.iter().flat_map(|polygon| polygon.rings()) {
            let n = open_len(ring);
            for i in 0..n {
                let (a, b) = (ring[i], ring[(i + 1) % n]);
                if (a.y < p.y) != (b.y < p.y) {
                    // Where the edge crosses the ray's line, exactly enough for points well off the edges.
                    let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                    if x < p.x {
                        winding += if b.y < a.y { 1 } else { -1 };
                    }
                }
            }
        }
        winding
    }

    /// A square ring, counter-clockwise, each side cut into 25 edges (so that the grid, of about one cell per
    /// vertex, has cells smaller than the squares).
    fn square(x: f64, y: f64, side: f64) -> Vec<[f64; 2]> {
        let corners = [
            [x, y],
            [x + side, y],
            [x + side, y + side],
            [x, y + side],
            [x, y],
        ];
        (corners.windows(2))
            .flat_map(|w| {
                (0..25).map(move |i| {
                    [0, 1].map(|k| w[0][k] + (w[1][k] - w[0][k]) * f64::from(i) / 25.0)
                })
            })
            .collect()
    }

    fn region_of(operand: &MultiPolygon) -> Bounds {
        let points = operand.0.iter().flat_map(|p| p.rings()).flatten();
        points.fold(Bounds::EMPTY, |b, p| b.around(&Bounds::at(p)))
    }

    #[test]
    fn knows_the_winding_number_away_from_the_edges() {
        // A square [0, 100]² with a square hole [40, 60]² (clockwise), and a second square over its lower right
        // corner, so that [80, 100] × [0, 20] is wound twice. On a grid of 18 × 18 cells.
        let mut hole = square(40.0, 40.0, 20.0);
        hole.reverse();
        let operand = MultiPolygon::from_coordinates(&[
            vec![square(0.0, 0.0, 100.0), hole],
            vec![square(80.0, -10.0, 30.0)],
        ]);
        let known = KnownWinding::new(&operand, region_of(&operand), 18);
        let at = |x: f64, y: f64, side: f64| {
            let b =
                Bounds::at(&Point::new(x, y)).around(&Bounds::at(&Point::new(x + side, y + side)));
            known.throughout(&b)
        };
        assert_eq!(at(10.0, 10.0, 5.0), Some(1), "inside");
        assert_eq!(at(48.0, 48.0, 4.0), Some(0), "in the hole");
        assert_eq!(at(90.0, 5.0, 3.0), Some(2), "wound twice");
        assert_eq!(at(200.0, 200.0, 5.0), Some(0), "apart from the operand");
        assert_eq!(at(35.0, 35.0, 10.0), None, "across the hole's edge");
        assert_eq!(at(-20.0, 50.0, 30.0), None, "partly outside the region");
    }

    /// A square [0, 100]² around a comb of 40 teeth that span nearly every row: on a grid of 100 rows the teeth's
    /// steps exceed the budget and the grid knows nothing (but that boxes apart from the region are outside); on
    /// one of 4 rows it knows the square's inside away from the comb.
    #[test]
    fn gives_up_on_edges_spanning_many_rows() {
        let mut comb = vec![[1.0, 1.0]];
        for tooth in 0..40 {
            let x = 1.0 + f64::from(tooth) * 0.2;
            comb.extend([[x, 99.0], [x + 0.1, 99.0], [x + 0.1, 1.0], [x + 0.2, 1.0]]);
        }
        comb.extend([[9.0, 0.5], [1.0, 0.5]]);
        let square = vec![[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]];
        let operand = MultiPolygon::from_coordinates(&[vec![square], vec![comb]]);
        let b = Bounds::at(&Point::new(50.0, 50.0)).around(&Bounds::at(&Point::new(51.0, 51.0)));
        let known = KnownWinding::new(&operand, region_of(&operand), 100);
        assert_eq!(known.throughout(&b), None);
        assert_eq!(
            known.throughout(&Bounds::at(&Point::new(300.0, 50.0))),
            Some(0)
        );
        let known = KnownWinding::new(&operand, region_of(&operand), 4);
        assert_eq!(known.throughout(&b), Some(1));
    }

    /// Wherever it knows the winding number of random polygons, it is right at random points of the box.
    #[test]
    fn agrees_with_counting_crossings() {
        let mut random = unit(41);
        let mut known_boxes = 0;
        for _ in 0..40 {
            // A few random rings, some crossing themselves and each other, of up to 200 vertices each.
            let rings: Vec<Vec<Vec<[f64; 2]>>> = (0..1 + (random() * 4.0) as usize)
                .map(|_| {
                    let (cx, cy, radius) =
                        (random() * 100.0, random() * 100.0, 5.0 + random() * 40.0);
                    let vertices = 3 + (random() * 200.0) as usize;
                    let ring = (0..vertices)
                        .map(|_| {
                            let (angle, reach) =
                                (random() * std::f64::consts::TAU, random() * radius);
                            [cx + reach * angle.cos(), cy + reach * angle.sin()]
                        })
                        .collect();
                    vec![ring]
                })
                .collect();
            let operand = MultiPolygon::from_coordinates(&rings);
            let cells = (operand.vertex_count() as f64).sqrt() as usize;
            let known = KnownWinding::new(&operand, region_of(&operand), cells);
            for _ in 0..400 {
                let (x, y, side) = (
                    random() * 160.0 - 30.0,
                    random() * 160.0 - 30.0,
                    random() * 8.0,
                );
                let b = Bounds::at(&Point::new(x, y))
                    .around(&Bounds::at(&Point::new(x + side, y + side)));
                let Some(w) = known.throughout(&b) else {
                    continue;
                };
                known_boxes += 1;
                for _ in 0..4 {
                    let p = Point::new(x + random() * side, y + random() * side);
                    assert_eq!(winding_at(&operand, p), w, "at {p:?} in box {b:?}");
                }
            }
        }
        assert!(known_boxes > 1000, "only {known_boxes} boxes known");
    }
}
