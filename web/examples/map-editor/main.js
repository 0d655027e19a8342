// The map editor: MapLibre shows the map (offline: see style.js), draw.js turns clicks into GeoJSON geometries,
// polysweep computes the edits, and each edit's result goes back into the map's GeoJSON sources.
//
// The editor's state is two lists: `features` (what was drawn and what operations made, in drawing order) and
// `parcels` (the parcel layer shown). Every edit replaces them with new lists and pushes the old ones on the undo
// stack, so Undo (or Ctrl+Z) is one pop. Coordinates are lon/lat read as plane coordinates, as polysweep reads any
// coordinates: areas are in square degrees, and edges are straight in lon/lat, not along great circles.
import 'maplibre-gl/dist/maplibre-gl.css';
import { MapLibreMap, setWorkerUrl } from 'maplibre-gl';
// MapLibre 6 runs its tile worker from a separate module next to its main one; bundled, the worker file is an asset.
import maplibreWorkerUrl from 'maplibre-gl/dist/maplibre-gl-worker.mjs?url';
import { union, intersection, difference, xor, split, clip } from 'polysweep';
import { createWorker } from 'polysweep/worker';
// Natural Earth land (tests/data, gzip-compressed GeoJSON): Vite copies it into the build as an asset.
import landUrl from '../../../tests/data/land-50m.json.gz?url';
import { createDraw } from './draw.js';
import { makeParcels } from './data.js';
import { makeStyle } from './style.js';

setWorkerUrl(maplibreWorkerUrl);

const SNAP_STEP = 20; // vertices snap to multiples of 1/20 degree when "Snap" is checked
const $ = (id) => document.getElementById(id);
const statusElement = $('status');

const map = new MapLibreMap({
  container: 'map',
  style: makeStyle(),
  bounds: [[-1, 39], [11, 51]],
  attributionControl: { compact: true, customAttribution: 'Natural Earth (land)' },
  maxPitch: 0,
  dragRotate: false,
  pitchWithRotate: false,
  touchPitch: false,
});

// ---- state, undo and rendering ---------------------------------------------------------------------------------

let features = [];
let parcels = makeParcels();
let selection = []; // ids of selected features, in the order they were clicked
const history = []; // earlier { features, parcels, label }
let nextId = 1;
let shownParcels = null;
let lastStatus = '';
let layerClip = null; // summary of the last parcel-layer clip

const isPolygonal = (f) => f.geometry.type === 'Polygon' || f.geometry.type === 'MultiPolygon';
const isLinear = (f) => f.geometry.type === 'LineString' || f.geometry.type === 'MultiLineString';
const byId = (id) => features.find((f) => f.id === id);
const newFeature = (geometry, properties) => ({ type: 'Feature', id: nextId++, properties, geometry });

function status(text, kind = 'info') {
  lastStatus = text;
  statusElement.textContent = text;
  statusElement.dataset.kind = kind;
}

function render() {
  const shown = (f) => ({ ...f, properties: { ...f.properties, fid: f.id, selected: selection.includes(f.id) } });
  map.getSource('polygons').setData({ type: 'FeatureCollection', features: features.filter(isPolygonal).map(shown) });
  map.getSource('lines').setData({ type: 'FeatureCollection', features: features.filter(isLinear).map(shown) });
  if (shownParcels !== parcels) {
    map.getSource('parcels').setData(parcels);
    shownParcels = parcels;
  }
}

/** Makes an undoable edit: the new feature list (and parcel layer) replace the current ones. */
function commit(label, nextFeatures, nextParcels = parcels) {
  history.push({ features, parcels, label });
  features = nextFeatures;
  parcels = nextParcels;
  selection = [];
  render();
}

/** The feature list with `operands` removed and `results` added on top. */
const replacing = (operands, results) => [...features.filter((f) => !operands.includes(f)), ...results];

function undo() {
  const previous = history.pop();
  if (!previous) return status('Nothing to undo');
  ({ features, parcels } = previous);
  selection = [];
  render();
  status(`Undone: ${previous.label}`);
}

// ---- geometry helpers (planar lon/lat) ---------------------------------------------------------------------------

const ringArea = (ring) => {
  let sum = 0;
  for (let i = 0; i + 1 < ring.length; i++) sum += ring[i][0] * ring[i + 1][1] - ring[i + 1][0] * ring[i][1];
  return Math.abs(sum) / 2;
};
const polygonsOf = (g) => (g.type === 'Polygon' ? [g.coordinates] : g.type === 'MultiPolygon' ? g.coordinates : []);
const areaOf = (g) => polygonsOf(g).reduce((a, [outer, ...holes]) => a + ringArea(outer) - holes.reduce((h, r) => h + ringArea(r), 0), 0);
const linesOf = (g) => (g.type === 'LineString' ? [g.coordinates] : g.type === 'MultiLineString' ? g.coordinates : []);
const lengthOf = (g) => linesOf(g).reduce((sum, line) => sum + line.slice(1).reduce((s, p, i) => s + Math.hypot(p[0] - line[i][0], p[1] - line[i][1]), 0), 0);
const format = (x) => x.toFixed(4).replace(/\.?0+$/, '');

/** Even-odd point in polygon over all rings. */
function contains(geometry, [x, y]) {
  let inside = false;
  for (const polygon of polygonsOf(geometry)) {
    for (const ring of polygon) {
      for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
        const [xi, yi] = ring[i];
        const [xj, yj] = ring[j];
        if (yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
      }
    }
  }
  return inside;
}

/** Distance in screen pixels from `point` to the line geometry. */
function pixelDistanceToLine(geometry, point) {
  let best = Infinity;
  for (const line of linesOf(geometry)) {
    const pixels = line.map((p) => map.project(p));
    for (let i = 0; i + 1 < pixels.length; i++) {
      const [a, b] = [pixels[i], pixels[i + 1]];
      const [dx, dy] = [b.x - a.x, b.y - a.y];
      const t = Math.max(0, Math.min(1, ((point.x - a.x) * dx + (point.y - a.y) * dy) / (dx * dx + dy * dy || 1)));
      best = Math.min(best, Math.hypot(a.x + t * dx - point.x, a.y + t * dy - point.y));
    }
  }
  return best;
}

/** The feature under a click: a line within 6 pixels first, else the topmost polygon containing it. */
function featureAt(lngLat, point) {
  const top = [...features].reverse();
  return (
    top.find((f) => isLinear(f) && pixelDistanceToLine(f.geometry, point) <= 6) ??
    top.find((f) => isPolygonal(f) && contains(f.geometry, [lngLat.lng, lngLat.lat]))
  );
}

// ---- drawing and selection ---------------------------------------------------------------------------------------

const snap = ([lon, lat]) => ($('snap').checked ? [Math.round(lon * SNAP_STEP) / SNAP_STEP, Math.round(lat * SNAP_STEP) / SNAP_STEP] : [lon, lat]);

const draw = createDraw(map, {
  sourceId: 'draft',
  snap,
  onFinish(geometry) {
    const feature = newFeature(geometry, { kind: 'drawn' });
    commit(`draw ${geometry.type}`, [...features, feature]);
    status(`Drew #${feature.id} (${geometry.type === 'Polygon' ? `polygon, area ${format(areaOf(geometry))}` : `line, length ${format(lengthOf(geometry))}`})`);
  },
  onSelect(lngLat, point) {
    const feature = featureAt(lngLat, point);
    if (!feature) return;
    selection = selection.includes(feature.id) ? selection.filter((id) => id !== feature.id) : [...selection, feature.id];
    render();
    const names = selection.map((id) => `#${id} (${isPolygonal(byId(id)) ? 'polygon' : 'line'})`);
    status(names.length ? `Selected, in order: ${names.join(', ')}` : 'Nothing selected');
  },
});

function setTool(name) {
  draw.setTool(name);
  for (const tool of ['select', 'polygon', 'line']) $(`tool-${tool}`).setAttribute('aria-pressed', String(tool === name));
}

// ---- operations --------------------------------------------------------------------------------------------------

const selectedPolygons = () => selection.map(byId).filter(isPolygonal);
const selectedLines = () => selection.map(byId).filter(isLinear);
const collection = (list) => ({ type: 'FeatureCollection', features: list });

/** Merge, Cut, Intersect and Xor: the selected polygons (in selection order) are replaced by the result. */
function booleanOperation(label, operation) {
  const operands = selectedPolygons();
  if (operands.length < 2) return status(`${label}: select two or more polygons first (Select tool)`, 'error');
  const result = operation(...operands); // a Feature with a MultiPolygon geometry
  if (result.geometry.coordinates.length === 0) return status(`${label}: the result is empty. Nothing was changed.`, 'warning');
  const feature = newFeature(result.geometry, { kind: 'result', operation: label.toLowerCase() });
  commit(label, replacing(operands, [feature]));
  status(`${label}: #${feature.id}, area ${format(areaOf(feature.geometry))}`);
}

/** Split: the selected polygon is replaced by its pieces along the selected lines (the lines stay). */
function splitOperation() {
  const [polygon, ...others] = selectedPolygons();
  const lines = selectedLines();
  if (!polygon || others.length > 0 || lines.length === 0) return status('Split: select one polygon and one or more lines', 'error');
  const pieces = split(polygon, collection(lines)).features;
  if (pieces.length < 2) return status('Split: the lines do not cut the polygon (a cut must cross it from boundary to boundary). Nothing was changed.', 'warning');
  const results = pieces.map((piece) => newFeature(piece.geometry, { kind: 'result', operation: 'split' }));
  commit('Split', replacing([polygon], results));
  status(`Split: ${results.length} pieces, areas ${results.map((f) => format(areaOf(f.geometry))).join(', ')}`);
}

/** Clip lines: the selected lines are replaced by their parts inside the selected polygon (which stays). */
function clipLinesOperation() {
  const [polygon, ...others] = selectedPolygons();
  const lines = selectedLines();
  if (!polygon || others.length > 0 || lines.length === 0) return status('Clip lines: select one polygon and one or more lines', 'error');
  const clipped = clip(collection(lines), polygon).features; // one feature per line that keeps a part
  if (clipped.length === 0) return status('Clip lines: the result is empty (no part of the lines is inside). Nothing was changed.', 'warning');
  const results = clipped.map((part) => newFeature(part.geometry, { kind: 'result', operation: 'clip' }));
  commit('Clip lines', replacing(lines, results));
  status(`Clip lines: ${results.length} line(s), length ${format(results.reduce((s, f) => s + lengthOf(f.geometry), 0))}`);
}

// The parcel clip runs in a Web Worker (polysweep/worker), so that the page keeps answering; a new request aborts
// the one still running, and so does Cancel.
let polysweepWorker;
let running; // the AbortController of the clip in progress

/** Measures the gaps between animation frames until the returned function is called. */
function frameMeter() {
  let last = performance.now();
  let longest = 0;
  let frames = 0;
  let on = true;
  const tick = (now) => {
    if (!on) return;
    longest = Math.max(longest, now - last);
    last = now;
    frames++;
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
  return () => {
    on = false;
    return { longestFrameMs: Math.max(longest, performance.now() - last), frames };
  };
}

async function clipParcelsOperation() {
  const [polygon, ...others] = selectedPolygons();
  if (!polygon || others.length > 0) return status('Clip parcels: select one polygon', 'error');
  running?.abort();
  const controller = new AbortController();
  running = controller;
  const progress = $('progress');
  const layer = parcels;
  progress.max = layer.features.length;
  progress.value = 0;
  $('cancel').disabled = false;
  status(`Clipping ${layer.features.length} parcels in a worker…`);
  const stop = frameMeter();
  const started = performance.now();
  try {
    polysweepWorker ??= createWorker();
    const result = await polysweepWorker.clipLayer(layer, polygon, {
      signal: controller.signal,
      onProgress(done, total) {
        if (running !== controller) return;
        progress.max = total;
        progress.value = done;
      },
    });
    const { longestFrameMs, frames } = stop();
    if (running !== controller) return; // superseded (an aborted request rejects, but be safe)
    const count = result.features.length;
    const totalArea = result.features.reduce((sum, f) => sum + areaOf(f.geometry), 0);
    layerClip = { count, totalArea, longestFrameMs, frames, ms: performance.now() - started };
    commit('Clip parcels', features, result);
    status(`${count} parcels, total area ${format(totalArea)} (planar, square degrees). Longest main-thread frame while the worker ran: ${Math.round(longestFrameMs)} ms over ${frames} frames.`);
  } catch (error) {
    stop();
    if (error?.name === 'AbortError') {
      if (running === controller) status('Clip parcels: cancelled', 'warning');
    } else if (running === controller) {
      throw error;
    }
  } finally {
    if (running === controller) {
      running = undefined;
      $('cancel').disabled = true;
    }
  }
}

// ---- wiring --------------------------------------------------------------------------------------------------------

/** Runs an action from a button or key; an error is shown in the status element, not only in the console. */
async function act(action) {
  try {
    await action();
  } catch (error) {
    status(`${error?.name ?? 'Error'}: ${error?.message ?? error}`, 'error');
  }
}

const buttons = {
  'tool-select': () => setTool('select'),
  'tool-polygon': () => setTool('polygon'),
  'tool-line': () => setTool('line'),
  'op-merge': () => booleanOperation('Merge', union),
  'op-cut': () => booleanOperation('Cut', difference),
  'op-intersect': () => booleanOperation('Intersect', intersection),
  'op-xor': () => booleanOperation('Xor', xor),
  'op-split': splitOperation,
  'op-clip-lines': clipLinesOperation,
  'op-clip-parcels': clipParcelsOperation,
  cancel: () => running?.abort(),
  undo,
  clear: () => (features.length ? (commit('Clear', []), status('Cleared (Undo brings the features back)')) : status('Nothing to clear')),
};
for (const [id, action] of Object.entries(buttons)) {
  $(id).addEventListener('click', (event) => {
    event.currentTarget.blur(); // so that Enter while drawing does not press the button again
    act(action);
  });
}

document.addEventListener('keydown', (event) => {
  if ((event.ctrlKey || event.metaKey) && !event.shiftKey && event.key.toLowerCase() === 'z') {
    event.preventDefault();
    act(undo);
  } else if (draw.key(event)) {
    event.preventDefault();
  }
});

async function loadLand() {
  const response = await fetch(landUrl);
  if (!response.ok) throw new Error(`could not load the land polygons: HTTP ${response.status}`);
  const bytes = new Uint8Array(await response.arrayBuffer());
  // A server that sends the file with `Content-Encoding: gzip` (Vite's dev server does) has the browser decompress
  // it already: decompress here only what still starts with gzip's magic number.
  const gzipped = bytes[0] === 0x1f && bytes[1] === 0x8b;
  const body = gzipped ? new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip')) : bytes;
  map.getSource('land').setData(await new Response(body).json());
}

// ---- the test hook: read-only views of the state, and lon/lat → page pixels ----------------------------------------

window.editor = {
  ready: false,
  map,
  get features() {
    return structuredClone(features);
  },
  get selection() {
    return [...selection];
  },
  get status() {
    return lastStatus;
  },
  get layerClip() {
    return layerClip && { ...layerClip };
  },
  get parcelCount() {
    return parcels.features.length;
  },
  parcel(id) {
    return structuredClone(parcels.features.find((f) => f.id === id) ?? null);
  },
  /** Page pixel coordinates of a lon/lat position. */
  project(lon, lat) {
    const p = map.project([lon, lat]);
    const box = map.getContainer().getBoundingClientRect();
    return [box.left + p.x, box.top + p.y];
  },
};

map.on('load', () =>
  act(async () => {
    render();
    await loadLand();
    await map.once('idle');
    window.editor.ready = true;
    status('Ready: draw polygons and lines, select them, and apply an operation.');
  }),
);
