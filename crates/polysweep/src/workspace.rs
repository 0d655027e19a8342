//! Working memory kept from one operation to the next on a thread (not in the paper; for speed).
//!
//! An operation's largest vectors (input edges, events, the sort's keys, the result's vertices and edges) are
//! megabytes at Table 1's sizes. Memory fresh from the operating system costs a page fault for each 4 KB page the
//! first time it is written, and the allocator gives large blocks back to the system when they are freed, so an
//! operation that allocates them anew pays those faults every time. So each thread keeps the vectors of its last
//! operation, emptied, for the next one, up to [`KEEP_BYTES`]; beyond that they are freed as before.
//! [`free_working_memory`] frees them at once.

use crate::edges::{InputEdge, ResultEdge};
use crate::events::{SortScratch, SweepEvent};
use crate::exact::SweepPoint;
use std::cell::Cell;
use std::mem::size_of;

/// The most memory a thread keeps between operations: 64 MiB, enough for land × 32,768 squares (the benchmark's largest
/// workload, 383,318 events).
pub const KEEP_BYTES: usize = 64 << 20;

/// The vectors an operation reuses. Each is handed out empty by [`take`] and given back full; what they held is
/// never read again.
#[derive(Default)]
pub(crate) struct Workspace {
    pub edges: Vec<InputEdge>,
    pub events: Vec<SweepEvent>,
    pub sort: SortScratch,
    pub vertices: Vec<SweepPoint>,
    pub result: Vec<ResultEdge>,
}

impl Workspace {
    fn bytes(&self) -> usize {
        fn of<T>(v: &Vec<T>) -> usize {
            v.capacity() * size_of::<T>()
        }
        let sort = &self.sort;
        of(&self.edges)
            + of(&self.events)
            + of(&sort.keys)
            + sort.buckets.bytes()
            + of(&sort.order)
            + of(&sort.position)
            + of(&self.vertices)
            + of(&self.result)
    }
}

/// `slot`'s vector, emptied, leaving an empty one (without memory) in its place until it is given back.
pub(crate) fn take<T>(slot: &mut Vec<T>) -> Vec<T> {
    let mut v = std::mem::take(slot);
    v.clear();
    v
}

thread_local! {
    static KEPT: Cell<Workspace> = Cell::new(Workspace::default());
}

/// Runs `operation` with this thread's kept vectors, and keeps them again afterwards if they are not too large.
/// (Called again from within `operation`, or while the thread ends, it runs with new vectors.)
/// With `keep` false (a test's switch, see [`crate::Shortcuts`]), it runs with new vectors and keeps none.
pub(crate) fn with<R>(keep: bool, operation: impl FnOnce(&mut Workspace) -> R) -> R {
    if !keep {
        return operation(&mut Workspace::default());
    }
    let mut workspace = KEPT.try_with(Cell::take).unwrap_or_default();
    let outcome = operation(&mut workspace);
    if workspace.bytes() <= KEEP_BYTES {
        // (While the thread ends there is nothing to keep it for: it is dropped.)
        let _ = KEPT.try_with(|kept| kept.set(workspace));
    }
    outcome
}

/// Is there room for `more` elements in `v`? It grows as a push would (doubling), but says so where the allocator
/// has no memory left, where a push would abort the process (or trap, in wasm).
pub(crate) fn room<T>(v: &mut Vec<T>, more: usize) -> bool {
    v.capacity() - v.len() >= more || v.try_reserve(more).is_ok()
}

/// Frees the memory this thread keeps between operations (see the crate's documentation, *Memory*). The next
/// operation allocates anew.
pub fn free_working_memory() {
    let _ = KEPT.try_with(Cell::take);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{intersection, union, MultiPolygon};

    /// Each test runs on a thread of its own, so what it keeps is its own.
    fn kept_events() -> usize {
        with(true, |workspace| workspace.events.capacity())
    }

    #[test]
    fn keeps_the_vectors_of_an_operation_for_the_next_unless_too_large() {
        with(true, |workspace| workspace.events.reserve(1000));
        assert!(kept_events() >= 1000);
        free_working_memory();
        assert_eq!(kept_events(), 0);
        // Past the bound, nothing is kept (the room reserved is address space only, never written).
        with(true, |workspace| {
            workspace
                .events
                .reserve(KEEP_BYTES / size_of::<SweepEvent>() + 1);
        });
        assert_eq!(kept_events(), 0);
        // Called from within an operation, an operation runs with vectors of its own.
        with(true, |outer| {
            outer.events.reserve(10);
            assert_eq!(with(true, |inner| inner.events.capacity()), 0);
        });
        assert!(kept_events() >= 10);
    }

    #[test]
    fn operations_on_kept_vectors_give_what_they_give_on_new_ones() {
        let grid = |n: usize, side: f64, offset: f64| {
            let squares: Vec<Vec<Vec<[f64; 2]>>> = (0..n * n)
                .map(|i| {
                    let (x, y) = ((i % n) as f64 + offset, (i / n) as f64 + offset);
                    vec![vec![
                        [x, y],
                        [x + side, y],
                        [x + side, y + side],
                        [x, y + side],
                    ]]
                })
                .collect();
            MultiPolygon::from_coordinates(&squares)
        };
        let (large, small) = (grid(30, 0.7, 0.0), grid(3, 0.9, 0.45));
        free_working_memory();
        let fresh = [
            intersection(&large, &small).unwrap(),
            union(&small, &small).unwrap(),
        ];
        free_working_memory();
        // A large operation first leaves longer vectors, with its data in them, to the smaller ones after it.
        union(&large, &large.clone()).unwrap();
        assert!(kept_events() > 0);
        assert_eq!(intersection(&large, &small).unwrap(), fresh[0]);
        assert_eq!(union(&small, &small).unwrap(), fresh[1]);
    }
}
