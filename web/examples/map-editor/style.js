// The map style: fully offline. No tiles, glyphs or sprites (so no text layers): a background (the sea), the
// Natural Earth land polygons, the parcel grid, and the editor's own features, all from GeoJSON sources that
// main.js fills. The colours are exported for the browser test's pixel checks.

export const COLORS = {
  sea: '#bcd7ea',
  land: '#efeadf',
  parcelOutline: '#8a8a7a',
  uses: { residential: '#f3c9a8', commercial: '#c9b3e6', farmland: '#e6e29a', forest: '#9fd19a', park: '#b7e4d8' },
  drawn: '#2f6fde', // drawn polygons, half transparent
  result: '#d6247f', // results of an operation, drawn at RESULT_OPACITY over the map (the test blends it so too)
  selected: '#ffb000', // outline and fill of selected features
  line: '#1b2a3a',
  draft: '#ff3d00',
};

export const RESULT_OPACITY = 0.7;
const DRAWN_OPACITY = 0.45;

const empty = { type: 'FeatureCollection', features: [] };
const isSelected = ['==', ['get', 'selected'], true];

export function makeStyle() {
  const useColour = ['match', ['get', 'use'], ...Object.entries(COLORS.uses).flat(), '#dddddd'];
  return {
    version: 8,
    name: 'polysweep map editor (offline)',
    sources: {
      land: { type: 'geojson', data: empty },
      parcels: { type: 'geojson', data: empty, tolerance: 0 },
      polygons: { type: 'geojson', data: empty, tolerance: 0 },
      lines: { type: 'geojson', data: empty, tolerance: 0 },
      draft: { type: 'geojson', data: empty, tolerance: 0 },
    },
    layers: [
      { id: 'sea', type: 'background', paint: { 'background-color': COLORS.sea } },
      { id: 'land', type: 'fill', source: 'land', paint: { 'fill-color': COLORS.land } },
      { id: 'parcels', type: 'fill', source: 'parcels', paint: { 'fill-color': useColour } },
      {
        id: 'parcel-outlines',
        type: 'line',
        source: 'parcels',
        minzoom: 4,
        paint: { 'line-color': COLORS.parcelOutline, 'line-width': 0.4, 'line-opacity': 0.6 },
      },
      {
        id: 'polygons',
        type: 'fill',
        source: 'polygons',
        paint: {
          'fill-color': ['case', isSelected, COLORS.selected, ['==', ['get', 'kind'], 'result'], COLORS.result, COLORS.drawn],
          'fill-opacity': ['case', isSelected, 0.6, ['==', ['get', 'kind'], 'result'], RESULT_OPACITY, DRAWN_OPACITY],
        },
      },
      {
        id: 'polygon-outlines',
        type: 'line',
        source: 'polygons',
        paint: { 'line-color': ['case', isSelected, COLORS.selected, COLORS.line], 'line-width': ['case', isSelected, 3, 1.2] },
      },
      {
        id: 'lines',
        type: 'line',
        source: 'lines',
        layout: { 'line-cap': 'round', 'line-join': 'round' },
        paint: { 'line-color': ['case', isSelected, COLORS.selected, COLORS.line], 'line-width': ['case', isSelected, 5, 3] },
      },
      {
        id: 'draft-line',
        type: 'line',
        source: 'draft',
        filter: ['==', ['geometry-type'], 'LineString'],
        paint: { 'line-color': COLORS.draft, 'line-width': 2, 'line-dasharray': [2, 1] },
      },
      {
        id: 'draft-vertices',
        type: 'circle',
        source: 'draft',
        filter: ['==', ['geometry-type'], 'Point'],
        paint: { 'circle-radius': 4, 'circle-color': '#ffffff', 'circle-stroke-color': COLORS.draft, 'circle-stroke-width': 2 },
      },
    ],
  };
}
