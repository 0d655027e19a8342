// Types of polysweep/worker: the operations of 'polysweep' in a Web Worker, as promises.
import type { FeatureCollection, MultiPolygon } from 'geojson';
import type {
  ClipLayerOptions,
  FlatMultiPolygon,
  Layer,
  Operand,
  Options,
  clip,
  dissolve,
  overlayLayers,
  split,
  splitAntimeridian,
  trace,
  union,
} from './polysweep.js';

/** What every job's options may add: a signal that aborts it (the promise rejects with an AbortError). */
export interface JobOptions {
  signal?: AbortSignal;
}

/** A function of 'polysweep' as a job of the worker: the same arguments (options may add a signal), a promise. */
type Job<F extends (...args: any[]) => any> = (...args: Parameters<F>) => Promise<ReturnType<F>>;

export interface PolysweepWorker {
  union(geom: Operand, ...more: (Operand | (Options & JobOptions))[]): Promise<ReturnType<typeof union>>;
  intersection(geom: Operand, ...more: (Operand | (Options & JobOptions))[]): Promise<ReturnType<typeof union>>;
  difference(geom: Operand, ...more: (Operand | (Options & JobOptions))[]): Promise<ReturnType<typeof union>>;
  xor(geom: Operand, ...more: (Operand | (Options & JobOptions))[]): Promise<ReturnType<typeof union>>;
  /** The operands' typed arrays are transferred to the worker: the caller's become empty (pass copies to keep them). */
  overlayFlat(
    operation: 'intersection' | 'union' | 'difference' | 'xor',
    operands: FlatMultiPolygon[],
    options?: Pick<Options, 'fillRule'> & JobOptions,
  ): Promise<FlatMultiPolygon>;
  clip: Job<typeof clip>;
  split: Job<typeof split>;
  /** Without `options.properties`: a function cannot go to a worker. */
  overlayLayers: Job<typeof overlayLayers>;
  /** With a property name as key: a function cannot go to a worker. */
  dissolve: Job<typeof dissolve>;
  splitAntimeridian: Job<typeof splitAntimeridian>;
  /** The sweep's steps, computed in the worker (a long trace leaves the page free). */
  trace: Job<typeof trace>;
  /**
   * Each feature of `layer` clipped to `polygon`, as clipLayer of 'polysweep': the layer is read and the result's
   * features built on the calling thread, the clipping done in the worker, batch by batch, with progress.
   */
  clipLayer<P>(layer: Layer<P>, polygon: Operand, options?: ClipLayerOptions & JobOptions): Promise<FeatureCollection<MultiPolygon, P>>;
  /** Stops the worker: jobs not finished are rejected with an AbortError. */
  terminate(): void;
}

/**
 * Starts a worker (a module Worker running the package's worker-script.js; `spawn` makes it yourself, where a
 * bundler needs the URL spelled out). Jobs run one at a time, in the order asked.
 */
export function createWorker(options?: { spawn?: () => Worker }): PolysweepWorker;
