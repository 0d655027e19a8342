//! Polygons of one operand that lie inside one convex polygon of the other, away from its edges.

use super::grid::BoxIndex;
use crate::geometry::{closed, next_around, open_len, orient, MultiPolygon};
use crate::input::Bounds;
use crate::select::FillRule;
use crate::validate::convex_turn;
use std::cmp::Ordering;

/// Which of the polygons whose boxes are `judged` lie inside one convex polygon of `operand` (whose boxes are
/// `boxes`), away from its edges and from the other polygons: their box grown by `margin` has its corners strictly
/// inside that polygon, a strictly convex ring without holes, and meets no other polygon's box. Throughout the grown
/// box, then, no edge of `operand` passes and its winding number is that ring's, ±1: inside under `fill_rule` when
/// it takes that winding number for inside (every rule but the positive or negative one of the other sign).
/// A union or a difference leaves such polygons out (see [`super::plan`]). Where a box's cells hold too many others
/// (see [`BoxIndex`]), or past a budget of orientation tests linear in the vertices and polygons, the answer is "not
/// inside": the pass stays linear.
pub(crate) fn inside_one_convex(
    operand: &MultiPolygon,
    boxes: &[Bounds],
    judged: &[Bounds],
    fill_rule: FillRule,
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
        let Some(turn) =
            turn.filter(|&t| fill_rule.is_inside(if t == Ordering::Greater { 1 } else { -1 }))
        else {
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
