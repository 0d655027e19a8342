//! Boolean operation on two GeoJSON files, result as GeoJSON on stdout.
//!
//! ```text
//! cargo run --release --features geojson --example boolean -- <intersection|union|difference|xor> a.geojson b.geojson
//! ```
//!
//! Each file holds GeoJSON as [`polysweep::geojson::parse`] reads it; all polygons of a file form one operand (a
//! polygon set under the even-odd rule). Files ending in `.gz` are read gzip-compressed. The result is a GeoJSON MultiPolygon geometry; its area, vertex counts and the time of the
//! operation go to stderr.

use polysweep::{geojson, overlay_with_stats, MultiPolygon, Operation, Options};
use std::io::Read;
use std::process::ExitCode;
use std::time::Instant;

fn read(path: &str) -> Result<String, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    let mut text = String::new();
    if path.ends_with(".gz") {
        flate2::read::GzDecoder::new(&bytes[..])
            .read_to_string(&mut text)
            .map_err(|e| format!("{path}: {e}"))?;
    } else {
        text = String::from_utf8(bytes).map_err(|e| format!("{path}: {e}"))?;
    }
    Ok(text)
}

fn operand(path: &str) -> Result<MultiPolygon, String> {
    geojson::parse(&read(path)?).map_err(|e| format!("{path}: {e}"))
}

fn run(args: &[String]) -> Result<(), String> {
    let [op, a, b] = args else {
        return Err(
            "usage: boolean <intersection|union|difference|xor> a.geojson b.geojson".into(),
        );
    };
    let operation = match op.as_str() {
        "intersection" => Operation::Intersection,
        "union" => Operation::Union,
        "difference" => Operation::Difference,
        "xor" => Operation::Xor,
        _ => {
            return Err(format!(
                "unknown operation {op:?}: expected intersection, union, difference or xor"
            ))
        }
    };
    let (subject, clipping) = (operand(a)?, operand(b)?);
    let start = Instant::now();
    let (result, stats) = overlay_with_stats(operation, &subject, &clipping, &Options::default())
        .map_err(|e| e.to_string())?;
    let elapsed = start.elapsed();
    eprintln!(
        "{op}: {} + {} vertices in, {} out, {} polygons, {} crossings, {} snap-rounding sweeps, area {:.6}, {:.2} ms",
        subject.vertex_count(),
        clipping.vertex_count(),
        result.vertex_count(),
        result.0.len(),
        stats.crossings,
        stats.snap_rounding_sweeps,
        result.area(),
        elapsed.as_secs_f64() * 1e3
    );
    println!("{}", geojson::to_geometry(&result));
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}
