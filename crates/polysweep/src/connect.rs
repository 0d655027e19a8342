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

use crate::events::NONE;
use crate::exact::{Exact, SweepPoint};
use crate::geometry::{MultiPolygon, Point, Polygon, Ring};
use crate::sweep::ResultEdge;
use std::cmp::Ordering;

/// Sign of the cross product of the travel directions of two result edges.
fn cross(exact: &Exact, e: &ResultEdge, f: &ResultEdge) -> Ordering {
    let sign = exact.cross_directions(&e.line, &f.line);
    if e.forward == f.forward {
        sign
    } else {
        sign.reverse()
    }
}

/// Of the edges leaving a vertex, the first clockwise from the reverse of `incoming`.
fn next_edge(exact: &Exact, edges: &[ResultEdge], incoming: usize, candidates: impl Iterator<Item = usize>) -> Option<usize> {
    let back = {
        let mut e = edges[incoming];
        e.forward = !e.forward;
        e
    };
    // Clockwise angle from `back`: right half-plane first, then straight on, then the left half-plane.
    let half = |e: &ResultEdge| match cross(exact, &back, e) {
        Ordering::Less => 0,
        Ordering::Equal => 1,
        Ordering::Greater => 2,
    };
    candidates.min_by(|&a, &b| {
        let (ea, eb) = (&edges[a], &edges[b]);
        half(ea).cmp(&half(eb)).then_with(|| cross(exact, ea, eb).reverse())
    })
}

/// Walks the result edges into simple rings, each as its list of edge indices.
fn walk_rings(exact: &Exact, vertex_count: usize, edges: &[ResultEdge]) -> Vec<Vec<usize>> {
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
    let mut used = vec![false; edges.len()];
    let mut position_on_path = vec![NONE; vertex_count];
    let mut rings = Vec::new();
    for &start in &outgoing {
        if used[start] {
            continue;
        }
        let mut path_vertices = vec![edges[start].from];
        let mut path_edges: Vec<usize> = Vec::new();
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
                rings.push(path_edges.split_off(at));
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
            match next_edge(exact, edges, current, candidates) {
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

/// Builds the output polygons from the result edges of a sweep.
pub(crate) fn connect(exact: &Exact, vertices: &[SweepPoint], edges: &mut [ResultEdge], below_edge: impl Fn(u32) -> u32) -> MultiPolygon {
    for e in edges.iter_mut() {
        e.below = if e.below == NONE { NONE } else { below_edge(e.below) };
    }
    let rings = walk_rings(exact, vertices.len(), edges);
    let mut ring_of_edge = vec![NONE; edges.len()];
    for (r, ring) in rings.iter().enumerate() {
        for &e in ring {
            ring_of_edge[e] = r as u32;
        }
    }
    // The two edges of each ring at its first vertex in sweep order (the lowest vertex id): the incoming and the
    // outgoing one. The ring is counter-clockwise when it turns left there.
    let leftmost: Vec<(usize, usize)> = rings
        .iter()
        .map(|ring| {
            let k = (0..ring.len()).min_by_key(|&k| edges[ring[k]].from).expect("rings are not empty");
            (ring[(k + ring.len() - 1) % ring.len()], ring[k])
        })
        .collect();
    let is_shell: Vec<bool> =
        leftmost.iter().map(|&(i, o)| cross(exact, &edges[i], &edges[o]) == Ordering::Greater).collect();
    let mut polygon_of_ring = vec![NONE; rings.len()];
    let mut polygons: Vec<Polygon> = Vec::new();
    let to_ring = |ring: &[usize]| -> Ring {
        let mut points: Ring = Vec::with_capacity(ring.len() + 1);
        for &e in ring {
            let [x, y] = vertices[edges[e].from as usize].approx;
            // Distinct exact points can round to one float: never repeat a point.
            if points.last() != Some(&Point::new(x, y)) {
                points.push(Point::new(x, y));
            }
        }
        while points.len() > 1 && points.first() == points.last() {
            points.pop();
        }
        if let Some(&first) = points.first() {
            points.push(first);
        }
        points
    };
    for (r, ring) in rings.iter().enumerate() {
        if is_shell[r] {
            polygon_of_ring[r] = polygons.len() as u32;
            polygons.push(Polygon { exterior: to_ring(ring), holes: Vec::new() });
        }
    }
    for (r, ring) in rings.iter().enumerate() {
        if is_shell[r] {
            continue;
        }
        // The hole's lower edge at its leftmost vertex has a result edge of another ring below it.
        let (i, o) = leftmost[r];
        let below = [edges[i].below, edges[o].below]
            .into_iter()
            .find(|&b| b != NONE && ring_of_edge[b as usize] != r as u32);
        let mut owner = below.map(|b| ring_of_edge[b as usize]);
        // Walk down through holes to the shell; at most one step per ring, so this always ends.
        for _ in 0..rings.len() {
            match owner {
                Some(o) if !is_shell[o as usize] => {
                    let (i, out) = leftmost[o as usize];
                    owner = [edges[i].below, edges[out].below]
                        .into_iter()
                        .find(|&b| b != NONE && ring_of_edge[b as usize] != o)
                        .map(|b| ring_of_edge[b as usize]);
                }
                _ => break,
            }
        }
        debug_assert!(owner.is_some_and(|o| is_shell[o as usize]), "a hole without a shell");
        if let Some(shell) = owner.filter(|&o| is_shell[o as usize]) {
            polygons[polygon_of_ring[shell as usize] as usize].holes.push(to_ring(ring));
        }
    }
    polygons.retain(|p| p.exterior.len() >= 4);
    for p in &mut polygons {
        p.holes.retain(|h| h.len() >= 4);
    }
    MultiPolygon(polygons)
}
