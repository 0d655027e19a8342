//! Boolean operation on two GeoJSON files, result as GeoJSON on stdout.
//!
//! ```text
//! cargo run --release --example boolean -- <intersection|union|difference|xor> a.geojson b.geojson
//! ```
//!
//! Each file holds a Polygon or MultiPolygon geometry, a Feature with one, or a FeatureCollection of them; all
//! polygons of a file form one operand (a polygon set under the even-odd rule). Files ending in `.gz` are read
//! gzip-compressed. The result is a GeoJSON MultiPolygon geometry; its area, vertex counts and the time of the
//! operation go to stderr.

use polysweep::{overlay_with_stats, MultiPolygon, Operation, Options};
use serde_json::{json, Value};
use std::io::Read;
use std::process::ExitCode;
use std::time::Instant;

fn read(path: &str) -> Result<Value, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    let mut text = String::new();
    if path.ends_with(".gz") {
        flate2::read::GzDecoder::new(&bytes[..])
            .read_to_string(&mut text)
            .map_err(|e| format!("{path}: {e}"))?;
    } else {
        text = String::from_utf8(bytes).map_err(|e| format!("{path}: {e}"))?;
    }
    serde_json::from_str(&text).map_err(|e| format!("{path}: {e}"))
}

fn coordinates(value: &Value, what: &str) -> Result<Vec<Vec<[f64; 2]>>, String> {
    let rings = value.as_array().ok_or(format!(
        "{what}: polygon coordinates must be an array of rings"
    ))?;
    rings
        .iter()
        .map(|ring| {
            ring.as_array()
                .ok_or(format!("{what}: a ring must be an array of positions"))?
                .iter()
                .map(|p| {
                    match p.as_array().map(|a| {
                        (
                            a.first().and_then(Value::as_f64),
                            a.get(1).and_then(Value::as_f64),
                        )
                    }) {
                        Some((Some(x), Some(y))) => Ok([x, y]),
                        _ => Err(format!("{what}: a position must be [x, y] numbers")),
                    }
                })
                .collect()
        })
        .collect()
}

/// Collects the polygons of a GeoJSON object into `out`.
fn polygons(value: &Value, out: &mut Vec<Vec<Vec<[f64; 2]>>>) -> Result<(), String> {
    match value["type"].as_str() {
        Some("Polygon") => out.push(coordinates(&value["coordinates"], "Polygon")?),
        Some("MultiPolygon") => {
            for p in value["coordinates"].as_array().ok_or("MultiPolygon: coordinates must be an array")? {
                out.push(coordinates(p, "MultiPolygon")?);
            }
        }
        Some("Feature") => polygons(&value["geometry"], out)?,
        Some("FeatureCollection") => {
            for f in value["features"].as_array().ok_or("FeatureCollection: features must be an array")? {
                polygons(f, out)?;
            }
        }
        other => return Err(format!("unsupported GeoJSON type {other:?}: expected Polygon, MultiPolygon, Feature or FeatureCollection")),
    }
    Ok(())
}

fn operand(path: &str) -> Result<MultiPolygon, String> {
    let mut coords = Vec::new();
    polygons(&read(path)?, &mut coords).map_err(|e| format!("{path}: {e}"))?;
    Ok(MultiPolygon::from_coordinates(&coords))
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
        "{op}: {} + {} vertices in, {} out, {} polygons, {} crossings, {} repair passes, area {:.6}, {:.2} ms",
        subject.vertex_count(),
        clipping.vertex_count(),
        result.vertex_count(),
        result.0.len(),
        stats.crossings,
        stats.repair_passes,
        result.area(),
        elapsed.as_secs_f64() * 1e3
    );
    println!(
        "{}",
        json!({ "type": "MultiPolygon", "coordinates": result.to_coordinates() })
    );
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
