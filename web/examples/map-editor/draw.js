// Drawing polygons and lines on a MapLibre map with the map's own mouse events: a small, swappable module (terra-draw
// or maplibre-gl-draw could stand in its place). It knows nothing of polysweep: it hands each finished geometry
// (GeoJSON Polygon or LineString, lon/lat) to `onFinish`, and each click of the Select tool to `onSelect`.
//
// Why our own: every step is a plain click, double-click or key, so a browser test can drive it with
// page.mouse.click at pixels from map.project and get exactly the vertices it meant (with snapping on); and it
// adds no dependency.
//
// Polygon tool: a click adds a vertex; a click on the first vertex, a double-click or Enter finishes the ring.
// Line tool: the same, finishing a LineString (double-click or Enter). Esc drops the geometry being drawn and
// Backspace removes its last vertex. While a drawing tool is active the map's double-click zoom is off.

const CLOSE_PIXELS = 8; // a click this close to the first vertex (in screen pixels) closes the ring

/**
 * @param {import('maplibre-gl').Map} map with a GeoJSON source named `sourceId` for the geometry being drawn
 * @param {{ sourceId: string, snap: (position: number[]) => number[],
 *           onFinish: (geometry: object) => void, onSelect: (lngLat: object, point: object) => void }} options
 */
export function createDraw(map, { sourceId, snap, onFinish, onSelect }) {
  let tool = 'select';
  let vertices = []; // [lon, lat] of the geometry being drawn
  let hover = null; // the snapped mouse position, for the rubber band

  const same = (p, q) => p[0] === q[0] && p[1] === q[1];
  const pixelDistance = (p, q) => {
    const [a, b] = [map.project(p), map.project(q)];
    return Math.hypot(a.x - b.x, a.y - b.y);
  };
  const at = (event) => snap([event.lngLat.lng, event.lngLat.lat]);

  /** Shows the vertices so far, the rubber band to the mouse and (for a polygon) back to the first vertex. */
  function update() {
    const features = vertices.map((p) => ({ type: 'Feature', properties: {}, geometry: { type: 'Point', coordinates: p } }));
    const path = hover ? [...vertices, hover] : [...vertices];
    if (tool === 'polygon' && vertices.length >= 2) path.push(vertices[0]);
    if (vertices.length >= 1 && path.length >= 2) {
      features.push({ type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: path } });
    }
    map.getSource(sourceId)?.setData({ type: 'FeatureCollection', features });
  }

  function cancel() {
    vertices = [];
    hover = null;
    update();
  }

  /** Hands the geometry drawn so far to onFinish, when it has enough distinct vertices. */
  function finish() {
    const points = vertices;
    cancel();
    if (tool === 'polygon' && points.length >= 3) {
      onFinish({ type: 'Polygon', coordinates: [[...points, points[0]]] });
    } else if (tool === 'line' && points.length >= 2) {
      onFinish({ type: 'LineString', coordinates: points });
    }
  }

  map.on('click', (event) => {
    if (tool === 'select') return onSelect(event.lngLat, event.point);
    const p = at(event);
    if (tool === 'polygon' && vertices.length >= 3 && pixelDistance(p, vertices[0]) <= CLOSE_PIXELS) return finish();
    // The second click of a double-click lands on the vertex the first one added: not a new vertex.
    if (vertices.length > 0 && same(p, vertices[vertices.length - 1])) return;
    vertices.push(p);
    update();
  });

  map.on('dblclick', (event) => {
    if (tool === 'select') return;
    event.preventDefault(); // no zoom (it is also disabled while drawing)
    finish();
  });

  map.on('mousemove', (event) => {
    if (tool === 'select' || vertices.length === 0) return;
    hover = at(event);
    update();
  });

  return {
    get tool() {
      return tool;
    },
    get drawing() {
      return vertices.length > 0;
    },
    /** 'polygon', 'line' or 'select'; drops any geometry being drawn. */
    setTool(name) {
      cancel();
      tool = name;
      if (tool === 'select') map.doubleClickZoom.enable();
      else map.doubleClickZoom.disable();
      map.getCanvas().style.cursor = tool === 'select' ? '' : 'crosshair';
    },
    /** Enter, Escape and Backspace while drawing; returns whether the key was used. */
    key(event) {
      if (tool === 'select' || vertices.length === 0) return false;
      if (event.key === 'Enter') finish();
      else if (event.key === 'Escape') cancel();
      else if (event.key === 'Backspace') {
        vertices.pop();
        update();
      } else return false;
      return true;
    },
  };
}
