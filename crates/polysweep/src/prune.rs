//! Polygons that lie wholly inside or outside the other operand, away from its boundary (not in the paper).
//!
//! Where no edge of an operand passes, its winding number cannot change: a clipping polygon whose box lies in such
//! a place and outside the subject cannot change an intersection or a difference, and one inside it cannot change
//! a union, so it is left out of the sweep (see [`plan`]). This is what makes clipping a coastline
//! with a grid of tiles cost little more than the tiles that meet the coast: most tiles lie out at sea. Of those
//! inside, an intersection copies to its result the ones it can tell are their own part of it, simple rings apart
//! from the other tiles (see [`copied_whole`]). A union, a xor or a difference copies the polygons that are simple
//! rings apart from all others, of either operand (see [`copied_apart`]): islands, or the separate features of a
//! layer.
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
//! polygon's box that is swept. (One that meets only copied ones changes nothing where they are, as they lie
//! wholly inside the subject, nor anywhere else.)
//!
//! The other way round, a subject polygon inside the clipping operand cannot change a union or a difference
//! either. A union or a difference leaves out a subject polygon whose box, grown by the margin, lies inside one
//! convex clipping polygon and meets no other one's box (see [`inside_one_convex`]; not a grid: one convex ring is
//! told exactly by the corners of the box): islands inside a tile, say. It stays exact together with leaving out clipping polygons inside (union) or outside (difference)
//! the subject. Each polygon left out lies in a grown box that no edge of the other operand passes through. Where a
//! subject polygon's box and a clipping polygon's box overlap, neither box lies inside the other (it would hold
//! the other polygon's edges), so part of each lies outside the other, where that other polygon winds around
//! nothing; having no edge there, it winds around nothing anywhere in the box. So where the boxes overlap, the
//! polygons left out wind around no point, and elsewhere only one operand lost a polygon, the one whose winding
//! number is known there from the other.
//!
//! Exact means here that the exact result, before it is rounded to floats, is the same: all of this, and the
//! pruning by boxes, can change the rounding step elsewhere in the result. Whether any crossing was made at all,
//! and which vertices came within a few ulps of which edges, are asked of the edges swept (see `sweep_once`), so a
//! polygon left out (a self-crossing one, say) can switch snap rounding far from it on or off, which moves a result
//! edge by about an ulp. Either way the rounded result is valid (see the robustness page); only its last bits
//! depend on what was swept.

mod convex;
mod copy;
mod grid;
mod winding;

use crate::geometry::{closed, larger, MultiPolygon, Point, Polygon};
use crate::input::Bounds;
use crate::options::Shortcuts;
use crate::select::{FillRule, Operation};
use crate::validate::{locate, Side};
use convex::inside_one_convex;
use copy::{copied_apart, copied_whole};
use grid::{Coverage, Grid};
use winding::KnownWinding;

/// What the sweep takes of two operands: which polygons of the subject and of the clipping operand it sweeps, and
/// the polygons copied to the result instead (see [`copied_whole`] and [`copied_apart`]).
pub(crate) struct Plan {
    pub subject: Vec<bool>,
    pub clipping: Vec<bool>,
    pub copies: Vec<Polygon>,
    /// Some clipping polygon was judged inside or outside the subject by the subject's winding number.
    pub judged_by_subject: bool,
}

/// What to sweep of `subject` and `clipping` (their polygons' boxes `boxes`) for `operation`, with the shortcuts
/// that `shortcuts` turns on. `margin`: farther apart than rounding moves anything, twice over. Not a tolerance that
/// decides the result: it only chooses which polygons are left out or copied rather than swept, and always errs
/// towards sweeping. A box is grown by it before it is judged (inside or outside the other operand, apart from the
/// other boxes), so a polygon is left out or copied on a stricter test than exactness needs; the judgments
/// themselves are exact, and a copy is written exactly as the sweep would write it.
pub(crate) fn plan(
    operation: Operation,
    [subject, clipping]: [&MultiPolygon; 2],
    [subject_boxes, clipping_boxes]: [&[Bounds]; 2],
    fill_rule: FillRule,
    shortcuts: &Shortcuts,
    margin: f64,
) -> Plan {
    let mut plan = Plan {
        subject: vec![true; subject.0.len()],
        clipping: vec![true; clipping.0.len()],
        copies: Vec::new(),
        judged_by_subject: false,
    };
    if operation != Operation::Intersection && shortcuts.copy_apart {
        let copy_clipping = operation != Operation::Difference;
        let boxes = [subject_boxes, clipping_boxes];
        let copied;
        (copied, plan.copies) =
            copied_apart([subject, clipping], boxes, copy_clipping, fill_rule, margin);
        [plan.subject, plan.clipping] = copied.map(|c| c.iter().map(|&c| !c).collect());
    }
    if operation == Operation::Xor {
        return plan; // every other polygon of either operand changes a xor
    }
    // Each clipping polygon inside the subject (`Some(true)`) or outside it (`Some(false)`) throughout its box
    // grown by `margin`, where known; judged by the whole subject, before any of it is left out. An intersection
    // and a difference leave out those outside, a union those inside.
    let inside = if shortcuts.prune_by_winding {
        let boxes = [subject_boxes, clipping_boxes];
        inside_subject(operation, subject, clipping, boxes, fill_rule, margin)
    } else {
        vec![None; clipping.0.len()]
    };
    plan.judged_by_subject = inside.iter().any(Option::is_some);
    let left_out = if operation == Operation::Union {
        Some(true)
    } else {
        Some(false)
    };
    for (swept, inside) in plan.clipping.iter_mut().zip(&inside) {
        *swept &= *inside != left_out;
    }
    if operation == Operation::Intersection && shortcuts.copy_inside {
        let copied;
        (copied, plan.copies) = copied_whole(clipping, clipping_boxes, &inside, fill_rule, margin);
        for (swept, copied) in plan.clipping.iter_mut().zip(copied) {
            *swept &= !copied;
        }
    }
    // A subject polygon inside one convex clipping polygon, away from the others, cannot change a union or a
    // difference either (exact together with leaving out clipping polygons as above).
    if operation != Operation::Intersection
        && shortcuts.prune_inside_convex
        && some_sample_within_one(subject_boxes, clipping_boxes, margin)
    {
        let inside_clipping =
            inside_one_convex(clipping, clipping_boxes, subject_boxes, fill_rule, margin);
        for (swept, inside) in plan.subject.iter_mut().zip(inside_clipping) {
            *swept &= !inside;
        }
    }
    // An intersection lies where polygons of both operands are, and a difference where the subject's are: a polygon
    // whose box meets no polygon's box of the other operand cannot change the result. Exact: a ring's winding
    // number is 0 outside its box, so wherever the result can lie the operand's interior, under either fill rule,
    // is that of the polygons kept. The subject's polygons are judged by the boxes of the clipping polygons swept.
    if operation != Operation::Union && shortcuts.prune_by_boxes {
        // About as many cells as polygons.
        let cells = Grid::side_for(subject.0.len() + clipping.0.len());
        if operation == Operation::Intersection {
            let swept_boxes: Vec<Bounds> = (clipping_boxes.iter().zip(&plan.clipping))
                .filter(|(_, &swept)| swept)
                .map(|(b, _)| *b)
                .collect();
            let near_clipping = Coverage::new(&swept_boxes, cells);
            for (swept, b) in plan.subject.iter_mut().zip(subject_boxes) {
                *swept &= near_clipping.may_meet(b);
            }
        }
        let near_subject = Coverage::new(subject_boxes, cells);
        for (swept, b) in plan.clipping.iter_mut().zip(clipping_boxes) {
            *swept = *swept && near_subject.may_meet(b);
        }
    }
    plan
}

/// Fewer clipping polygons than this are not judged by the subject's winding number: each would have to lie within
/// a cell of a grid of a few cells, away from all of the subject's edges, to be left out.
const MIN_POLYGONS_TO_JUDGE: usize = 16;

/// Each clipping polygon inside the subject (`Some(true)`) or outside it (`Some(false)`) throughout its box grown
/// by `margin`, where the subject's winding number on a grid tells (see [`KnownWinding`]).
fn inside_subject(
    operation: Operation,
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    [subject_boxes, clipping_boxes]: [&[Bounds]; 2],
    fill_rule: FillRule,
    margin: f64,
) -> Vec<Option<bool>> {
    // The grid costs about a pass over the subject's vertices: it can pay only when the clipping operand, in many
    // polygons, has at least a share of the subject's vertices. A union, which leaves out only the polygons
    // inside, gains less from it than an intersection or a difference, which leave out those outside: it needs
    // half the subject's vertices, they a quarter (measured on Table 1's data, see docs/benchmarks.md).
    let share = if operation == Operation::Union { 2 } else { 4 };
    let subject_vertices = subject.vertex_count();
    // A union leaves out only clipping polygons inside the subject, away from its edges: each inside one subject
    // polygon, and so within its box.
    // A difference leaves out only clipping polygons outside the subject: where every one sampled starts inside it
    // (holes punched into the subject's polygons), the grid is not made.
    if clipping.0.len() < MIN_POLYGONS_TO_JUDGE
        || share * clipping.vertex_count() < subject_vertices
        || (operation == Operation::Union
            && !some_sample_within_one(clipping_boxes, subject_boxes, margin))
        || (operation == Operation::Difference
            && !some_sample_starts_outside(clipping, subject, subject_boxes))
    {
        return vec![None; clipping.0.len()];
    }
    // About four cells per clipping polygon, as pruning needs cells smaller than the polygons it leaves out, and no
    // more cells than the subject has vertices.
    let cells = Grid::side_for((4 * clipping.0.len()).min(subject_vertices));
    let known = KnownWinding::new(subject, Bounds::around_all(subject_boxes), cells);
    (clipping_boxes.iter())
        .map(|b| (known.throughout(&b.grown(margin))).map(|w| fill_rule.is_inside(w)))
        .collect()
}

/// Polygons sampled by a shortcut before it does its work (see [`some_sample_within_one`]).
const SAMPLES: usize = 16;

/// Does one at least of a sample of `judged` boxes, grown by `margin`, lie within one of `boxes`? A polygon left out
/// for lying inside one polygon of the other operand, or inside it away from its edges, lies within that polygon's
/// box; where none of the sample does, the polygons are taken to lie across each other (a board, a parcel map), and
/// the shortcut is not tried. Only a matter of speed: `false` means "sweep them all".
fn some_sample_within_one(judged: &[Bounds], boxes: &[Bounds], margin: f64) -> bool {
    let step = judged.len().div_ceil(SAMPLES).max(1);
    // A box fits within another only if it is no wider and no taller (float extents: rounding is monotone), so a
    // sampled box larger than the largest extents (a board's cells are all one size) needs no pass over `boxes`.
    let extent = |b: &Bounds| [b.max[0] - b.min[0], b.max[1] - b.min[1]];
    let largest = (boxes.iter().map(extent))
        .fold([0.0f64; 2], |m, e| [larger(m[0], e[0]), larger(m[1], e[1])]);
    (judged.iter().step_by(step)).any(|b| {
        let grown = b.grown(margin);
        let [width, height] = extent(&grown);
        width <= largest[0]
            && height <= largest[1]
            && boxes.iter().any(|container| grown.within(container))
    })
}

/// Does one at least of a sample of `judged`'s polygons start outside `operand` (its first vertex in no polygon of
/// `operand`, whose boxes are `boxes`, or in a hole of one)? A vertex on a boundary counts as inside. Only a matter
/// of speed, as [`some_sample_within_one`]: `false` means "these lie inside it, as a rule".
fn some_sample_starts_outside(
    judged: &MultiPolygon,
    operand: &MultiPolygon,
    boxes: &[Bounds],
) -> bool {
    let step = judged.0.len().div_ceil(SAMPLES).max(1);
    let starts = (judged.0.iter().step_by(step)).filter_map(|p| p.exterior.first());
    let inside = |polygon: &Polygon, v: Point| {
        locate(&closed(&polygon.exterior), v) != Side::Outside
            && (polygon.holes.iter()).all(|hole| locate(&closed(hole), v) != Side::Inside)
    };
    starts.copied().any(|v| {
        !(operand.0.iter().zip(boxes))
            .any(|(polygon, b)| Bounds::at(&v).within(b) && inside(polygon, v))
    })
}

#[cfg(test)]
mod tests {
    use super::copy::as_written;
    use super::grid::apart;
    use super::*;
    use crate::geometry::{open_len, Point};
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

    /// A simple ring is written closed, counter-clockwise, from its lowest-leftmost vertex; not one that the sweep
    /// would write otherwise: a sliver whose float area is 0 (exactly 2^-95, which `connect` drops; its vertex
    /// across from the long edge is also too close to that edge, by the float cross product, 0), or one with a
    /// vertex 2.4e-15 from an edge not its own (which snap rounding may bend through it).
    #[test]
    fn writes_a_ring_as_the_sweep_does_or_not_at_all() {
        let ring = |points: &[[f64; 2]]| -> Vec<Point> {
            points.iter().map(|&[x, y]| Point::new(x, y)).collect()
        };
        // The margin the pipeline gives coordinates of these magnitudes.
        let margin = |magnitude: f64| 2.0 * crate::rounding::clearance(magnitude);
        let counter_clockwise = ring(&[[1.0, 1.0], [0.0, 1.0], [0.0, 0.0], [1.0, 0.0]]);
        assert_eq!(
            as_written(&counter_clockwise, FillRule::Positive, margin(1.0)),
            as_written(&counter_clockwise, FillRule::EvenOdd, margin(1.0))
        );
        // A counter-clockwise ring is empty under the negative rule, a clockwise one under the positive: nothing
        // to copy.
        assert_eq!(
            as_written(&counter_clockwise, FillRule::Negative, margin(1.0)),
            None
        );
        let clockwise: Vec<Point> = counter_clockwise.iter().rev().copied().collect();
        assert_eq!(
            as_written(&clockwise, FillRule::Positive, margin(1.0)),
            None
        );
        assert!(as_written(&clockwise, FillRule::Negative, margin(1.0)).is_some());
        assert_eq!(
            as_written(&counter_clockwise, FillRule::EvenOdd, margin(1.0)),
            Some(ring(&[
                [0.0, 0.0],
                [1.0, 0.0],
                [1.0, 1.0],
                [0.0, 1.0],
                [0.0, 0.0]
            ]))
        );
        let e = f64::powi(2.0, -47);
        let sliver = ring(&[[40.0, 40.0], [41.0 + e, 41.0], [41.0, 41.0 - e]]);
        assert_eq!(as_written(&sliver, FillRule::EvenOdd, 0.0), None);
        let close = ring(&[
            [40.0, 40.0],
            [43.0, 41.0],
            [43.0, 43.0],
            [41.0, 121.0 / 3.0],
            [40.0, 43.0],
        ]);
        assert_eq!(as_written(&close, FillRule::EvenOdd, margin(43.0)), None);
        // The same with the vertex farther off: written.
        let apart = ring(&[
            [40.0, 40.0],
            [43.0, 41.0],
            [43.0, 43.0],
            [41.0, 40.5],
            [40.0, 43.0],
        ]);
        assert!(as_written(&apart, FillRule::EvenOdd, margin(43.0)).is_some());
    }

    /// A box is inside one convex polygon only where, grown by the margin, its corners lie strictly inside a
    /// strictly convex ring without holes whose box is the only one it meets: inside a square either way round; not
    /// against its side, nor in a star's middle (which it winds around twice), an L's arm (not convex), a square
    /// with a hole, or where the boxes of two squares overlap.
    #[test]
    fn tells_boxes_inside_one_convex_polygon() {
        // (Four vertices: `square`'s sides go straight on through 24 more, and a convex ring turns at every vertex.)
        let square = |x: f64, y: f64, side: f64| {
            vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]
        };
        let star = (0..5).map(|i| {
            let angle =
                std::f64::consts::FRAC_PI_2 + (2 * i % 5) as f64 * 0.4 * std::f64::consts::PI;
            [50.0 + 10.0 * angle.cos(), 5.0 + 10.0 * angle.sin()]
        });
        let l = vec![
            [70.0, 0.0],
            [80.0, 0.0],
            [80.0, 5.0],
            [75.0, 5.0],
            [75.0, 10.0],
            [70.0, 10.0],
        ];
        let operand = MultiPolygon::from_coordinates(&[
            vec![square(0.0, 0.0, 10.0)],
            vec![square(20.0, 0.0, 10.0).into_iter().rev().collect()],
            vec![star.collect()],
            vec![l],
            vec![square(90.0, 0.0, 10.0), square(92.0, 2.0, 2.0)],
            vec![square(110.0, 0.0, 10.0)],
            vec![square(118.0, 8.0, 10.0)],
        ]);
        let boxes = crate::input::boxes(&operand);
        let judged = |x0: f64, y0: f64, x1: f64, y1: f64| {
            Bounds::at(&Point::new(x0, y0)).around(&Bounds::at(&Point::new(x1, y1)))
        };
        let cases = [
            (judged(4.0, 4.0, 6.0, 6.0), true),
            (judged(0.0, 4.0, 2.0, 6.0), false),
            (judged(24.0, 4.0, 26.0, 6.0), true),
            (judged(49.0, 4.0, 51.0, 6.0), false),
            (judged(71.0, 1.0, 73.0, 3.0), false),
            (judged(95.0, 5.0, 96.0, 6.0), false),
            (judged(112.0, 2.0, 114.0, 4.0), true),
            (judged(119.0, 9.0, 119.5, 9.5), false),
        ];
        let judged: Vec<Bounds> = cases.iter().map(|&(b, _)| b).collect();
        let margin = 2.0 * crate::rounding::clearance(128.0);
        let expected: Vec<bool> = cases.iter().map(|&(_, inside)| inside).collect();
        assert_eq!(
            inside_one_convex(&operand, &boxes, &judged, FillRule::EvenOdd, margin),
            expected
        );
        // Under the positive rule the clockwise square at x = 20 is empty, under the negative rule the
        // counter-clockwise ones are.
        let only = |keep: [usize; 2]| -> Vec<bool> {
            (0..expected.len()).map(|i| keep.contains(&i)).collect()
        };
        assert_eq!(
            inside_one_convex(&operand, &boxes, &judged, FillRule::Positive, margin),
            only([0, 6])
        );
        assert_eq!(
            inside_one_convex(&operand, &boxes, &judged, FillRule::Negative, margin),
            only([2, 2])
        );
    }

    /// A thousand small boxes inside one convex ring of a thousand vertices: testing each against every edge would be
    /// quadratic, so past the budget the rest are answered "not inside"; the first ones are inside.
    #[test]
    fn stays_linear_with_many_boxes_inside_one_ring_of_many_vertices() {
        let circle: Vec<[f64; 2]> = (0..1000)
            .map(|i| {
                let angle = f64::from(i) * std::f64::consts::TAU / 1000.0;
                [100.0 * angle.cos(), 100.0 * angle.sin()]
            })
            .collect();
        let operand = MultiPolygon::from_coordinates(&[vec![circle]]);
        let boxes = vec![region_of(&operand)];
        let judged: Vec<Bounds> = (0..1000)
            .map(|i| {
                let (x, y) = (f64::from(i % 40) - 20.0, f64::from(i / 40) - 12.0);
                Bounds::at(&Point::new(x, y)).around(&Bounds::at(&Point::new(x + 0.5, y + 0.5)))
            })
            .collect();
        // The margin the pipeline uses, for coordinates up to 100 (the boxes lie far inside the ring anyway).
        let margin = 2.0 * crate::rounding::clearance(100.0);
        let inside = inside_one_convex(&operand, &boxes, &judged, FillRule::EvenOdd, margin);
        let count = inside.iter().filter(|&&i| i).count();
        assert!(count > 0 && count < 100 && inside[0], "{count}");
    }

    /// `apart` against comparing every pair, on boxes of a coarse lattice (many touching at a side or a corner,
    /// some points or segments), where a margin of 0.1 or 0.3 separates some pairs and not others.
    #[test]
    fn tells_boxes_apart_from_all_others_as_comparing_every_pair_does() {
        let mut random = unit(43);
        // Multiples of 1/4 up to 20.
        let mut lattice = || (random() * 80.0).floor() / 4.0;
        let (mut told, mut asked_in_all) = (0, 0);
        for (count, margin) in [(1, 0.1), (2, 0.3), (30, 0.1), (200, 0.1), (200, 0.3)] {
            // (With the box of a polygon without vertices, which meets nothing, among them.)
            let boxes: Vec<Bounds> = (0..count)
                .map(|i| {
                    if i == 1 {
                        return Bounds::EMPTY;
                    }
                    let (x, y) = (lattice(), lattice());
                    let (w, h) = (lattice() / 16.0, lattice() / 16.0);
                    Bounds::at(&Point::new(x, y)).around(&Bounds::at(&Point::new(x + w, y + h)))
                })
                .collect();
            let asked: Vec<bool> = (0..count).map(|i| i % 3 != 2).collect();
            let is_listed = |i: usize| asked[i] || i % 4 != 3;
            let listed: Vec<u32> = (0..count as u32)
                .filter(|&i| is_listed(i as usize))
                .collect();
            let found = apart(&boxes, margin, &asked, &listed);
            for (p, b) in boxes.iter().enumerate() {
                let grown = b.grown(margin);
                let expected = asked[p]
                    && (boxes.iter().enumerate())
                        .all(|(q, c)| q == p || !is_listed(q) || !c.meets(&grown));
                assert_eq!(found[p], expected, "box {p} of {count}: {b:?}");
                (told, asked_in_all) = (
                    told + usize::from(expected),
                    asked_in_all + usize::from(asked[p]),
                );
            }
        }
        // Both answers are given often (98 boxes apart of the 291 asked).
        assert!(
            told > 20 && told + 20 < asked_in_all,
            "{told} of {asked_in_all}"
        );
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
