//! The shared fixtures of `tests/fixtures/lines-and-layers/` (clip, split, overlay of layers, dissolve; expectations
//! from GEOS and exact rationals, see its README), run through the core; every polygon result also validated.

mod common;

use common::{fixtures_dir, multipolygon, normalise};
use polysweep::{
    clip, dissolve, overlay_layers, split, validate, ClipOptions, FillRule, Keep, LayerMode,
    LineString, MultiPolygon, Options, Point,
};
use serde_json::Value;

fn load() -> Vec<Value> {
    let dir = fixtures_dir().join("lines-and-layers");
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .expect("tests/fixtures/lines-and-layers exists")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    (paths.iter())
        .map(|p| serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap())
        .collect()
}

fn fill_rule(case: &Value) -> FillRule {
    match case["fill_rule"].as_str().unwrap() {
        "evenodd" => FillRule::EvenOdd,
        "nonzero" => FillRule::NonZero,
        other => panic!("fill rule {other}"),
    }
}

fn lines(value: &Value) -> Vec<LineString> {
    let lines: Vec<Vec<[f64; 2]>> = serde_json::from_value(value.clone()).unwrap();
    (lines.into_iter())
        .map(|l| l.into_iter().map(Point::from).collect())
        .collect()
}

fn coordinates(parts: &[Vec<LineString>]) -> Vec<Vec<Vec<[f64; 2]>>> {
    (parts.iter())
        .map(|line| {
            (line.iter())
                .map(|part| part.iter().map(|&p| p.into()).collect())
                .collect()
        })
        .collect()
}

fn polygons(value: &Value) -> Vec<MultiPolygon> {
    value.as_array().unwrap().iter().map(multipolygon).collect()
}

fn valid(m: &MultiPolygon, what: &str) {
    if let Err(e) = validate(m) {
        panic!("{what}: invalid result: {e:?}");
    }
}

fn cases(operation: &str) -> Vec<Value> {
    let cases: Vec<Value> = (load().into_iter())
        .filter(|c| c["operation"] == operation)
        .collect();
    assert!(
        cases.len() >= 4,
        "only {} {operation} fixtures",
        cases.len()
    );
    cases
}

#[test]
fn clip_fixtures() {
    for case in cases("clip") {
        let name = case["name"].as_str().unwrap();
        let (input, polygon) = (lines(&case["lines"]), multipolygon(&case["polygon"]));
        for (keep, key) in [(Keep::Inside, "inside"), (Keep::Outside, "outside")] {
            let options = ClipOptions::default()
                .keeping(keep)
                .with_fill_rule(fill_rule(&case));
            let parts = clip(&input, &polygon, &options).unwrap();
            let expected: Vec<Vec<Vec<[f64; 2]>>> =
                serde_json::from_value(case["expected"][key].clone()).unwrap();
            assert_eq!(coordinates(&parts), expected, "{name}: {key}");
        }
    }
}

#[test]
fn split_fixtures() {
    for case in cases("split") {
        let name = case["name"].as_str().unwrap();
        let options = Options::default().with_fill_rule(fill_rule(&case));
        let pieces = split(
            &multipolygon(&case["polygon"]),
            &lines(&case["lines"]),
            &options,
        )
        .unwrap();
        let pieces = MultiPolygon(pieces);
        for piece in &pieces.0 {
            valid(&MultiPolygon(vec![piece.clone()]), name);
        }
        // (The pieces, each one polygon, are a MultiPolygon's coordinates.)
        let expected = multipolygon(&case["expected"]["pieces"]);
        assert_eq!(normalise(&pieces), normalise(&expected), "{name}");
    }
}

#[test]
fn overlay_layers_fixtures() {
    for case in cases("overlay_layers") {
        let name = case["name"].as_str().unwrap();
        let options = Options::default().with_fill_rule(fill_rule(&case));
        let (a, b) = (polygons(&case["layer_a"]), polygons(&case["layer_b"]));
        let faces = overlay_layers(&a, &b, LayerMode::Union, &options).unwrap();
        let expected = case["expected"]["faces"].as_array().unwrap();
        let tags = |v: &Value| -> Vec<u32> { serde_json::from_value(v.clone()).unwrap() };
        assert_eq!(
            faces
                .iter()
                .map(|f| (f.a.clone(), f.b.clone()))
                .collect::<Vec<_>>(),
            (expected.iter())
                .map(|e| (tags(&e["a"]), tags(&e["b"])))
                .collect::<Vec<_>>(),
            "{name}: the faces' features"
        );
        for (face, e) in faces.iter().zip(expected) {
            valid(&face.polygons, name);
            assert_eq!(
                normalise(&face.polygons),
                normalise(&multipolygon(&e["polygon"])),
                "{name}: face {:?} {:?}",
                face.a,
                face.b
            );
        }
        // Every mode is a filter over the same faces.
        for (mode, keeps) in [
            (
                LayerMode::Intersection,
                (|a, b| a && b) as fn(bool, bool) -> bool,
            ),
            (LayerMode::Identity, |a, _| a),
            (LayerMode::Difference, |a, b| a && !b),
            (LayerMode::Xor, |a, b| a != b),
        ] {
            let some = overlay_layers(&a, &b, mode, &options).unwrap();
            let wanted: Vec<_> = (faces.iter())
                .filter(|f| keeps(!f.a.is_empty(), !f.b.is_empty()))
                .collect();
            assert_eq!(some.iter().collect::<Vec<_>>(), wanted, "{name}: {mode:?}");
        }
    }
}

#[test]
fn dissolve_fixtures() {
    for case in cases("dissolve") {
        let name = case["name"].as_str().unwrap();
        let options = Options::default().with_fill_rule(fill_rule(&case));
        let features = case["features"].as_array().unwrap();
        let keyed: Vec<(&str, MultiPolygon)> = (features.iter())
            .map(|f| (f["key"].as_str().unwrap(), multipolygon(&f["polygon"])))
            .collect();
        let mut groups = dissolve(&keyed, &options).unwrap();
        groups.sort_by_key(|g| g.0);
        let expected = case["expected"]["groups"].as_array().unwrap();
        assert_eq!(groups.len(), expected.len(), "{name}");
        for ((key, merged), e) in groups.iter().zip(expected) {
            assert_eq!(*key, e["key"].as_str().unwrap(), "{name}");
            valid(merged, name);
            assert_eq!(
                normalise(merged),
                normalise(&multipolygon(&e["polygon"])),
                "{name}: {key}"
            );
        }
    }
}

#[test]
fn bad_input_is_an_error_that_names_the_line_or_feature() {
    use polysweep::{Error, Location};
    let square = multipolygon(&serde_json::json!([[[[0, 0], [4, 0], [4, 4], [0, 4]]]]));
    let at = |error: Error| error.location().expect("names a vertex");
    let good = vec![Point::new(-1.0, 1.0), Point::new(5.0, 1.0)];
    let bad = vec![
        Point::new(0.0, 0.0),
        Point::new(1.0, 1.0),
        Point::new(f64::NAN, 2.0),
    ];
    // A line is operand 1, its index the polygon's, ring 0.
    let line_at = Location {
        operand: 1,
        polygon: 1,
        ring: 0,
        vertex: 2,
    };
    let lines = [good.clone(), bad];
    assert_eq!(
        at(clip(&lines, &square, &ClipOptions::default()).unwrap_err()),
        line_at
    );
    assert_eq!(
        at(split(&square, &lines, &Options::default()).unwrap_err()),
        line_at
    );
    // A layer's polygons are counted through its features.
    let far = multipolygon(&serde_json::json!([[[[0, 0], [1, 0], [1, 1e300]]]]));
    let layer = [square.clone(), square.clone(), far];
    let error = overlay_layers(
        std::slice::from_ref(&square),
        &layer,
        LayerMode::Union,
        &Options::default(),
    )
    .unwrap_err();
    assert_eq!(
        at(error),
        Location {
            operand: 1,
            polygon: 2,
            ring: 0,
            vertex: 2
        }
    );
    // Dissolve names the feature as the operand.
    let nan = multipolygon(&serde_json::json!([[[[0, 0], [1, 0], [1, 1]]]]));
    let mut with_nan = nan.clone();
    with_nan.0[0].exterior[1].y = f64::NAN;
    let keyed = [("a", nan), ("b", square.clone()), ("a", with_nan)];
    let error = dissolve(&keyed, &Options::default()).unwrap_err();
    assert_eq!(
        at(error),
        Location {
            operand: 2,
            polygon: 0,
            ring: 0,
            vertex: 1
        }
    );
    // And the library goes on.
    let parts = clip(&[good], &square, &ClipOptions::default()).unwrap();
    assert_eq!(
        parts,
        vec![vec![vec![Point::new(0.0, 1.0), Point::new(4.0, 1.0)]]]
    );
}

#[test]
fn a_closed_line_is_not_cut_where_it_closes() {
    let square = multipolygon(&serde_json::json!([[[[0, 0], [4, 0], [4, 4], [0, 4]]]]));
    let points = |p: &[[f64; 2]]| -> LineString { p.iter().map(|&q| Point::from(q)).collect() };
    let ring = points(&[[2.0, 2.0], [6.0, 2.0], [6.0, 6.0], [2.0, 6.0], [2.0, 2.0]]);
    let inside = clip(
        std::slice::from_ref(&ring),
        &square,
        &ClipOptions::default(),
    )
    .unwrap();
    assert_eq!(
        inside,
        vec![vec![points(&[[2.0, 4.0], [2.0, 2.0], [4.0, 2.0]])]]
    );
    let outside = clip(
        &[ring],
        &square,
        &ClipOptions::default().keeping(Keep::Outside),
    )
    .unwrap();
    let around = points(&[[4.0, 2.0], [6.0, 2.0], [6.0, 6.0], [2.0, 6.0], [2.0, 4.0]]);
    assert_eq!(outside, vec![vec![around]]);
    // Open, the same points are cut at the start.
    let open = points(&[[2.0, 2.0], [6.0, 2.0], [6.0, 6.0], [2.0, 6.0], [2.0, 2.5]]);
    assert_eq!(
        clip(&[open], &square, &ClipOptions::default()).unwrap()[0].len(),
        2
    );
}

#[test]
fn a_line_that_bends_inside_cuts() {
    // The square [2, 4]² and lines that bend inside it: the walk at the bend must turn along the line, not back
    // along the half-edge it came in by (found in the playground).
    let square = multipolygon(&serde_json::json!([[[[2, 2], [4, 2], [4, 4], [2, 4]]]]));
    let points = |p: &[[f64; 2]]| -> LineString { p.iter().map(|&q| Point::from(q)).collect() };
    let areas = |lines: &[LineString]| {
        let mut areas: Vec<f64> = (split(&square, lines, &Options::default()).unwrap().iter())
            .map(|p| p.area())
            .collect();
        areas.sort_by(f64::total_cmp);
        areas
    };
    assert_eq!(
        areas(&[points(&[[1.0, 3.0], [3.0, 3.0], [3.0, 7.0]])]),
        [1.0, 3.0]
    );
    assert_eq!(
        areas(&[points(&[[3.0, 7.0], [3.0, 3.0], [1.0, 3.0]])]),
        [1.0, 3.0]
    );
    assert_eq!(
        areas(&[points(&[[3.0, 1.0], [3.0, 3.0], [5.0, 3.0]])]),
        [1.0, 3.0]
    );
    // Two lines meeting inside; and a bend down by 1/8, through (2, 2.9375) and (4, 2.9375): below it two
    // trapezoids of mean height 0.90625.
    let two = [
        points(&[[1.0, 3.0], [3.0, 3.0]]),
        points(&[[3.0, 3.0], [3.0, 7.0]]),
    ];
    assert_eq!(areas(&two), [1.0, 3.0]);
    assert_eq!(
        areas(&[points(&[[1.0, 3.0], [3.0, 2.875], [5.0, 3.0]])]),
        [1.8125, 2.1875]
    );
}
