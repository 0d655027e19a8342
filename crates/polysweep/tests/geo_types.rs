//! The `geo-types` feature: geo's polygons convert to and from polysweep's, and an operation on converted operands
//! gives the hand-worked answer.
#![cfg(feature = "geo-types")]

use geo_types::{coord, LineString, MultiPolygon as GeoMultiPolygon, Polygon as GeoPolygon};
use polysweep::{union, MultiPolygon};

fn square(x: f64, y: f64, side: f64) -> LineString<f64> {
    LineString::from(vec![
        (x, y),
        (x + side, y),
        (x + side, y + side),
        (x, y + side),
        (x, y),
    ])
}

#[test]
fn geo_polygons_go_through_an_operation_and_come_back() {
    // A 4 × 4 square with a 1 × 1 hole, and a 2 × 2 square overlapping its right side by 1 × 2.
    let hole = LineString::from(vec![
        (1.0, 1.0),
        (1.0, 2.0),
        (2.0, 2.0),
        (2.0, 1.0),
        (1.0, 1.0),
    ]);
    let holed = GeoPolygon::new(square(0.0, 0.0, 4.0), vec![hole]);
    let right = GeoPolygon::new(square(3.0, 1.0, 2.0), vec![]);
    let (a, b) = (
        MultiPolygon::from(&GeoMultiPolygon(vec![holed.clone()])),
        MultiPolygon::from(&GeoMultiPolygon(vec![right])),
    );
    assert_eq!(a.0[0].holes.len(), 1);
    assert_eq!(a.area(), 15.0);
    let result = union(&a, &b).unwrap();
    polysweep::validate(&result).unwrap();
    // 16 − 1 + 4 − 2 (the overlap).
    assert_eq!(result.area(), 17.0);
    let back = GeoMultiPolygon::from(&result);
    assert_eq!(back.0.len(), 1);
    assert_eq!(back.0[0].interiors().len(), 1);
    // Every vertex of the result is one of the hand-worked ones.
    let expected = [
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 1.0),
        (5.0, 1.0),
        (5.0, 3.0),
        (4.0, 3.0),
        (4.0, 4.0),
        (0.0, 4.0),
    ];
    let exterior = back.0[0].exterior();
    assert_eq!(exterior.0.len(), expected.len() + 1, "closed, 8 vertices");
    for c in &exterior.0 {
        assert!(expected.contains(&(c.x, c.y)), "unexpected vertex {c:?}");
    }
    // Converting geo's polygon and back keeps its coordinates.
    let round_trip =
        GeoMultiPolygon::from(&MultiPolygon::from(&GeoMultiPolygon(vec![holed.clone()])));
    assert_eq!(round_trip.0[0], holed);
    assert_eq!(round_trip.0[0].exterior().0[1], coord! { x: 4.0, y: 0.0 });
}
