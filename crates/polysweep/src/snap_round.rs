//! Snap rounding of a sweep's exact result (Hobby 1999; not in the paper, which computes in real arithmetic), for
//! the case where the plainly rounded result breaks the output contract (see the robustness page, §3).
//!
//! A grid of cells tiles the plane, each cell around the float its points round to. Snap rounding calls the cells
//! of the result's vertices *hot* and writes each result edge as the polyline through the centres of the hot cells
//! it passes through, in order. Every test here is exact. On a uniform grid, snapped edges meet only at common
//! vertices or along common fragments, never cross (Guibas and Marimont 1998), so the sweep that reads them back
//! constructs no point: its result is exact, and final.
//!
//! Two grids are used. First the floats' own rounding cells ([`Grid::Floats`]): vertices are written exactly where
//! plain rounding writes them (input vertices bit-for-bit), and an edge only gains the vertices it passes within
//! half an ulp of. Those cells are uniform only between powers of two, where their size doubles (and they shrink
//! towards zero), so snapped edges whose cells lie across one can still cross; then the uniform grid of the
//! largest coordinate's spacing ([`Grid::Uniform`]), where the argument holds, and every vertex moves to it.

use crate::edges::{InputEdge, ResultEdge};
use crate::exact::{Exact, Line, SweepPoint};
use crate::geometry::larger;
use crate::input::push_edge;
use std::cmp::Ordering;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Grid {
    /// Each float's rounding cell (round half to even): the reals that round to it.
    Floats,
    /// The squares of side `spacing` (a power of two) around its multiples, closed on the left and bottom and open
    /// on the right and top.
    Uniform { spacing: f64 },
}

/// One axis of a cell: its centre, and its two sides, each given as the two floats it lies halfway between (the
/// same float twice for a side that is a float), and whether it belongs to the cell.
struct Span {
    centre: f64,
    sides: [([f64; 2], bool); 2],
}

impl Grid {
    /// The uniform grid for points whose coordinates are `magnitude` at most (a normal float): twice the spacing of
    /// the floats in [2^(k+1), 2^(k+2)) for `magnitude` in [2^k, 2^(k+1)), so that the centres and sides of all
    /// cells that can hold a point (multiples of half the spacing, below 2^(k+2)) are floats.
    pub fn uniform(magnitude: f64) -> Grid {
        let exponent = ((magnitude.to_bits() >> 52) & 0x7ff) as i64 - 1023;
        Grid::Uniform {
            spacing: f64::from_bits(((exponent + 2 - 52 + 1023) as u64) << 52),
        }
    }

    /// The centre of the cell that holds `p`.
    fn centre(&self, exact: &Exact, p: &SweepPoint) -> [f64; 2] {
        match *self {
            // (Plus zero for minus zero, which rounds and compares as zero.)
            Grid::Floats => p.approx.map(|c| c + 0.0),
            Grid::Uniform { spacing } => [0, 1].map(|axis| {
                // The rounded coordinate is within half an ulp of the exact one: at most one cell off.
                let mut i = (p.approx[axis] / spacing).round();
                let side = |i: f64| {
                    let v = i * spacing;
                    exact.cmp_coordinate(p, &SweepPoint::input([v, v]), axis)
                };
                if side(i - 0.5) == Ordering::Less {
                    i -= 1.0;
                } else if side(i + 0.5) != Ordering::Less {
                    i += 1.0;
                }
                i * spacing + 0.0
            }),
        }
    }

    /// The extent of the cell centred at `centre` on one axis.
    fn span(&self, centre: f64) -> Span {
        match *self {
            Grid::Floats => {
                // A tie rounds to the even float, whose cell holds both its sides.
                let even = centre.to_bits() & 1 == 0;
                Span {
                    centre,
                    sides: [
                        ([centre.next_down(), centre], even),
                        ([centre, centre.next_up()], even),
                    ],
                }
            }
            Grid::Uniform { spacing } => {
                let (low, high) = (centre - spacing / 2.0, centre + spacing / 2.0);
                Span {
                    centre,
                    sides: [([low, low], true), ([high, high], false)],
                }
            }
        }
    }
}

/// The input edges of the snap-rounded `result` of a sweep (edges between its exact `vertices`, on the lines of
/// `input`) on `grid`: for each result edge, the fragments between the hot cells it passes through, with the
/// winding that leaves the result on their left, as a ring's edges have it.
///
/// Each edge is tested against the hot cells within its x-range, with a float filter on the distance first: work
/// up to the edges times the hot cells beside them, spent only where the plainly rounded result failed validation.
pub(crate) fn snap_rounded_edges(
    exact: &Exact,
    input: &[InputEdge],
    vertices: &[SweepPoint],
    result: &[ResultEdge],
    grid: Grid,
) -> Vec<InputEdge> {
    let by_x = |p: &[f64; 2], q: &[f64; 2]| p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]));
    let centre = |v: u32| grid.centre(exact, &vertices[v as usize]);
    let mut hot: Vec<[f64; 2]> = result
        .iter()
        .flat_map(|e| [centre(e.from), centre(e.to)])
        .collect();
    hot.sort_by(by_x);
    hot.dedup();
    let mut edges = Vec::new();
    let mut path: Vec<[f64; 2]> = Vec::new();
    for e in result {
        let line = &input[e.segment as usize].line;
        // The cells of the edge's ends, left first: a cell on its way lies within their ranges (rounding to cells
        // keeps the order).
        let (left, right) = if e.forward {
            (centre(e.from), centre(e.to))
        } else {
            (centre(e.to), centre(e.from))
        };
        let (low, high) = (left[1].min(right[1]), left[1].max(right[1]));
        let within =
            hot.partition_point(|p| p[0] < left[0])..hot.partition_point(|p| p[0] <= right[0]);
        path.clear();
        path.extend(hot[within].iter().filter(|&&c| {
            low <= c[1] && c[1] <= high && near(line, c, grid) && meets_cell(exact, line, c, grid)
        }));
        // Along the edge from left to right: by x, and at one x up or down as the line goes.
        let upward = line.b[1] >= line.a[1];
        path.sort_by(|p, q| {
            let ys = p[1].total_cmp(&q[1]);
            p[0].total_cmp(&q[0])
                .then(if upward { ys } else { ys.reverse() })
        });
        debug_assert_eq!((path.first(), path.last()), (Some(&left), Some(&right)));
        if !e.forward {
            path.reverse();
        }
        for pair in path.windows(2) {
            push_edge(&mut edges, pair[0], pair[1], 0);
        }
    }
    edges
}

/// Can `line` pass through the cell centred at `c`? A float filter, not a tolerance: it decides nothing, only
/// skips cells that [`meets_cell`] would reject. A cell reaches less than an ulp of the magnitude from its centre
/// (or `spacing`, on the uniform grid), and the float offset of a point from a line is off by at most about 12 ulps
/// of it, so a cell the line passes through is never filtered out: the margin cannot change a decision.
fn near(line: &Line, c: [f64; 2], grid: Grid) -> bool {
    let magnitude = [line.a, line.b, c]
        .iter()
        .flatten()
        .fold(0.0, |m, v| larger(m, v.abs()));
    let reach = match grid {
        Grid::Floats => 0.0,
        Grid::Uniform { spacing } => spacing,
    };
    line.float_within(c, 16.0 * (magnitude.next_up() - magnitude) + reach)
}

/// Does `line` pass through the cell centred at `c`? (With the ranges of the segment, which the caller compares,
/// this is whether the segment does: three intervals of its parameter that meet pairwise meet together.)
fn meets_cell(exact: &Exact, line: &Line, c: [f64; 2], grid: Grid) -> bool {
    let (xs, ys) = (grid.span(c[0]), grid.span(c[1]));
    debug_assert!(xs.centre == c[0] && ys.centre == c[1]);
    // Corners: bottom left, bottom right, top left, top right.
    let corners = [(0, 0), (1, 0), (0, 1), (1, 1)];
    let on = corners.map(|(i, j)| exact.orient_midpoint(line, xs.sides[i].0, ys.sides[j].0));
    if on.contains(&Ordering::Less) && on.contains(&Ordering::Greater) {
        return true; // through the cell's interior
    }
    // Else the line touches the cell's boundary at most: along a side, or at a corner; the cell holds it where it
    // holds that side, or both sides that meet at the corner.
    let touching: Vec<(usize, usize)> = (corners.iter().zip(on))
        .filter(|&(_, side)| side == Ordering::Equal)
        .map(|(&corner, _)| corner)
        .collect();
    match touching[..] {
        [] => false,
        [(i, j)] => xs.sides[i].1 && ys.sides[j].1,
        [(i, _), (k, _)] if i == k => xs.sides[i].1, // a vertical side
        [(_, j), (_, l)] if j == l => ys.sides[j].1, // a horizontal side
        _ => unreachable!("a line through two opposite corners passes through the interior"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hand-worked around 1, whose neighbours 1 − 2^-53 and 1 + 2^-52 are odd: the corner (1 + 2^-53, 1 + 2^-53)
    /// rounds to (1, 1), and is a corner of the cells of its three odd neighbours too.
    #[test]
    fn lines_meet_rounding_cells_with_the_corners_that_round_half_to_even() {
        let exact = Exact::default();
        let meets = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
            meets_cell(&exact, &Line { a, b }, c, Grid::Floats)
        };
        // (`f64::EPSILON` is 2^-52, used to place lines exactly through corners, not as a tolerance.)
        let (one, next) = (1.0f64, 1.0f64.next_up());
        assert!(meets([0.0, 0.0], [2.0, 2.0], [one, one])); // through the middle
        assert!(!meets([0.0, 0.5], [2.0, 0.5], [one, one])); // below
                                                             // x + y = 2 + 2^-52 touches the cell of (1, 1) at its top-right corner only, which rounds to (1, 1), and the
                                                             // cell of (1 + 2^-52, 1 + 2^-52) at its bottom-left corner, the same point. It passes through the cells of
                                                             // (1, 1 + 2^-52) and (1 + 2^-52, 1), which reach down to 1 - 2^-54 on the axis where they are at 1.
        let corner = |c: [f64; 2]| meets([2.0, f64::EPSILON], [f64::EPSILON, 2.0], c);
        assert!(corner([one, one]));
        assert!(!corner([next, next]));
        assert!(corner([one, next]));
        assert!(corner([next, one]));
        // x + y = 2 + 2^-51 passes through (1 + 2^-52, 1 + 2^-52).
        assert!(meets(
            [2.0, 2.0 * f64::EPSILON],
            [2.0 * f64::EPSILON, 2.0],
            [next, next]
        ));
    }

    /// Hand-worked: the cell of side 1 around (0, 0) is [-0.5, 0.5) × [-0.5, 0.5).
    #[test]
    fn lines_meet_uniform_cells_closed_left_and_bottom_and_open_right_and_top() {
        let exact = Exact::default();
        let grid = Grid::Uniform { spacing: 1.0 };
        let meets = |a: [f64; 2], b: [f64; 2]| meets_cell(&exact, &Line { a, b }, [0.0, 0.0], grid);
        assert!(meets([-2.0, 0.0], [2.0, 0.1])); // through
        assert!(meets([-2.0, -0.5], [2.0, -0.5])); // along the bottom side
        assert!(!meets([-2.0, 0.5], [2.0, 0.5])); // along the top side
        assert!(meets([-0.5, -2.0], [-0.5, 2.0])); // along the left side
        assert!(!meets([0.5, -2.0], [0.5, 2.0])); // along the right side
        assert!(meets([-1.5, 0.5], [0.5, -1.5])); // through the bottom-left corner only
        assert!(!meets([-0.5, 1.5], [1.5, -0.5])); // through the top-right corner only
        assert!(!meets([-1.5, -0.5], [-0.5, 0.5])); // through the top-left corner only
        assert!(!meets([-2.0, 3.0], [2.0, 3.0])); // above
    }

    #[test]
    fn the_uniform_grid_is_a_power_of_two_whose_half_multiples_are_floats() {
        for magnitude in [1.0, 1.5, 3.0, 1e9, 1e-9, 2f64.powi(200)] {
            let Grid::Uniform { spacing } = Grid::uniform(magnitude) else {
                unreachable!()
            };
            assert_eq!(
                spacing.to_bits() & ((1 << 52) - 1),
                0,
                "{spacing} is a power of two"
            );
            let side = ((magnitude / spacing).ceil() + 0.5) * spacing;
            assert_eq!(side - spacing / 2.0 + spacing / 2.0, side);
            assert!(spacing > 2.0 * (magnitude.next_up() - magnitude));
        }
    }
}
