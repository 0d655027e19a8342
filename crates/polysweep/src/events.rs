//! Sweep events and the event queue (§3, Fig. 5, Fig. 8; the event order of §4 and §7.1).
//!
//! An event is one endpoint of an edge and stands for the edge (Fig. 8): `point`, the `other` endpoint, `left`,
//! and, through its input segment, the operand (the paper's `pl`). The paper's `inOut` and `inside` flags are
//! generalised to winding counts (`coverage_above`, see [`crate::select`]), kept with the edge's node in S while
//! the edge is there (the only time they are read); its edge `type` of §7.2 is replaced by merging overlapping
//! edges (see [`crate::subdivide`]).
//!
//! Departures from the paper:
//! - Every edge remembers the input segment it lies on (`segment`, whose line the sweep reads from the input
//!   edges): sub-edges made by subdivision lie exactly on it, so predicates are evaluated against input coordinates
//!   only (see the robustness page).
//! - The queue is the initial 2n events, sorted once and stored in that order, plus a binary heap for the events
//!   that subdivision adds (a crossing's four as one entry, see `Sweep::process_crossing`). Popping takes the
//!   smaller head, so the bulk of the work is one sort (of the ring vertices' points by value, not through their
//!   ids), and the sweep then reads the events front to back.

use crate::edges::{EventId, InputEdge, Operand, NONE};
use crate::exact::{Exact, Line, SweepPoint};
use std::cmp::Ordering;
use std::hint::select_unpredictable;

mod queue;
mod sort;

pub(crate) use queue::{EventQueue, Head};
pub(crate) use sort::{ordered_bits, sort_by_key, Buckets};

/// 40 bytes: the events are the sweep's largest array, read front to back and, for an edge's other end or a
/// neighbour's, far from where the sweep is, so their size is most of its memory traffic. (Larger events made the
/// largest benchmark workloads markedly slower.) What the sweep reads of an edge while the edge is in S is in
/// its node instead (see [`crate::sweep::InStatus`]).
#[derive(Clone, Debug)]
pub(crate) struct SweepEvent {
    pub point: SweepPoint,
    pub other: EventId,
    /// The input segment, the side, and whether `other` is still one of the segment's initial events, as one word
    /// (see [`Self::segment`], [`Self::left`] and [`far_point`]).
    segment_and_side: u32,
    /// How crossing this edge upwards (or, when vertical, from right to left) changes the winding number of each
    /// operand. Overlapping edges merged into this one add theirs (§7.2).
    pub winding: [i32; 2],
    /// Left events only: while the edge is in the sweep-line status, its node there (see [`Self::node`]); once it
    /// has left S, its index among the result edges if it was recorded there, marked by `RECORDED` (see
    /// [`Self::result_edge`]); otherwise `NONE`. One word for both, as an edge enters the result when it leaves S.
    place: u32,
}

/// The bit of [`SweepEvent::place`] that marks a result edge's index, not a node. Both are fewer than 2^31 - 1: a
/// node is an edge in S, a result edge a left event, and events are fewer than 2^32.
const RECORDED: u32 = 1 << 31;

/// The bit of [`SweepEvent::segment_and_side`] that marks a left endpoint.
const LEFT: u32 = 1 << 31;
/// The bit of [`SweepEvent::segment_and_side`] that says the other end is the input segment's own endpoint: the
/// edge has not been split on that side, so its other end's point is read from the input edge, which the sweep
/// reads anyway, instead of from an event far away in memory. Input segments are fewer than 2^30 (see
/// [`MAX_EVENTS`]).
const OTHER_AT_INPUT_END: u32 = 1 << 30;

/// The most events one sweep holds (an input that needs more is refused, see [`crate::Error::TooLarge`]). Within
/// it, every index fits where it is kept: an event's id and its node in S are below `RECORDED`, and so are a
/// vertex's and a result edge's (at most one per event); the input segments, two initial events each, are below
/// `OTHER_AT_INPUT_END`.
pub(crate) const MAX_EVENTS: usize = RECORDED as usize - 1;

impl SweepEvent {
    /// Index of the input segment this edge lies on, among the sweep's input edges, which give its line (oriented
    /// in sweep order) and its operand; also a stable tie-break shared by all fragments of one input edge.
    pub fn segment(&self) -> u32 {
        self.segment_and_side & !(LEFT | OTHER_AT_INPUT_END)
    }

    /// Is this the left endpoint of its edge (first in sweep order)?
    pub fn left(&self) -> bool {
        self.segment_and_side & LEFT != 0
    }

    /// The left or right event of input edge `segment`, `edge`, whose other event is `other`, also an initial one.
    pub fn initial(edge: &InputEdge, segment: u32, left: bool, other: EventId) -> Self {
        // (Both words made at once: a store of one, indexed, read back as a pair at once, stalls the load.)
        let winding = select_unpredictable(edge.operand == 0, [edge.winding, 0], [0, edge.winding]);
        let point = SweepPoint::input(select_unpredictable(left, edge.line.a, edge.line.b));
        let mut event = Self::unprocessed(point, left, segment, winding, other);
        event.segment_and_side |= OTHER_AT_INPUT_END;
        event
    }

    /// A copy of this edge's identity (segment, winding) for a new event of one of its fragments, made by a split:
    /// its other end, `other`, is the split point or the far end of this edge.
    pub fn fragment(&self, point: SweepPoint, left: bool, other: EventId) -> Self {
        Self::unprocessed(point, left, self.segment(), self.winding, other)
    }

    /// The edge's node in the sweep-line status, `NONE` when not in it (left events only). The node holds what the
    /// sweep knows of the edge while it is in S, its flags of Fig. 9 among them (see [`crate::sweep::InStatus`]).
    pub fn node(&self) -> u32 {
        if self.place & RECORDED != 0 {
            NONE // (`NONE` has the bit too)
        } else {
            self.place
        }
    }

    /// The edge's index among the result edges, `NONE` while it is not recorded there (left events only).
    pub fn result_edge(&self) -> u32 {
        if self.place != NONE && self.place & RECORDED != 0 {
            self.place & !RECORDED
        } else {
            NONE
        }
    }

    /// The edge enters S at `node`.
    pub fn enter_status(&mut self, node: u32) {
        debug_assert!(node < RECORDED);
        self.place = node;
    }

    /// The edge leaves S, not recorded as a result edge.
    pub fn leave_status(&mut self) {
        self.place = NONE;
    }

    /// The edge leaves S as result edge `index`.
    pub fn record(&mut self, index: u32) {
        debug_assert!(index < RECORDED - 1, "would read as NONE");
        self.place = index | RECORDED;
    }

    /// Makes `other` the other end: a new event, made by a split (so not at the input segment's end).
    pub fn set_other(&mut self, other: EventId) {
        self.other = other;
        self.segment_and_side &= !OTHER_AT_INPUT_END;
    }

    /// An event that the sweep has not reached yet: not in S, not in the result.
    fn unprocessed(
        point: SweepPoint,
        left: bool,
        segment: u32,
        winding: [i32; 2],
        other: EventId,
    ) -> Self {
        debug_assert!(
            segment < OTHER_AT_INPUT_END,
            "more input segments than an event can name"
        );
        SweepEvent {
            point,
            other,
            segment_and_side: if left { segment | LEFT } else { segment },
            winding,
            place: NONE,
        }
    }
}

/// The point of the other end of event `e`'s edge.
pub(crate) fn far_point(events: &[SweepEvent], edges: &[InputEdge], e: EventId) -> SweepPoint {
    let event = &events[e as usize];
    if event.segment_and_side & OTHER_AT_INPUT_END == 0 {
        return events[event.other as usize].point;
    }
    let line = &edges[event.segment() as usize].line;
    SweepPoint::input(if event.left() { line.b } else { line.a })
}

/// What the event order reads of an event besides its point.
struct AtPoint {
    left: bool,
    line: Line,
    /// The edge's other endpoint.
    far: SweepPoint,
    operand: Operand,
    segment: u32,
}

/// The order of two events at one point (§4, §7.1): right endpoints before left ones; then the lower edge first;
/// collinear edges by operand and input segment.
fn order_at_point(exact: &Exact, a: &AtPoint, b: &AtPoint) -> Ordering {
    a.left
        .cmp(&b.left)
        // `b`'s far endpoint above `a`'s line means `a` is the lower edge, so `a` goes first.
        .then_with(|| exact.orient(&a.line, &b.far).reverse())
        .then(a.operand.cmp(&b.operand))
        .then(a.segment.cmp(&b.segment))
}

/// The order in which events are processed (§4 and §7.1): by point, left to right and bottom to top; at one point
/// by [`order_at_point`].
pub(crate) fn event_order(
    events: &[SweepEvent],
    edges: &[InputEdge],
    exact: &Exact,
    a: EventId,
    b: EventId,
) -> Ordering {
    let at_point = |e: EventId| {
        let event = &events[e as usize];
        let edge = &edges[event.segment() as usize];
        AtPoint {
            left: event.left(),
            line: edge.line,
            far: far_point(events, edges, e),
            operand: edge.operand,
            segment: event.segment(),
        }
    };
    let (ea, eb) = (&events[a as usize], &events[b as usize]);
    exact
        .cmp_points(&ea.point, &eb.point)
        // Right before left (as `order_at_point` begins), without reading the edges: the events of one crossing,
        // two of each, meet in the heap.
        .then_with(|| ea.left().cmp(&eb.left()))
        .then_with(|| order_at_point(exact, &at_point(a), &at_point(b)))
        .then(a.cmp(&b))
}

/// The working memory of [`initial_events`], kept from one sweep to the next (see [`crate::workspace`]): what it
/// holds is overwritten.
#[derive(Default)]
pub(crate) struct SortScratch {
    /// A key and the endpoints it stands for, and the sort's working memory.
    pub keys: Vec<(u64, [u32; 2])>,
    pub buckets: Buckets<[u32; 2]>,
    /// The endpoints in event order, and each endpoint's place in it.
    pub order: Vec<u32>,
    pub position: Vec<u32>,
    /// Per operand: more than two of its endpoints at one point, rings of it that touch or meet there or a ring
    /// that passes twice through it (read by [`crate::structure`], whose watched sweeps never merge identical
    /// edges: noted only then, as on boards and parcel maps every inner corner is such a point).
    pub shared_vertex: [bool; 2],
    /// For each input edge, the edge it is merged into (see `merge_identical` in [`initial_events`]), or `NONE`.
    pub merged_into: Vec<u32>,
}

impl SortScratch {
    /// The bytes it holds (see [`crate::workspace`]).
    pub fn bytes(&self) -> usize {
        use crate::workspace::bytes_of;
        bytes_of(&self.keys)
            + self.buckets.bytes()
            + bytes_of(&self.order)
            + bytes_of(&self.position)
            + bytes_of(&self.merged_into)
    }
}

/// Notes in `shared` each operand with more than two of the endpoints `at_one_point`: found where the sort already
/// looks at every endpoint at a point where several vertices meet, so it costs nothing elsewhere.
#[cold]
#[inline(never)]
fn note_shared_vertex(shared: &mut [bool; 2], at_one_point: &[u32], edges: &[InputEdge]) {
    for (k, shared) in shared.iter_mut().enumerate() {
        let ends = at_one_point
            .iter()
            .filter(|&&end| edges[end as usize / 2].operand as usize == k);
        *shared |= ends.count() > 2;
    }
}

/// [`order_at_point`] for the endpoints `at_one_point` where every edge there is vertical or horizontal (grids,
/// boards, parcel maps), by a key of each rather than comparisons that read two edges' lines each: at a point, a
/// right end's edge comes from the left (horizontal) or from below (vertical), a left end's goes right or up, and
/// the lower edge comes first: the vertical one of right ends, the horizontal one of left ends; then by operand and
/// segment, as `order_at_point` orders collinear edges. Says whether it sorted them (`false`: an edge is neither,
/// and `at_one_point` is as it was). `keys` is working memory.
fn sort_axis_parallel(at_one_point: &mut [u32], edges: &[InputEdge], keys: &mut Vec<u64>) -> bool {
    keys.clear();
    for &end in at_one_point.iter() {
        let (segment, left) = (end / 2, end % 2 == 1);
        let edge = &edges[segment as usize];
        let (vertical, horizontal) = (
            edge.line.a[0] == edge.line.b[0],
            edge.line.a[1] == edge.line.b[1],
        );
        if vertical == horizontal {
            return false;
        }
        let later = if left { vertical } else { horizontal };
        keys.push(
            (u64::from(left) << 63)
                | (u64::from(later) << 62)
                | (u64::from(edge.operand) << 32)
                | u64::from(segment),
        );
    }
    keys.sort_unstable();
    for (end, key) in at_one_point.iter_mut().zip(keys.iter()) {
        *end = 2 * (*key as u32) + (key >> 63) as u32;
    }
    true
}

/// Runs of vertices with one x longer than this are sorted by y as the x's are sorted, by value (see [`sort`]);
/// shorter ones by comparison.
const SORTED_BY_VALUE: usize = 64;

/// The initial events: two per input edge, created in the order of [`event_order`], so that the sweep reads them
/// front to back.
///
/// Where one edge ends and the next begins (a vertex of a ring: the edges come ring by ring), the two endpoints are
/// sorted as one: half as many keys as endpoints. Input points are exact floats, so they are sorted by x as integer
/// keys that order like the coordinates, by value (see [`sort`]); those with one x, which then come out
/// next to each other, are sorted again by y, and the endpoints at one point by [`order_at_point`]. The sort moves
/// small keys and reads the compact edges, never the larger events. It works in `scratch`, and writes the events
/// into `events` (given empty, with the room of an earlier sweep), and, unless it merges identical edges, notes
/// `scratch.shared_vertex`.
pub(crate) fn initial_events(
    edges: &[InputEdge],
    exact: &Exact,
    scratch: &mut SortScratch,
    mut events: Vec<SweepEvent>,
    merge_identical: bool,
) -> Vec<SweepEvent> {
    scratch.shared_vertex = [false; 2];
    let merged_into = &mut scratch.merged_into;
    merged_into.clear();
    let mut any_merged = false;
    if merge_identical {
        merged_into.resize(edges.len(), NONE);
    }
    // An endpoint is `2 · edge + 1` for a left endpoint, `2 · edge` for a right one.
    let point = |end: u32| {
        let line = &edges[end as usize / 2].line;
        if end % 2 == 1 {
            line.a
        } else {
            line.b
        }
    };
    let at_point = |end: u32| {
        let edge = &edges[end as usize / 2];
        let left = end % 2 == 1;
        AtPoint {
            left,
            line: edge.line,
            far: SweepPoint::input(if left { edge.line.b } else { edge.line.a }),
            operand: edge.operand,
            segment: end / 2,
        }
    };
    // The endpoint where edge `j` begins along its ring (it ends at the other one).
    let begin = |j: usize| 2 * j as u32 + u32::from(edges[j].winding > 0);
    // A vertex's key (its x, as an integer that orders like it) and its two endpoints (or one and `NONE`).
    let vertices = &mut scratch.keys;
    vertices.clear();
    vertices.reserve(edges.len() + 1);
    let mut vertex = |ends: [u32; 2]| vertices.push((ordered_bits(point(ends[0])[0]), ends));
    let mut chain_start = 0; // the first edge of the current chain of edges meeting end to beginning
    for j in 0..edges.len() {
        let end = begin(j) ^ 1;
        if j + 1 < edges.len() && point(begin(j + 1)) == point(end) {
            vertex([end, begin(j + 1)]);
            continue;
        }
        // The chain ends here: a closed ring if it ends where it began (otherwise two loose endpoints).
        let first = begin(chain_start);
        if point(first) == point(end) {
            vertex([end, first]);
        } else {
            vertex([end, NONE]);
            vertex([first, NONE]);
        }
        chain_start = j + 1;
    }
    // Keys that tie are ordered again below.
    sort::sort_by_key(vertices, &mut scratch.buckets);
    let order = &mut scratch.order;
    order.clear();
    order.reserve(2 * edges.len());
    let (mut at_one_point, mut axis_parallel_keys) = (Vec::new(), Vec::new());
    for same_x in vertices.chunk_by_mut(|a, b| a.0 == b.0) {
        if same_x.len() > 1 {
            // Long runs share an x (a column of a grid): by y as keys again, by value as the x's were where the
            // run is long.
            for (key, ends) in same_x.iter_mut() {
                *key = ordered_bits(point(ends[0])[1]);
            }
            if same_x.len() <= SORTED_BY_VALUE {
                same_x.sort_unstable_by_key(|&(y, _)| y);
            } else if !same_x.is_sorted_by_key(|&(y, _)| y) {
                sort::sort_by_key(same_x, &mut scratch.buckets);
            }
        }
        for same_point in same_x.chunk_by(|a, b| a.0 == b.0) {
            // (A spike's two edges, merged where another ring meets one of its ends, may meet alone at the other:
            // they take the path below, which leaves out the merged one's end.)
            if let [(_, ends)] = same_point {
                if !(any_merged && has_merged_right_end(*ends, merged_into)) {
                    // The usual case, one vertex at its point: its two endpoints in order, without a sort.
                    let ends = *ends;
                    if ends[1] == NONE {
                        order.push(ends[0]);
                        continue;
                    }
                    // Where the ring goes on through the vertex (one edge ends, the next begins), the right
                    // endpoint comes first (§4): the lines need not be read. Which one that is, is a coin toss in x
                    // order: the pair is put in order by a selection, not a branch.
                    let (first_left, second_left) = (ends[0] % 2 == 1, ends[1] % 2 == 1);
                    let second_first = if first_left != second_left {
                        first_left
                    } else {
                        order_at_point(exact, &at_point(ends[1]), &at_point(ends[0]))
                            == Ordering::Less
                    };
                    let (a, b) = (ends[0], ends[1]);
                    order.extend([
                        select_unpredictable(second_first, b, a),
                        select_unpredictable(second_first, a, b),
                    ]);
                    continue;
                }
            }
            at_one_point.clear();
            at_one_point.extend(
                (same_point.iter())
                    .flat_map(|&(_, ends)| ends)
                    .filter(|&end| end != NONE),
            );
            if merge_identical {
                // The right ends of edges merged at their left ends make no events.
                at_one_point.retain(|&end| end % 2 == 1 || merged_into[end as usize / 2] == NONE);
            } else {
                note_shared_vertex(&mut scratch.shared_vertex, &at_one_point, edges);
            }
            if !sort_axis_parallel(&mut at_one_point, edges, &mut axis_parallel_keys) {
                // (Right ends before left ones, as `order_at_point` begins, told without reading the edges.)
                at_one_point.sort_unstable_by(|&a, &b| {
                    (a % 2)
                        .cmp(&(b % 2))
                        .then_with(|| order_at_point(exact, &at_point(a), &at_point(b)))
                });
            }
            if merge_identical {
                any_merged |= merge_at_point(&mut at_one_point, edges, exact, merged_into);
            }
            order.extend_from_slice(&at_one_point);
        }
    }
    // By endpoint: more than `order` where edges were merged.
    crate::workspace::refill(&mut scratch.position, 2 * edges.len(), 0);
    // (As slices, whose bounds stay in registers: through the vectors, a loop may read them again at every step,
    // as it cannot tell that what it writes does not change them.)
    let (order, position) = (scratch.order.as_slice(), scratch.position.as_mut_slice());
    for (i, &end) in order.iter().enumerate() {
        position[end as usize] = i as EventId;
    }
    let position = &*position;
    // Room for a quarter as many events again from subdivision before the vector has to move (and be copied):
    // more than Table 1's workloads add. Room never used costs address space, not memory: its pages are never
    // touched.
    crate::workspace::reserve(&mut events, order.len() + order.len() / 4);
    events.extend(order.iter().map(|&end| {
        let segment = end / 2;
        let other = position[end as usize ^ 1];
        SweepEvent::initial(&edges[segment as usize], segment, end % 2 == 1, other)
    }));
    if any_merged {
        for (merged, &kept) in scratch.merged_into.iter().enumerate() {
            if kept != NONE {
                let edge = &edges[merged];
                for end in [2 * kept, 2 * kept + 1] {
                    events[position[end as usize] as usize].winding[edge.operand as usize] +=
                        edge.winding;
                }
            }
        }
    }
    events
}

/// Is either of `ends` the right end of an edge merged into another?
#[cold]
fn has_merged_right_end(ends: [u32; 2], merged_into: &[u32]) -> bool {
    (ends.iter()).any(|&e| e != NONE && e % 2 == 0 && merged_into[e as usize / 2] != NONE)
}

/// §7.2 before the sweep: among the endpoints at one point, in event order, the left ends of edges identical to an
/// edge before them (the same far end: they are collinear, so `order_at_point` put them in one run) are taken out
/// and their edges noted in `merged_into` as merged into that edge, which carries their windings (as the sweep's
/// merge of overlapping edges does, sooner: shared borders of parcel maps and boards are half their edges, each met
/// once here instead of twice in S). Says whether any was merged.
#[cold]
#[inline(never)]
fn merge_at_point(
    at_one_point: &mut Vec<u32>,
    edges: &[InputEdge],
    exact: &Exact,
    merged_into: &mut [u32],
) -> bool {
    let line = |end: u32| &edges[end as usize / 2].line;
    let before = at_one_point.len();
    let mut kept = 0;
    for i in 0..at_one_point.len() {
        let end = at_one_point[i];
        if end % 2 == 1 {
            // Edges identical to this one come right after it or after other edges on its line (the run of left
            // ends collinear with it, going back): the first kept one with its far end takes it.
            let far = SweepPoint::input(line(end).b);
            let same = (at_one_point[..kept].iter().rev())
                .take_while(|&&k| k % 2 == 1 && exact.orient(line(k), &far) == Ordering::Equal)
                .find(|&&k| line(k).b == line(end).b);
            if let Some(&k) = same {
                merged_into[end as usize / 2] = k / 2;
                continue;
            }
        }
        at_one_point[kept] = end;
        kept += 1;
    }
    at_one_point.truncate(kept);
    kept < before
}

#[cfg(test)]
mod tests;
