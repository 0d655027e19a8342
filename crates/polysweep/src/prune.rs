//! Polygons that lie wholly inside or outside the other operand, away from its boundary (not in the paper).
//!
//! Where no edge of an operand passes, its winding number cannot change: a clipping polygon whose box lies in such
//! a place and outside the subject cannot change an intersection or a difference, and one inside it cannot change
//! a union, so it is left out of the sweep (see `overlay_pair`). This is what makes clipping a coastline
//! with a grid of tiles cost little more than the tiles that meet the coast: at land × 32,768 squares, most
//! squares are out at sea. Of those inside, an intersection copies to its result the ones it can tell are their
//! own part of it, simple rings apart from the other tiles (see [`copied_whole`]): at 32,768 squares, 8,510 of
//! them, and 34,040 edges fewer to sweep.
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
//! told exactly by the corners of the box). At land × 3,895 squares these are the 7,768 edges of islands inside
//! the squares. It stays exact together with leaving out clipping polygons inside (union) or outside (difference)
//! the subject. Each polygon left out lies in a grown box that no edge of the other operand passes through. Where a
//! subject polygon's box and a clipping polygon's box overlap, neither box lies inside the other (it would hold
//! the other polygon's edges), so part of each lies outside the other, where that other polygon winds around
//! nothing; having no edge there, it winds around nothing anywhere in the box. So where the boxes overlap, the
//! polygons left out wind around no point, and elsewhere only one operand lost a polygon, the one whose winding
//! number is known there from the other.
//!
//! Exact means here that the exact result, before it is rounded to floats, is the same: all of this, and the
//! pruning by boxes, can change the rounding step elsewhere in the result. Whether any crossing was made at all,
//! and which vertices came within a few ulps of which edges, are asked of the edges swept (see `sweep_once` and
//! [`crate::connect`]), so a polygon left out (a self-crossing one, say) can switch the snapping of a close call
//! far from it on or off, which moves a result edge by about an ulp. Either way the rounded result is valid (see
//! the robustness page); only its last bits depend on what was swept.

use crate::exact::Line;
use crate::geometry::{
    next_around, open_len, orient, ring_area, MultiPolygon, Point, Polygon, Ring,
};
use crate::input::{running_sums, Bounds, Grid};
use crate::validate::{convex_turn, lowest_leftmost, simple_ring_turn};
use std::borrow::Cow;
use std::cmp::Ordering;

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
            let mut counted = [[usize::MAX; 2]; 2];
            for &b in ring {
                let [cb, rb] = cell(b);
                let range = [[ca.min(cb), ca.max(cb)], [ra.min(rb), ra.max(rb)]];
                // (Most edges are short: one after another in one cell, which is counted once.)
                if counted != range {
                    grid.count_range(&mut touches, range);
                    counted = range;
                }
                let [[_, c1], [r0, r1]] = range;
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

/// The most vertices of a clipping polygon that an intersection copies whole (see [`copied_whole`]): its ring is
/// checked against itself pair of edges by pair of edges.
const MAX_VERTICES_TO_COPY: usize = 32;

/// The clipping polygons that an intersection copies to its result as they are, instead of sweeping them, and
/// their copies as result polygons. Copied is a polygon that is one simple ring of a few vertices, that `inside`
/// says lies wholly inside the subject (`Some(true)`, judged on its box grown by `margin`), and whose box is farther
/// than `margin` from every other clipping polygon's box (`boxes`). There the clipping operand is that ring alone
/// and the subject is everywhere, so the ring is its own part of the intersection. The rest of the result lies
/// within the other clipping polygons' boxes, and rounding moves it by less than `margin`: it cannot meet the
/// copies, nor be snapped to them (see [`crate::connect`]). (Polygons wholly outside the subject, `Some(false)`,
/// are apart from the copies without a look: their grown boxes lie outside the subject, the copies' inside it.)
pub(crate) fn copied_whole(
    clipping: &MultiPolygon,
    boxes: &[Bounds],
    inside: &[Option<bool>],
    margin: f64,
) -> (Vec<bool>, Vec<Polygon>) {
    let candidates: Vec<bool> = (clipping.0.iter().enumerate())
        .map(|(p, polygon)| {
            polygon.holes.is_empty()
                && open_len(&polygon.exterior) <= MAX_VERTICES_TO_COPY
                && inside[p] == Some(true)
        })
        .collect();
    let mut copied = vec![false; clipping.0.len()];
    if !candidates.contains(&true) {
        return (copied, Vec::new());
    }
    let listed: Vec<u32> = (0..inside.len() as u32)
        .filter(|&p| inside[p as usize] != Some(false))
        .collect();
    let apart = apart(boxes, margin, &candidates, &listed);
    let mut polygons = Vec::with_capacity(apart.iter().filter(|&&a| a).count());
    for (p, polygon) in clipping.0.iter().enumerate().filter(|&(p, _)| apart[p]) {
        if let Some(ring) = as_written(&polygon.exterior, margin) {
            copied[p] = true;
            polygons.push(Polygon::new(ring, Vec::new()));
        }
    }
    (copied, polygons)
}

/// `ring` as the sweep writes a simple ring: closed, counter-clockwise, from its lowest-leftmost vertex (where the
/// walk of [`crate::connect`] begins). `None` if it is not simple, or where the sweep would write it otherwise:
/// where its float area, by which `connect` tells a ring's orientation, has not the sign of its exact turn (a
/// sliver, which `connect` drops), or where a vertex lies within `margin` of an edge not its own (an edge that
/// `connect` could bend through the vertex, should the result be rounded anywhere).
fn as_written(ring: &[Point], margin: f64) -> Option<Ring> {
    let (n, closed) = (open_len(ring), closed(ring));
    let turn = simple_ring_turn(&closed)?;
    if ring_area(&closed).partial_cmp(&0.0) != Some(turn) || vertex_near_an_edge(&closed, margin) {
        return None;
    }
    // (A simple ring passes once through each vertex: its lowest-leftmost one is the same either way round.)
    let (open, first) = (&closed[..n], lowest_leftmost(&closed[..n]));
    let mut written = Vec::with_capacity(n + 1);
    if turn == Ordering::Greater {
        written.extend_from_slice(&open[first..]);
        written.extend_from_slice(&open[..first]);
    } else {
        written.extend(open[..=first].iter().rev());
        written.extend(open[first + 1..].iter().rev());
    }
    written.push(open[first]);
    Some(written)
}

/// `ring` closed: itself if it is (its first point repeated last), else a closed copy.
fn closed(ring: &[Point]) -> Cow<'_, [Point]> {
    if ring.len() > open_len(ring) {
        Cow::Borrowed(ring)
    } else {
        Cow::Owned(ring.iter().chain(ring.first()).copied().collect())
    }
}

/// Does a vertex of closed `ring` lie within about `margin` of one of its edges that does not end there? Asked in
/// floats, of twice `margin` and of the edge's box grown by as much. Not a tolerance that decides the result: it
/// only chooses between copying the ring and sweeping it, and it errs towards sweeping. Twice `margin` is 16 ulps
/// of the input's largest magnitude, where the sweep's close calls reach 4 and the float cross products (this one
/// and `connect`'s) err by under 5 each: a ring the sweep could bend through its own vertex is never copied.
fn vertex_near_an_edge(ring: &[Point], margin: f64) -> bool {
    let n = ring.len() - 1;
    let near = 2.0 * margin;
    (0..n).any(|e| {
        let (a, b) = (ring[e], ring[e + 1]);
        let around = Bounds::at(&a).around(&Bounds::at(&b)).grown(near);
        let line = Line {
            a: [a.x, a.y],
            b: [b.x, b.y],
        };
        let next = next_around(e, n);
        (0..n).filter(|&v| v != e && v != next).any(|v| {
            Bounds::at(&ring[v]).meets(&around) && line.float_within([ring[v].x, ring[v].y], near)
        })
    })
}

/// Cells per box, on average, beyond which a [`BoxIndex`] is not made: the grid is then too coarse for the boxes.
const CELLS_PER_BOX: usize = 16;
/// Boxes looked at for one box beyond which [`apart`] and [`inside_one_convex`] give up on it: it shares its cells
/// with too many.
const MAX_LOOKED_AT: usize = 64;

/// Boxes listed in the cells of a grid that each touches once grown by a margin, so that every box within the
/// margin of a listed box shares a cell with it: which boxes may meet a box is read from its cells.
struct BoxIndex {
    grid: Grid,
    /// The boxes of each cell, counting-sorted by cell: `starts[cell]..starts[cell + 1]` of `members`.
    starts: Vec<usize>,
    members: Vec<u32>,
}

impl BoxIndex {
    /// The boxes of `boxes` that `listed` names (by index, in ascending order, which each cell's list keeps), each
    /// grown by `margin`; `None` where they would touch too many cells (see [`CELLS_PER_BOX`]), so that making it
    /// stays linear in the boxes.
    fn new(boxes: &[Bounds], listed: &[u32], margin: f64) -> Option<Self> {
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
        // (Plain loops over each range's rows and columns: as chained iterators they took three times the
        // instructions.)
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
    fn all_near(&self, b: &Bounds, mut f: impl FnMut(usize) -> bool) -> bool {
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

/// Which of the polygons whose boxes are `judged` lie inside one convex polygon of `operand` (whose boxes are
/// `boxes`), away from its edges and from the other polygons: their box grown by `margin` has its corners strictly
/// inside that polygon, a strictly convex ring without holes, and meets no other polygon's box. Throughout the grown
/// box, then, no edge of `operand` passes and its winding number is that ring's, ±1: inside under either fill rule.
/// A union or a difference leaves such polygons out (see `overlay_pair`). Where a box's cells hold too many others
/// (see [`BoxIndex`]), or past a budget of orientation tests linear in the vertices and polygons, the answer is "not
/// inside": the pass stays linear.
pub(crate) fn inside_one_convex(
    operand: &MultiPolygon,
    boxes: &[Bounds],
    judged: &[Bounds],
    margin: f64,
) -> Vec<bool> {
    let mut inside = vec![false; judged.len()];
    let all: Vec<u32> = (0..boxes.len() as u32).collect();
    let Some(index) = BoxIndex::new(boxes, &all, margin) else {
        return inside;
    };
    // Each polygon's turn, if it is a strictly convex ring without holes, worked out when first asked.
    let mut turns: Vec<Option<Option<Ordering>>> = vec![None; boxes.len()];
    let mut orient_budget = 16 * (operand.vertex_count() + judged.len());
    for (j, b) in judged.iter().enumerate() {
        let grown = b.grown(margin);
        let mut only = None;
        let alone = index.all_near(&grown, |q| {
            // (A second box that meets it ends the look.)
            let meets = boxes[q].meets(&grown) && only != Some(q);
            if meets && only.is_none() {
                only = Some(q);
                return true;
            }
            !meets
        });
        let Some(q) = only.filter(|_| alone) else {
            continue;
        };
        let polygon = &operand.0[q];
        let turn = *turns[q].get_or_insert_with(|| {
            (polygon.holes.is_empty())
                .then(|| convex_turn(&closed(&polygon.exterior)))
                .flatten()
        });
        let Some(turn) = turn else {
            continue;
        };
        let ring = &polygon.exterior;
        let n = open_len(ring);
        // Many polygons inside one convex ring of many vertices would make this quadratic: past a few orientation
        // tests per vertex of both operands, the rest are not left out.
        if orient_budget < 4 * n {
            break;
        }
        orient_budget -= 4 * n;
        inside[j] = grown
            .corners()
            .iter()
            .all(|&c| (0..n).all(|i| orient(ring[i], ring[next_around(i, n)], c) == turn));
    }
    inside
}

/// Which of the boxes that `asked` names are farther than `margin` from every other box of `boxes` that `listed`
/// names by index, in ascending order (it names the asked ones too). Where the boxes touch too many cells of a
/// [`BoxIndex`], or a box's cells hold too many others, the answer is "not apart": the pass stays linear in the
/// boxes.
fn apart(boxes: &[Bounds], margin: f64, asked: &[bool], listed: &[u32]) -> Vec<bool> {
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

    /// A simple ring is written closed, counter-clockwise, from its lowest-leftmost vertex; not one that the sweep
    /// would write otherwise: a sliver whose float area is 0 (exactly 2^-95, which `connect` drops; its vertex
    /// across from the long edge is also too close to that edge, by the float cross product, 0), or one with a
    /// vertex 2.4e-15 from an edge not its own (which `connect` may bend through it).
    #[test]
    fn writes_a_ring_as_the_sweep_does_or_not_at_all() {
        let ring = |points: &[[f64; 2]]| -> Vec<Point> {
            points.iter().map(|&[x, y]| Point::new(x, y)).collect()
        };
        // The margin `overlay_pair` gives coordinates of these magnitudes.
        let margin = |magnitude: f64| 2.0 * crate::rounding::clearance(magnitude);
        let clockwise = ring(&[[1.0, 1.0], [0.0, 1.0], [0.0, 0.0], [1.0, 0.0]]);
        assert_eq!(
            as_written(&clockwise, margin(1.0)),
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
        assert_eq!(as_written(&sliver, 0.0), None);
        let close = ring(&[
            [40.0, 40.0],
            [43.0, 41.0],
            [43.0, 43.0],
            [41.0, 121.0 / 3.0],
            [40.0, 43.0],
        ]);
        assert_eq!(as_written(&close, margin(43.0)), None);
        // The same with the vertex farther off: written.
        let apart = ring(&[
            [40.0, 40.0],
            [43.0, 41.0],
            [43.0, 43.0],
            [41.0, 40.5],
            [40.0, 43.0],
        ]);
        assert!(as_written(&apart, margin(43.0)).is_some());
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
        let boxes: Vec<Bounds> = (operand.0.iter())
            .map(|p| {
                p.rings()
                    .flatten()
                    .fold(Bounds::EMPTY, |b, q| b.around(&Bounds::at(q)))
            })
            .collect();
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
            inside_one_convex(&operand, &boxes, &judged, margin),
            expected
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
        // The margin `overlay_pair` uses, for coordinates up to 100 (the boxes lie far inside the ring anyway).
        let margin = 2.0 * crate::rounding::clearance(100.0);
        let inside = inside_one_convex(&operand, &boxes, &judged, margin);
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
