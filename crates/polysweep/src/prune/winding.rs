//! An operand's winding number, known on the cells of a grid that none of its edges touch (see the module
//! [`super`] for why that is exact).

use super::grid::{running_sums, Grid};
use crate::geometry::{open_len, MultiPolygon, Point};
use crate::input::Bounds;

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
        // Each row's line, where one lies strictly inside the row (a row of a degenerate grid may have none: NaN).
        let lines: Vec<f64> = (0..n)
            .map(|r| {
                let y = region.min(1) + (r as f64 + 0.5) / grid.scale(1);
                if y.is_finite() && grid.cell(y, 1) == r {
                    y
                } else {
                    f64::NAN
                }
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
            let mut counted = (usize::MAX, usize::MAX, usize::MAX, usize::MAX);
            for &b in ring {
                let [cb, rb] = cell(b);
                let (c0, c1, r0, r1) = (ca.min(cb), ca.max(cb), ra.min(rb), ra.max(rb));
                // (Most edges are short: one after another in one cell, which is counted once. Compared as a tuple,
                // word by word: as arrays, the range just stored was read back as one wide word, which stalls.)
                if counted != (c0, c1, r0, r1) {
                    grid.count_range(&mut touches, [[c0, c1], [r0, r1]]);
                    counted = (c0, c1, r0, r1);
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
                // end's column: differences along each row, summed below. (A row without a line has NaN, which
                // no edge crosses.)
                if c1 + 1 < n {
                    let direction = if b.y < a.y { 1 } else { -1 };
                    for (r, &y) in lines[r0..=r1].iter().enumerate() {
                        if (a.y < y) != (b.y < y) {
                            winding[(r0 + r) * n + c1 + 1] += direction;
                        }
                    }
                }
                (a, ca, ra) = (b, cb, rb);
            }
        }
        let touches = grid.counts(touches);
        winding.chunks_exact_mut(n).for_each(running_sums);
        let unknown = grid.rectangle_sums(|r, c| lines[r].is_nan() || touches[r * n + c] > 0);
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
        if !b.within(region) {
            return None;
        }
        let range = self.grid.range(b);
        if self.grid.marked_in(&self.unknown, range) > 0 {
            return None;
        }
        let [[c, _], [r, _]] = range;
        Some(self.winding[r * self.grid.cells + c])
    }
}
