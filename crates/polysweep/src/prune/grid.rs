//! Grids over the operands' boxes: which cell a coordinate lies in, which cells a box touches, and which boxes
//! may meet a box, read from its cells instead of from every other box.

use crate::input::Bounds;

/// A grid of `cells` × `cells` over a region. A coordinate's cell is its place between the region's smallest and
/// largest, scaled to the number of cells and rounded down (clamped at the ends): monotone in floating point, so a
/// point of a box lies in a cell of the box's range, and two boxes with a common point both touch that point's cell.
#[derive(Clone, Copy)]
pub(crate) struct Grid {
    pub region: Bounds,
    pub cells: usize,
    scale: [f64; 2],
}

impl Grid {
    /// The side of a square grid of about `cells` cells in all: one at least, 1,024 at most.
    pub fn side_for(cells: usize) -> usize {
        (cells as f64).sqrt().ceil().clamp(1.0, 1024.0) as usize
    }

    /// A grid of `cells` × `cells` (one at least) over `region`.
    pub fn new(region: Bounds, cells: usize) -> Self {
        let cells = cells.max(1);
        let scale = [0, 1].map(|k| {
            let extent = region.max[k] - region.min[k];
            if extent > 0.0 {
                cells as f64 / extent
            } else {
                0.0
            }
        });
        Grid {
            region,
            cells,
            scale,
        }
    }

    /// Cells per unit of length along axis `k` (0 when the region has no extent along it).
    pub fn scale(&self, k: usize) -> f64 {
        self.scale[k]
    }

    /// The column (`k` = 0) or row (`k` = 1) of coordinate `v`. (Rounding down a negative or NaN place gives 0; by way
    /// of `u32`, as the cells are few: the conversion is cheaper than one to `usize`.)
    pub fn cell(&self, v: f64, k: usize) -> usize {
        (((v - self.region.min[k]) * self.scale[k]) as u32 as usize).min(self.cells - 1)
    }

    /// The first and last column and row that box `b` touches.
    pub fn range(&self, b: &Bounds) -> [[usize; 2]; 2] {
        [0, 1].map(|k| [self.cell(b.min[k], k), self.cell(b.max[k], k)])
    }

    /// A difference table for counting how many cell ranges touch each cell: add each range (see [`Self::range`])
    /// with [`Self::count_range`], one update whatever its size, then [`Self::counts`].
    pub fn difference_table(&self) -> Vec<i32> {
        vec![0; (self.cells + 1) * (self.cells + 1)]
    }

    pub fn count_range(&self, table: &mut [i32], [[c0, c1], [r0, r1]]: [[usize; 2]; 2]) {
        let width = self.cells + 1;
        table[r0 * width + c0] += 1;
        table[r0 * width + c1 + 1] -= 1;
        table[(r1 + 1) * width + c0] -= 1;
        table[(r1 + 1) * width + c1 + 1] += 1;
    }

    /// How many ranges touch each cell (row by row): the difference table summed along rows and columns.
    pub fn counts(&self, mut table: Vec<i32>) -> Vec<i32> {
        let width = self.cells + 1;
        table.chunks_exact_mut(width).for_each(running_sums);
        for r in 1..self.cells {
            let (above, row) = table.split_at_mut(r * width);
            for (v, a) in row.iter_mut().zip(&above[(r - 1) * width..]) {
                *v += a;
            }
        }
        (table.chunks_exact(width).take(self.cells))
            .flat_map(|row| &row[..self.cells])
            .copied()
            .collect()
    }

    /// The rectangle sums of the cells that `marked` (given a row and a column) marks: entry `r · (cells + 1) + c`
    /// counts the marked cells of rows below `r` and columns left of `c` (see [`Self::marked_in`]).
    pub fn rectangle_sums(&self, marked: impl Fn(usize, usize) -> bool) -> Vec<u32> {
        let (n, width) = (self.cells, self.cells + 1);
        let mut sums = vec![0u32; width * width];
        for r in 0..n {
            let (below, this) = sums.split_at_mut((r + 1) * width);
            let below = &below[r * width..];
            let mut in_row = 0;
            for c in 0..n {
                in_row += u32::from(marked(r, c));
                this[c + 1] = below[c + 1] + in_row;
            }
        }
        sums
    }

    /// How many marked cells, by `sums` (see [`Self::rectangle_sums`]), lie in `range` (see [`Self::range`]).
    pub fn marked_in(&self, sums: &[u32], [[c0, c1], [r0, r1]]: [[usize; 2]; 2]) -> u32 {
        let width = self.cells + 1;
        sums[(r1 + 1) * width + c1 + 1] + sums[r0 * width + c0]
            - sums[r0 * width + c1 + 1]
            - sums[(r1 + 1) * width + c0]
    }
}

/// Replaces each value of `row` by the sum of it and those before it.
pub(crate) fn running_sums(row: &mut [i32]) {
    let mut sum = 0;
    for v in row {
        sum += *v;
        *v = sum;
    }
}

/// Which cells of a grid some box of a set touches: tells in constant time whether another box may meet a box of
/// the set. Its "no" is exact, so a polygon it rules out can be left out of the sweep (see [`super::plan`]);
/// its "yes" may be wrong by a cell.
pub(crate) struct Coverage {
    grid: Grid,
    /// The rectangle sums of the cells that some box touches.
    touched: Vec<u32>,
}

impl Coverage {
    /// The coverage of `boxes` on a grid of `cells` × `cells` (one at least).
    pub fn new(boxes: &[Bounds], cells: usize) -> Self {
        let grid = Grid::new(Bounds::around_all(boxes), cells);
        let mut table = grid.difference_table();
        for b in boxes.iter().filter(|b| b.meets(&grid.region)) {
            grid.count_range(&mut table, grid.range(b));
        }
        let count = grid.counts(table);
        Coverage {
            grid,
            touched: grid.rectangle_sums(|r, c| count[r * grid.cells + c] > 0),
        }
    }

    /// Could `b` meet one of the boxes? `false` only if it meets none.
    pub fn may_meet(&self, b: &Bounds) -> bool {
        b.meets(&self.grid.region) && self.grid.marked_in(&self.touched, self.grid.range(b)) > 0
    }
}

/// Cells per box, on average, beyond which a [`BoxIndex`] is not made: the grid is then too coarse for the boxes.
const CELLS_PER_BOX: usize = 16;

/// Boxes looked at for one box beyond which [`apart`] and [`inside_one_convex`] give up on it: it shares its cells
/// with too many.
const MAX_LOOKED_AT: usize = 64;

/// Boxes listed in the cells of a grid that each touches once grown by a margin, so that every box within the
/// margin of a listed box shares a cell with it: which boxes may meet a box is read from its cells.
pub(super) struct BoxIndex {
    grid: Grid,
    /// The boxes of each cell, counting-sorted by cell: `starts[cell]..starts[cell + 1]` of `members`.
    starts: Vec<usize>,
    members: Vec<u32>,
}

impl BoxIndex {
    /// The boxes of `boxes` that `listed` names (by index, in ascending order, which each cell's list keeps), each
    /// grown by `margin`; `None` where they would touch too many cells (see [`CELLS_PER_BOX`]), so that making it
    /// stays linear in the boxes.
    pub(super) fn new(boxes: &[Bounds], listed: &[u32], margin: f64) -> Option<Self> {
        let region = (listed.iter()).fold(Bounds::EMPTY, |r, &i| r.around(&boxes[i as usize]));
        let grid = Grid::new(region, Grid::side_for(listed.len()));
        // The cells of each listed box grown by `margin`; none for an empty box (of a polygon without vertices),
        // which meets nothing.
        let ranges: Vec<[[usize; 2]; 2]> = (listed.iter())
            .map(|&i| {
                let b = &boxes[i as usize];
                if b.meets(&grid.region) {
                    grid.range(&b.grown(margin))
                } else {
                    [[1, 0], [1, 0]]
                }
            })
            .collect();
        let (budget, mut cells_listed) = (CELLS_PER_BOX * listed.len(), 0);
        for [[c0, c1], [r0, r1]] in &ranges {
            // (Counted box by box, checked as it goes: the sum of all could overflow a 32-bit `usize`.)
            cells_listed += (c1 + 1).saturating_sub(*c0) * (r1 + 1).saturating_sub(*r0);
            if cells_listed > budget {
                return None;
            }
        }
        // (Plain loops over each range's rows and columns: chained iterators did not compile to as little.)
        let width = grid.cells;
        let mut starts = vec![0usize; width * width + 1];
        for &[[c0, c1], [r0, r1]] in &ranges {
            for r in r0..=r1 {
                for count in &mut starts[r * width + c0 + 1..=r * width + c1 + 1] {
                    *count += 1;
                }
            }
        }
        for cell in 0..width * width {
            starts[cell + 1] += starts[cell];
        }
        let (mut members, mut next) = (vec![0u32; cells_listed], starts.clone());
        for (&i, &[[c0, c1], [r0, r1]]) in listed.iter().zip(&ranges) {
            for r in r0..=r1 {
                for slot in &mut next[r * width + c0..=r * width + c1] {
                    members[*slot] = i;
                    *slot += 1;
                }
            }
        }
        Some(BoxIndex {
            grid,
            starts,
            members,
        })
    }

    /// Does `f` hold for every listed box in the cells that `b` touches (each box as often as it shares a cell with
    /// `b`), at most [`MAX_LOOKED_AT`] of them? Every listed box within the margin of `b` is among them.
    pub(super) fn all_near(&self, b: &Bounds, mut f: impl FnMut(usize) -> bool) -> bool {
        if !b.meets(&self.grid.region) {
            return true;
        }
        let ([[c0, c1], [r0, r1]], width) = (self.grid.range(b), self.grid.cells);
        let mut looked_at = 0;
        (r0..=r1).all(|r| {
            let cells = self.starts[r * width + c0]..self.starts[r * width + c1 + 1];
            self.members[cells].iter().all(|&q| {
                looked_at += 1;
                looked_at <= MAX_LOOKED_AT && f(q as usize)
            })
        })
    }
}

/// Which of the boxes that `asked` names are farther than `margin` from every other box of `boxes` that `listed`
/// names by index, in ascending order (it names the asked ones too). Where the boxes touch too many cells of a
/// [`BoxIndex`], or a box's cells hold too many others, the answer is "not apart": the pass stays linear in the
/// boxes.
pub(super) fn apart(boxes: &[Bounds], margin: f64, asked: &[bool], listed: &[u32]) -> Vec<bool> {
    let mut apart = vec![false; boxes.len()];
    let Some(index) = BoxIndex::new(boxes, listed, margin) else {
        return apart;
    };
    for p in (0..boxes.len()).filter(|&p| asked[p]) {
        let grown = boxes[p].grown(margin);
        apart[p] = index.all_near(&grown, |q| q == p || !boxes[q].meets(&grown));
    }
    apart
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_random::unit;

    #[test]
    fn coverage_never_rules_out_a_box_that_meets_one() {
        let mut random = unit(29);
        // Boxes on a coarse lattice, so that many touch at an edge or a corner, some are points or segments.
        let mut lattice = || (random() * 40.0).floor() / 2.0 - 5.0;
        let mut random_box = || {
            let (x, y) = (lattice(), lattice());
            let (w, h) = ((lattice() + 5.0) / 8.0, (lattice() + 5.0) / 8.0);
            Bounds {
                min: [x, y],
                max: [x + w, y + h],
            }
        };
        let (mut ruled_out, mut apart) = (0, 0);
        for (set_size, cells) in [
            (0, 1),
            (1, 1),
            (1, 7),
            (30, 1),
            (30, 5),
            (30, 16),
            (200, 15),
        ] {
            let boxes: Vec<Bounds> = (0..set_size).map(|_| random_box()).collect();
            let coverage = Coverage::new(&boxes, cells);
            for _ in 0..400 {
                let b = random_box();
                let meets = boxes.iter().any(|c| c.meets(&b));
                let may_meet = coverage.may_meet(&b);
                assert!(may_meet || !meets, "{b:?} meets one of {boxes:?}");
                // Those within the set's box, which the cells have to tell apart.
                if !meets && b.meets(&coverage.grid.region) {
                    apart += 1;
                    ruled_out += usize::from(!may_meet);
                }
            }
        }
        // Not a filter that always says yes: a fair share (here 227 of 814) of the boxes between the set's are ruled
        // out.
        assert!(ruled_out * 5 > apart, "{ruled_out} of {apart}");
        // No cells asked for: one cell, not a panic.
        let square = |x: f64| Bounds {
            min: [x, 0.0],
            max: [x + 1.0, 1.0],
        };
        let one_cell = Coverage::new(&[square(0.0), square(4.0)], 0);
        assert!(one_cell.may_meet(&square(4.5)) && !one_cell.may_meet(&square(6.0)));
    }
}
