// The engines of the wasm/JS benchmark, each behind one interface:
//
//   const engine = await loadEngine(name);
//   const input = engine.prepare ? engine.prepare(a, b) : [a, b];   // not timed (only polysweep-flat has one)
//   const output = engine.run(operation, ...input, fillRule);         // timed: conversions in and out included
//   engine.area(output)                                                // not timed
//
// `a` and `b` are GeoJSON MultiPolygon coordinates (JavaScript arrays); every engine but polysweep-flat returns
// GeoJSON MultiPolygon coordinates (polygons of closed rings, exterior first), so each does the same work a user
// of it would do to go from GeoJSON to GeoJSON. Operations: 'intersection', 'union', 'difference', 'xor'.
//
// Fill rule: 'evenodd' or 'nonzero', how each operand's rings define its interior. Omitted (Table 1, whose inputs
// do not overlap themselves): even-odd for the peers, the npm package's default (the structural reading, the same
// regions as even-odd on such input) for polysweep. The engines of READS_RINGS_ONLY take no fill rule: they read
// each ring's region, which is even-odd's on operands that do not overlap themselves, and cannot run 'nonzero'.

import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { ROOT, multiPolygonArea } from './data.mjs';

const require = createRequire(import.meta.url);

/** The peers and polysweep, in the order of the report. polysweep-flat is informational, not a peer. */
export const ENGINES = [
  'polysweep',
  'polysweep-flat',
  'clipper2-wasm',
  'js-angusj-clipper',
  'clipper2-ts',
  'ishape_wasm',
  'martinez-polygon-clipping',
  'polygon-clipping',
  'polyclip-ts',
];

/** Engines without a fill rule (see above). */
export const READS_RINGS_ONLY = new Set(['martinez-polygon-clipping', 'polygon-clipping', 'polyclip-ts']);

/** Whether an engine can read its operands by this fill rule (undefined: Table 1's reading, which all can). */
export function takesFillRule(engine, fillRule) {
  return fillRule === undefined || fillRule === 'evenodd' || !READS_RINGS_ONLY.has(engine);
}

/** npm package of each engine (for its version). */
export const PACKAGE_OF = {
  polysweep: 'polysweep',
  'polysweep-flat': 'polysweep',
  'clipper2-wasm': 'clipper2-wasm',
  'js-angusj-clipper': 'js-angusj-clipper',
  'clipper2-ts': 'clipper2-ts',
  ishape_wasm: 'ishape_wasm',
  'martinez-polygon-clipping': 'martinez-polygon-clipping',
  'polygon-clipping': 'polygon-clipping',
  'polyclip-ts': 'polyclip-ts',
};

export function packageVersion(pkg) {
  return JSON.parse(readFileSync(join(ROOT, 'node_modules', pkg, 'package.json'), 'utf8')).version;
}

/** Clipper2's decimal precision (ClipperD scales by 10^precision to int64; 8 is its maximum). */
export const CLIPPER2_PRECISION = 8;
/**
 * Clipper1 (js-angusj-clipper) takes integer coordinates only. 2^22 keeps |x| ≤ 180 · 2^22 < 2^30, inside the
 * range its docs recommend for speed (±0x3FFFFFFF, no 128-bit products); a power of two makes scaling back exact.
 */
export const CLIPPER1_SCALE = 2 ** 22;

/** How each engine is set up and what its conversions are, for the report. */
export const NOTES = {
  polysweep: 'npm package pkg/ (wasm); GeoJSON coordinates in and out through its polygon-clipping-style API (fill rule: the package default in Table 1, the workload\'s rule in the dense workloads)',
  'polysweep-flat': 'same package, overlayFlat: typed arrays in and out (GeoJSON→flat conversion not timed); informational, not a peer',
  'clipper2-wasm': `ClipperD via BooleanOpOutD (PolyTreeD for holes), precision ${CLIPPER2_PRECISION} decimals, even-odd (non-zero where a dense workload says so); rings copied into PathD with assign(Float64Array), results read with view(); closing vertex dropped in, added out`,
  'js-angusj-clipper': `Clipper 1 (wasm), clipToPolyTree, even-odd (non-zero where a dense workload says so), coordinates scaled by 2^22 and rounded to integers (within ±2^30 on land, where Clipper needs no 128-bit products; beyond it on the larger dense inputs, where a scale keeping them within was measured no faster); closing vertex dropped in, added out`,
  'clipper2-ts': `Clipper2 ported to TypeScript: ClipperD into a PolyTreeD (holes as children), precision ${CLIPPER2_PRECISION} decimals, even-odd (non-zero where a dense workload says so); rings copied into {x, y} points, closing vertex dropped in, added out`,
  ishape_wasm: 'i_overlay (Rust) in wasm: Overlay.new_with_subj_and_clip on the coordinate arrays (its float API, which rounds to an integer grid over the operands\' bounding box), overlay(rule, fill rule); shapes come back as outer ring then holes, open: the closing vertex is added',
  'martinez-polygon-clipping': 'GeoJSON coordinates in and out (a Polygon-shaped or null result is normalised to MultiPolygon coordinates)',
  'polygon-clipping': 'GeoJSON coordinates in and out',
  'polyclip-ts': 'GeoJSON coordinates in and out (bignumber.js arithmetic)',
};

function closeRing(ring) {
  ring.push([ring[0][0], ring[0][1]]);
  return ring;
}

function openLength(ring) {
  const n = ring.length;
  return n > 1 && ring[0][0] === ring[n - 1][0] && ring[0][1] === ring[n - 1][1] ? n - 1 : n;
}

// ---------------------------------------------------------------------------------------------------------------

async function polysweep() {
  const ps = await import('polysweep');
  return {
    run: (op, a, b, fillRule) => (fillRule ? ps[op](a, b, { fillRule }) : ps[op](a, b)),
    area: multiPolygonArea,
  };
}

function flatOf(polygons) {
  let vertices = 0;
  let rings = 0;
  for (const polygon of polygons) {
    rings += polygon.length;
    for (const ring of polygon) vertices += ring.length;
  }
  const coords = new Float64Array(2 * vertices);
  const ringOffsets = new Uint32Array(rings + 1);
  const polygonOffsets = new Uint32Array(polygons.length + 1);
  let v = 0;
  let r = 0;
  polygons.forEach((polygon, p) => {
    for (const ring of polygon) {
      for (const [x, y] of ring) {
        coords[2 * v] = x;
        coords[2 * v + 1] = y;
        v++;
      }
      ringOffsets[++r] = v;
    }
    polygonOffsets[p + 1] = r;
  });
  return { coords, ringOffsets, polygonOffsets };
}

function flatArea({ coords, ringOffsets, polygonOffsets }) {
  let area = 0;
  for (let p = 0; p + 1 < polygonOffsets.length; p++) {
    for (let r = polygonOffsets[p]; r < polygonOffsets[p + 1]; r++) {
      let s = 0;
      const start = ringOffsets[r];
      const end = ringOffsets[r + 1];
      for (let v = start, u = end - 1; v < end; u = v++) {
        s += coords[2 * u] * coords[2 * v + 1] - coords[2 * v] * coords[2 * u + 1];
      }
      const a = Math.abs(s / 2);
      area += r === polygonOffsets[p] ? a : -a;
    }
  }
  return area;
}

async function polysweepFlat() {
  const ps = await import('polysweep');
  return {
    prepare: (a, b) => [flatOf(a), flatOf(b)],
    run: (op, a, b, fillRule) => ps.overlayFlat(op, [a, b], fillRule ? { fillRule } : undefined),
    area: flatArea,
  };
}

// ---------------------------------------------------------------------------------------------------------------

async function clipper2() {
  const { default: Clipper2Z } = await import('clipper2-wasm/dist/es/clipper2z.js');
  const C = await Clipper2Z();
  const CLIP = { intersection: C.ClipType.Intersection, union: C.ClipType.Union, difference: C.ClipType.Difference, xor: C.ClipType.Xor };
  const FILL = { evenodd: C.FillRule.EvenOdd, nonzero: C.FillRule.NonZero };

  function toPathsD(polygons) {
    const paths = new C.PathsD();
    for (const polygon of polygons) {
      for (const ring of polygon) {
        const n = openLength(ring);
        const flat = new Float64Array(3 * n); // x, y, z per point (this build carries a z)
        for (let i = 0; i < n; i++) {
          flat[3 * i] = ring[i][0];
          flat[3 * i + 1] = ring[i][1];
        }
        const path = new C.PathD();
        path.assign(flat);
        paths.push_back(path); // copies
        path.delete();
      }
    }
    return paths;
  }

  function ringOf(node) {
    const path = node.polygon(); // a copy, owned here
    const view = path.view();
    const n = view.length / 3;
    const ring = new Array(n + 1);
    for (let i = 0; i < n; i++) ring[i] = [view[3 * i], view[3 * i + 1]];
    ring[n] = [view[0], view[1]];
    path.delete();
    return ring;
  }

  function collect(outer, out) {
    // `outer` is an exterior; its children are holes, whose children are exteriors again.
    const polygon = [ringOf(outer)];
    for (let h = 0, holes = outer.count(); h < holes; h++) {
      const hole = outer.child(h);
      polygon.push(ringOf(hole));
      for (let k = 0, islands = hole.count(); k < islands; k++) collect(hole.child(k), out);
    }
    out.push(polygon);
  }

  return {
    run(op, a, b, fillRule = 'evenodd') {
      const subjects = toPathsD(a);
      const clips = toPathsD(b);
      const tree = new C.PolyPathD();
      try {
        C.BooleanOpOutD(CLIP[op], FILL[fillRule], subjects, clips, tree, CLIPPER2_PRECISION);
        const out = [];
        for (let i = 0, n = tree.count(); i < n; i++) collect(tree.child(i), out);
        return out;
      } finally {
        subjects.delete();
        clips.delete();
        tree.delete();
      }
    },
    area: multiPolygonArea,
  };
}

// ---------------------------------------------------------------------------------------------------------------

async function angusjClipper() {
  const lib = require('js-angusj-clipper');
  const clipper = await lib.loadNativeClipperLibInstanceAsync(lib.NativeClipperLibRequestedFormat.WasmOnly);
  const S = CLIPPER1_SCALE;
  const CLIP = { intersection: lib.ClipType.Intersection, union: lib.ClipType.Union, difference: lib.ClipType.Difference, xor: lib.ClipType.Xor };
  const FILL = { evenodd: lib.PolyFillType.EvenOdd, nonzero: lib.PolyFillType.NonZero };

  function toPaths(polygons) {
    const paths = [];
    for (const polygon of polygons) {
      for (const ring of polygon) {
        const n = openLength(ring);
        const path = new Array(n);
        for (let i = 0; i < n; i++) path[i] = { x: Math.round(ring[i][0] * S), y: Math.round(ring[i][1] * S) };
        paths.push(path);
      }
    }
    return paths;
  }

  function ringOf(contour) {
    const n = contour.length;
    const ring = new Array(n + 1);
    for (let i = 0; i < n; i++) ring[i] = [contour[i].x / S, contour[i].y / S];
    ring[n] = [contour[0].x / S, contour[0].y / S];
    return ring;
  }

  function collect(outer, out) {
    const polygon = [ringOf(outer.contour)];
    for (const hole of outer.childs) {
      polygon.push(ringOf(hole.contour));
      for (const island of hole.childs) collect(island, out);
    }
    out.push(polygon);
  }

  return {
    run(op, a, b, fillRule = 'evenodd') {
      const tree = clipper.clipToPolyTree({
        clipType: CLIP[op],
        subjectInputs: [{ data: toPaths(a), closed: true }],
        clipInputs: [{ data: toPaths(b) }],
        subjectFillType: FILL[fillRule],
        clipFillType: FILL[fillRule],
      });
      const out = [];
      for (const outer of tree.childs) collect(outer, out);
      return out;
    },
    area: multiPolygonArea,
  };
}

// ---------------------------------------------------------------------------------------------------------------

async function clipper2Ts() {
  const C = await import('clipper2-ts');
  const CLIP = { intersection: C.ClipType.Intersection, union: C.ClipType.Union, difference: C.ClipType.Difference, xor: C.ClipType.Xor };
  const FILL = { evenodd: C.FillRule.EvenOdd, nonzero: C.FillRule.NonZero };

  function toPathsD(polygons) {
    const paths = [];
    for (const polygon of polygons) {
      for (const ring of polygon) {
        const n = openLength(ring);
        const path = new Array(n);
        for (let i = 0; i < n; i++) path[i] = { x: ring[i][0], y: ring[i][1] };
        paths.push(path);
      }
    }
    return paths;
  }

  function ringOf(path) {
    const ring = path.map((p) => [p.x, p.y]);
    return closeRing(ring);
  }

  function collect(outer, out) {
    // As clipper2-wasm's tree: an exterior's children are holes, whose children are exteriors again.
    const polygon = [ringOf(outer.poly)];
    for (let h = 0; h < outer.count; h++) {
      const hole = outer.child(h);
      polygon.push(ringOf(hole.poly));
      for (let k = 0; k < hole.count; k++) collect(hole.child(k), out);
    }
    out.push(polygon);
  }

  return {
    run(op, a, b, fillRule = 'evenodd') {
      const clipper = new C.ClipperD(CLIPPER2_PRECISION);
      clipper.addSubjectPaths(toPathsD(a));
      clipper.addClipPaths(toPathsD(b));
      const tree = new C.PolyTreeD();
      if (!clipper.execute(CLIP[op], FILL[fillRule], tree)) throw new Error('ClipperD.execute failed');
      const out = [];
      for (let i = 0; i < tree.count; i++) collect(tree.child(i), out);
      return out;
    },
    area: multiPolygonArea,
  };
}

async function ishape() {
  const lib = await import('ishape_wasm');
  // The package loads its wasm with fetch() unless given the bytes; Node's fetch takes no file: URLs.
  lib.initSync({ module: readFileSync(join(dirname(require.resolve('ishape_wasm')), 'ishape_wasm_bg.wasm')) });
  const RULE = { intersection: lib.OverlayRule.Intersect, union: lib.OverlayRule.Union, difference: lib.OverlayRule.Difference, xor: lib.OverlayRule.Xor };
  const FILL = { evenodd: lib.FillRule.EvenOdd, nonzero: lib.FillRule.NonZero };
  return {
    run(op, a, b, fillRule = 'evenodd') {
      // Shapes in (polygons of rings; a closing vertex is harmless), shapes out: the outer ring, then its holes,
      // open. `overlay` consumes the Overlay; no free() after it.
      const overlay = lib.Overlay.new_with_subj_and_clip(a, b);
      if (!overlay) throw new Error('Overlay.new_with_subj_and_clip returned nothing');
      const shapes = overlay.overlay(RULE[op], FILL[fillRule]);
      for (const shape of shapes) for (const ring of shape) closeRing(ring);
      return shapes;
    },
    area: multiPolygonArea,
  };
}

// ---------------------------------------------------------------------------------------------------------------

async function martinez() {
  const m = await import('martinez-polygon-clipping');
  const fn = { intersection: m.intersection, union: m.union, difference: m.diff, xor: m.xor };
  return {
    run(op, a, b) {
      const result = fn[op](a, b);
      if (result == null || result.length === 0) return [];
      // A Polygon (rings of positions) comes back when there is one polygon.
      return typeof result[0][0][0] === 'number' ? [result] : result;
    },
    area: multiPolygonArea,
  };
}

async function polygonClipping() {
  const { default: pc } = await import('polygon-clipping');
  return { run: (op, a, b) => pc[op](a, b), area: multiPolygonArea };
}

async function polyclipTs() {
  const pc = await import('polyclip-ts');
  return { run: (op, a, b) => pc[op](a, b), area: multiPolygonArea };
}

const LOADERS = {
  polysweep,
  'polysweep-flat': polysweepFlat,
  'clipper2-wasm': clipper2,
  'js-angusj-clipper': angusjClipper,
  'clipper2-ts': clipper2Ts,
  ishape_wasm: ishape,
  'martinez-polygon-clipping': martinez,
  'polygon-clipping': polygonClipping,
  'polyclip-ts': polyclipTs,
};

export async function loadEngine(name) {
  const load = LOADERS[name];
  if (!load) throw new Error(`unknown engine ${name}`);
  return load();
}
