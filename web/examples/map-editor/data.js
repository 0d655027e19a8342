// The generated parcel layer: a deterministic grid of 100 × 100 square parcels over lon 0..10, lat 40..50 (each
// 0.1° × 0.1°), built in JavaScript at start-up so that nothing but the page itself is needed.
//
// Parcel (row, col), counted from the south-west corner, spans lon [col/10, (col+1)/10] and lat
// [40 + row/10, 40 + (row+1)/10]. Its feature id and `properties.id` are row·100 + col; its owner is
// `owner (row·31 + col·17) mod 97` and its use USES[(row·7 + col·3) mod 5]. The browser test recomputes these.

export const GRID = { west: 0, south: 40, perDegree: 10, cols: 100, rows: 100 };
export const USES = ['residential', 'commercial', 'farmland', 'forest', 'park'];

/** The properties of the parcel in `row`, `col`. */
export function parcelProperties(row, col) {
  return {
    id: row * GRID.cols + col,
    owner: `owner ${(row * 31 + col * 17) % 97}`,
    use: USES[(row * 7 + col * 3) % USES.length],
  };
}

/** The 10,000 parcels as a GeoJSON FeatureCollection of Polygon features (counter-clockwise rings). */
export function makeParcels() {
  const { west, south, perDegree, cols, rows } = GRID;
  // Edges as west + k/perDegree: k/perDegree is the double nearest the decimal, so neighbours share edges exactly.
  const x = (col) => west + col / perDegree;
  const y = (row) => south + row / perDegree;
  const features = [];
  for (let row = 0; row < rows; row++) {
    for (let col = 0; col < cols; col++) {
      const [x0, x1, y0, y1] = [x(col), x(col + 1), y(row), y(row + 1)];
      const properties = parcelProperties(row, col);
      features.push({
        type: 'Feature',
        id: properties.id,
        properties,
        geometry: { type: 'Polygon', coordinates: [[[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]]] },
      });
    }
  }
  return { type: 'FeatureCollection', features };
}
