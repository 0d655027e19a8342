//! Cases found by review, each with its expectation worked out by hand.

use polysweep::{difference, intersection, MultiPolygon};

/// Intersection and difference skip polygons outside the box where the result can lie. A hole ring may reach
/// outside its own exterior (under even-odd its outer part is filled), so that box must be of all the rings.
#[test]
fn a_hole_reaching_outside_its_shell_still_counts() {
    let square =
        |x0: f64, y0: f64, x1: f64, y1: f64| vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]];
    let p = MultiPolygon::from_coordinates(&[vec![
        square(0.0, 0.0, 4.0, 4.0),
        square(3.0, 3.0, 8.0, 8.0),
    ]]);
    let q = MultiPolygon::from_coordinates(&[vec![square(5.0, 5.0, 7.0, 7.0)]]);
    // Q lies inside the "hole" ring and outside the exterior: covered once, so inside P.
    assert_eq!(intersection(&p, &q).unwrap().area(), 4.0);
    assert_eq!(intersection(&q, &p).unwrap().area(), 4.0);
    assert_eq!(difference(&q, &p).unwrap().area(), 0.0);
    assert_eq!(
        difference(&p, &q).unwrap().area(),
        16.0 + 25.0 - 2.0 * 1.0 - 4.0
    );
}
