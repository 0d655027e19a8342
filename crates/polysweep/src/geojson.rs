//! GeoJSON (RFC 7946) in and out, behind the `geojson` feature: the format map tools exchange polygons in.
//!
//! [`parse`] reads every polygon of a Polygon, MultiPolygon, Feature, FeatureCollection or GeometryCollection into
//! one [`MultiPolygon`] — one operand, whose rings together define its interior under the chosen fill rule.
//! Other geometry types (points, lines) carry no area and are skipped, so a mixed collection still loads. Coordinates
//! are only read here; whether they are usable is checked by the operations, which name the offending vertex.

use crate::geometry::{MultiPolygon, Polygon};
use serde_json::{json, Value};
use std::fmt;

/// Why a text is not a GeoJSON polygon set, with where in the document it went wrong.
#[derive(Clone, Debug, PartialEq)]
pub struct GeoJsonError(String);

impl fmt::Display for GeoJsonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "GeoJSON: {}", self.0)
    }
}

impl std::error::Error for GeoJsonError {}

/// All polygons of a GeoJSON text as one operand.
pub fn parse(text: &str) -> Result<MultiPolygon, GeoJsonError> {
    let value: Value = serde_json::from_str(text).map_err(|e| GeoJsonError(e.to_string()))?;
    let mut polygons = Vec::new();
    collect(&value, "document", &mut polygons)?;
    Ok(MultiPolygon(polygons))
}

/// A MultiPolygon geometry, with every ring closed as RFC 7946 requires (open rings are closed here).
pub fn to_geometry(m: &MultiPolygon) -> Value {
    let mut coordinates = m.to_coordinates();
    for ring in coordinates.iter_mut().flatten() {
        if let (Some(&first), Some(&last)) = (ring.first(), ring.last()) {
            if first != last {
                ring.push(first);
            }
        }
    }
    json!({ "type": "MultiPolygon", "coordinates": coordinates })
}

fn collect(value: &Value, path: &str, out: &mut Vec<Polygon>) -> Result<(), GeoJsonError> {
    let list = |key: &str| {
        value[key]
            .as_array()
            .ok_or_else(|| GeoJsonError(format!("{path}: \"{key}\" must be an array")))
    };
    match value["type"].as_str() {
        Some("Polygon") => out.push(polygon(
            &value["coordinates"],
            &format!("{path}.coordinates"),
        )?),
        Some("MultiPolygon") => {
            for (i, p) in list("coordinates")?.iter().enumerate() {
                out.push(polygon(p, &format!("{path}.coordinates[{i}]"))?);
            }
        }
        Some("Feature") if value["geometry"].is_null() => {}
        Some("Feature") => collect(&value["geometry"], &format!("{path}.geometry"), out)?,
        Some("FeatureCollection") => {
            for (i, f) in list("features")?.iter().enumerate() {
                collect(f, &format!("{path}.features[{i}]"), out)?;
            }
        }
        Some("GeometryCollection") => {
            for (i, g) in list("geometries")?.iter().enumerate() {
                collect(g, &format!("{path}.geometries[{i}]"), out)?;
            }
        }
        Some("Point" | "MultiPoint" | "LineString" | "MultiLineString") => {}
        Some(other) => return Err(GeoJsonError(format!("{path}: unknown type \"{other}\""))),
        None => return Err(GeoJsonError(format!("{path}: no \"type\" member"))),
    }
    Ok(())
}

fn polygon(value: &Value, path: &str) -> Result<Polygon, GeoJsonError> {
    let rings = value
        .as_array()
        .ok_or_else(|| GeoJsonError(format!("{path}: a polygon must be an array of rings")))?;
    let mut rings = rings.iter().enumerate().map(|(r, ring)| {
        let ring = ring.as_array().ok_or_else(|| {
            GeoJsonError(format!("{path}[{r}]: a ring must be an array of positions"))
        })?;
        ring.iter()
            .enumerate()
            .map(|(v, p)| match (p[0].as_f64(), p[1].as_f64()) {
                (Some(x), Some(y)) => Ok([x, y].into()),
                _ => Err(GeoJsonError(format!(
                    "{path}[{r}][{v}]: a position must be [x, y] numbers"
                ))),
            })
            .collect()
    });
    let exterior = rings.next().transpose()?.unwrap_or_default();
    Ok(Polygon::new(exterior, rings.collect::<Result<_, _>>()?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_every_container_and_skips_geometries_without_area() {
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,0]]]}},
            {"type":"Feature","properties":{},"geometry":null},
            {"type":"Feature","geometry":{"type":"GeometryCollection","geometries":[
                {"type":"Point","coordinates":[5,5]},
                {"type":"MultiPolygon","coordinates":[[[[3,0],[4,0],[4,1],[3,0]]],[[[5,0],[6,0],[6,1],[5,0]],[[5.5,0.1],[5.9,0.1],[5.9,0.5],[5.5,0.1]]]]}
            ]}}]}"#;
        let m = parse(text).unwrap();
        assert_eq!(m.0.len(), 3);
        assert_eq!(m.0[2].holes.len(), 1);
        assert_eq!(m.0[0].exterior[1], [2.0, 0.0].into());
        assert_eq!(parse(&to_geometry(&m).to_string()).unwrap(), m);
    }

    #[test]
    fn writes_open_rings_closed() {
        let open =
            MultiPolygon::from_coordinates(&[vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]]]);
        let ring = &to_geometry(&open)["coordinates"][0][0];
        assert_eq!(ring.as_array().unwrap().len(), 4);
        assert_eq!(ring[0], ring[3]);
    }

    #[test]
    fn says_where_the_document_is_wrong() {
        let err = parse(r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,"a"],[1,1]]]]}"#)
            .unwrap_err();
        assert_eq!(
            err.to_string(),
            "GeoJSON: document.coordinates[0][0][1]: a position must be [x, y] numbers"
        );
        assert_eq!(
            parse(r#"{"type":"Circle"}"#).unwrap_err().to_string(),
            "GeoJSON: document: unknown type \"Circle\""
        );
        assert!(parse("{").is_err());
    }
}
