//! The paper's Table 1 on real data, native: Natural Earth land (59,212 vertices) against grids of N squares,
//! polysweep beside i_overlay, geo's BooleanOps and Clipper2 (the C++ library through the `clipper2` crate), in one
//! process and one run. Each engine gets its input already in its own types; the time is the operation alone.
//! Several runs taken in rounds, each round a run of every engine at every size in a shuffled order, each right
//! after a warm-up run; medians. Result areas are checked against each other and against the reference areas of
//! tests/data/README.md. Also the floor: sorting the 2n event points.
//!
//! Writes target/bench/native.json, and the square grids of every N as GeoJSON (target/bench/squares-N.json) for
//! the wasm benchmark (web/bench/wasm.mjs). `cargo run --release -p polysweep-bench`.
//!
//! For profiling, arguments narrow the run: `-- polysweep 3895` runs only the engines and sizes named (engine names,
//! `floor` for the sort floor, numbers of squares) and writes no report. `BENCH_FILL_RULE=structure` runs polysweep
//! under the structural reading (the npm package's default) instead of even-odd.

mod dense;
mod memory;

use geo::algorithm::bool_ops::{FillRule as GeoFillRule, OpType};
use geo::{Area, BooleanOps};
use i_overlay::core::fill_rule::FillRule as IFillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use polysweep::{FillRule, MultiPolygon, Operation, Options};
use serde_json::{json, Value};
use std::io::Read;
use std::path::Path;
use std::time::Instant;

const SCALING: [usize; 7] = [8, 32, 128, 512, 2048, 8192, 32768];
const PAPER: [usize; 4] = [8, 162, 974, 3895];
/// Reference areas of the intersections (tests/data/README.md), and of union and difference at 3,895.
const REFERENCE: [(usize, f64); 4] = [
    (8, 12707.833308),
    (162, 13044.967019),
    (974, 13451.382211),
    (3895, 13307.146280),
];
/// Timed runs per engine and workload; `BENCH_RUNS` overrides it (more runs steady the minimum for A/B comparisons
/// on a noisy machine). 21: on this shared 2-core machine, medians of 11 moved by up to 10% between runs of the same
/// code; the native benchmark takes about a minute and a half with 21.
const RUNS: usize = 21;
/// Timed runs of each dense workload (`BENCH_DENSE_RUNS` overrides it): fewer, as the largest take seconds.
const DENSE_RUNS: usize = 7;
/// A run slower than this (in ms) is timed once (see [`timed_rounds`]).
const SLOW_MS: f64 = 2000.0;

/// Clipper2 works on integers: coordinates scaled by 10^8, its finest documented precision.
#[derive(Debug, Default, Clone, Copy, PartialEq, Hash)]
struct Nano;
impl clipper2::PointScaler for Nano {
    const MULTIPLIER: f64 = 100_000_000.0;
}

type Coordinates = Vec<Vec<Vec<[f64; 2]>>>;

fn read_gz(path: &Path) -> Value {
    let mut text = String::new();
    flate2::read::GzDecoder::new(std::fs::File::open(path).expect("data file"))
        .read_to_string(&mut text)
        .unwrap();
    serde_json::from_str(&text).unwrap()
}

fn coordinates(v: &Value) -> Coordinates {
    serde_json::from_value(v["coordinates"].clone()).unwrap()
}

/// The grid rule of tests/data/README.md.
fn squares(n: usize) -> Coordinates {
    let (min_x, min_y, max_x, max_y) = (-180.0f64, -89.999f64, 180.0f64, 83.59960937500003f64);
    let (w, h) = (max_x - min_x, max_y - min_y);
    let cols = ((n as f64 * w / h).sqrt().round() as usize).max(1);
    let rows = n.div_ceil(cols);
    let (cw, ch) = (w / cols as f64, h / rows as f64);
    let half = 0.8 * cw.min(ch) / 2.0;
    (0..n)
        .map(|i| {
            let cell = i * cols * rows / n;
            let (cx, cy) = (
                min_x + ((cell % cols) as f64 + 0.5) * cw,
                min_y + ((cell / cols) as f64 + 0.5) * ch,
            );
            vec![vec![
                [cx - half, cy - half],
                [cx + half, cy - half],
                [cx + half, cy + half],
                [cx - half, cy + half],
                [cx - half, cy - half],
            ]]
        })
        .collect()
}

/// Timed runs of every engine on every workload, in rounds: each round takes every engine on every workload, in
/// an order of its own (shuffled, from a fixed seed), and times each run right after a warm-up run of the same, so
/// that it finds its own data in the caches, as after the warm-up the method asks for, and not another engine's
/// (after Clipper2 at 32,768 squares, say, which goes through hundreds of megabytes). Taken in rounds, a change in
/// the machine's speed (this one has slow phases of several seconds) falls on all engines and all sizes alike:
/// taken workload by workload instead, a slow phase that fell on one size moved the scaling slopes of all engines
/// by more than their difference. Returns each run's times, sorted, and area (of the first warm-up).
fn timed_rounds(runs: &mut [Run], rounds: usize) -> Vec<(Vec<f64>, f64)> {
    // The first run gives the area, and its time: a run slower than `SLOW_MS` (Clipper2 on the larger nested
    // squares takes minutes) is not repeated, and that time is its only one.
    let first: Vec<(f64, f64)> = (runs.iter_mut())
        .map(|r| {
            let start = Instant::now();
            let area = (r.engine)();
            (area, start.elapsed().as_secs_f64() * 1e3)
        })
        .collect();
    let areas: Vec<f64> = first.iter().map(|&(area, _)| area).collect();
    let mut times = vec![Vec::with_capacity(rounds); runs.len()];
    let mut order: Vec<usize> = (0..runs.len()).collect();
    // xorshift64: any fixed sequence of shuffles will do, the same in every benchmark run.
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut random = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for _ in 0..rounds.max(1) {
        for i in (1..order.len()).rev() {
            order.swap(i, (random() % (i as u64 + 1)) as usize);
        }
        for &run in order.iter().filter(|&&run| first[run].1 <= SLOW_MS) {
            std::hint::black_box((runs[run].engine)());
            let start = Instant::now();
            std::hint::black_box((runs[run].engine)());
            times[run].push(start.elapsed().as_secs_f64() * 1e3);
        }
    }
    for (t, &(_, ms)) in times.iter_mut().zip(&first) {
        if t.is_empty() {
            t.push(ms);
        }
        t.sort_by(f64::total_cmp);
    }
    times.into_iter().zip(areas).collect()
}

fn geo_multipolygon(c: &Coordinates) -> geo::MultiPolygon<f64> {
    let line = |r: &Vec<[f64; 2]>| {
        geo::LineString::from(r.iter().map(|p| (p[0], p[1])).collect::<Vec<_>>())
    };
    geo::MultiPolygon(
        c.iter()
            .map(|p| geo::Polygon::new(line(&p[0]), p[1..].iter().map(line).collect()))
            .collect(),
    )
}

fn clipper_paths(c: &Coordinates) -> clipper2::Paths<Nano> {
    // Clipper takes rings without structure and fills them by a rule; drop the closing vertex.
    let rings: Vec<Vec<(f64, f64)>> = c
        .iter()
        .flatten()
        .map(|r| r[..r.len() - 1].iter().map(|p| (p[0], p[1])).collect())
        .collect();
    rings.into()
}

fn shoelace(ring: &[[f64; 2]]) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| ring[i][0] * ring[(i + 1) % n][1] - ring[(i + 1) % n][0] * ring[i][1])
        .sum::<f64>()
        / 2.0
}

struct Inputs {
    ours: MultiPolygon,
    shapes: Coordinates,
    geo: geo::MultiPolygon<f64>,
    clipper: clipper2::Paths<Nano>,
}

impl Inputs {
    fn new(c: Coordinates) -> Self {
        Inputs {
            ours: MultiPolygon::from_coordinates(&c),
            geo: geo_multipolygon(&c),
            clipper: clipper_paths(&c),
            shapes: c,
        }
    }
}

const ENGINES: [&str; 5] = ["polysweep", "i_overlay", "geo", "clipper2", "floor"];

/// The engines, workloads (`table1` or a dense workload's name) and sizes named on the command line; empty means
/// all.
struct Filter {
    engines: Vec<String>,
    workloads: Vec<String>,
    sizes: Vec<usize>,
}

impl Filter {
    fn from_args() -> Self {
        let (sizes, names): (Vec<String>, Vec<String>) = std::env::args()
            .skip(1)
            .partition(|a| a.parse::<usize>().is_ok());
        let (engines, workloads) = names
            .into_iter()
            .partition(|a| ENGINES.contains(&a.as_str()));
        Filter {
            engines,
            workloads,
            sizes: sizes.iter().map(|s| s.parse().unwrap()).collect(),
        }
    }

    fn is_narrowed(&self) -> bool {
        !self.engines.is_empty() || !self.workloads.is_empty() || !self.sizes.is_empty()
    }

    fn workload(&self, name: &str) -> bool {
        self.workloads.is_empty() || self.workloads.iter().any(|w| w == name)
    }

    fn dense_names(&self) -> Vec<String> {
        let names: Vec<String> = self
            .workloads
            .iter()
            .filter(|w| *w != "table1")
            .cloned()
            .collect();
        if !self.workloads.is_empty() && names.is_empty() {
            vec!["none".into()]
        } else {
            names
        }
    }

    fn engine(&self, name: &str) -> bool {
        self.engines.is_empty() || self.engines.iter().any(|e| e == name)
    }

    fn size(&self, n: usize) -> bool {
        self.sizes.is_empty() || self.sizes.contains(&n)
    }
}

/// One engine's run of a workload, returning the result's area.
type Engine<'a> = Box<dyn FnMut() -> f64 + 'a>;

/// A timed run: an engine (or the sort floor, `floor`) on one workload.
struct Run<'a> {
    name: &'static str,
    operation: &'static str,
    squares: usize,
    engine: Engine<'a>,
}

/// The engines on one pair of operands under one operation and fill rule, each returning its result's area. geo has
/// no fill rule of its own for self-overlapping input beyond i_overlay's, which it wraps; it gets the same rule.
fn engines<'a>(
    operation: &'static str,
    fill_rule: &str,
    a: &'a Inputs,
    b: &'a Inputs,
) -> Vec<(&'static str, Engine<'a>)> {
    let (op, i_op, geo_op) = match operation {
        "intersection" => (
            Operation::Intersection,
            OverlayRule::Intersect,
            OpType::Intersection,
        ),
        "union" => (Operation::Union, OverlayRule::Union, OpType::Union),
        "difference" => (
            Operation::Difference,
            OverlayRule::Difference,
            OpType::Difference,
        ),
        "xor" => (Operation::Xor, OverlayRule::Xor, OpType::Xor),
        _ => panic!("unknown operation {operation}"),
    };
    let nonzero = fill_rule == "nonzero";
    let ours = if nonzero {
        FillRule::NonZero
    } else {
        match std::env::var("BENCH_FILL_RULE").as_deref() {
            Ok("structure") => FillRule::Structure,
            _ => FillRule::EvenOdd,
        }
    };
    let options = Options::default().with_fill_rule(ours);
    let (i_fill, geo_fill, clipper_fill) = if nonzero {
        (
            IFillRule::NonZero,
            GeoFillRule::NonZero,
            clipper2::FillRule::NonZero,
        )
    } else {
        (
            IFillRule::EvenOdd,
            GeoFillRule::EvenOdd,
            clipper2::FillRule::EvenOdd,
        )
    };
    vec![
        (
            "polysweep",
            Box::new(move || {
                polysweep::overlay(op, &a.ours, &b.ours, &options)
                    .unwrap()
                    .area()
            }),
        ),
        (
            "i_overlay",
            Box::new(move || {
                let shapes = a.shapes.overlay(&b.shapes, i_op, i_fill);
                shapes
                    .iter()
                    .flatten()
                    .map(|c| shoelace(c))
                    .sum::<f64>()
                    .abs()
            }),
        ),
        (
            "geo",
            Box::new(move || {
                a.geo
                    .boolean_op_with_fill_rule(&b.geo, geo_op, geo_fill)
                    .unsigned_area()
            }),
        ),
        (
            "clipper2",
            Box::new(move || {
                let c = clipper2::Clipper::new()
                    .add_subject(a.clipper.clone())
                    .add_clip(b.clipper.clone());
                let result = match operation {
                    "intersection" => c.intersect(clipper_fill),
                    "union" => c.union(clipper_fill),
                    "difference" => c.difference(clipper_fill),
                    _ => c.xor(clipper_fill),
                };
                result.unwrap().signed_area().abs()
            }),
        ),
    ]
}

/// The runs of one Table 1 workload: every engine the filter names, and the sort floor (see `main`), each timed in
/// the same rounds as all the others (see [`timed_rounds`]), so that the floor and the engines meet the machine's
/// slow and fast phases alike.
fn workload<'a>(
    operation: &'static str,
    land: &'a Inputs,
    clip: &'a Inputs,
    n: usize,
    filter: &Filter,
) -> Vec<Run<'a>> {
    // The floor: sorting the 2n endpoints of the edges, as the event queue's initial sort does. The same inputs give
    // the same floor for the three operations at 3,895 squares; it is timed for each all the same, so that each
    // ratio to it has a floor of its own (and the three show the noise).
    let points: Vec<[f64; 2]> = if filter.engine("floor") {
        (land.shapes.iter().chain(&clip.shapes))
            .flatten()
            .flat_map(|r| r.windows(2).flat_map(|w| [w[0], w[1]]))
            .collect()
    } else {
        Vec::new()
    };
    // Copied into the same vector every run, as polysweep keeps its vectors from one operation to the next: a
    // fresh copy would add the page faults of new memory, which are not the sort's.
    let mut sorted = points.clone();
    let has_floor = !points.is_empty();
    let floor: Engine<'a> = Box::new(move || {
        sorted.copy_from_slice(&points);
        sorted.sort_unstable_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        sorted[0][0]
    });
    let floor = has_floor.then_some(("floor", floor));
    (engines(operation, "evenodd", land, clip)
        .into_iter()
        .chain(floor))
    .filter(|(e, _)| filter.engine(e))
    .map(|(name, engine)| Run {
        name,
        operation,
        squares: n,
        engine,
    })
    .collect()
}

/// Table 1: land ∩ N squares over the series, ∪ and − at 3,895. Returns the engines' runs and the sort floor's.
fn table1(filter: &Filter, out_dir: &Path) -> (Vec<Value>, Vec<Value>) {
    let data = out_dir.join("../../tests/data");
    let land_value = read_gz(&data.join("land-50m.json.gz"));
    std::fs::write(out_dir.join("land.json"), land_value.to_string()).unwrap();
    let land = Inputs::new(coordinates(&land_value));
    let mut sizes: Vec<usize> = SCALING.iter().chain(&PAPER).copied().collect();
    sizes.sort();
    sizes.dedup();
    sizes.retain(|&n| filter.size(n));
    let grids: Vec<(usize, Inputs)> = sizes
        .iter()
        .map(|&n| {
            // The paper's grids are the shipped files; the rest of the series is generated by the same rule.
            let shipped = data.join(format!("squares-{n}.json.gz"));
            let grid = if shipped.exists() {
                coordinates(&read_gz(&shipped))
            } else {
                squares(n)
            };
            std::fs::write(
                out_dir.join(format!("squares-{n}.json")),
                json!({ "type": "MultiPolygon", "coordinates": grid }).to_string(),
            )
            .unwrap();
            (n, Inputs::new(grid))
        })
        .collect();
    let mut timed: Vec<Run> = Vec::new();
    for (n, clip) in &grids {
        timed.extend(workload("intersection", &land, clip, *n, filter));
        if *n == 3895 {
            timed.extend(workload("union", &land, clip, *n, filter));
            timed.extend(workload("difference", &land, clip, *n, filter));
        }
    }
    let (mut runs, mut floor) = (Vec::new(), Vec::new());
    let rounds = std::env::var("BENCH_RUNS")
        .map_or(RUNS, |r| r.parse().expect("BENCH_RUNS: a number of runs"));
    let results = timed_rounds(&mut timed, rounds);
    for (run, (times, area)) in timed.iter().zip(results) {
        let (ms, fastest) = (times[times.len() / 2], times[0]);
        let (engine, operation, n) = (run.name, run.operation, run.squares);
        if engine == "floor" {
            println!(
                "{:>12} {n:>6} squares  {operation:<10} {ms:>9.2} ms",
                "sort floor"
            );
            floor.push(json!({ "squares": n, "operation": operation, "median_ms": ms }));
            continue;
        }
        println!("{operation:>12} {n:>6} squares  {engine:<10} {ms:>9.2} ms  (fastest {fastest:>8.2})  area {area:.6}");
        runs.push(json!({ "engine": engine, "operation": operation, "squares": n, "median_ms": ms, "area": area }));
    }
    for (n, reference) in REFERENCE {
        for run in runs
            .iter()
            .filter(|r| r["squares"] == n && r["operation"] == "intersection")
        {
            let area = run["area"].as_f64().unwrap();
            if (area - reference).abs() / reference > 1e-6 {
                println!(
                    "note: {} at {n} squares: area {area} differs from the reference {reference}",
                    run["engine"]
                );
            }
        }
    }
    (runs, floor)
}

/// The dense workloads (see `dense`): every engine at every size, timed in rounds as Table 1, then each engine's
/// peak memory in a process of its own (see [`memory::peak_memory`]). Writes each workload's operands to
/// target/bench/dense/ for the wasm benchmark.
fn dense_runs(filter: &Filter, out_dir: &Path, measure_memory: bool) -> Vec<Value> {
    let dir = out_dir.join("dense");
    std::fs::create_dir_all(&dir).unwrap();
    let workloads = dense::workloads(&filter.dense_names(), &filter.sizes);
    let mut index = Vec::new();
    let inputs: Vec<(Inputs, Inputs)> = workloads
        .iter()
        .map(|w| {
            let file = format!("{}-{}.json", w.name, w.n);
            let edges = dense::edge_count(&w.subject) + dense::edge_count(&w.clip);
            let head = json!({ "workload": w.name, "n": w.n, "operation": w.operation, "fill_rule": w.fill_rule, "edges": edges });
            let mut body = head.clone();
            body["subject"] = json!(w.subject);
            body["clip"] = json!(w.clip);
            std::fs::write(dir.join(&file), body.to_string()).unwrap();
            let mut entry = head;
            entry["file"] = json!(file);
            index.push(entry);
            (Inputs::new(w.subject.clone()), Inputs::new(w.clip.clone()))
        })
        .collect();
    if !filter.is_narrowed() {
        std::fs::write(
            dir.join("index.json"),
            serde_json::to_string_pretty(&index).unwrap(),
        )
        .unwrap();
    }
    let (mut timed, mut counts): (Vec<Run>, Vec<usize>) = (Vec::new(), Vec::new());
    for (w, (a, b)) in workloads.iter().zip(&inputs) {
        counts.push(timed.len());
        for (name, engine) in engines(w.operation, w.fill_rule, a, b) {
            if filter.engine(name) {
                timed.push(Run {
                    name,
                    operation: w.operation,
                    squares: w.n,
                    engine,
                });
            }
        }
    }
    let rounds = std::env::var("BENCH_DENSE_RUNS").map_or(DENSE_RUNS, |r| {
        r.parse().expect("BENCH_DENSE_RUNS: a number of runs")
    });
    let results = timed_rounds(&mut timed, rounds);
    let mut records = Vec::new();
    counts.push(timed.len());
    for (i, (w, entry)) in workloads.iter().zip(&index).enumerate() {
        let (at, runs) = (counts[i], counts[i + 1] - counts[i]);
        for (run, (times, area)) in timed[at..at + runs].iter().zip(&results[at..at + runs]) {
            let (ms, fastest) = (times[times.len() / 2], times[0]);
            let peak = measure_memory
                .then(|| memory::peak_memory(run.name, w.name, w.n))
                .flatten();
            println!(
                "{:>15} {:>6} {:<12} {:<10} {ms:>9.2} ms  (fastest {fastest:>8.2})  area {area:.6}  peak {}",
                w.name,
                w.n,
                w.operation,
                run.name,
                peak.map_or("-".to_string(), |b| format!("{:.1} MB", b as f64 / 1e6))
            );
            records.push(json!({ "workload": w.name, "n": w.n, "operation": w.operation, "edges": entry["edges"],
                "engine": run.name, "median_ms": ms, "area": area, "peak_bytes": peak }));
        }
    }
    records
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("memory") {
        memory::memory_child(&args[1], &args[2], args[3].parse().expect("a size"));
        return;
    }
    let filter = Filter::from_args();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let out_dir = root.join("target/bench");
    std::fs::create_dir_all(&out_dir).unwrap();
    let (runs, floor) = if filter.workload("table1") {
        table1(&filter, &out_dir)
    } else {
        Default::default()
    };
    let dense = dense_runs(
        &filter,
        &out_dir,
        std::env::var("BENCH_MEMORY").as_deref() != Ok("0"),
    );
    if filter.is_narrowed() {
        return;
    }
    let machine = format!(
        "{} cores, {}",
        std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1),
        std::fs::read_to_string("/proc/cpuinfo")
            .ok()
            .and_then(
                |s| s.lines().find(|l| l.starts_with("model name")).map(|l| l
                    .split(':')
                    .nth(1)
                    .unwrap_or("")
                    .trim()
                    .to_string())
            )
            .unwrap_or_default()
    );
    let report = json!({ "machine": machine, "runs": runs, "sort_floor": floor, "dense": dense });
    std::fs::write(
        out_dir.join("native.json"),
        serde_json::to_string_pretty(&report).unwrap(),
    )
    .unwrap();
    println!("wrote {}", out_dir.join("native.json").display());
}
