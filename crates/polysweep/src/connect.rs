//! Connecting the result edges into rings and the rings into polygons (§5).
//!
//! Every result edge is oriented with the result on its left, so rings come out counter-clockwise when they bound
//! a polygon from outside and clockwise when they bound a hole. A ring is walked from edge to edge; where several
//! result edges leave one vertex (two regions touching at a point), the walk takes the first edge clockwise from
//! the way it came in, and whenever it comes back to a vertex already on its path it cuts that loop off as a ring
//! of its own. So no ring touches itself: two squares touching at a corner are two polygons, a hole touching its
//! shell at one point stays a hole.
//!
//! A hole belongs to the polygon of the closest result edge below its leftmost vertex, which the sweep noted when
//! it inserted the hole's lowest edge there (`result_below`): if that edge is on a shell, that shell; if it is on
//! another hole, the shell of that hole. An island inside a hole is a counter-clockwise ring and so a polygon of
//! its own.
//!
//! Departure from the paper: §5 joins edges into chains by their end points in any order, which cannot tell which
//! way to go at a vertex shared by more than two result edges, and does not say how holes find their polygons.
//! The walk above decides both from the orientation of the edges.
//!
//! Not in the paper, which does not round: the vertices are rounded to floats here, and where the sweep saw an edge
//! pass within a few ulps of a vertex and the edge passes through the vertex's rounding cell, the written ring
//! bends the edge through the rounded vertex (snap rounding's hot pixel, see `snap_points` and the robustness
//! page); the result is then swept again.

use crate::events::{InputEdge, NONE};
use crate::exact::{Exact, SweepPoint};
use crate::geometry::{larger, MultiPolygon, Point, Polygon, Ring};
use crate::sweep::ResultEdge;
use crate::validate::Side;
use std::cmp::Ordering;
use std::collections::HashMap;

/// The exact predicates, and the input edges whose lines the result edges lie on.
#[derive(Clone, Copy)]
struct Lines<'a> {
    exact: &'a Exact,
    input: &'a [InputEdge],
}

impl Lines<'_> {
    /// Sign of the cross product of the travel directions of two result edges.
    fn cross(&self, e: &ResultEdge, f: &ResultEdge) -> Ordering {
        let line = |e: &ResultEdge| &self.input[e.segment as usize].line;
        let sign = self.exact.cross_directions(line(e), line(f));
        if e.forward == f.forward {
            sign
        } else {
            sign.reverse()
        }
    }
}

/// Of the edges leaving a vertex, the first clockwise from the reverse of `incoming`.
fn next_edge(
    lines: Lines,
    edges: &[ResultEdge],
    incoming: usize,
    candidates: impl Iterator<Item = usize>,
) -> Option<usize> {
    let back = {
        let mut e = edges[incoming];
        e.forward = !e.forward;
        e
    };
    // Clockwise angle from `back`: right half-plane first, then straight on, then the left half-plane.
    let half = |e: &ResultEdge| match lines.cross(&back, e) {
        Ordering::Less => 0,
        Ordering::Equal => 1,
        Ordering::Greater => 2,
    };
    candidates.min_by(|&a, &b| {
        let (ea, eb) = (&edges[a], &edges[b]);
        // Within a half, `a` first when `b` is clockwise from it.
        half(ea).cmp(&half(eb)).then_with(|| lines.cross(ea, eb))
    })
}

/// Rings as lists of edge indices, one after the other in one vector (rather than a vector each: a result can
/// have tens of thousands of rings).
struct Rings {
    edges: Vec<usize>,
    /// Where each ring's edges begin in `edges`, and where the last one ends.
    starts: Vec<usize>,
}

impl Rings {
    fn push(&mut self, ring: &[usize]) {
        if self.starts.is_empty() {
            self.starts.push(0);
        }
        self.edges.extend_from_slice(ring);
        self.starts.push(self.edges.len());
    }

    fn len(&self) -> usize {
        self.starts.len().saturating_sub(1)
    }

    fn iter(&self) -> impl Iterator<Item = &[usize]> {
        self.starts.windows(2).map(|w| &self.edges[w[0]..w[1]])
    }
}

/// Walks the result edges into simple rings, each as its list of edge indices.
fn walk_rings(lines: Lines, vertex_count: usize, edges: &[ResultEdge]) -> Rings {
    // Edges leaving each vertex, bucketed (counting sort by `from`).
    let mut first_out = vec![0usize; vertex_count + 1];
    for e in edges {
        first_out[e.from as usize + 1] += 1;
    }
    for v in 0..vertex_count {
        first_out[v + 1] += first_out[v];
    }
    let mut outgoing = vec![0usize; edges.len()];
    let mut fill = first_out.clone();
    for (i, e) in edges.iter().enumerate() {
        outgoing[fill[e.from as usize]] = i;
        fill[e.from as usize] += 1;
    }
    // Edges that rounding shrank to a point are no part of any ring.
    let mut used: Vec<bool> = edges.iter().map(|e| e.from == e.to).collect();
    let mut position_on_path = vec![NONE; vertex_count];
    // Every edge is in one ring at most: room for all, so that the vector is not copied as it grows.
    let mut rings = Rings {
        edges: Vec::with_capacity(edges.len()),
        starts: Vec::new(),
    };
    // The path walked from `start`: its vertices and edges (kept from one start to the next, for their room).
    let (mut path_vertices, mut path_edges): (Vec<u32>, Vec<usize>) = (Vec::new(), Vec::new());
    for &start in &outgoing {
        if used[start] {
            continue;
        }
        path_vertices.clear();
        path_vertices.push(edges[start].from);
        path_edges.clear();
        position_on_path[edges[start].from as usize] = 0;
        let mut current = start;
        loop {
            used[current] = true;
            path_edges.push(current);
            let v = edges[current].to;
            let at = position_on_path[v as usize];
            if at != NONE {
                // Back at a vertex of the path: the loop since then is a ring.
                let at = at as usize;
                rings.push(&path_edges[at..]);
                path_edges.truncate(at);
                for &w in &path_vertices[at + 1..] {
                    position_on_path[w as usize] = NONE;
                }
                path_vertices.truncate(at + 1);
                if path_edges.is_empty() {
                    break;
                }
            } else {
                position_on_path[v as usize] = path_vertices.len() as u32;
                path_vertices.push(v);
            }
            let range = first_out[v as usize]..first_out[v as usize + 1];
            let candidates = outgoing[range].iter().copied().filter(|&i| !used[i]);
            match next_edge(lines, edges, current, candidates) {
                Some(next) => current = next,
                // Cannot happen: every vertex has as many result edges in as out. Drop the open path.
                None => break,
            }
        }
        for &w in &path_vertices {
            position_on_path[w as usize] = NONE;
        }
    }
    rings
}

/// Is the sign of `area`, the area of the rounded `ring` as `ring_area` computes it, that of the exact ring's? It
/// is when `area` is larger than rounding and the float sum can change it (here twice as large, for the bound's own
/// rounding): each vertex moved by less than `clearance` of the largest coordinate, d, which changes the area by
/// at most d times the sum of the edges' lengths (plus n·d²); and the shoelace sum, relative to the first vertex,
/// has n terms of at most 2·r² each (r its largest offset from that vertex), each off by 4ε of itself at most, and
/// the sum by nε more.
fn sign_survives_rounding(ring: &[Point], area: f64) -> bool {
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
/// vertex of the result. An edge that passes that close to a crossing point crosses its edges there too, or ends
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
        .filter(|&i| !vertices[i].is_input())
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
/// input is kept) are left out, so that the ring walk's tables are only as large as the result.
fn merge_rounded(vertices: &[SweepPoint], edges: &[ResultEdge]) -> (Vec<u32>, Vec<Point>) {
    // `NONE` for a vertex on no result edge; the others are marked (0) here and numbered below.
    let mut ids: Vec<u32> = vec![NONE; vertices.len()];
    for e in edges {
        (ids[e.from as usize], ids[e.to as usize]) = (0, 0);
    }
    let mut points: Vec<Point> = Vec::with_capacity(edges.len());
    // Rounding is monotone, so the vertices that round to one x are consecutive in sweep order. While they all
    // have that x exactly (input vertices, and crossings on a vertical line or a grid's column), they come in y
    // order, so those that round to one point are consecutive too: each is compared with the one before. Once a
    // crossing whose x is rounded joins the block, exact x and y order no longer agree with the rounded point's,
    // and the block's points go into a map of rounded points. The map is keyed by both coordinates and never
    // cleared, so a large block does not make every later block pay for its size.
    let mut block: Vec<usize> = Vec::new();
    let mut block_has_rounded_x = false;
    // A fixed-seed fast hash: SipHash, std's default, was 5% of the time at 32,768 squares.
    let mut in_crossing_blocks: HashMap<[u64; 2], u32, foldhash::fast::FixedState> =
        HashMap::default();
    let key = |p: [f64; 2]| p.map(|v| (v + 0.0).to_bits()); // -0 as 0
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
        }
    }
    (ids, points)
}

/// The polygon with the smallest exterior that contains `hole`, by exact point-in-ring tests of its vertices.
fn innermost_shell_around(polygons: &[Polygon], hole: &[Point]) -> Option<usize> {
    polygons
        .iter()
        .enumerate()
        .filter(|(_, p)| {
            let side = hole
                .iter()
                .map(|&v| crate::validate::locate(&p.exterior, v))
                .find(|s| *s != Side::Boundary);
            side == Some(Side::Inside)
        })
        .min_by(|(_, p), (_, q)| {
            crate::ring_area(&p.exterior).total_cmp(&crate::ring_area(&q.exterior))
        })
        .map(|(i, _)| i)
}

/// Builds the output polygons from the result edges of a sweep. `below_edge` maps a left event to its result
/// edge; `close_pairs` are the sweep's close calls as (vertex, result edge), to be snapped. Also says whether any
/// edge was bent through a vertex (then the result has to be swept again).
///
/// Rounding is the one inexact step. A vertex moves by at most half an ulp; where several exact vertices round to
/// one point they become one vertex (a pinch, cut by the walk), edges that shrink to nothing are dropped, and so
/// are rings whose rounded area is zero.
pub(crate) fn connect(
    exact: &Exact,
    input: &[InputEdge],
    vertices: &[SweepPoint],
    edges: &mut [ResultEdge],
    below_edge: impl Fn(u32) -> u32,
    close_pairs: &[(u32, u32)],
) -> (MultiPolygon, bool) {
    let (vertex_ids, points) = merge_rounded(vertices, edges);
    // The exact vertices of each edge, before rounding merges some of them.
    let exact_ends: Vec<(u32, u32)> = edges.iter().map(|e| (e.from, e.to)).collect();
    for e in edges.iter_mut() {
        e.from = vertex_ids[e.from as usize];
        e.to = vertex_ids[e.to as usize];
    }
    let snaps = snap_points(input, edges, &vertex_ids, &points, close_pairs);
    let lines = Lines { exact, input };
    let rings = walk_rings(lines, points.len(), edges);
    let mut ring_of_edge = vec![NONE; edges.len()];
    for (r, ring) in rings.iter().enumerate() {
        for &e in ring {
            ring_of_edge[e] = r as u32;
        }
    }
    // Each ring as it is written out: its rounded vertices, closed (the first repeated last). Made once, and read
    // below instead of the edges, which lie scattered in memory.
    let mut written: Vec<Ring> = rings
        .iter()
        .map(|ring| {
            let mut out: Ring = Vec::with_capacity(ring.len() + 1);
            for &e in ring {
                out.push(points[edges[e].from as usize]);
                if !snaps.is_empty() {
                    let from = snaps.partition_point(|&(s, _)| (s as usize) < e);
                    let to = snaps.partition_point(|&(s, _)| (s as usize) <= e);
                    out.extend(snaps[from..to].iter().map(|&(_, p)| p));
                }
            }
            out.push(out[0]);
            out
        })
        .collect();
    // Each ring's edges into and out of its lowest-leftmost vertex, and its orientation there.
    let lexicographic = |a: &Point, b: &Point| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y));
    let leftmost: Vec<(usize, usize)> = (rings.iter().zip(&written))
        .map(|(ring, points)| {
            let k = (0..ring.len())
                .min_by(|&i, &j| lexicographic(&points[i], &points[j]))
                .expect("rings are not empty");
            (ring[(k + ring.len() - 1) % ring.len()], ring[k])
        })
        .collect();
    // Orientation of the rounded ring (its signed area). Where rounding could have flipped it (a ring thin enough),
    // it is checked exactly at the ring's first exact vertex in sweep order (exact vertex ids follow the sweep;
    // rounding can merge a later exact vertex into an earlier one, so the rounded vertices' order is not the exact
    // one): the turn at an extreme vertex of a closed ring is its orientation. A ring whose rounded copy has no
    // area, or the opposite orientation, is a sliver thinner than rounding: it is dropped (`Equal`).
    let turn: Vec<Ordering> = (rings.iter().zip(&written))
        .map(|(ring, rounded)| {
            let area = crate::ring_area(rounded);
            let rounded_turn = area.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
            if sign_survives_rounding(rounded, area) {
                return rounded_turn;
            }
            let k = (0..ring.len())
                .min_by_key(|&k| exact_ends[ring[k]].0)
                .expect("rings are not empty");
            let (incoming, outgoing) = (ring[(k + ring.len() - 1) % ring.len()], ring[k]);
            let exact_turn = lines.cross(&edges[incoming], &edges[outgoing]);
            // Where rounding merged vertices, the two edges need not meet at one exact point (an edge that shrank
            // to nothing was between them, and they can even run back along each other), or the ring can pass
            // straight through: then the turn says nothing and only the rounded orientation tells.
            let meet_exactly = exact_ends[incoming].1 == exact_ends[outgoing].0;
            if !meet_exactly || exact_turn == Ordering::Equal || exact_turn == rounded_turn {
                rounded_turn
            } else {
                Ordering::Equal
            }
        })
        .collect();
    let is_shell = |r: u32| turn[r as usize] == Ordering::Greater;
    // The ring of the result edge below ring `r`'s lowest edge at its leftmost vertex (asked for holes only, so
    // the edge below is looked up only for them).
    let ring_below = |r: u32| {
        let (i, o) = leftmost[r as usize];
        [edges[i].below, edges[o].below]
            .into_iter()
            .filter(|&b| b != NONE)
            .map(&below_edge)
            .filter(|&b| b != NONE) // an edge the sweep stopped before recording
            .map(|b| ring_of_edge[b as usize])
            .find(|&b| b != NONE && b != r)
    };
    let mut polygon_of_ring = vec![NONE; rings.len()];
    let mut polygons: Vec<Polygon> = Vec::with_capacity(rings.len());
    for (r, ring) in rings.iter().enumerate() {
        if is_shell(r as u32) && ring.len() >= 3 {
            polygon_of_ring[r] = polygons.len() as u32;
            polygons.push(Polygon {
                exterior: std::mem::take(&mut written[r]),
                holes: Vec::new(),
            });
        }
    }
    for (r, ring) in rings.iter().enumerate() {
        if turn[r] != Ordering::Less || ring.len() < 3 {
            continue; // a shell, or a ring that rounding flattened
        }
        // Walk down through holes to a shell; at most one step per ring, so this always ends.
        let mut owner = ring_below(r as u32);
        for _ in 0..rings.len() {
            match owner {
                Some(o) if !is_shell(o) => owner = ring_below(o),
                _ => break,
            }
        }
        let hole = std::mem::take(&mut written[r]);
        let polygon = match owner.filter(|&o| is_shell(o) && polygon_of_ring[o as usize] != NONE) {
            Some(shell) => Some(polygon_of_ring[shell as usize] as usize),
            // The edge below was one that rounding shrank to a point: find the shell by position instead.
            None => innermost_shell_around(&polygons, &hole),
        };
        // No shell around a hole happens only where rounding inverted a sliver next to it (docs/robustness.md,
        // known limit); the strict tests check membership, so a hole lost otherwise would not go unnoticed.
        if let Some(p) = polygon {
            polygons[p].holes.push(hole);
        }
    }
    (MultiPolygon(polygons), !snaps.is_empty())
}

/// Snap rounding of the close calls (Hobby's hot pixels): a result edge that passes through the rounding cell of a
/// result vertex it came within a few ulps of is bent through that vertex's rounded point. Returns, for each such
/// edge, the points to insert after its start, in order along it, sorted by edge.
///
/// The cell is the square of half an ulp around the rounded point, and the tests are in floats. They decide no
/// predicate of the sweep, only where the written ring takes a detour of an ulp or less: a bend made or missed by
/// their error is left to the repair sweep that always follows a bend, which is exact.
fn snap_points(
    input: &[InputEdge],
    edges: &[ResultEdge],
    vertex_ids: &[u32],
    points: &[Point],
    close_pairs: &[(u32, u32)],
) -> Vec<(u32, Point)> {
    let mut snaps: Vec<(u32, f64, Point)> = Vec::new();
    for &(v, r) in close_pairs {
        let id = vertex_ids[v as usize];
        if id == NONE {
            continue; // not a vertex of the result
        }
        let e = &edges[r as usize];
        let (p, a, b) = (
            points[id as usize],
            points[e.from as usize],
            points[e.to as usize],
        );
        if p == a || p == b {
            continue;
        }
        let line = &input[e.segment as usize].line;
        let ([dx, dy], cross) = line.float_offset([p.x, p.y]);
        let (hx, hy) = (ulp(p.x) / 2.0, ulp(p.y) / 2.0);
        // A line meets a box when its offset from the centre is at most the box's reach across it.
        if cross.abs() > hx * dy.abs() + hy * dx.abs() {
            continue;
        }
        // Where along the edge, from its start (0) to its end (1).
        let (ex, ey) = (b.x - a.x, b.y - a.y);
        let t = ((p.x - a.x) * ex + (p.y - a.y) * ey) / (ex * ex + ey * ey);
        if t > 0.0 && t < 1.0 {
            snaps.push((r, t, p));
        }
    }
    snaps.sort_by(|x, y| x.0.cmp(&y.0).then(x.1.total_cmp(&y.1)));
    snaps.dedup_by(|x, y| x.0 == y.0 && x.2 == y.2);
    snaps.into_iter().map(|(r, _, p)| (r, p)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Line;

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
        let (ids, points) = merge_rounded(&vertices, &edges);
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
                .filter(|&i| !vertices[i].is_input())
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
