#!/usr/bin/env python3
"""GEOS engine of the layer-overlay benchmark (web/bench/layers.mjs runs it as a child process).

    python web/bench/layers_geos.py PARCELS.geojson ZONES.geojson [--runs N] [--warmup N]

Reads both FeatureCollections and overlays them the way geopandas.overlay(how='intersection') does it, with shapely
2 (GEOS) directly: an STRtree over the zones, queried with every parcel (predicate 'intersects', GEOS's prepared
geometries), then one vectorised shapely.intersection over the arrays of candidate pairs, keeping the pieces of
positive area. Each run is timed in phases:

    in    shapely.from_geojson of the FeatureCollection text (GEOS's GeoJSON reader) -> arrays of geometries
    core  STRtree build + query + intersection of the candidate pairs + the area filter
    out   shapely.to_geojson of the pieces, wrapped as Features with the two layers' properties -> GeoJSON text

Prints one JSON object to stdout: versions, the timings (ms, per run and per phase), the counts (candidate pairs,
pieces) and, from the last run, the pieces' (parcel index, zone index, area) as parallel lists (GEOS's area).
"""

import argparse
import json
import statistics
import sys
import time

import numpy as np
import shapely


def load(text):
    collection = shapely.from_geojson(text)
    return shapely.get_parts(collection)


def run_once(text_a, text_b, props_a, props_b):
    t0 = time.perf_counter()
    a = load(text_a)
    b = load(text_b)
    t1 = time.perf_counter()

    tree = shapely.STRtree(b)
    ia, ib = tree.query(a, predicate="intersects")  # (parcel index, zone index), sorted by parcel
    candidates = len(ia)
    pieces = shapely.intersection(a[ia], b[ib])
    areas = shapely.area(pieces)
    keep = areas > 0
    ia, ib, pieces, areas = ia[keep], ib[keep], pieces[keep], areas[keep]
    t2 = time.perf_counter()

    geometries = shapely.to_geojson(pieces)
    pa = [json.dumps(p) for p in props_a]
    pb = [json.dumps(p) for p in props_b]
    features = [
        '{"type":"Feature","geometry":%s,"properties":{"a":%s,"b":%s,"aIndex":%d,"bIndex":%d}}'
        % (g, pa[i], pb[j], i, j)
        for g, i, j in zip(geometries.tolist(), ia.tolist(), ib.tolist())
    ]
    out = '{"type":"FeatureCollection","features":[' + ",".join(features) + "]}"
    t3 = time.perf_counter()

    timing = {"in": 1e3 * (t1 - t0), "core": 1e3 * (t2 - t1), "out": 1e3 * (t3 - t2), "total": 1e3 * (t3 - t0)}
    return timing, {
        "count_a": len(a),
        "count_b": len(b),
        "candidates": candidates,
        "pieces": len(pieces),
        "output_bytes": len(out),
        "ia": ia,
        "ib": ib,
        "areas": areas,
        "types": shapely.get_type_id(pieces),
        "invalid_a": int((~shapely.is_valid(a)).sum()),
        "invalid_b": int((~shapely.is_valid(b)).sum()),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("parcels")
    parser.add_argument("zones")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--warmup", type=int, default=1)
    args = parser.parse_args()

    with open(args.parcels, encoding="utf-8") as f:
        text_a = f.read()
    with open(args.zones, encoding="utf-8") as f:
        text_b = f.read()
    props_a = [f.get("properties") for f in json.loads(text_a)["features"]]
    props_b = [f.get("properties") for f in json.loads(text_b)["features"]]

    for _ in range(args.warmup):
        run_once(text_a, text_b, props_a, props_b)
    runs = []
    last = None
    for _ in range(args.runs):
        timing, last = run_once(text_a, text_b, props_a, props_b)
        runs.append(timing)

    def summary(key):
        values = [r[key] for r in runs]
        return {"runs": values, "min": min(values), "median": statistics.median(values)}

    type_names = {3: "Polygon", 6: "MultiPolygon", 7: "GeometryCollection"}
    types, counts = np.unique(last["types"], return_counts=True)
    result = {
        "engine": "geos",
        "python": sys.version.split()[0],
        "shapely": shapely.__version__,
        "geos": shapely.geos_version_string,
        "numpy": np.__version__,
        "runs": args.runs,
        "warmup": args.warmup,
        "ms": {key: summary(key) for key in ("total", "in", "core", "out")},
        "count_a": last["count_a"],
        "count_b": last["count_b"],
        "invalid_a": last["invalid_a"],
        "invalid_b": last["invalid_b"],
        "candidates": last["candidates"],
        "pieces": last["pieces"],
        "piece_types": {type_names.get(int(t), str(int(t))): int(c) for t, c in zip(types, counts)},
        "output_bytes": last["output_bytes"],
        "pairs": {"a": last["ia"].tolist(), "b": last["ib"].tolist(), "area": last["areas"].tolist()},
    }
    json.dump(result, sys.stdout)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
