//! The shared fixtures of `tests/fixtures/` (one JSON file per case, see its README), run through the core: every
//! operation's result must equal the expected one after normalisation, pass the output validator, and stay the
//! same under translation, rotation by 90°, swapped operands of symmetric operations and reversed rings, and with
//! every optimisation that is not in the paper switched off.

mod common;

use common::*;
use polysweep::{overlay, validate, FillRule, MultiPolygon, Operation, Options, Point};
use serde_json::Value;

struct Fixture {
    name: String,
    subject: MultiPolygon,
    clipping: MultiPolygon,
    options: Options,
    expected: Vec<(&'static str, Operation, MultiPolygon)>,
}

fn load() -> Vec<Fixture> {
    let mut paths: Vec<_> = std::fs::read_dir(fixtures_dir())
        .expect("tests/fixtures exists")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    paths
        .iter()
        .map(|path| {
            let v: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
            let fill_rule = match v["fill_rule"].as_str() {
                Some("evenodd") => FillRule::EvenOdd,
                Some("nonzero") => FillRule::NonZero,
                Some("positive") => FillRule::Positive,
                Some("negative") => FillRule::Negative,
                Some("structure") => FillRule::Structure,
                other => panic!("{}: bad fill_rule {other:?}", path.display()),
            };
            Fixture {
                name: v["name"].as_str().unwrap().to_string(),
                subject: multipolygon(&v["subject"]),
                clipping: multipolygon(&v["clipping"]),
                options: Options::default().with_fill_rule(fill_rule),
                expected: OPERATIONS
                    .iter()
                    .map(|&(key, op)| (key, op, multipolygon(&v["expected"][key])))
                    .collect(),
            }
        })
        .collect()
}

/// Runs every fixture with `on_operands` applied to the operands and `on_expected` to the expected results, and
/// returns the failures.
fn check_all(
    label: &str,
    on_operands: impl Fn(&MultiPolygon) -> MultiPolygon,
    on_expected: impl Fn(&MultiPolygon) -> MultiPolygon,
    swap_symmetric: bool,
) -> Vec<String> {
    check_all_with(label, on_operands, on_expected, swap_symmetric, |o| o)
}

/// [`check_all`], with each fixture's options changed by `on_options`.
fn check_all_with(
    label: &str,
    on_operands: impl Fn(&MultiPolygon) -> MultiPolygon,
    on_expected: impl Fn(&MultiPolygon) -> MultiPolygon,
    swap_symmetric: bool,
    on_options: impl Fn(Options) -> Options,
) -> Vec<String> {
    let mut failures = Vec::new();
    for f in load() {
        let winding_rule = [FillRule::NonZero, FillRule::Positive, FillRule::Negative];
        if label == "reversed rings" && winding_rule.contains(&f.options.fill_rule) {
            continue; // reversing rings changes the meaning of the input under the winding rules
        }
        let (subject, clipping) = (on_operands(&f.subject), on_operands(&f.clipping));
        for (key, op, expected) in &f.expected {
            let (a, b) = if swap_symmetric && *op != Operation::Difference {
                (&clipping, &subject)
            } else {
                (&subject, &clipping)
            };
            let what = format!("{} / {key} / {label}", f.name);
            match overlay(*op, a, b, &on_options(f.options)) {
                Err(e) => failures.push(format!("{what}: error {e}")),
                Ok(result) => {
                    if let Err(e) = validate(&result) {
                        failures.push(format!(
                            "{what}: invalid output: {e}\n  {:?}",
                            result.to_coordinates()
                        ));
                    }
                    let expected = normalise(&on_expected(expected));
                    let got = normalise(&result);
                    if got != expected {
                        failures.push(format!(
                            "{what}:\n  expected {expected:?}\n  got      {got:?}"
                        ));
                    }
                }
            }
        }
    }
    failures
}

fn assert_none(failures: Vec<String>) {
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn there_are_fixtures_for_every_case_of_the_paper() {
    let names: Vec<String> = load().into_iter().map(|f| f.name).collect();
    assert!(names.len() >= 30, "only {} fixtures", names.len());
    for figure in ["fig2", "fig3", "fig4", "fig6", "fig7", "fig10", "fig11"] {
        assert!(
            names.iter().any(|n| n.starts_with(figure)),
            "no fixture for {figure}"
        );
    }
}

#[test]
fn fixtures_as_given() {
    assert_none(check_all(
        "as given",
        MultiPolygon::clone,
        MultiPolygon::clone,
        false,
    ));
}

#[test]
fn fixtures_translated() {
    let shift = |m: &MultiPolygon| map_points(m, |p| Point::new(p.x + 1024.0, p.y - 512.0));
    assert_none(check_all("translated", shift, shift, false));
}

#[test]
fn fixtures_rotated_by_90_degrees() {
    let rotate = |m: &MultiPolygon| map_points(m, |p| Point::new(-p.y, p.x));
    assert_none(check_all("rotated", rotate, rotate, false));
}

#[test]
fn fixtures_with_swapped_operands() {
    assert_none(check_all(
        "swapped",
        MultiPolygon::clone,
        MultiPolygon::clone,
        true,
    ));
}

#[test]
fn fixtures_with_reversed_rings() {
    assert_none(check_all(
        "reversed rings",
        reverse_rings,
        MultiPolygon::clone,
        false,
    ));
}

#[test]
fn fixtures_with_the_papers_algorithm_alone() {
    assert_none(check_all_with(
        "without shortcuts",
        MultiPolygon::clone,
        MultiPolygon::clone,
        false,
        Options::without_shortcuts,
    ));
}
