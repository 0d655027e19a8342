//! Polygons that an operation copies to its result as they are, instead of sweeping them: clipping polygons inside
//! the subject for an intersection, polygons apart from all others for the other operations.

use super::grid::apart;
use super::SAMPLES;
use crate::exact::Line;
use crate::geometry::{
    closed, next_around, open_len, ring_area, MultiPolygon, Point, Polygon, Ring,
};
use crate::input::Bounds;
use crate::select::FillRule;
use crate::validate::{lowest_leftmost, simple_ring_turn};
use std::cmp::Ordering;

/// The most vertices of a clipping polygon that an intersection copies whole (see [`copied_whole`]): its ring is
/// checked against itself pair of edges by pair of edges.
const MAX_VERTICES_TO_COPY: usize = 32;

/// The clipping polygons that an intersection copies to its result as they are, instead of sweeping them, and
/// their copies as result polygons. Copied is a polygon that is one simple ring of a few vertices, that `inside`
/// says lies wholly inside the subject (`Some(true)`, judged on its box grown by `margin`), and whose box is farther
/// than `margin` from every other clipping polygon's box (`boxes`). There the clipping operand is that ring alone
/// and the subject is everywhere, so the ring is its own part of the intersection. The rest of the result lies
/// within the other clipping polygons' boxes, and rounding moves it by less than `margin`: it cannot meet the
/// copies, nor be snapped to them (see [`crate::snap_round`]). (Polygons wholly outside the subject, `Some(false)`,
/// are apart from the copies without a look: their grown boxes lie outside the subject, the copies' inside it.)
pub(crate) fn copied_whole(
    clipping: &MultiPolygon,
    boxes: &[Bounds],
    inside: &[Option<bool>],
    fill_rule: FillRule,
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
        if let Some(ring) = as_written(&polygon.exterior, fill_rule, margin) {
            copied[p] = true;
            polygons.push(Polygon::new(ring, Vec::new()));
        }
    }
    (copied, polygons)
}

/// The polygons that a union, a xor or a difference copies to its result as they are, instead of sweeping them, for
/// each operand, and their copies as result polygons (clipping polygons only where `copy_clipping`: not for a
/// difference, which leaves them out). Copied is a polygon that is one simple ring of a few vertices whose box is
/// farther than `margin` from every other polygon's box, of either operand (`boxes`). There that ring is the only
/// one, so its own region is its part of the result, as for [`copied_whole`]: the rest of the result lies within
/// the other polygons' boxes, and rounding moves it by less than `margin`.
pub(crate) fn copied_apart(
    operands: [&MultiPolygon; 2],
    boxes: [&[Bounds]; 2],
    copy_clipping: bool,
    fill_rule: FillRule,
    margin: f64,
) -> ([Vec<bool>; 2], Vec<Polygon>) {
    let one_small_ring =
        |p: &Polygon| p.holes.is_empty() && open_len(&p.exterior) <= MAX_VERTICES_TO_COPY;
    let [subject, clipping] = operands.map(|operand| operand.0.as_slice());
    let asked: Vec<bool> = (subject.iter().map(one_small_ring))
        .chain(clipping.iter().map(|p| copy_clipping && one_small_ring(p)))
        .collect();
    let mut copied = [vec![false; subject.len()], vec![false; clipping.len()]];
    if !any_sample_may_be_apart(boxes, &asked, margin) {
        return (copied, Vec::new());
    }
    let all_boxes: Vec<Bounds> = boxes.concat();
    let every_one: Vec<u32> = (0..all_boxes.len() as u32).collect();
    let apart = apart(&all_boxes, margin, &asked, &every_one);
    let mut polygons = Vec::new();
    for (i, polygon) in subject.iter().chain(clipping).enumerate() {
        if !apart[i] {
            continue;
        }
        if let Some(ring) = as_written(&polygon.exterior, fill_rule, margin) {
            let (operand, p) = operand_and_index(i, subject.len());
            copied[operand][p] = true;
            polygons.push(Polygon::new(ring, Vec::new()));
        }
    }
    (copied, polygons)
}

/// The operand and the index in it of polygon `i` of the two operands listed one after the other, the subject's
/// `subject_len` first.
fn operand_and_index(i: usize, subject_len: usize) -> (usize, usize) {
    if i < subject_len {
        (0, i)
    } else {
        (1, i - subject_len)
    }
}

/// How many polygons before and after a sampled candidate of [`copied_apart`] in either operand's list are looked at
/// for one whose box meets it.
const NEAR_IN_LIST: usize = 64;

/// Might any of `asked` (the subject's polygons, then the clipping operand's) be apart from all others? Told from a
/// sample of them, each against the boxes near it in the lists (where polygons usually lie near their neighbours in
/// space): where each sampled box meets one of those, the polygons are taken to lie packed together (a board, a
/// parcel map, tiles that overlap), where indexing all boxes would cost an eighth of the sweep and find nothing
/// apart. Only a matter of speed: `false` means "sweep them all".
fn any_sample_may_be_apart(boxes: [&[Bounds]; 2], asked: &[bool], margin: f64) -> bool {
    let candidates = || (0..asked.len()).filter(|&i| asked[i]);
    let step = candidates().count().div_ceil(SAMPLES).max(1);
    candidates().step_by(step).any(|i| {
        let (own, p) = operand_and_index(i, boxes[0].len());
        let grown = boxes[own][p].grown(margin);
        // Its place in its own list, and the same share of the way along the other.
        let share = p as f64 / boxes[own].len() as f64;
        !(0..2).any(|list| {
            let at = (share * boxes[list].len() as f64) as usize;
            let near = at.saturating_sub(NEAR_IN_LIST)..(at + NEAR_IN_LIST).min(boxes[list].len());
            near.into_iter()
                .any(|q| (list, q) != (own, p) && boxes[list][q].meets(&grown))
        })
    })
}

/// `ring` as the sweep writes a simple ring: closed, counter-clockwise, from its lowest-leftmost vertex (where the
/// walk of [`crate::connect`] begins). `None` if it is not simple, or where the sweep would write it otherwise:
/// where its float area, by which `connect` tells a ring's orientation, has not the sign of its exact turn (a
/// sliver, which `connect` drops), or where a vertex lies within `margin` of an edge not its own (an edge that
/// snap rounding could bend through the vertex, should the result be snap-rounded, see [`crate::snap_round`]). Also `None` where the ring's own
/// region under `fill_rule` is empty: a clockwise ring under the positive rule, a counter-clockwise one under the
/// negative.
pub(super) fn as_written(ring: &[Point], fill_rule: FillRule, margin: f64) -> Option<Ring> {
    let (n, closed) = (open_len(ring), closed(ring));
    let turn = simple_ring_turn(&closed)?;
    if !fill_rule.is_inside(if turn == Ordering::Greater { 1 } else { -1 }) {
        return None;
    }
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

/// Does a vertex of closed `ring` lie within about `margin` of one of its edges that does not end there? Asked in
/// floats, of twice `margin` and of the edge's box grown by as much. Not a tolerance that decides the result: it
/// only chooses between copying the ring and sweeping it, and it errs towards sweeping. Twice `margin` is 16 ulps
/// of the input's largest magnitude, where a rounding cell reaches half of one and the float cross products (this
/// one and snap rounding's filter) err by under 5 each: a ring snap rounding could bend through its own vertex is
/// never copied.
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
