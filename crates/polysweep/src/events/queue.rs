//! The event-point set Q of Fig. 5.
//!
//! Departure from the paper: Q is the initial 2n events, sorted once and stored in that order (see
//! [`super::initial_events`]), plus a binary heap for the events that subdivision adds. Popping takes the smaller
//! head, so the bulk of the work is one sort and the sweep then reads the events front to back.

use crate::edges::{EventId, NONE};
use std::cmp::Ordering;

/// The next event of Q: the next initial one or the top of the heap.
#[derive(Clone, Copy)]
pub(crate) struct Head {
    pub event: EventId,
    /// The other right event of a crossing whose four events wait as one entry (see [`Pending::partner`]), or
    /// `NONE`.
    pub partner: EventId,
    from_heap: bool,
}

/// The event-point set Q of Fig. 5: the initial events, already in order (see [`super::initial_events`]), and a binary
/// heap for the events that subdivision adds. Popping takes the smaller head; the order is the same as one priority
/// queue's.
pub(crate) struct EventQueue {
    initial: EventId,
    next_initial: EventId,
    heap: Vec<Pending>,
}

/// An event in the heap, with its point's x. Most pairs are ordered by their x's alone, without reading the events,
/// which lie far apart in memory: an x is exact or correctly rounded, and rounding is monotone, so points whose x's
/// differ lie in the order of their x's. Only pairs with one x are given to the full order.
#[derive(Clone, Copy)]
struct Pending {
    x: f64,
    event: EventId,
    /// For the first event of a crossing in the event order, a right event, the other one: the four events of the
    /// crossing wait as this one entry (see `Sweep::process_crossing`). `NONE` for an event on its own. (In the
    /// room the alignment of `x` leaves.)
    partner: EventId,
}

/// Does `a` come before `b`, by x and then by `order`?
#[inline(always)]
fn before(a: Pending, b: Pending, order: &impl Fn(EventId, EventId) -> Ordering) -> bool {
    a.x < b.x || (a.x == b.x && order(a.event, b.event) == Ordering::Less)
}

impl EventQueue {
    /// A queue whose first `initial` events are `0..initial` in order.
    pub fn new(initial: usize) -> Self {
        EventQueue {
            initial: initial as EventId,
            next_initial: 0,
            heap: Vec::new(),
        }
    }

    /// Room for `more` events without allocating (see [`crate::workspace::room`]).
    pub fn room(&mut self, more: usize) -> bool {
        crate::workspace::room(&mut self.heap, more)
    }

    /// Empties the queue.
    pub fn clear(&mut self) {
        self.next_initial = self.initial;
        self.heap.clear();
    }

    /// Puts in `event`, whose point's x is `x`, with its `partner` (see [`Pending::partner`]; usually `NONE`).
    pub fn push(
        &mut self,
        event: EventId,
        partner: EventId,
        x: f64,
        order: impl Fn(EventId, EventId) -> Ordering,
    ) {
        self.heap.push(Pending { x, event, partner });
        let mut child = self.heap.len() - 1;
        while child > 0 {
            let parent = (child - 1) / 2;
            if !before(self.heap[child], self.heap[parent], &order) {
                break;
            }
            self.heap.swap(child, parent);
            child = parent;
        }
    }

    /// The next event, without taking it (see [`Self::take`]). `x` gives an event's point's x.
    pub fn peek(
        &self,
        x: impl Fn(EventId) -> f64,
        order: impl Fn(EventId, EventId) -> Ordering,
    ) -> Option<Head> {
        let initial = Some(self.next_initial).filter(|&i| i < self.initial);
        let first = |i| {
            Some(Head {
                event: i,
                partner: NONE,
                from_heap: false,
            })
        };
        let top = |h: &Pending| {
            Some(Head {
                event: h.event,
                partner: h.partner,
                from_heap: true,
            })
        };
        match (initial, self.heap.first()) {
            (None, None) => None,
            (Some(i), None) => first(i),
            (None, Some(h)) => top(h),
            (Some(i), Some(h)) => {
                let next_initial = Pending {
                    x: x(i),
                    event: i,
                    partner: NONE,
                };
                if before(*h, next_initial, &order) {
                    top(h)
                } else {
                    first(i)
                }
            }
        }
    }

    #[inline(always)]
    pub fn pop(
        &mut self,
        x: impl Fn(EventId) -> f64,
        order: impl Fn(EventId, EventId) -> Ordering,
    ) -> Option<Head> {
        let head = self.peek(x, &order)?;
        self.take(head, order);
        Some(head)
    }

    /// Takes out `head`, which [`Self::peek`] has just given (nothing pushed since): the two heads are not
    /// compared again.
    #[inline(always)]
    pub fn take(&mut self, head: Head, order: impl Fn(EventId, EventId) -> Ordering) {
        if !head.from_heap {
            self.next_initial += 1;
            return;
        }
        let top = self.heap.swap_remove(0);
        let mut parent = 0;
        loop {
            let (l, r) = (2 * parent + 1, 2 * parent + 2);
            let mut smallest = parent;
            for child in [l, r] {
                if child < self.heap.len() && before(self.heap[child], self.heap[smallest], &order)
                {
                    smallest = child;
                }
            }
            if smallest == parent {
                break;
            }
            self.heap.swap(parent, smallest);
            parent = smallest;
        }
        debug_assert_eq!(top.event, head.event, "the head taken is the one peeked");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn queue_pops_in_order_across_initial_and_pushed_events() {
        // Points ordered by x and then y: the heap tells apart those of different x by x, the others by the order.
        let points = [
            [1, 0],
            [5, 1],
            [9, 0],
            [5, 0],
            [7, 0],
            [1, 1],
            [5, 2],
            [5, -1],
        ];
        let order = |a: EventId, b: EventId| points[a as usize].cmp(&points[b as usize]);
        let x = |e: EventId| f64::from(points[e as usize][0]);
        let mut queue = EventQueue::new(3);
        for e in [3, 4, 5, 6, 7] {
            queue.push(e, NONE, x(e), order);
        }
        let mut popped = Vec::new();
        while let Some(head) = queue.pop(x, order) {
            popped.push(points[head.event as usize]);
        }
        let mut sorted = points.to_vec();
        sorted.sort();
        assert_eq!(popped, sorted);
    }
}
