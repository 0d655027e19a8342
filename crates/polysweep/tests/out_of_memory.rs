//! Running out of memory is an error naming the sizes, not an abort, and the library works afterwards (issue 24).
//! A global allocator that refuses allocations beyond a limit stands in for wasm32's 4 GiB: where the allocator
//! has nothing left, Rust aborts a push, but the sweep reserves what each split needs and stops instead.
//! (One test in this file: the limit is process-wide.)

use polysweep::{intersection, Error, MultiPolygon};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

struct Limited;

static IN_USE: AtomicUsize = AtomicUsize::new(0);
static LIMIT: AtomicUsize = AtomicUsize::new(usize::MAX);

unsafe impl GlobalAlloc for Limited {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if IN_USE.load(Relaxed).saturating_add(layout.size()) > LIMIT.load(Relaxed) {
            return std::ptr::null_mut();
        }
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            IN_USE.fetch_add(layout.size(), Relaxed);
        }
        p
    }

    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        unsafe { System.dealloc(p, layout) };
        IN_USE.fetch_sub(layout.size(), Relaxed);
    }
}

#[global_allocator]
static ALLOCATOR: Limited = Limited;

/// `n` bars of width 1, 2 apart, horizontal or vertical, each 2n long: n × n bars cross n² times, in n² unit
/// squares.
fn bars(n: usize, vertical: bool) -> MultiPolygon {
    let length = 2.0 * n as f64;
    let rings: Vec<Vec<Vec<[f64; 2]>>> = (0..n)
        .map(|i| {
            let (lo, hi) = (2.0 * i as f64, 2.0 * i as f64 + 1.0);
            let ring = [[0.0, lo], [length, lo], [length, hi], [0.0, hi]];
            vec![ring
                .iter()
                .map(|&[a, b]| if vertical { [b, a] } else { [a, b] })
                .collect()]
        })
        .collect();
    MultiPolygon::from_coordinates(&rings)
}

#[test]
fn running_out_of_memory_is_an_error_and_the_library_works_afterwards() {
    let (across, down) = (bars(200, false), bars(200, true));
    // 40,000 crossings need about 10 MB; 2 MB more than what is in use now is not enough.
    LIMIT.store(IN_USE.load(Relaxed) + (2 << 20), Relaxed);
    let outcome = intersection(&across, &down);
    LIMIT.store(usize::MAX, Relaxed);
    match outcome {
        Err(Error::OutOfMemory { edges, crossings }) => {
            assert_eq!(edges, 1600);
            assert!(crossings > 0 && crossings < 40_000, "{crossings}");
            let message = Error::OutOfMemory { edges, crossings }.to_string();
            assert!(message.starts_with("out of memory"), "{message}");
        }
        other => panic!("expected an out-of-memory error, got {other:?}"),
    }
    // The same operation with memory: 40,000 unit squares.
    let result = intersection(&across, &down).expect("memory enough");
    assert_eq!(result.0.len(), 40_000);
    assert_eq!(result.area(), 40_000.0);
}
