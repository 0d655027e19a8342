// trace(): the sweep's steps on the paper's Fig. 7 case (tests/fixtures/fig7-sweep-line.json), checked against §3's
// walk-through worked out by hand for its two triangles (the same reasoning as crates/polysweep/tests/trace.rs):
// P = (0,4) (4,0) (8,4) with edges a = (0,4)–(4,0) and c = (0,4)–(8,4); Q = (0,−1) (12,−1) (6,5) with edges
// d = (0,−1)–(12,−1) and e = (0,−1)–(6,5). Inserting a at x = 0 puts it above e, which it crosses at i = (2.5, 1.5):
// both are subdivided, and after c is inserted S holds d, e up to i, a up to i, c (the paper: "S = {q2q3, iq2,
// p1i, p0p1}").
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { trace } from 'polysweep';
import { normalise } from './normalise.mjs';

const fig7 = JSON.parse(readFileSync(new URL('../../tests/fixtures/fig7-sweep-line.json', import.meta.url), 'utf8'));
const subject = { type: 'MultiPolygon', coordinates: fig7.subject };
const clipping = { type: 'MultiPolygon', coordinates: fig7.clipping };
const I = [2.5, 1.5];
const ends = (edge) => [edge.left, edge.right, edge.operand];
const D = [[0, -1], [12, -1], 1];
const E_TO_I = [[0, -1], I, 1];
const A_TO_I = [[0, 4], I, 0];
const C = [[0, 4], [8, 4], 0];

test('trace: S, possibleInter, the flags and the selection on Fig. 7 follow §3', () => {
  const steps = trace('intersection', subject, clipping, { fillRule: 'evenodd' });
  const events = steps.flatMap((step, i) => (step.type === 'event' ? [i] : []));
  assert.equal(events.length, 28, '14 edges after 4 crossings, two events each');
  const during = (k) => steps.slice(events[k] + 1, events[k + 1] ?? steps.length);
  const statusAfter = (k) => {
    const last = during(k).at(-1);
    assert.equal(last.type, 'status');
    return last.edges.map(ends);
  };
  assert.deepEqual(ends(steps[events[2]].edge), [[0, 4], [4, 0], 0], 'a, third');
  const meetings = during(2).filter((s) => s.type === 'meeting');
  assert.deepEqual(meetings.map((m) => [m.meeting, m.at, m.lower.operand, m.upper.operand]), [['crossing', I, 1, 0]]);
  assert.deepEqual(during(2).filter((s) => s.type === 'subdivision').map((s) => s.at), [I, I]);
  assert.deepEqual(statusAfter(2), [D, E_TO_I, A_TO_I]);
  assert.deepEqual(statusAfter(3), [D, E_TO_I, A_TO_I, C]);

  const flagsOf = (edge) => steps.find((s) => s.type === 'flags' && JSON.stringify(ends(s.edge)) === JSON.stringify(edge));
  const { inOut, insideOther, inResult } = flagsOf([I, [4, 0], 0]);
  assert.deepEqual([inOut, insideOther, inResult], [false, true, true], "a's part from i enters S inside Q");
  const selectionOf = (edge) => steps.find((s) => s.type === 'selection' && JSON.stringify(ends(s.edge)) === JSON.stringify(edge));
  assert.deepEqual([selectionOf(E_TO_I).inResult, selectionOf(E_TO_I).reason], [false, 'outside-other']);
  assert.deepEqual([selectionOf([I, [4, 0], 0]).inResult, selectionOf([I, [4, 0], 0]).reason], [true, 'inside-other']);

  const rings = steps.filter((s) => s.type === 'ring');
  assert.equal(rings.length, 1);
  assert.deepEqual(normalise([[rings[0].points]]), normalise(fig7.expected.intersection));
});

test('trace: errors name the operand and vertex, and the library goes on', () => {
  const bad = { type: 'Polygon', coordinates: [[[0, 0], [Number.NaN, 1], [1, 1], [0, 0]]] };
  assert.throws(() => trace('union', subject, bad), (e) => e instanceof RangeError && /operand 1, polygon 0, ring 0, vertex 1/.test(e.message));
  assert.throws(() => trace('nand', subject, clipping), TypeError);
  assert.equal(trace('xor', subject, clipping).filter((s) => s.type === 'ring').length, fig7.expected.xor.length);
});
