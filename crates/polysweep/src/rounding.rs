//! Rounding the result to floats (not in the paper, which computes in real arithmetic; see the robustness page).
//!
//! The sweep decides everything exactly; only the written rings are rounded. Rounding moves a vertex by at most
//! half an ulp, so it can matter only where a rounded crossing lands within a few ulps of another vertex
//! ([`rounding_may_matter`], which asks for the result to be validated), or where a short edge becomes vertical
//! ([`rounding_made_vertical`]). Distinct exact vertices that round to one point become one vertex
//! ([`merge_rounded`]). Where the rounded result fails validation, it is snap-rounded instead ([`crate::snap_round`]).

use crate::edges::{InputEdge, ResultEdge, NONE};
use crate::exact::SweepPoint;
use crate::geometry::{larger, Point};
use crate::workspace::refill;
use std::collections::HashMap;

/// Is the sign of `area`, the area of the rounded `ring` as `ring_area` computes it, that of the exact ring's? It
/// is when `area` is larger than rounding and the float sum can change it (here twice as large, for the bound's own
/// rounding): each vertex moved by less than `clearance` of the largest coordinate, d, which changes the area by
/// at most d times the sum of the edges' lengths (plus n·d²); and the shoelace sum, relative to the first vertex,
/// has n terms of at most 2·r² each (r its largest offset from that vertex), each off by 4ε of itself at most, and
/// the sum by nε more.
pub(crate) fn sign_survives_rounding(ring: &[Point], area: f64) -> bool {
    let first = ring[0];
    let (mut magnitude, mut reach, mut perimeter) = (0.0f64, 0.0f64, 0.0f64);
    for pair in ring.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        magnitude = larger(magnitude, larger(a.x.abs(), a.y.abs()));
        reach = larger(reach, larger((a.x - first.x).abs(), (a.y - first.y).abs()));
        perimeter += (b.x - a.x).abs() + (b.y - a.y).abs(); // at least the length
    }
    // Not a tolerance: a proven bound on how far rounding and the float sum can move the area. It cannot change a
    // decision, only who makes it: beyond the bound the rounded sign is the exact one, and within it the caller
    // asks the exact turn at the ring's first exact vertex.
    let (n, d) = (ring.len() as f64, clearance(magnitude));
    let rounding = d * perimeter + n * d * d;
    let evaluation = (n + 4.0) * n * (f64::EPSILON / 2.0) * reach * reach;
    area.abs() > 2.0 * (rounding + evaluation)
}

/// How far, in ulps of its coordinates, a rounded crossing point must be from every other vertex for rounding to
/// be harmless: it moved by at most half an ulp, and so did its neighbours.
const ROUNDING_CLEARANCE_ULPS: f64 = 4.0;

/// The distance under which rounding could move points of magnitude `magnitude` across each other.
pub(crate) fn clearance(magnitude: f64) -> f64 {
    ulp(magnitude) * ROUNDING_CLEARANCE_ULPS
}

/// The distance from `v` to the next float away from 0.
fn ulp(v: f64) -> f64 {
    let v = v.abs();
    f64::from_bits(v.to_bits() + 1) - v
}

/// Could rounding have broken the output? Only where a rounded crossing point lands within a few ulps of another
/// vertex of the result (a crossing of a vertical and a horizontal line is not rounded: its coordinates are
/// floats). An edge that passes that close to a crossing point crosses its edges there too, or ends
/// there, so it has a vertex in the cluster as well; far from any cluster, rounding moves nothing across anything.
pub(crate) fn rounding_may_matter(vertices: &[SweepPoint]) -> bool {
    // Sweep order is x order and rounding is monotone, so the vertices within a few ulps of a point in x are a
    // range of the sweep order, found by galloping. A short range is scanned. In a long one (a grid's column of
    // thousands of vertices at one x), vertices of one x come in y order (the sweep's), in runs found once over
    // the whole order. Where the range lies in one run, the vertices nearest in y are the point's two neighbours
    // in it; otherwise each run is searched by halving.
    let coordinate = |j: usize, axis: usize| vertices[j].approx[axis];
    let mut runs: Vec<usize> = Vec::new();
    let ulp = |v: f64| clearance(v.abs());
    (0..vertices.len())
        .filter(|&i| vertices[i].is_rounded())
        .any(|i| {
            let [x, y] = vertices[i].approx;
            let (dx, dy) = (ulp(x), ulp(y));
            let (start, end) = within_in_x(vertices, i, dx);
            let near_in_y = |j: usize| j != i && (coordinate(j, 1) - y).abs() <= dy;
            if end - start <= LONG_RANGE {
                return (start..end).any(near_in_y);
            }
            if runs.is_empty() {
                runs = run_starts(vertices);
            }
            let first_run = runs.partition_point(|&r| r <= start) - 1;
            if runs[first_run + 1] >= end {
                return (i > start && near_in_y(i - 1)) || (i + 1 < end && near_in_y(i + 1));
            }
            runs[first_run..]
                .windows(2)
                .take_while(|run| run[0] < end)
                .any(|run| {
                    let (from, to) = (run[0].max(start), run[1].min(end));
                    let in_run = &vertices[from..to];
                    let below = from + in_run.partition_point(|v| v.approx[1] < y - dy);
                    let above = from + in_run.partition_point(|v| v.approx[1] <= y + dy);
                    (below..above).any(near_in_y)
                })
        })
}

/// Where each run of `vertices` (not empty) of one x in y order begins, a new x or y going down, and then where the
/// last one ends. One pass writes every index and moves on past a run's start only: no branch per vertex, which
/// no predictor could guess.
fn run_starts(vertices: &[SweepPoint]) -> Vec<usize> {
    let mut starts = vec![0; vertices.len() + 1];
    let mut count = 1; // the first vertex begins a run
    for (j, pair) in vertices.windows(2).enumerate() {
        let ([x0, y0], [x1, y1]) = (pair[0].approx, pair[1].approx);
        starts[count] = j + 1;
        count += usize::from((x1 != x0) | (y1 < y0));
    }
    starts[count] = vertices.len();
    starts.truncate(count + 1);
    starts
}

/// The range of `vertices` (in sweep order, so by x) whose x lies within `dx` of vertex `i`'s. It holds `i`; it is
/// found by galloping out from `i` and halving the last step, so that its cost grows with the range, not with the
/// whole order: most crossings' x is theirs alone, and one step each way tells.
fn within_in_x(vertices: &[SweepPoint], i: usize, dx: f64) -> (usize, usize) {
    let x = vertices[i].approx[0];
    let mut step = 1;
    while step <= i && vertices[i - step].approx[0] >= x - dx {
        step *= 2;
    }
    let low = i.saturating_sub(step);
    let start = low + vertices[low..i].partition_point(|v| v.approx[0] < x - dx);
    step = 1;
    while i + step < vertices.len() && vertices[i + step].approx[0] <= x + dx {
        step *= 2;
    }
    let high = (i + step).min(vertices.len());
    let end = i + 1 + vertices[i + 1..high].partition_point(|v| v.approx[0] <= x + dx);
    (start, end)
}

/// Ranges of vertices longer than this are searched run by run rather than scanned (see `rounding_may_matter`).
const LONG_RANGE: usize = 64;

/// Output vertex of each sweep vertex on a result edge: its coordinates rounded to f64, where distinct exact points
/// that round to the same floats become one vertex. Vertices on no result edge (most of them, when little of the
/// input is kept) are left out, so that the ring walk's tables are only as large as the result. Also says whether
/// two of them round to one x, one of them from a crossing whose x is not a float (see [`rounding_made_vertical`]).
/// The output vertices are written into `ids`, by sweep vertex, and their points into `points` (both emptied first).
pub(crate) fn merge_rounded(
    vertices: &[SweepPoint],
    edges: &[ResultEdge],
    ids: &mut Vec<u32>,
    points: &mut Vec<Point>,
) -> bool {
    // `NONE` for a vertex on no result edge; the others are marked (0) here and numbered below.
    refill(ids, vertices.len(), NONE);
    let ids = ids.as_mut_slice(); // (its bounds kept in registers)
    for e in edges {
        (ids[e.from as usize], ids[e.to as usize]) = (0, 0);
    }
    points.clear();
    points.reserve(edges.len());
    // Rounding is monotone, so the vertices that round to one x are consecutive in sweep order. While they all
    // have that x exactly (input vertices, and crossings on a vertical line or a grid's column), they come in y
    // order, so those that round to one point are consecutive too: each is compared with the one before. Once a
    // crossing whose x is rounded joins the block, exact x and y order no longer agree with the rounded point's,
    // and the block's points go into a map of rounded points. The map is keyed by both coordinates and never
    // cleared, so a large block does not make every later block pay for its size.
    let mut block: Vec<usize> = Vec::new();
    let mut block_has_rounded_x = false;
    // A fixed-seed fast hash: SipHash, std's default, was a noticeable part of the time on large grids.
    let mut in_crossing_blocks: HashMap<[u64; 2], u32, foldhash::fast::FixedState> =
        HashMap::default();
    let key = |p: [f64; 2]| p.map(|v| (v + 0.0).to_bits()); // -0 as 0
    let mut x_rounded_onto_another = false;
    for (i, v) in vertices.iter().enumerate() {
        if ids[i] == NONE {
            continue;
        }
        let [x, y] = v.approx;
        if block.last().is_some_and(|&j| vertices[j].approx[0] != x) {
            block.clear();
            block_has_rounded_x = false;
        }
        if !v.is_exact(0) && !block_has_rounded_x {
            block_has_rounded_x = true;
            for &j in &block {
                in_crossing_blocks.insert(key(vertices[j].approx), ids[j]);
            }
        }
        let same = if block_has_rounded_x {
            in_crossing_blocks.get(&key(v.approx)).copied()
        } else {
            // (Two input vertices are distinct floats: only a crossing can round onto its neighbour.)
            (block.last())
                .filter(|&&j| !(v.is_input() && vertices[j].is_input()))
                .filter(|&&j| { vertices[j].approx } == [x, y])
                .map(|&j| ids[j])
        };
        let id = same.unwrap_or_else(|| {
            points.push(Point::new(x, y));
            (points.len() - 1) as u32
        });
        ids[i] = id;
        block.push(i);
        if block_has_rounded_x {
            in_crossing_blocks.insert(key(v.approx), id);
            x_rounded_onto_another |= block.len() > 1;
        }
    }
    x_rounded_onto_another
}

/// Did rounding make a result edge vertical? The sweep meets the points of one x in y order, so an edge narrower
/// than an ulp leaves S before the points above its right end at that x are met (or enters it after those below
/// its left end): the vertices it passes within an ulp of there are no close calls of the sweep. Once vertical, it
/// can run along their edges, or through them. Exactly, such an edge is not vertical: it lies on a line that is not.
///
/// Its ends round to one x, and one of them is a crossing whose x is not a float: asked only where
/// [`merge_rounded`] found two such vertices (on Table 1's data, never).
pub(crate) fn rounding_made_vertical(
    input: &[InputEdge],
    edges: &[ResultEdge],
    points: &[Point],
) -> bool {
    edges.iter().any(|e| {
        e.from != e.to
            && points[e.from as usize].x == points[e.to as usize].x
            && !input[e.segment as usize].line.is_vertical()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{Exact, Line};
    use crate::geometry::Ring;
    use std::cmp::Ordering;

    #[test]
    fn runs_of_one_x_in_y_order() {
        let points = [
            [0.0, 0.0],
            [0.0, 1.0],
            [0.0, 0.5],
            [1.0, 0.0],
            [1.0, 2.0],
            [2.0, 2.0],
        ];
        let vertices: Vec<SweepPoint> = points.iter().map(|&p| SweepPoint::input(p)).collect();
        assert_eq!(run_starts(&vertices), [0, 2, 3, 5, 6]);
        assert_eq!(run_starts(&vertices[..1]), [0, 1]);
    }

    #[test]
    fn exact_points_that_round_to_one_point_become_one_vertex() {
        let mut exact = Exact::default();
        let line = |a: [f64; 2], b: [f64; 2]| Line { a, b };
        // On the column x = 1: a crossing with a slanted line, whose y (1 + 2^-40) / 3 is no float, and the input
        // vertex at its rounding; they come next to each other in sweep order.
        let on_column = exact.crossing(
            &line([1.0, -5.0], [1.0, 5.0]),
            &line([0.0, 0.0], [3.0, 1.0 + 2f64.powi(-40)]),
        );
        // Off any column: the crossing (6/5, 2/5) of two slanted lines, whose x rounds down, and the input vertex
        // at its rounding; an input vertex above that one comes between them in sweep order.
        let off_column =
            exact.crossing(&line([0.0, 0.0], [3.0, 1.0]), &line([0.0, 1.0], [2.0, 0.0]));
        let [x, y] = off_column.approx;
        let mut vertices = vec![
            SweepPoint::input([1.0, 0.0]),
            SweepPoint::input(on_column.approx),
            on_column,
            SweepPoint::input([1.0, 2.0]),
            SweepPoint::input([x, y]),
            SweepPoint::input([x, y + 1.0]),
            off_column,
        ];
        vertices.sort_by(|p, q| exact.cmp_points(p, q));
        let position = |p: &SweepPoint| {
            (vertices.iter())
                .position(|v| {
                    exact.cmp_points(v, p) == Ordering::Equal && v.is_input() == p.is_input()
                })
                .unwrap()
        };
        let pairs = [
            (
                position(&on_column),
                position(&SweepPoint::input(on_column.approx)),
            ),
            (position(&off_column), position(&SweepPoint::input([x, y]))),
        ];
        assert_eq!(
            pairs[1].0,
            pairs[1].1 + 2,
            "one vertex comes between the second pair"
        );
        let edges: Vec<ResultEdge> = (0..vertices.len() - 1)
            .map(|i| ResultEdge {
                from: i as u32,
                to: i as u32 + 1,
                segment: 0,
                forward: true,
                below: NONE,
            })
            .collect();
        let (mut ids, mut points) = (Vec::new(), Vec::new());
        merge_rounded(&vertices, &edges, &mut ids, &mut points);
        for (a, b) in pairs {
            assert_eq!(ids[a], ids[b]);
        }
        assert_eq!(points.len(), vertices.len() - 2);
    }

    #[test]
    fn an_area_is_trusted_only_beyond_what_rounding_can_change() {
        let ring = |points: &[[f64; 2]]| -> Ring {
            (points.iter().chain(&points[..1]))
                .map(|&[x, y]| Point::new(x, y))
                .collect()
        };
        let sure = |r: &Ring| sign_survives_rounding(r, crate::ring_area(r));
        // Far from the origin, where an ulp is 2^-45: a unit square, and triangles of height 1, 2^-20 and 2^-44 on a
        // base of 1, which rounding by an ulp or two moves by about 2^-45 of area per unit of perimeter.
        let (x, y) = (200.0, 100.0);
        assert!(sure(&ring(&[
            [x, y],
            [x + 1.0, y],
            [x + 1.0, y + 1.0],
            [x, y + 1.0]
        ])));
        for (height, expected) in [(1.0, true), (2f64.powi(-20), true), (2f64.powi(-44), false)] {
            for points in [
                [[x, y], [x + 1.0, y], [x + 0.5, y + height]],
                [[x, y], [x + 0.5, y + height], [x + 1.0, y]],
            ] {
                assert_eq!(sure(&ring(&points)), expected, "height {height}");
            }
        }
    }

    #[test]
    fn galloping_finds_the_range_within_dx_that_halving_the_whole_order_finds() {
        let mut random = crate::test_random::unit(0x9e37_79b9_7f4a_7c15);
        for trial in 0..200 {
            // Runs of one x (a grid's columns), lone x, and x a few ulps apart, at both ends too.
            let mut xs: Vec<f64> = (0..1 + (random() * 300.0) as usize)
                .map(|_| match (random() * 3.0) as u32 {
                    0 => (random() * 4.0).floor(),
                    1 => f64::from_bits(2.0f64.to_bits() + (random() * 8.0) as u64),
                    _ => random() * 4.0,
                })
                .collect();
            xs.sort_by(f64::total_cmp);
            let vertices: Vec<SweepPoint> =
                xs.iter().map(|&x| SweepPoint::input([x, 0.0])).collect();
            for i in 0..vertices.len() {
                let dx = [0.0, clearance(xs[i]), random() * 0.5][trial % 3];
                let halving = (
                    xs.partition_point(|&u| u < xs[i] - dx),
                    xs.partition_point(|&u| u <= xs[i] + dx),
                );
                assert_eq!(
                    within_in_x(&vertices, i, dx),
                    halving,
                    "trial {trial}, vertex {i}"
                );
            }
        }
    }

    #[test]
    fn rounding_check_finds_exactly_the_points_within_a_few_ulps_of_a_crossing() {
        // Columns of input vertices (a grid's, longer than `LONG_RANGE`), crossings on the columns and near them,
        // and input vertices put a few ulps from some crossings: the search must agree with comparing every pair.
        let mut random = crate::test_random::unit(0x2545_f491_4f6c_dd1d);
        let mut outcomes = [0; 2];
        for trial in 0..400 {
            let mut exact = Exact::default();
            let columns = [1.5, 2.0, 3.25];
            let mut vertices: Vec<SweepPoint> = Vec::new();
            for &x in &columns {
                for k in 0..100 {
                    vertices.push(SweepPoint::input([x, k as f64 * 0.05]));
                }
            }
            for _ in 0..20 {
                let x = columns[(random() * 3.0) as usize];
                let slanted = Line {
                    a: [x - random(), random() * 5.0],
                    b: [x + random(), random() * 5.0],
                };
                let near_column = Line {
                    a: [x + (random() - 0.5) * 1e-3, -1.0],
                    b: [x + (random() - 0.5) * 1e-3, 6.0],
                };
                let column = Line {
                    a: [x, -1.0],
                    b: [x, 6.0],
                };
                let crossing = exact.crossing(
                    &slanted,
                    if random() < 0.5 {
                        &column
                    } else {
                        &near_column
                    },
                );
                vertices.push(crossing);
                if trial % 2 == 0 && random() < 0.1 {
                    // An input vertex a few ulps away in each coordinate (some within the clearance, some not).
                    let nudge = |v: f64| {
                        let steps = (random() * 12.0) as i64 - 6;
                        f64::from_bits((v.to_bits() as i64 + steps) as u64)
                    };
                    vertices.push(SweepPoint::input(crossing.approx.map(nudge)));
                }
            }
            vertices.sort_by(|p, q| exact.cmp_points(p, q));
            vertices.dedup_by(|p, q| exact.cmp_points(p, q) == Ordering::Equal);
            let every_pair = (0..vertices.len())
                .filter(|&i| vertices[i].is_rounded())
                .any(|i| {
                    let [x, y] = vertices[i].approx;
                    (0..vertices.len()).any(|j| {
                        let [u, v] = vertices[j].approx;
                        j != i
                            && (u - x).abs() <= clearance(x.abs())
                            && (v - y).abs() <= clearance(y.abs())
                    })
                });
            assert_eq!(rounding_may_matter(&vertices), every_pair, "trial {trial}");
            outcomes[usize::from(every_pair)] += 1;
        }
        assert!(outcomes[0] > 50 && outcomes[1] > 50, "{outcomes:?}");
    }
}
