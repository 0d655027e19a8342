//! The seam between the core and JavaScript: one function over flat arrays (the GeoArrow / earcut layout), so
//! that a call crosses the boundary with a few typed arrays instead of one JS object per vertex. The conversion
//! from and to GeoJSON lives in the package's JavaScript (`web/src/api.js`). No algorithm code here.

use polysweep::{
    clip, overlay, overlay_all, overlay_layers, split, Boundary, ClipOptions, FillRule, Keep,
    LayerMode, LineString, Meeting, MultiPolygon, Operation, Options, Point, Polygon, Reason, Step,
    TraceEdge,
};
use wasm_bindgen::prelude::*;

/// Operands in flat form. `coords` holds x, y pairs; ring `r` spans vertices `ring_offsets[r]..ring_offsets[r+1]`;
/// polygon `p` spans rings `polygon_offsets[p]..polygon_offsets[p+1]` (its first ring is the exterior); operand
/// `o` spans polygons `operand_offsets[o]..operand_offsets[o+1]`.
fn operands(
    coords: &[f64],
    rings: &[u32],
    polygons: &[u32],
    operands: &[u32],
) -> Result<Vec<MultiPolygon>, String> {
    let span = |offsets: &[u32], i: usize, what: &str| -> Result<std::ops::Range<usize>, String> {
        match (offsets.get(i), offsets.get(i + 1)) {
            (Some(&a), Some(&b)) if a <= b => Ok(a as usize..b as usize),
            _ => Err(format!("{what} offsets are not increasing at {i}")),
        }
    };
    let mut out = Vec::new();
    for o in 0..operands.len().saturating_sub(1) {
        let mut polygon_list = Vec::new();
        for p in span(operands, o, "operand")? {
            let mut ring_list: Vec<Vec<Point>> = Vec::new();
            for r in span(polygons, p, "polygon")? {
                let vertices = span(rings, r, "ring")?;
                // Compared as vertex counts before doubling: on wasm32, doubling an offset of 2^31 or more wraps.
                if vertices.end > coords.len() / 2 {
                    return Err(format!("ring {r} runs past the coordinates"));
                }
                let xy = &coords[2 * vertices.start..2 * vertices.end];
                ring_list.push(xy.chunks_exact(2).map(|c| Point::new(c[0], c[1])).collect());
            }
            let mut rings = ring_list.into_iter();
            polygon_list.push(Polygon::new(
                rings.next().unwrap_or_default(),
                rings.collect(),
            ));
        }
        out.push(MultiPolygon(polygon_list));
    }
    Ok(out)
}

/// The result packed in one array: `[polygons, rings, polygon offsets (polygons + 1), ring offsets (rings + 1),
/// x, y, ...]`. One array, so that the JavaScript side never holds a handle to free.
fn pack(result: &MultiPolygon) -> Vec<f64> {
    let rings: Vec<&Vec<Point>> = result.0.iter().flat_map(|p| p.rings()).collect();
    let vertices: usize = rings.iter().map(|r| r.len()).sum();
    let mut out = Vec::with_capacity(2 + result.0.len() + 1 + rings.len() + 1 + 2 * vertices);
    out.extend([result.0.len() as f64, rings.len() as f64]);
    let mut ring_count = 0;
    out.push(0.0);
    for p in &result.0 {
        ring_count += 1 + p.holes.len();
        out.push(ring_count as f64);
    }
    let mut vertex_count = 0;
    out.push(0.0);
    for r in &rings {
        vertex_count += r.len();
        out.push(vertex_count as f64);
    }
    for r in &rings {
        for p in r.iter() {
            out.extend([p.x, p.y]);
        }
    }
    out
}

/// `operation` (0 intersection, 1 union, 2 difference, 3 xor) over the flat operands, with `fill_rule` (0
/// even-odd, 1 non-zero, 2 positive, 3 negative, 4 structure). Two operands take the paper's binary sweep; any other number the n-ary one.
#[wasm_bindgen]
pub fn overlay_flat(
    operation: u8,
    fill_rule: u8,
    coords: &[f64],
    ring_offsets: &[u32],
    polygon_offsets: &[u32],
    operand_offsets: &[u32],
) -> Result<Vec<f64>, JsError> {
    let (operation, options, operands) = read_call(
        operation,
        fill_rule,
        coords,
        [ring_offsets, polygon_offsets, operand_offsets],
    )?;
    let result = match &operands[..] {
        [a, b] => overlay(operation, a, b, &options),
        _ => overlay_all(operation, &operands, &options),
    };
    result
        .map(|r| pack(&r))
        .map_err(|e| JsError::new(&e.to_string()))
}

/// The operation, options and operands of a call over flat operands (see [`operands`]).
fn read_call(
    operation: u8,
    fill_rule: u8,
    coords: &[f64],
    [rings, polygons, operands_at]: [&[u32]; 3],
) -> Result<(Operation, Options, Vec<MultiPolygon>), JsError> {
    let operation = operation_of(operation)?;
    let options = options(fill_rule)?;
    let operands = operands(coords, rings, polygons, operands_at).map_err(|e| JsError::new(&e))?;
    Ok((operation, options, operands))
}

fn operation_of(operation: u8) -> Result<Operation, JsError> {
    Ok(match operation {
        0 => Operation::Intersection,
        1 => Operation::Union,
        2 => Operation::Difference,
        3 => Operation::Xor,
        _ => {
            return Err(JsError::new(
                "operation must be 0 (intersection), 1 (union), 2 (difference) or 3 (xor)",
            ))
        }
    })
}

/// The options with fill rule `fill_rule` (0 even-odd, 1 non-zero, 2 positive, 3 negative, 4 structure).
fn options(fill_rule: u8) -> Result<Options, JsError> {
    Ok(Options::default().with_fill_rule(fill_rule_of(fill_rule)?))
}

fn fill_rule_of(fill_rule: u8) -> Result<FillRule, JsError> {
    let fill_rule = match fill_rule {
        0 => FillRule::EvenOdd,
        1 => FillRule::NonZero,
        2 => FillRule::Positive,
        3 => FillRule::Negative,
        4 => FillRule::Structure,
        _ => {
            return Err(JsError::new(
                "fill rule must be 0 (even-odd), 1 (non-zero), 2 (positive), 3 (negative) or 4 (structure)",
            ))
        }
    };
    Ok(fill_rule)
}

/// One polygon set in flat form (see [`operands`]).
fn polygon_set(coords: &[f64], rings: &[u32], polygons: &[u32]) -> Result<MultiPolygon, JsError> {
    let end = polygons.len().saturating_sub(1) as u32;
    let mut all = operands(coords, rings, polygons, &[0, end]).map_err(|e| JsError::new(&e))?;
    Ok(all.pop().unwrap_or_default())
}

/// Lines in flat form: line `l` spans vertices `line_offsets[l]..line_offsets[l+1]` of `coords`.
fn lines(coords: &[f64], line_offsets: &[u32]) -> Result<Vec<LineString>, JsError> {
    // (A line is read as a ring of one polygon each: the same checks of the offsets.)
    let each: Vec<u32> = (0..line_offsets.len() as u32).collect();
    let end = line_offsets.len().saturating_sub(1) as u32;
    let as_rings =
        operands(coords, line_offsets, &each, &[0, end]).map_err(|e| JsError::new(&e))?;
    Ok((as_rings.into_iter().flat_map(|m| m.0))
        .map(|p| p.exterior)
        .collect())
}

fn js_error(error: polysweep::Error) -> JsError {
    JsError::new(&error.to_string())
}

/// `lines` clipped by the polygon set: `keep` 0 inside, 1 outside; `boundary` 0 counts parts along the boundary as
/// inside, 1 as outside. Packed as `[lines, part offsets per line (lines + 1), vertex offsets per part (parts +
/// 1), x, y, ...]`.
#[wasm_bindgen]
#[allow(clippy::too_many_arguments)]
pub fn clip_flat(
    keep: u8,
    boundary: u8,
    fill_rule: u8,
    line_coords: &[f64],
    line_offsets: &[u32],
    coords: &[f64],
    ring_offsets: &[u32],
    polygon_offsets: &[u32],
) -> Result<Vec<f64>, JsError> {
    let clip_options = ClipOptions::default()
        .with_fill_rule(fill_rule_of(fill_rule)?)
        .keeping(if keep == 0 {
            Keep::Inside
        } else {
            Keep::Outside
        })
        .with_boundary(if boundary == 0 {
            Boundary::Inside
        } else {
            Boundary::Outside
        });
    let polygon = polygon_set(coords, ring_offsets, polygon_offsets)?;
    let parts =
        clip(&lines(line_coords, line_offsets)?, &polygon, &clip_options).map_err(js_error)?;
    let part_count: usize = parts.iter().map(Vec::len).sum();
    let mut out = vec![parts.len() as f64, 0.0];
    let mut count = 0;
    for line in &parts {
        count += line.len();
        out.push(count as f64);
    }
    let mut vertices = 0;
    out.push(0.0);
    for part in parts.iter().flatten() {
        vertices += part.len();
        out.push(vertices as f64);
    }
    debug_assert_eq!(out.len(), parts.len() + 3 + part_count);
    for p in parts.iter().flatten().flatten() {
        out.extend([p.x, p.y]);
    }
    Ok(out)
}

/// The pieces of the polygon set cut along the lines, packed as [`overlay_flat`]'s result (a polygon per piece).
#[wasm_bindgen]
pub fn split_flat(
    fill_rule: u8,
    coords: &[f64],
    ring_offsets: &[u32],
    polygon_offsets: &[u32],
    line_coords: &[f64],
    line_offsets: &[u32],
) -> Result<Vec<f64>, JsError> {
    let polygon = polygon_set(coords, ring_offsets, polygon_offsets)?;
    let pieces = split(
        &polygon,
        &lines(line_coords, line_offsets)?,
        &options(fill_rule)?,
    )
    .map_err(js_error)?;
    Ok(pack(&MultiPolygon(pieces)))
}

/// The overlay of two layers of features, flat: feature `f` spans polygons `feature_offsets[f]..[f+1]`, layer `l`
/// features `layer_offsets[l]..[l+1]` (two layers); `mode` 0 intersection, 1 union, 2 identity, 3 difference, 4
/// xor. Packed as `[faces, then per face: its count of layer-A features and their indices, its count of layer-B
/// features and theirs, its count of polygons; then all the faces' polygons packed as overlay_flat's result]`.
#[wasm_bindgen]
#[allow(clippy::too_many_arguments)]
pub fn overlay_layers_flat(
    mode: u8,
    fill_rule: u8,
    coords: &[f64],
    ring_offsets: &[u32],
    polygon_offsets: &[u32],
    feature_offsets: &[u32],
    layer_offsets: &[u32],
) -> Result<Vec<f64>, JsError> {
    let mode =
        match mode {
            0 => LayerMode::Intersection,
            1 => LayerMode::Union,
            2 => LayerMode::Identity,
            3 => LayerMode::Difference,
            4 => LayerMode::Xor,
            _ => return Err(JsError::new(
                "mode must be 0 (intersection), 1 (union), 2 (identity), 3 (difference) or 4 (xor)",
            )),
        };
    let features = operands(coords, ring_offsets, polygon_offsets, feature_offsets)
        .map_err(|e| JsError::new(&e))?;
    let layer = |l: usize| -> Result<&[MultiPolygon], JsError> {
        match (layer_offsets.get(l), layer_offsets.get(l + 1)) {
            (Some(&a), Some(&b)) if a <= b && b as usize <= features.len() => {
                Ok(&features[a as usize..b as usize])
            }
            _ => Err(JsError::new(
                "layer offsets must be three increasing feature offsets",
            )),
        }
    };
    let faces =
        overlay_layers(layer(0)?, layer(1)?, mode, &options(fill_rule)?).map_err(js_error)?;
    let mut out = vec![faces.len() as f64];
    for face in &faces {
        for list in [&face.a, &face.b] {
            out.push(list.len() as f64);
            out.extend(list.iter().map(|&i| i as f64));
        }
        out.push(face.polygons.0.len() as f64);
    }
    let all = MultiPolygon(faces.into_iter().flat_map(|f| f.polygons.0).collect());
    out.extend(pack(&all));
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_operands_unpack_and_results_pack() {
        // Two unit squares, one per operand.
        let coords = [
            0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 2.0, 0.0, 3.0, 0.0, 3.0, 1.0, 2.0, 1.0,
        ];
        let ops = operands(&coords, &[0, 4, 8], &[0, 1, 2], &[0, 1, 2]).unwrap();
        assert_eq!(ops.len(), 2);
        assert_eq!(ops[1].0[0].exterior[0], Point::new(2.0, 0.0));
        let union = overlay(Operation::Union, &ops[0], &ops[1], &Options::default()).unwrap();
        let packed = pack(&union);
        assert_eq!(&packed[..2], &[2.0, 2.0]);
        assert_eq!(&packed[2..5], &[0.0, 1.0, 2.0]);
        assert_eq!(&packed[5..8], &[0.0, 5.0, 10.0]);
        assert_eq!(packed.len(), 8 + 20);
        assert!(operands(&coords, &[0, 4, 9], &[0, 1, 2], &[0, 1, 2]).is_err());
        // Offsets whose double wraps around in 32 bits (wasm32's usize) still run past the coordinates.
        let far = [1 << 31, (1 << 31) + 4];
        assert_eq!(
            operands(&coords, &far, &[0, 1], &[0, 1]).err().as_deref(),
            Some("ring 0 runs past the coordinates")
        );
    }
}

/// The steps of the sweep of `operation` on two operands in flat form (see [`polysweep::trace`]), as JSON text: an
/// array of objects, each with a `type` ("event", "meeting", "subdivision", "flags", "selection", "status",
/// "ring") and its fields (web/src/trace.js documents them).
#[wasm_bindgen]
pub fn trace_flat(
    operation: u8,
    fill_rule: u8,
    coords: &[f64],
    ring_offsets: &[u32],
    polygon_offsets: &[u32],
    operand_offsets: &[u32],
) -> Result<String, JsError> {
    let (operation, options, operands) = read_call(
        operation,
        fill_rule,
        coords,
        [ring_offsets, polygon_offsets, operand_offsets],
    )?;
    let [a, b] = &operands[..] else {
        return Err(JsError::new("a trace takes two operands"));
    };
    let steps = polysweep::trace(operation, a, b, &options).map_err(js_error)?;
    let mut json = String::from("[");
    for (i, step) in steps.iter().enumerate() {
        if i > 0 {
            json.push(',');
        }
        step_json(&mut json, step);
    }
    json.push(']');
    Ok(json)
}

fn step_json(out: &mut String, step: &Step) {
    use std::fmt::Write;
    let point = |[x, y]: [f64; 2]| format!("[{x},{y}]");
    let edge = |e: &TraceEdge| {
        format!(
            r#"{{"left":{},"right":{},"operand":{},"winding":[{},{}]}}"#,
            point(e.left),
            point(e.right),
            e.operand,
            e.winding[0],
            e.winding[1]
        )
    };
    // (Writing to a String cannot fail.)
    let _ = match step {
        Step::Event {
            point: at,
            left,
            edge: e,
        } => write!(
            out,
            r#"{{"type":"event","point":{},"left":{left},"edge":{}}}"#,
            point(*at),
            edge(e)
        ),
        Step::Meeting {
            lower,
            upper,
            meeting,
            at,
        } => {
            let meeting = match meeting {
                Meeting::Crossing => "crossing",
                Meeting::VertexOnEdge => "vertex-on-edge",
                Meeting::Overlap => "overlap",
                _ => "other",
            };
            write!(
                out,
                r#"{{"type":"meeting","lower":{},"upper":{},"meeting":"{meeting}","at":{}}}"#,
                edge(lower),
                edge(upper),
                point(*at)
            )
        }
        Step::Subdivision { edge: e, at } => write!(
            out,
            r#"{{"type":"subdivision","edge":{},"at":{}}}"#,
            edge(e),
            point(*at)
        ),
        Step::Flags {
            edge: e,
            coverage_below: [c0, c1],
            in_out,
            inside_other,
            in_result,
        } => write!(
            out,
            r#"{{"type":"flags","edge":{},"coverageBelow":[{c0},{c1}],"inOut":{in_out},"insideOther":{inside_other},"inResult":{in_result}}}"#,
            edge(e)
        ),
        Step::Selection {
            edge: e,
            in_result,
            reason,
        } => {
            let reason = match reason {
                Reason::InsideOther => "inside-other",
                Reason::OutsideOther => "outside-other",
                Reason::SameTransition => "same-transition",
                Reason::DifferentTransition => "different-transition",
                Reason::NoTransition => "no-transition",
                _ => "other",
            };
            write!(
                out,
                r#"{{"type":"selection","edge":{},"inResult":{in_result},"reason":"{reason}"}}"#,
                edge(e)
            )
        }
        Step::Status(edges) => {
            let edges: Vec<String> = edges.iter().map(edge).collect();
            write!(out, r#"{{"type":"status","edges":[{}]}}"#, edges.join(","))
        }
        Step::Ring {
            polygon,
            ring,
            points,
        } => {
            let points: Vec<String> = points.iter().copied().map(point).collect();
            write!(
                out,
                r#"{{"type":"ring","polygon":{polygon},"ring":{ring},"points":[{}]}}"#,
                points.join(",")
            )
        }
        _ => write!(out, r#"{{"type":"other"}}"#),
    };
}
