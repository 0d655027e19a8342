//! The paper's Table 1 on real data, native: Natural Earth land (59,212 vertices) against grids of N squares,
//! polysweep beside i_overlay, geo's BooleanOps and Clipper2 (the C++ library through the `clipper2` crate), in one
//! process and one run. Each engine gets its input already in its own types; the time is the operation alone.
//! Warm-up once, then several runs taken in turns with the other engines; medians. Result areas are checked against
//! each other and against the reference areas of tests/data/README.md. Also the floor: sorting the 2n event points.
//!
//! Writes target/bench/native.json, and the square grids of every N as GeoJSON (target/bench/squares-N.json) for
//! the wasm benchmark (web/bench/wasm.mjs). `cargo run --release -p polysweep-bench`.
//!
//! For profiling, arguments narrow the run: `-- polysweep 3895` runs only the engines and sizes named (engine names,
//! `floor` for the sort floor, numbers of squares) and writes no report.

use geo::{Area, BooleanOps};
use i_overlay::core::fill_rule::FillRule as IFillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use polysweep::{MultiPolygon, Operation, Options};
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

/// Timed runs of each engine: a warm-up each (which gives the result area), then the runs in rounds, one of every
/// engine per round, so that a change in the machine's speed over the seconds of a workload falls on all engines
/// alike. Each round starts one engine further on, so that no engine always runs after the same one (and finds the
/// caches and the allocator as that one left them). Returns each engine's times, sorted, and area.
fn timed_rounds(engines: &mut [&mut dyn FnMut() -> f64]) -> Vec<(Vec<f64>, f64)> {
    let areas: Vec<f64> = engines.iter_mut().map(|run| run()).collect();
    let runs = std::env::var("BENCH_RUNS")
        .map_or(RUNS, |r| r.parse().expect("BENCH_RUNS: a number of runs"));
    let mut times = vec![Vec::with_capacity(runs); engines.len()];
    for round in 0..runs.max(1) {
        for turn in 0..engines.len() {
            let engine = (round + turn) % engines.len();
            let start = Instant::now();
            std::hint::black_box(engines[engine]());
            times[engine].push(start.elapsed().as_secs_f64() * 1e3);
        }
    }
    for t in &mut times {
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

/// The engines and sizes named on the command line; empty means all.
struct Filter {
    engines: Vec<String>,
    sizes: Vec<usize>,
}

impl Filter {
    fn from_args() -> Self {
        let (sizes, engines): (Vec<String>, Vec<String>) = std::env::args()
            .skip(1)
            .partition(|a| a.parse::<usize>().is_ok());
        Filter {
            engines,
            sizes: sizes.iter().map(|s| s.parse().unwrap()).collect(),
        }
    }

    fn is_narrowed(&self) -> bool {
        !self.engines.is_empty() || !self.sizes.is_empty()
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

/// Runs every engine on one workload, and with the intersection the sort floor (see `main`) in the same rounds, so
/// that the floor and the engines meet the machine's slow and fast phases alike.
fn run_all(
    operation: &str,
    land: &Inputs,
    clip: &Inputs,
    n: usize,
    filter: &Filter,
    out: &mut Vec<Value>,
    floors: &mut Vec<Value>,
) {
    let op = match operation {
        "intersection" => (Operation::Intersection, OverlayRule::Intersect),
        "union" => (Operation::Union, OverlayRule::Union),
        _ => (Operation::Difference, OverlayRule::Difference),
    };
    let engines: Vec<(&str, Engine)> = vec![
        (
            "polysweep",
            Box::new(|| {
                polysweep::overlay(op.0, &land.ours, &clip.ours, &Options::default())
                    .unwrap()
                    .area()
            }),
        ),
        (
            "i_overlay",
            Box::new(|| {
                let shapes = land.shapes.overlay(&clip.shapes, op.1, IFillRule::EvenOdd);
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
            Box::new(|| match operation {
                "intersection" => land.geo.intersection(&clip.geo).unsigned_area(),
                "union" => land.geo.union(&clip.geo).unsigned_area(),
                _ => land.geo.difference(&clip.geo).unsigned_area(),
            }),
        ),
        (
            "clipper2",
            Box::new(|| {
                let c = clipper2::Clipper::new()
                    .add_subject(land.clipper.clone())
                    .add_clip(clip.clipper.clone());
                let result = match operation {
                    "intersection" => c.intersect(clipper2::FillRule::EvenOdd),
                    "union" => c.union(clipper2::FillRule::EvenOdd),
                    _ => c.difference(clipper2::FillRule::EvenOdd),
                };
                result.unwrap().signed_area().abs()
            }),
        ),
    ];
    // The floor: sorting the 2n endpoints of the edges, as the event queue's initial sort does. The same inputs give
    // the same floor for union and difference, but it is timed in their rounds too, so that each ratio to it
    // compares times taken in the same stretch of this noisy machine's time.
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
    let (points, mut sorted) = (&points, points.clone());
    let floor: Engine = Box::new(move || {
        sorted.copy_from_slice(points);
        sorted.sort_unstable_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        sorted[0][0]
    });
    let floor = (!points.is_empty()).then_some(("floor", floor));
    let (names, mut runs): (Vec<&str>, Vec<Engine>) = (engines.into_iter().chain(floor))
        .filter(|(e, _)| filter.engine(e))
        .unzip();
    let mut runs: Vec<&mut dyn FnMut() -> f64> = runs.iter_mut().map(|r| &mut **r as _).collect();
    for (engine, (times, area)) in names.into_iter().zip(timed_rounds(&mut runs)) {
        let (ms, fastest) = (times[times.len() / 2], times[0]);
        if engine == "floor" {
            println!(
                "{:>12} {n:>6} squares  {:<10} {ms:>9.2} ms",
                "sort floor", operation
            );
            floors.push(json!({ "squares": n, "operation": operation, "median_ms": ms }));
            continue;
        }
        println!("{operation:>12} {n:>6} squares  {engine:<10} {ms:>9.2} ms  (fastest {fastest:>8.2})  area {area:.6}");
        out.push(json!({ "engine": engine, "operation": operation, "squares": n, "median_ms": ms, "area": area }));
    }
}

fn main() {
    let filter = Filter::from_args();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let data = root.join("tests/data");
    let out_dir = root.join("target/bench");
    std::fs::create_dir_all(&out_dir).unwrap();
    let land_value = read_gz(&data.join("land-50m.json.gz"));
    std::fs::write(out_dir.join("land.json"), land_value.to_string()).unwrap();
    let land = Inputs::new(coordinates(&land_value));
    let mut sizes: Vec<usize> = SCALING.iter().chain(&PAPER).copied().collect();
    sizes.sort();
    sizes.dedup();
    sizes.retain(|&n| filter.size(n));
    let mut runs = Vec::new();
    let mut floor = Vec::new();
    for &n in &sizes {
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
        let clip = Inputs::new(grid);
        run_all(
            "intersection",
            &land,
            &clip,
            n,
            &filter,
            &mut runs,
            &mut floor,
        );
        if n == 3895 {
            run_all("union", &land, &clip, n, &filter, &mut runs, &mut floor);
            run_all(
                "difference",
                &land,
                &clip,
                n,
                &filter,
                &mut runs,
                &mut floor,
            );
        }
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
    let report = json!({ "machine": machine, "runs": runs, "sort_floor": floor });
    std::fs::write(
        out_dir.join("native.json"),
        serde_json::to_string_pretty(&report).unwrap(),
    )
    .unwrap();
    println!("wrote {}", out_dir.join("native.json").display());
}
