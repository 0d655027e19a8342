//! Ready-made scenes: the paper's figures, taken from the shared test fixtures (the same files the Rust, Node and
//! browser tests read), and its Table 1 workload on real data (Natural Earth land × grids of squares, see
//! tests/data/README.md for provenance).

use polysweep::{geojson, MultiPolygon};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Preset {
    /// Fig. 3: two concave polygons; every operation has several parts.
    Fig3,
    /// Fig. 2: a vertex of one polygon on an edge of the other (the degenerate case of §1).
    Fig2,
    /// Fig. 11: a self-intersecting polygon set under the even-odd rule (§7.3).
    Fig11,
    /// Fig. 7: two triangles whose edges cross while both are in S, the walk-through of §3 (the sweep explorer's
    /// first case).
    Fig7,
    /// Table 1: world land (59,212 vertices) against `n` squares.
    Table1 { squares: usize },
}

impl Preset {
    pub const ALL: [Preset; 8] = [
        Preset::Fig3,
        Preset::Fig2,
        Preset::Fig11,
        Preset::Fig7,
        Preset::Table1 { squares: 8 },
        Preset::Table1 { squares: 162 },
        Preset::Table1 { squares: 974 },
        Preset::Table1 { squares: 3895 },
    ];

    pub fn label(self) -> String {
        match self {
            Preset::Fig3 => "Fig. 3: concave polygons".into(),
            Preset::Fig2 => "Fig. 2: vertex on an edge".into(),
            Preset::Fig11 => "Fig. 11: self-intersecting set".into(),
            Preset::Fig7 => "Fig. 7: the sweep line (explore it: X)".into(),
            Preset::Table1 { squares } => format!("Table 1: land × {squares} squares"),
        }
    }

    /// Its name in links to the playground (`?preset=fig3`, `?preset=land-8`).
    pub fn name(self) -> String {
        match self {
            Preset::Fig3 => "fig3".into(),
            Preset::Fig2 => "fig2".into(),
            Preset::Fig11 => "fig11".into(),
            Preset::Fig7 => "fig7".into(),
            Preset::Table1 { squares } => format!("land-{squares}"),
        }
    }

    pub fn named(name: &str) -> Option<Preset> {
        Preset::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The subject and clipping operands.
    pub fn operands(self) -> (MultiPolygon, MultiPolygon) {
        match self {
            Preset::Fig3 => fixture(include_str!(
                "../../../tests/fixtures/fig3-boolean-operations.json"
            )),
            Preset::Fig2 => fixture(include_str!(
                "../../../tests/fixtures/fig2-vertex-on-edge-two-regions.json"
            )),
            Preset::Fig11 => fixture(include_str!(
                "../../../tests/fixtures/fig11-self-intersecting-polygon-set.json"
            )),
            Preset::Fig7 => fixture(include_str!("../../../tests/fixtures/fig7-sweep-line.json")),
            Preset::Table1 { squares } => {
                let grid: &[u8] = match squares {
                    8 => include_bytes!("../../../tests/data/squares-8.json.gz"),
                    162 => include_bytes!("../../../tests/data/squares-162.json.gz"),
                    974 => include_bytes!("../../../tests/data/squares-974.json.gz"),
                    _ => include_bytes!("../../../tests/data/squares-3895.json.gz"),
                };
                (
                    gzipped(include_bytes!("../../../tests/data/land-50m.json.gz")),
                    gzipped(grid),
                )
            }
        }
    }
}

fn fixture(text: &str) -> (MultiPolygon, MultiPolygon) {
    let value: serde_json::Value = serde_json::from_str(text).expect("the fixtures are valid JSON");
    let operand = |key: &str| {
        let geometry = serde_json::json!({ "type": "MultiPolygon", "coordinates": value[key] });
        geojson::parse(&geometry.to_string()).expect("the fixtures hold polygon sets")
    };
    (operand("subject"), operand("clipping"))
}

fn gzipped(bytes: &[u8]) -> MultiPolygon {
    let text = crate::io::text_of(bytes).expect("the Table 1 data is gzipped text");
    geojson::parse(&text).expect("the Table 1 data is GeoJSON")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_loads_with_the_sizes_of_its_source() {
        for preset in Preset::ALL {
            let (p, q) = preset.operands();
            assert!(!p.is_empty() && !q.is_empty(), "{preset:?}");
            match preset {
                Preset::Fig11 => assert_eq!(p.0.len(), 3),
                Preset::Table1 { squares } => {
                    assert_eq!(q.0.len(), squares);
                    assert_eq!(p.0.len(), 1420);
                }
                _ => {}
            }
            assert_eq!(Preset::named(&preset.name()), Some(preset));
        }
        assert_eq!(Preset::named("land-9"), None);
    }
}
