//! The paper's Table 1 workload on real data (tests/data, see its README): Natural Earth land intersected with
//! grids of squares. Result areas must match the reference areas of tests/data/README.md (all exact float
//! engines agree to these digits) to 1e-9 relative, the number of edge crossings must match, and every result must
//! pass the validator. With any optimisation that is not in the paper switched off, the results are the same.

mod common;

use polysweep::{
    overlay_with_stats, validate, FillRule, MultiPolygon, Operation, Options, Shortcuts,
};
use std::io::Read;

fn load(name: &str) -> MultiPolygon {
    let path = common::fixtures_dir()
        .join("../data")
        .join(format!("{name}.json.gz"));
    let mut text = String::new();
    flate2::read::GzDecoder::new(std::fs::File::open(&path).unwrap())
        .read_to_string(&mut text)
        .unwrap();
    let value: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(value["type"], "MultiPolygon");
    common::multipolygon(&value["coordinates"])
}

fn check(operation: Operation, squares: &str, area: f64, crossings: usize, land: &MultiPolygon) {
    check_with(
        operation,
        squares,
        area,
        crossings,
        land,
        &Options::default(),
    );
}

/// [`check`] with `options`; returns the result.
fn check_with(
    operation: Operation,
    squares: &str,
    area: f64,
    crossings: usize,
    land: &MultiPolygon,
    options: &Options,
) -> MultiPolygon {
    let clip = load(squares);
    let (result, stats) = overlay_with_stats(operation, land, &clip, options).unwrap();
    let relative = (result.area() - area).abs() / area;
    // The reference is given to 6 decimals (about 1e-10 relative at these magnitudes).
    assert!(
        relative < 1e-9,
        "{operation:?} land × {squares}: area {} vs {area} ({relative:e} relative)",
        result.area()
    );
    assert_eq!(
        stats.crossings, crossings,
        "{operation:?} land × {squares}: edge crossings"
    );
    validate(&result).unwrap_or_else(|e| panic!("{operation:?} land × {squares}: {e}"));
    result
}

#[test]
fn land_intersected_with_squares() {
    let land = load("land-50m");
    assert_eq!(land.vertex_count(), 59_212);
    check(
        Operation::Intersection,
        "squares-8",
        12707.833308,
        160,
        &land,
    );
    check(
        Operation::Intersection,
        "squares-162",
        13044.967019,
        792,
        &land,
    );
    check(
        Operation::Intersection,
        "squares-974",
        13451.382211,
        2006,
        &land,
    );
    check(
        Operation::Intersection,
        "squares-3895",
        13307.146280,
        3960,
        &land,
    );
}

#[test]
fn land_union_and_difference_with_3895_squares() {
    let land = load("land-50m");
    check(Operation::Union, "squares-3895", 46913.956575, 3960, &land);
    check(
        Operation::Difference,
        "squares-3895",
        8110.128937,
        3960,
        &land,
    );
}

/// Under the structural reading the land and the squares, valid input, are read as they are, without a structural
/// pass: the same areas and crossings as under even-odd (the reference areas), and `structure_sweeps` 0: the operation's own
/// sweep saw both valid. With the watch off every operand is read by its structure, to the same areas.
#[test]
fn valid_input_is_read_by_its_structure_without_a_structural_pass() {
    let land = load("land-50m");
    let structure = Options::default().with_fill_rule(FillRule::Structure);
    let cases = [
        (Operation::Intersection, "squares-8", 12707.833308, 160),
        (Operation::Intersection, "squares-3895", 13307.146280, 3960),
        (Operation::Union, "squares-3895", 46913.956575, 3960),
        (Operation::Difference, "squares-3895", 8110.128937, 3960),
    ];
    for (operation, squares, area, crossings) in cases {
        let clip = load(squares);
        let (_, stats) = overlay_with_stats(operation, &land, &clip, &structure).unwrap();
        assert_eq!(stats.structure_sweeps, 0, "{operation:?} land × {squares}");
        check_with(operation, squares, area, crossings, &land, &structure);
    }
    let mut unwatched = structure;
    unwatched.shortcuts.watch_structure = false;
    let clip = load("squares-974");
    let (result, stats) =
        overlay_with_stats(Operation::Intersection, &land, &clip, &unwatched).unwrap();
    // A sweep per ring, one per polygon with holes (one land polygon has a hole) and one for their union, for each.
    let rings = |m: &MultiPolygon| m.0.iter().map(|p| 1 + p.holes.len()).sum::<usize>();
    let with_holes = |m: &MultiPolygon| m.0.iter().filter(|p| !p.holes.is_empty()).count();
    let sweeps = |m: &MultiPolygon| rings(m) + with_holes(m) + 1;
    assert_eq!(stats.structure_sweeps, sweeps(&land) + sweeps(&clip));
    let relative = (result.area() - 13451.382211).abs() / 13451.382211;
    assert!(relative < 1e-9, "area {}", result.area());
}

/// A shortcut's name, and what switches it off.
type Switch = (&'static str, fn(&mut Shortcuts));

/// Each optimisation not in the paper, switched off.
const SWITCHES: [Switch; 13] = [
    ("prune_by_boxes", |s| s.prune_by_boxes = false),
    ("prune_by_winding", |s| s.prune_by_winding = false),
    ("copy_inside", |s| s.copy_inside = false),
    ("copy_apart", |s| s.copy_apart = false),
    ("prune_inside_convex", |s| s.prune_inside_convex = false),
    ("stop_early", |s| s.stop_early = false),
    ("crossing_step", |s| s.crossing_step = false),
    ("successor_in_place", |s| s.successor_in_place = false),
    ("insert_after_last", |s| s.insert_after_last = false),
    ("shared_start", |s| s.shared_start = false),
    ("merge_identical_edges", |s| s.merge_identical_edges = false),
    ("keep_working_memory", |s| s.keep_working_memory = false),
    ("watch_structure", |s| s.watch_structure = false),
];

#[test]
fn every_shortcut_off_gives_the_same_results() {
    let land = load("land-50m");
    let cases = [
        (Operation::Intersection, "squares-974", 13451.382211, 2006),
        (Operation::Union, "squares-3895", 46913.956575, 3960),
        (Operation::Difference, "squares-3895", 8110.128937, 3960),
    ];
    for (operation, squares, area, crossings) in cases {
        let with_all = check_with(
            operation,
            squares,
            area,
            crossings,
            &land,
            &Options::default(),
        );
        let mut variants: Vec<(&str, Options)> = SWITCHES
            .iter()
            .map(|&(name, switch_off)| {
                let mut options = Options::default();
                switch_off(&mut options.shortcuts);
                (name, options)
            })
            .collect();
        variants.push(("all", Options::default().without_shortcuts()));
        for (name, options) in variants {
            let result = check_with(operation, squares, area, crossings, &land, &options);
            assert!(
                common::normalise(&result) == common::normalise(&with_all),
                "{operation:?} land × {squares} with {name} off: not the result with every shortcut on"
            );
        }
    }
}
