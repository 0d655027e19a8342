//! Checking the input and turning its rings into sweep events (step 1 of Fig. 5).

use crate::edges::{InputEdge, Operand};
use crate::error::{Error, Location};
use crate::exact::Line;
use crate::geometry::{larger, next_around, open_len, smaller, MultiPolygon, Point, Polygon};

/// Largest coordinate magnitude accepted: 2^200. Within it (and above [`MIN_COORDINATE`]) the products formed by
/// the exact predicates neither overflow nor underflow, which their proofs assume.
pub const MAX_COORDINATE: f64 = (1u128 << 100) as f64 * (1u128 << 100) as f64;
/// Smallest non-zero coordinate magnitude accepted: 2^-200.
pub const MIN_COORDINATE: f64 = 1.0 / MAX_COORDINATE;

/// Checks every coordinate of `operand` (its index among the operation's operands is `index`), and returns the box
/// of each of its polygons (of all its rings: a hole may reach outside its shell), made on the same pass. The pass
/// only notes whether a polygon has a bad coordinate, without a branch per coordinate; such a polygon is read again
/// to name the first one.
pub(crate) fn check(index: usize, operand: &MultiPolygon) -> Result<Vec<Bounds>, Error> {
    let mut boxes = Vec::with_capacity(operand.0.len());
    for (polygon, p) in operand.0.iter().enumerate() {
        let mut bounds = Bounds::EMPTY;
        let mut accepted = true;
        for ring in p.rings() {
            for point in ring {
                accepted &= is_accepted(point.x) & is_accepted(point.y);
                bounds = bounds.around(&Bounds::at(point));
            }
        }
        if let Some(error) = (!accepted)
            .then(|| first_rejected(index, polygon, p))
            .flatten()
        {
            return Err(error);
        }
        boxes.push(bounds);
    }
    Ok(boxes)
}

/// Is `value` a coordinate the exact predicates' proofs cover: finite, and 0 or of a magnitude within
/// [`MIN_COORDINATE`]..=[`MAX_COORDINATE`]?
fn is_accepted(value: f64) -> bool {
    // On the bits of the magnitude, which order non-negative floats as their values (NaNs above infinity): 0, or
    // within the range by one unsigned comparison.
    let magnitude = value.to_bits() & !(1 << 63);
    let (min, max) = (MIN_COORDINATE.to_bits(), MAX_COORDINATE.to_bits());
    magnitude == 0 || magnitude.wrapping_sub(min) <= max - min
}

/// The error for the first coordinate of polygon `p` (number `polygon` of operand `index`) that [`is_accepted`]
/// rejects, if any.
fn first_rejected(index: usize, polygon: usize, p: &Polygon) -> Option<Error> {
    let (ring, vertex, value) = (p.rings().enumerate())
        .flat_map(|(ring, r)| {
            r.iter()
                .enumerate()
                .map(move |(vertex, point)| (ring, vertex, point))
        })
        .flat_map(|(ring, vertex, point)| [point.x, point.y].map(|value| (ring, vertex, value)))
        .find(|&(_, _, value)| !is_accepted(value))?;
    let at = Location {
        operand: index,
        polygon,
        ring,
        vertex,
    };
    Some(if value.is_finite() {
        Error::CoordinateOutOfRange { at, value }
    } else {
        Error::NonFiniteCoordinate { at, value }
    })
}

/// An axis-aligned box, closed; the empty box has min > max.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Bounds {
    min: [f64; 2],
    max: [f64; 2],
}

impl Bounds {
    pub const EMPTY: Bounds = Bounds {
        min: [f64::INFINITY; 2],
        max: [f64::NEG_INFINITY; 2],
    };

    /// The box of one point.
    pub fn at(p: &Point) -> Bounds {
        Bounds {
            min: [p.x, p.y],
            max: [p.x, p.y],
        }
    }

    /// The box around this one and `other`.
    pub fn around(&self, other: &Bounds) -> Bounds {
        Bounds {
            min: [
                smaller(self.min[0], other.min[0]),
                smaller(self.min[1], other.min[1]),
            ],
            max: [
                larger(self.max[0], other.max[0]),
                larger(self.max[1], other.max[1]),
            ],
        }
    }

    /// The box around `boxes`.
    pub fn around_all(boxes: &[Bounds]) -> Bounds {
        boxes.iter().fold(Bounds::EMPTY, |b, c| b.around(c))
    }

    pub fn max_x(&self) -> f64 {
        self.max[0]
    }

    /// The smallest coordinate on axis `k` (0: x, 1: y).
    pub fn min(&self, k: usize) -> f64 {
        self.min[k]
    }

    /// The four corners (of a box that is not empty).
    pub fn corners(&self) -> [Point; 4] {
        let ([x0, y0], [x1, y1]) = (self.min, self.max);
        [
            Point::new(x0, y0),
            Point::new(x1, y0),
            Point::new(x1, y1),
            Point::new(x0, y1),
        ]
    }

    /// The largest magnitude of a coordinate in the box (0 for an empty box): every point the sweep makes from
    /// edges within the box lies within it, crossings included.
    pub fn magnitude(&self) -> f64 {
        if self.min[0] > self.max[0] {
            return 0.0;
        }
        (self.min.iter().chain(&self.max)).fold(0.0, |m, v| larger(m, v.abs()))
    }

    /// This box grown by `margin` on every side.
    pub fn grown(&self, margin: f64) -> Bounds {
        Bounds {
            min: self.min.map(|v| v - margin),
            max: self.max.map(|v| v + margin),
        }
    }

    pub fn meets(&self, other: &Bounds) -> bool {
        (0..2).all(|k| self.min[k] <= other.max[k] && other.min[k] <= self.max[k])
    }

    /// Does this box lie within `other`?
    pub fn within(&self, other: &Bounds) -> bool {
        (0..2).all(|k| other.min[k] <= self.min[k] && self.max[k] <= other.max[k])
    }
}

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
    /// of `u32`, as the cells are few, the conversion takes half the instructions of one to `usize`.)
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
/// the set. Its "no" is exact, so a polygon it rules out can be left out of the sweep (see `overlay_with_stats`);
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

/// Appends the edges of every ring of the polygons of `polygons` that `keep` (given a polygon's index) keeps.
/// Edges of zero length are skipped; a ring with fewer than three vertices still gives its edges, which cancel each
/// other (§7.2).
pub(crate) fn add_edges(
    edges: &mut Vec<InputEdge>,
    polygons: &MultiPolygon,
    operand: Operand,
    keep: impl Fn(usize) -> bool,
) {
    edges.reserve(polygons.vertex_count()); // at most one edge per vertex
    let kept = polygons.0.iter().enumerate().filter(|&(p, _)| keep(p));
    for ring in kept.flat_map(|(_, p)| p.rings()) {
        let n = open_len(ring);
        for i in 0..n {
            let (from, to) = (ring[i], ring[next_around(i, n)]);
            if from == to {
                continue;
            }
            let (from, to) = ([from.x, from.y], [to.x, to.y]);
            // Sweep order: by x, then y (§7.1: a vertical edge's lower end is its left end).
            let forward = (from[0], from[1]) < (to[0], to[1]);
            let (a, b) = if forward { (from, to) } else { (to, from) };
            edges.push(InputEdge {
                line: Line { a, b },
                operand,
                // Crossing an edge upwards enters a counter-clockwise ring when the edge runs left to right.
                winding: if forward { 1 } else { -1 },
            });
        }
    }
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

    fn operand(rings: &[&[[f64; 2]]]) -> MultiPolygon {
        let polygon: Vec<Vec<[f64; 2]>> = rings.iter().map(|r| r.to_vec()).collect();
        let square = vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]];
        MultiPolygon::from_coordinates(&[square, polygon])
    }

    #[test]
    fn coordinates_are_accepted_exactly_within_the_range_and_at_its_ends() {
        let (above, below) = (MAX_COORDINATE.next_up(), MIN_COORDINATE.next_down());
        for (value, accepted) in [
            (0.0, true),
            (-0.0, true),
            (1.0, true),
            (-1.5, true),
            (MIN_COORDINATE, true),
            (-MIN_COORDINATE, true),
            (MAX_COORDINATE, true),
            (-MAX_COORDINATE, true),
            (above, false),
            (-above, false),
            (below, false),
            (-below, false),
            (f64::MIN_POSITIVE / 4.0, false), // subnormal
            (f64::MAX, false),
            (f64::INFINITY, false),
            (f64::NEG_INFINITY, false),
            (f64::NAN, false),
            (-f64::NAN, false),
        ] {
            assert_eq!(is_accepted(value), accepted, "{value:e}");
        }
    }

    #[test]
    fn the_first_rejected_coordinate_is_named_and_boxes_cover_every_ring() {
        let shell: &[[f64; 2]] = &[[-0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]];
        let hole: &[[f64; 2]] = &[[1.0, 1.0], [9.0, -2.0], [1.0, 2.0]];
        let boxes = check(3, &operand(&[shell, hole])).unwrap();
        assert_eq!(
            boxes[1],
            Bounds {
                min: [-0.0, -2.0],
                max: [9.0, 3.0]
            }
        );
        let tiny = MIN_COORDINATE / 2.0;
        for (bad_hole, vertex, value, finite) in [
            (
                &[[1.0, 1.0], [2.0, 1.0], [f64::NAN, 2.0]][..],
                2,
                f64::NAN,
                false,
            ),
            (
                &[[1.0, 1.0], [2.0, f64::INFINITY], [1e300, 2.0]][..],
                1,
                f64::INFINITY,
                false,
            ),
            (
                &[[1.0, 1.0], [2.0, tiny], [1.0, f64::NAN]][..],
                1,
                tiny,
                true,
            ),
            (
                &[[-1e300, 1.0], [2.0, 1.0], [1.0, 2.0]][..],
                0,
                -1e300,
                true,
            ),
        ] {
            let error = check(3, &operand(&[shell, bad_hole])).unwrap_err();
            let at = Location {
                operand: 3,
                polygon: 1,
                ring: 1,
                vertex,
            };
            match error {
                Error::NonFiniteCoordinate {
                    at: found,
                    value: v,
                } if !finite => {
                    assert_eq!((found, v.is_nan()), (at, value.is_nan()));
                    assert!(v.is_nan() || v == value);
                }
                Error::CoordinateOutOfRange {
                    at: found,
                    value: v,
                } if finite => {
                    assert_eq!((found, v), (at, value));
                }
                other => panic!("{bad_hole:?}: {other:?}"),
            }
        }
    }
}
