//! Working memory kept from one operation to the next on a thread (not in the paper; for speed).
//!
//! An operation's largest vectors (input edges, events, the sort's keys, the result's vertices and edges, the
//! connection step's tables) are megabytes at Table 1's sizes. Memory fresh from the operating system costs a page
//! fault for each 4 KB page the first time it is written, and the allocator gives large blocks back to the system
//! when they are freed, so an operation that allocates them anew pays those faults every time (on this project's
//! benchmark machine, a virtual one, about 2.4 µs a page: most of the time of the largest dense arrangements). So
//! each thread keeps the vectors of its last operation, emptied, for the next one, as many as fit in
//! [`KEEP_BYTES`] (the largest first); the others are freed. [`free_working_memory`] frees them at once.

use crate::connect::ConnectTables;
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
    pub connect: ConnectTables,
}

impl Workspace {
    /// Frees vectors until those left hold `budget` bytes at most: the largest that fit are kept, as each byte kept
    /// saves the next operation as much as any other (a page fault per 4 KB page it writes).
    fn fit(&mut self, budget: usize) {
        let bytes = [
            bytes_of(&self.edges),
            bytes_of(&self.events),
            self.sort.bytes(),
            bytes_of(&self.vertices),
            bytes_of(&self.result),
            self.connect.bytes(),
        ];
        let mut largest_first = [0, 1, 2, 3, 4, 5];
        largest_first.sort_by_key(|&part| std::cmp::Reverse(bytes[part]));
        let mut left = budget;
        for part in largest_first {
            if bytes[part] <= left {
                left -= bytes[part];
                continue;
            }
            match part {
                0 => self.edges = Vec::new(),
                1 => self.events = Vec::new(),
                2 => self.sort = SortScratch::default(),
                3 => self.vertices = Vec::new(),
                4 => self.result = Vec::new(),
                _ => self.connect = ConnectTables::default(),
            }
        }
    }
}

/// The memory `v` holds.
pub(crate) fn bytes_of<T>(v: &Vec<T>) -> usize {
    v.capacity() * size_of::<T>()
}

/// `v` emptied and filled with `len` copies of `value` (a kept vector, its room reused).
pub(crate) fn refill<T: Clone>(v: &mut Vec<T>, len: usize, value: T) {
    v.clear();
    v.resize(len, value);
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

/// Runs `operation` with this thread's kept vectors, and keeps them again afterwards, as many as fit in
/// [`KEEP_BYTES`].
/// (Called again from within `operation`, or while the thread ends, it runs with new vectors.)
/// With `keep` false (a test's switch, see [`crate::Shortcuts`]), it runs with new vectors and keeps none.
pub(crate) fn with<R>(keep: bool, operation: impl FnOnce(&mut Workspace) -> R) -> R {
    if !keep {
        return operation(&mut Workspace::default());
    }
    let mut workspace = KEPT.try_with(Cell::take).unwrap_or_default();
    let outcome = operation(&mut workspace);
    workspace.fit(KEEP_BYTES);
    // (While the thread ends there is nothing to keep it for: it is dropped.)
    let _ = KEPT.try_with(|kept| kept.set(workspace));
    outcome
}

/// Is there room for `more` elements in `v`? It grows as a push would (doubling), but says so where the allocator
/// has no memory left, where a push would abort the process (or trap, in wasm).
pub(crate) fn room<T>(v: &mut Vec<T>, more: usize) -> bool {
    v.capacity() - v.len() >= more || grow(v, more)
}

/// Grows `v` by `more` elements at least (doubling), or says that there is no memory for it.
///
/// Where it becomes large, it is moved into a new allocation advised huge pages before the copy: the allocator's
/// own growth copies into fresh memory it has not been told about (a fault per 4 KiB), except for allocations it
/// maps on their own, which it moves without copying. glibc maps allocations of 32 MiB and more on their own
/// (smaller ones, as it goes), so those are left to it.
#[cold]
#[inline(never)]
fn grow<T>(v: &mut Vec<T>, more: usize) -> bool {
    const MAPPED_ON_THEIR_OWN: usize = 32 << 20;
    // (Saturating: a request too large for memory fails below, as out of memory, rather than overflowing here.)
    let wanted = (v.len().saturating_add(more)).max(v.capacity().saturating_mul(2));
    if cfg!(target_os = "linux")
        && wanted.saturating_mul(size_of::<T>()) >= LARGE
        && v.capacity() * size_of::<T>() < MAPPED_ON_THEIR_OWN
    {
        let mut grown = Vec::new();
        if grown.try_reserve_exact(wanted).is_err() {
            return false;
        }
        advise_huge_pages(&grown);
        grown.append(v);
        *v = grown;
        return true;
    }
    let grown = v.try_reserve(more).is_ok();
    if grown {
        advise_huge_pages(v);
    }
    grown
}

/// Makes room for `more` elements in `v`, as [`Vec::reserve`] does (for vectors made once per operation, whose
/// size is known: input edges, initial events).
pub(crate) fn reserve<T>(v: &mut Vec<T>, more: usize) {
    if v.capacity() - v.len() < more {
        v.reserve(more);
        advise_huge_pages(v);
    }
}

/// The size from which a vector is advised huge pages (see [`advise_huge_pages`]).
const LARGE: usize = 4 << 20;

/// Asks Linux to back the memory of `v`, where it is large, with transparent huge pages: a page fault per 2 MiB
/// written instead of one per 4 KiB. The sweep writes its vectors once, front to back, so on a large operation
/// with memory fresh from the system the faults were most of the time: on the benchmark's machine (a virtual
/// one, about 2.4 µs a fault) 40% of the 500 × 500 bars' intersection (docs/benchmarks.md). The advice covers
/// every page the vector touches, so that a large allocation's mapping is advised whole: advising a part of it
/// splits it, and the allocator can then no longer grow it in place (it copies instead). Where the system's
/// setting is `never`, and on other systems, nothing changes.
#[cfg(target_os = "linux")]
#[cold]
#[inline(never)]
fn advise_huge_pages<T>(v: &Vec<T>) {
    let bytes = v.capacity() * size_of::<T>();
    if bytes < LARGE {
        return;
    }
    // SAFETY: sysconf only reads; madvise's range is the pages that hold the allocation `v` owns, mapped while it
    // does. The advice changes how pages are backed, never what they hold, and an error (an old kernel, or one
    // without huge pages) leaves the memory as it was: it is ignored.
    unsafe {
        let page = libc::sysconf(libc::_SC_PAGESIZE).max(1) as usize;
        let start = v.as_ptr() as usize / page * page;
        let end = (v.as_ptr() as usize + bytes).next_multiple_of(page);
        libc::madvise(start as *mut libc::c_void, end - start, libc::MADV_HUGEPAGE);
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_huge_pages<T>(_: &Vec<T>) {}

/// Frees the memory this thread keeps between operations (see the crate's documentation, *Memory*). The next
/// operation allocates anew.
pub fn free_working_memory() {
    let _ = KEPT.try_with(Cell::take);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{difference, intersection, union, MultiPolygon};

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
        // Past the bound, the largest vectors that fit are kept (the room reserved is address space only, never
        // written).
        with(true, |workspace| {
            workspace
                .events
                .reserve(KEEP_BYTES / size_of::<SweepEvent>() + 1);
            workspace.vertices.reserve(1000);
        });
        assert_eq!(kept_events(), 0);
        assert!(with(true, |workspace| workspace.vertices.capacity()) >= 1000);
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
        let around_small = grid(1, 4.0, 0.0);
        free_working_memory();
        let fresh = [
            intersection(&large, &small).unwrap(),
            union(&small, &small).unwrap(),
            difference(&around_small, &small).unwrap(),
        ];
        // The difference is one square with the nine small ones as its holes, the tables of `connect` that place
        // holes among what the large operation leaves.
        assert_eq!(fresh[2].0.len(), 1);
        assert_eq!(fresh[2].0[0].holes.len(), 9);
        free_working_memory();
        // A large operation first leaves longer vectors, with its data in them, to the smaller ones after it.
        difference(&large, &small).unwrap();
        assert!(kept_events() > 0);
        assert_eq!(intersection(&large, &small).unwrap(), fresh[0]);
        assert_eq!(union(&small, &small).unwrap(), fresh[1]);
        assert_eq!(difference(&around_small, &small).unwrap(), fresh[2]);
    }

    /// The huge pages' advice covers a grown large vector's whole mapping, as one mapping with the flag (`hg` in
    /// /proc/self/smaps): advising a part splits the mapping, and the allocator can then no longer grow it in place.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_large_vector_is_advised_huge_pages_as_one_mapping() {
        // (Grown from a small vector, whose elements move into the new one.)
        let mut v: Vec<u64> = (0..1000).collect();
        assert!(room(&mut v, (16 << 20) / 8));
        assert!(v.iter().copied().eq(0..1000));
        let (start, end) = (v.as_ptr() as usize, v.as_ptr() as usize + (16 << 20));
        let smaps = std::fs::read_to_string("/proc/self/smaps").unwrap();
        let mut lines = smaps.lines();
        let mut found = false;
        while let Some(line) = lines.next() {
            let Some((range, _)) = line.split_once(' ') else {
                continue;
            };
            let Some((low, high)) = range.split_once('-') else {
                continue;
            };
            let (Ok(low), Ok(high)) = (
                usize::from_str_radix(low, 16),
                usize::from_str_radix(high, 16),
            ) else {
                continue;
            };
            if (low..high).contains(&start) {
                assert!(high >= end, "the vector spans more than one mapping");
                // (A kernel built without transparent huge pages refuses the advice, and nothing changes.)
                let flags = lines.find(|l| l.starts_with("VmFlags:")).unwrap();
                let kernel_has_them =
                    std::path::Path::new("/sys/kernel/mm/transparent_hugepage").exists();
                assert!(
                    !kernel_has_them || flags.split_whitespace().any(|f| f == "hg"),
                    "{flags}"
                );
                found = true;
                break;
            }
        }
        assert!(found, "no mapping holds the vector");
    }
}
