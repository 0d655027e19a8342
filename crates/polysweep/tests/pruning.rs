//! Polygons an operation leaves out of its sweep or copies to its result (the shortcuts of `prune::plan`), each
//! case with its expectation worked out by hand: the area, and the number of edges swept.

use polysweep::{overlay_with_stats, MultiPolygon, Operation, Options};

/// Polygons whose box meets no polygon's box of the other operand are left out of an intersection (and clipping
/// polygons out of a difference), even inside the other operand's box; those that meet one are kept. Subject:
/// A = [10, 11] × [90, 91] and B = [50, 52]²; clipping: C = [0, 1]², D = [100, 101]² and E = [51, 53]². A lies
/// inside the clipping operand's box but apart from C, D and E (on the grid of 3 × 3 cells the five polygons get,
/// A's cell is one no clipping box touches); C and D lie outside the subject's box. Expected by hand: the
/// intersection is B ∩ E = [51, 52]², area 1, from B and E only (8 edges swept); the difference is
/// A + B − E, area 1 + 4 − 1, from B and E swept (8 edges) and A, apart from every other polygon, copied.
#[test]
fn polygons_apart_from_the_other_operand_are_left_out() {
    let boxes = |corners: &[[f64; 3]]| {
        let coordinates: Vec<Vec<Vec<[f64; 2]>>> = (corners.iter())
            .map(|&[x, y, size]| {
                vec![vec![
                    [x, y],
                    [x + size, y],
                    [x + size, y + size],
                    [x, y + size],
                ]]
            })
            .collect();
        MultiPolygon::from_coordinates(&coordinates)
    };
    let subject = boxes(&[[10.0, 90.0, 1.0], [50.0, 50.0, 2.0]]);
    let clipping = boxes(&[[0.0, 0.0, 1.0], [100.0, 100.0, 1.0], [51.0, 51.0, 2.0]]);
    assert_area_and_edges_swept(
        &subject,
        &clipping,
        &[
            (Operation::Intersection, 1.0, 8),
            (Operation::Difference, 4.0, 8),
        ],
    );
}

/// Polygons that are simple rings apart from every other polygon are copied to a union, a xor or a difference, not
/// swept, and those of the clipping operand left out of a difference. Subject: A = [0, 2]², which overlaps the
/// clipping square C = [1, 3]², B = [10, 11]² and the triangle T = (20, 0), (20, 1), (21, 0), given clockwise;
/// clipping: C and D = [30, 31]². Expected by hand, with only A and C swept (8 edges): the union A ∪ C (7) plus B
/// (1), T (0.5) and D (1), 9.5 in four polygons; the xor, two L-shapes of 3 touching at two corners, + B + T + D = 8.5
/// in five; the difference, A − C (3) + B + T = 4.5 in three. The same without any shortcut.
#[test]
fn polygons_apart_from_all_others_are_copied() {
    let subject = MultiPolygon::from_coordinates(&[
        vec![vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]],
        vec![vec![[10.0, 10.0], [11.0, 10.0], [11.0, 11.0], [10.0, 11.0]]],
        vec![vec![[20.0, 0.0], [20.0, 1.0], [21.0, 0.0]]],
    ]);
    let clipping = MultiPolygon::from_coordinates(&[
        vec![vec![[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]],
        vec![vec![[30.0, 30.0], [31.0, 30.0], [31.0, 31.0], [30.0, 31.0]]],
    ]);
    let expected = [
        (Operation::Union, 9.5, 4),
        (Operation::Xor, 8.5, 5),
        (Operation::Difference, 4.5, 3),
    ];
    assert_area_and_edges_swept(
        &subject,
        &clipping,
        &expected.map(|(operation, area, _)| (operation, area, 8)),
    );
    for (operation, area, polygons) in expected {
        for options in [Options::default(), Options::default().without_shortcuts()] {
            let result = polysweep::overlay(operation, &subject, &clipping, &options).unwrap();
            assert_eq!(
                (result.area(), result.0.len()),
                (area, polygons),
                "{operation:?}"
            );
        }
    }
}

/// Each operation's result has the area expected and is valid, and the sweep took the number of edges expected.
fn assert_area_and_edges_swept(
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    expected: &[(Operation, f64, usize)],
) {
    for &(operation, area, edges) in expected {
        let options = Options::default();
        let (result, stats) = overlay_with_stats(operation, subject, clipping, &options).unwrap();
        assert_eq!(
            (result.area(), stats.input_edges),
            (area, edges),
            "{operation:?}"
        );
        assert!(polysweep::validate(&result).is_ok());
    }
}

/// A clipping polygon wholly outside the subject and away from its edges is left out of an intersection and a
/// difference, and one wholly inside it out of a union; an intersection copies one wholly inside it, apart from
/// the other clipping polygons, to its result without sweeping it. Subject: [0, 100]² (each side cut into 100
/// edges) with the hole [40, 60]² (each side cut into 25): 500 edges. Clipping: 100 squares of side 2 at
/// (10i + 4, 10j + 4), i and j from 0 to 9. The subject's winding number is known on a grid of 20 × 20 cells of side
/// 5 (four cells per clipping square, fewer than the subject's vertices), in the cells that no edge touches: not in
/// the outermost rows and columns (the square's sides) nor where the hole's sides run (columns and rows 8 and 12,
/// from 8 to 12).
/// Square (i, j) covers columns 2i and 2i + 1 and rows 2j and 2j + 1, so, worked out by hand:
/// - known inside: i and j from 1 to 8 but not both from 4 to 6: 64 − 9 = 55 squares;
/// - known outside: (5, 5), in the hole, away from its sides: 1 square;
/// - in the hole: (4, 4), (4, 5), (5, 4) and (5, 5), so 96 squares inside.
///
/// Expected: intersection 96 · 4 = 384, from 500 + 44 · 4 = 676 edges (the 55 squares known inside are copied);
/// union 9,600 + 4 · 4 = 9,616, from 500 + 45 · 4 = 680 edges. The difference, 10,000 − 400 − 384 = 9,216, sweeps
/// all 500 + 100 · 4 = 900 edges: it could leave out only squares outside the subject, and none of the 16 it
/// samples first (every seventh) starts outside, so it does not work out the winding numbers (see the next test).
#[test]
fn clipping_polygons_wholly_inside_or_outside_the_subject_are_left_out() {
    let subject = square_with_hole(40.0, 20.0, 25);
    assert_area_and_edges_swept(
        &subject,
        &ten_by_ten_squares(),
        &[
            (Operation::Intersection, 384.0, 676),
            (Operation::Difference, 9216.0, 900),
            (Operation::Union, 9616.0, 680),
        ],
    );
}

/// A difference leaves out clipping polygons in a hole of the subject. Subject: as above with the hole [20, 80]²
/// (each side cut into 60 edges): 640 edges and vertices, and the same grid of cells of side 5. Clipping: the same
/// 100 squares; square (i, j) lies in the hole for i and j from 2 to 7 (36 squares). The hole's sides run through
/// columns and rows 4 and 16 (from 4 to 16), so the squares with i or j = 2 (columns or rows 4 and 5) are not known;
/// known outside are i and j from 3 to 7: 25 squares, of which the sample (every seventh) meets (5, 3). Expected:
/// 10,000 − 3,600 − 64 · 4 = 6,144, from 640 + 75 · 4 = 940 edges.
#[test]
fn a_difference_leaves_out_clipping_polygons_in_a_hole_of_the_subject() {
    assert_area_and_edges_swept(
        &square_with_hole(20.0, 60.0, 60),
        &ten_by_ten_squares(),
        &[(Operation::Difference, 6144.0, 940)],
    );
}

/// [0, 100]² with each side cut into 100 edges, and a square hole from (`at`, `at`) of side `side`, each of its sides
/// cut into `pieces` edges.
fn square_with_hole(at: f64, side: f64, pieces: u32) -> MultiPolygon {
    let cut_square = |x: f64, side: f64, pieces: u32| {
        let corners = [
            [x, x],
            [x + side, x],
            [x + side, x + side],
            [x, x + side],
            [x, x],
        ];
        (corners.windows(2))
            .flat_map(|w| {
                (0..pieces).map(move |i| {
                    [0, 1].map(|k| w[0][k] + (w[1][k] - w[0][k]) * f64::from(i) / f64::from(pieces))
                })
            })
            .collect::<Vec<[f64; 2]>>()
    };
    let mut hole = cut_square(at, side, pieces);
    hole.reverse();
    MultiPolygon::from_coordinates(&[vec![cut_square(0.0, 100.0, 100), hole]])
}

/// 100 squares of side 2 at (10i + 4, 10j + 4), i and j from 0 to 9, listed row by row.
fn ten_by_ten_squares() -> MultiPolygon {
    let squares: Vec<Vec<Vec<[f64; 2]>>> = (0..100)
        .map(|n| {
            let (x, y) = (
                f64::from(n % 10) * 10.0 + 4.0,
                f64::from(n / 10) * 10.0 + 4.0,
            );
            vec![vec![[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]]]
        })
        .collect();
    MultiPolygon::from_coordinates(&squares)
}
