//! Each engine's peak memory in one operation, measured in a process of its own so that no other run's memory
//! counts: the benchmark starts itself again as `polysweep-bench memory ENGINE WORKLOAD N`.

use crate::{dense, engines, Inputs};

/// The peak memory of one engine's run of a dense workload: the bench started again in a process of its own
/// (`polysweep-bench memory ENGINE WORKLOAD N`, see [`memory_child`]), so that no other run's memory counts. None
/// where /proc is not there to say.
pub fn peak_memory(engine: &str, workload: &str, n: usize) -> Option<u64> {
    let output = std::process::Command::new(std::env::current_exe().ok()?)
        .args(["memory", engine, workload, &n.to_string()])
        .output()
        .ok()?;
    String::from_utf8(output.stdout).ok()?.trim().parse().ok()
}

/// One field of /proc/self/status, in bytes.
fn status_bytes(field: &str) -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(field))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// The child of [`peak_memory`]: builds the inputs, resets the peak of the resident set (Linux: 5 to
/// /proc/self/clear_refs), runs the engine once and prints the peak's growth above the resident set before the run:
/// what the operation itself touched, for Rust's allocator and for Clipper2's C++ alike.
pub fn memory_child(engine_name: &str, workload: &str, n: usize) {
    let w = dense::workloads(&[workload.to_string()], &[n])
        .pop()
        .expect("a dense workload and size");
    let (a, b) = (Inputs::new(w.subject), Inputs::new(w.clip));
    let (_, mut engine) = engines(w.operation, w.fill_rule, &a, &b)
        .into_iter()
        .find(|(name, _)| *name == engine_name)
        .expect("an engine name");
    let measured = (|| {
        std::fs::write("/proc/self/clear_refs", "5").ok()?;
        let before = status_bytes("VmRSS:")?;
        std::hint::black_box(engine());
        Some(status_bytes("VmHWM:")?.saturating_sub(before))
    })();
    if let Some(bytes) = measured {
        println!("{bytes}");
    }
}
