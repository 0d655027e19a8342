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
//! Not in the paper, which does not round: the vertices are rounded to floats first, merged where they round to one
//! point and with edges bent through the vertices they came within a few ulps of (see [`crate::rounding`]).

use crate::edges::{InputEdge, ResultEdge, NONE};
use crate::exact::{Exact, SweepPoint};
use crate::geometry::{ring_area, MultiPolygon, Point, Polygon, Ring};
use crate::rounding::{merge_rounded, rounding_made_vertical, sign_survives_rounding};
use crate::validate::Side;
use crate::workspace::{bytes_of, refill};
use std::cmp::Ordering;

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
    // Clockwise angle from `back`: right half-plane first, then straight on, then the left half-plane, then back.
    // (Collinear edges' lines all point the same way, left to right in sweep order: two edges along one line go the
    // same way when both run along it or both against it.)
    let half = |e: &ResultEdge| match lines.cross(&back, e) {
        Ordering::Less => 0,
        Ordering::Equal if e.forward != back.forward => 1,
        Ordering::Greater => 2,
        // Straight back where the walk came from: last, the way out of a dangling end. (Only the arrangement's
        // walks have both half-edges of an edge, see `arrangement`; a Boolean result never does.)
        Ordering::Equal => 3,
    };
    candidates.min_by(|&a, &b| {
        let (ea, eb) = (&edges[a], &edges[b]);
        // Within a half, `a` first when `b` is clockwise from it.
        half(ea).cmp(&half(eb)).then_with(|| lines.cross(ea, eb))
    })
}

/// The working tables of [`connect`], kept from one operation to the next with the sweep's vectors (see
/// [`crate::workspace`]): they are as long as the result, and fresh memory for them cost a page fault per 4 KB page
/// at every operation, a tenth of the time of a dense arrangement's intersection. What they hold is overwritten.
/// Indices here are `u32`, as the sweep's are: these tables can be millions of edges long.
#[derive(Default)]
pub(crate) struct ConnectTables {
    /// Each sweep vertex's output vertex, and the output vertices' points (see [`merge_rounded`]).
    vertex_ids: Vec<u32>,
    points: Vec<Point>,
    /// The exact vertices of each result edge, before rounding merges some of them.
    exact_ends: Vec<(u32, u32)>,
    walk: Walk,
    rings: Rings,
    /// Each ring as it is written out, its orientation, and its polygon.
    written: Vec<Ring>,
    turn: Vec<Ordering>,
    polygon_of_ring: Vec<u32>,
    /// Each edge's ring, and each ring's edges into and out of its lowest-leftmost vertex (where there are holes).
    ring_of_edge: Vec<u32>,
    leftmost: Vec<[u32; 2]>,
}

impl ConnectTables {
    /// The bytes they hold (see [`crate::workspace`]).
    pub fn bytes(&self) -> usize {
        let walk = &self.walk;
        bytes_of(&self.vertex_ids)
            + bytes_of(&self.points)
            + bytes_of(&self.exact_ends)
            + bytes_of(&walk.first_out)
            + bytes_of(&walk.outgoing)
            + bytes_of(&walk.used)
            + bytes_of(&walk.position_on_path)
            + bytes_of(&walk.path_vertices)
            + bytes_of(&walk.path_edges)
            + bytes_of(&self.rings.edges)
            + bytes_of(&self.rings.starts)
            + bytes_of(&self.written)
            + bytes_of(&self.turn)
            + bytes_of(&self.polygon_of_ring)
            + bytes_of(&self.ring_of_edge)
            + bytes_of(&self.leftmost)
    }
}

/// The ring walk's tables (see [`walk_rings`]).
#[derive(Default)]
struct Walk {
    /// Where each vertex's outgoing edges begin in `outgoing`.
    first_out: Vec<u32>,
    outgoing: Vec<u32>,
    used: Vec<bool>,
    /// Each vertex's place on the path being walked, or `NONE`.
    position_on_path: Vec<u32>,
    /// The path walked from a start: its vertices and edges.
    path_vertices: Vec<u32>,
    path_edges: Vec<u32>,
}

/// Rings as lists of edge indices, one after the other in one vector (rather than a vector each: a result can
/// have tens of thousands of rings).
#[derive(Default)]
struct Rings {
    edges: Vec<u32>,
    /// Where each ring's edges begin in `edges`, and where the last one ends.
    starts: Vec<u32>,
}

impl Rings {
    fn clear(&mut self) {
        self.edges.clear();
        self.starts.clear();
    }

    fn push(&mut self, ring: &[u32]) {
        if self.starts.is_empty() {
            self.starts.push(0);
        }
        self.edges.extend_from_slice(ring);
        self.starts.push(self.edges.len() as u32);
    }

    fn len(&self) -> usize {
        self.starts.len().saturating_sub(1)
    }

    fn ring(&self, r: usize) -> &[u32] {
        &self.edges[self.starts[r] as usize..self.starts[r + 1] as usize]
    }

    fn iter(&self) -> impl Iterator<Item = &[u32]> {
        (0..self.len()).map(|r| self.ring(r))
    }
}

/// Walks the result edges into simple rings, each as its list of edge indices, written into `rings`; with `class`
/// (one per edge, or none), each ring of edges of one class.
fn walk_rings(
    lines: Lines,
    vertex_count: usize,
    edges: &[ResultEdge],
    class: &[u32],
    walk: &mut Walk,
    rings: &mut Rings,
) {
    let Walk {
        first_out,
        outgoing,
        used,
        position_on_path,
        path_vertices,
        path_edges,
    } = walk;
    // Edges leaving each vertex, bucketed (counting sort by `from`): each vertex's edges are filled in from the
    // end of its range, which leaves `first_out` at the range's beginning.
    refill(first_out, vertex_count + 1, 0);
    for e in edges {
        first_out[e.from as usize] += 1;
    }
    for v in 0..vertex_count {
        first_out[v + 1] += first_out[v];
    }
    refill(outgoing, edges.len(), 0);
    for (i, e) in edges.iter().enumerate().rev() {
        let slot = &mut first_out[e.from as usize];
        *slot -= 1;
        outgoing[*slot as usize] = i as u32;
    }
    // Edges that rounding shrank to a point are no part of any ring.
    used.clear();
    used.extend(edges.iter().map(|e| e.from == e.to));
    refill(position_on_path, vertex_count, NONE);
    // Every edge is in one ring at most: room for all, so that the vector is not copied as it grows.
    rings.clear();
    rings.edges.reserve(edges.len());
    // (As slices, whose bounds stay in registers: through the vectors, the walk read them again at every step.)
    let (first_out, outgoing) = (first_out.as_slice(), outgoing.as_slice());
    let (used, position_on_path) = (used.as_mut_slice(), position_on_path.as_mut_slice());
    for &start in outgoing {
        let start = start as usize;
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
            path_edges.push(current as u32);
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
            let range = first_out[v as usize] as usize..first_out[v as usize + 1] as usize;
            let same_class = |i: usize| class.is_empty() || class[i] == class[current];
            let candidates = (outgoing[range].iter().map(|&i| i as usize))
                .filter(|&i| !used[i] && same_class(i));
            match next_edge(lines, edges, current, candidates) {
                Some(next) => current = next,
                // Cannot happen: every vertex has as many result edges in as out. Drop the open path.
                None => break,
            }
        }
        for &w in path_vertices.iter() {
            position_on_path[w as usize] = NONE;
        }
    }
}

/// The polygon with the smallest exterior that contains `hole`, by exact point-in-ring tests of its vertices, among
/// those `candidate` accepts.
fn innermost_shell_around(
    polygons: &[Polygon],
    hole: &[Point],
    candidate: impl Fn(usize) -> bool,
) -> Option<usize> {
    polygons
        .iter()
        .enumerate()
        .filter(|&(i, p)| {
            if !candidate(i) {
                return false;
            }
            let side = hole
                .iter()
                .map(|&v| crate::validate::locate(&p.exterior, v))
                .find(|s| *s != Side::Boundary);
            side == Some(Side::Inside)
        })
        .min_by(|(_, p), (_, q)| ring_area(&p.exterior).total_cmp(&ring_area(&q.exterior)))
        .map(|(i, _)| i)
}

/// Builds the output polygons from the result edges of a sweep. `below_edge` maps a left event to its result
/// edge. Also says whether rounding made an edge vertical (see [`rounding_made_vertical`]).
///
/// Rounding is the one inexact step. A vertex moves by at most half an ulp; where several exact vertices round to
/// one point they become one vertex (a pinch, cut by the walk), edges that shrink to nothing are dropped, and so
/// are rings whose rounded area is zero. `tables` is working memory.
pub(crate) fn connect(
    exact: &Exact,
    input: &[InputEdge],
    vertices: &[SweepPoint],
    edges: &mut [ResultEdge],
    below_edge: impl Fn(u32) -> u32,
    tables: &mut ConnectTables,
) -> (MultiPolygon, bool) {
    let (result, _, made_vertical) =
        connect_classes(exact, input, vertices, edges, below_edge, &[], tables);
    (result, made_vertical)
}

/// [`connect`] where every edge has a class (`class`, one per edge; empty: all one class): rings are walked
/// along edges of one class, holes join polygons of their class, and the class of each polygon is returned too.
pub(crate) fn connect_classes(
    exact: &Exact,
    input: &[InputEdge],
    vertices: &[SweepPoint],
    edges: &mut [ResultEdge],
    below_edge: impl Fn(u32) -> u32,
    class: &[u32],
    tables: &mut ConnectTables,
) -> (MultiPolygon, Vec<u32>, bool) {
    let ConnectTables {
        vertex_ids,
        points,
        exact_ends,
        walk,
        rings,
        written,
        turn,
        polygon_of_ring,
        ring_of_edge,
        leftmost,
    } = tables;
    let x_rounded_onto_another = merge_rounded(vertices, edges, vertex_ids, points);
    exact_ends.clear();
    exact_ends.extend(edges.iter().map(|e| (e.from, e.to)));
    for e in edges.iter_mut() {
        e.from = vertex_ids[e.from as usize];
        e.to = vertex_ids[e.to as usize];
    }
    let lines = Lines { exact, input };
    walk_rings(lines, points.len(), edges, class, walk, rings);
    let rings = &*rings;
    let class_of_ring = |ring: &[u32]| class.get(ring[0] as usize).copied().unwrap_or(0);
    // Each ring as it is written out: its rounded vertices, closed (the first repeated last). Made once, and read
    // below instead of the edges, which lie scattered in memory.
    written.clear();
    written.extend(rings.iter().map(|ring| {
        let mut out: Ring = Vec::with_capacity(ring.len() + 1);
        for &e in ring {
            out.push(points[edges[e as usize].from as usize]);
        }
        out.push(out[0]);
        out
    }));
    // Orientation of the rounded ring (its signed area). Where rounding could have flipped it (a ring thin enough),
    // it is checked exactly at the ring's first exact vertex in sweep order (exact vertex ids follow the sweep;
    // rounding can merge a later exact vertex into an earlier one, so the rounded vertices' order is not the exact
    // one): the turn at an extreme vertex of a closed ring is its orientation. A ring whose rounded copy has no
    // area, or the opposite orientation, is a sliver thinner than rounding: it is dropped (`Equal`).
    turn.clear();
    turn.extend((rings.iter().zip(written.iter())).map(|(ring, rounded)| {
        let area = ring_area(rounded);
        let rounded_turn = area.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
        if sign_survives_rounding(rounded, area) {
            return rounded_turn;
        }
        let k = (0..ring.len())
            .min_by_key(|&k| exact_ends[ring[k] as usize].0)
            .expect("rings are not empty");
        let [incoming, outgoing] =
            [ring[(k + ring.len() - 1) % ring.len()], ring[k]].map(|e| e as usize);
        let exact_turn = lines.cross(&edges[incoming], &edges[outgoing]);
        // Where rounding merged vertices, the two edges need not meet at one exact point (an edge that shrank
        // to nothing was between them, and they can even run back along each other), or the ring can pass
        // straight through: then the turn says nothing and only the rounded orientation tells.
        let meet_exactly = exact_ends[incoming].1 == exact_ends[outgoing].0;
        // A ring written exactly (no vertex of it rounded) is not turned by rounding: its float area can only
        // have been summed wrong (a sliver), and its exact turn is its orientation.
        let written_exactly = || {
            (ring.iter()).all(|&e| {
                let v = &vertices[exact_ends[e as usize].0 as usize];
                v.is_exact(0) && v.is_exact(1)
            })
        };
        if meet_exactly && exact_turn != Ordering::Equal && written_exactly() {
            return exact_turn;
        }
        if !meet_exactly || exact_turn == Ordering::Equal || exact_turn == rounded_turn {
            rounded_turn
        } else {
            Ordering::Equal
        }
    }));
    let turn = &*turn;
    let is_shell = |r: u32| turn[r as usize] == Ordering::Greater;
    let is_hole = |r: usize| turn[r] == Ordering::Less && rings.ring(r).len() >= 3;
    // Each edge's ring, and each ring's edges into and out of its lowest-leftmost vertex: read only to place holes
    // (so made only where there are any).
    if (0..rings.len()).any(is_hole) {
        refill(ring_of_edge, edges.len(), NONE);
        for (r, ring) in rings.iter().enumerate() {
            for &e in ring {
                ring_of_edge[e as usize] = r as u32;
            }
        }
        let lexicographic = |a: &Point, b: &Point| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y));
        leftmost.clear();
        leftmost.extend((rings.iter().zip(written.iter())).map(|(ring, points)| {
            let k = (0..ring.len())
                .min_by(|&i, &j| lexicographic(&points[i], &points[j]))
                .expect("rings are not empty");
            [ring[(k + ring.len() - 1) % ring.len()], ring[k]]
        }));
    }
    let (ring_of_edge, leftmost) = (&*ring_of_edge, &*leftmost);
    // The ring of the result edge below ring `r`'s lowest edge at its leftmost vertex (asked for holes only, so
    // the edge below is looked up only for them).
    let ring_below = |r: u32| {
        let [i, o] = leftmost[r as usize].map(|e: u32| e as usize);
        [edges[i].below, edges[o].below]
            .into_iter()
            .filter(|&b| b != NONE)
            .map(&below_edge)
            .filter(|&b| b != NONE) // an edge the sweep stopped before recording
            .map(|b| ring_of_edge[b as usize])
            .find(|&b| b != NONE && b != r)
    };
    refill(polygon_of_ring, rings.len(), NONE);
    let mut polygons: Vec<Polygon> = Vec::with_capacity(rings.len());
    let mut polygon_class = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        if is_shell(r as u32) && ring.len() >= 3 {
            polygon_of_ring[r] = polygons.len() as u32;
            if !class.is_empty() {
                polygon_class.push(class_of_ring(ring));
            }
            polygons.push(Polygon {
                exterior: std::mem::take(&mut written[r]),
                holes: Vec::new(),
            });
        }
    }
    for (r, ring) in rings.iter().enumerate() {
        if !is_hole(r) {
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
            None => innermost_shell_around(&polygons, &hole, |p| {
                polygon_class
                    .get(p)
                    .is_none_or(|&c| c == class_of_ring(ring))
            }),
        };
        // No shell around a hole happens only where rounding inverted a sliver next to it (docs/robustness.md,
        // known limit); the strict tests check membership, so a hole lost otherwise would not go unnoticed.
        if let Some(p) = polygon {
            polygons[p].holes.push(hole);
        }
    }
    let made_vertical = x_rounded_onto_another && rounding_made_vertical(input, edges, points);
    written.clear(); // (the rings dropped, not kept with the tables)
    (MultiPolygon(polygons), polygon_class, made_vertical)
}
