// Every shared fixture of tests/fixtures (the files the Rust tests read) through the built npm package.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { union, intersection, difference, xor } from 'polysweep';
import { normalise } from './normalise.mjs';

const dir = new URL('../../tests/fixtures/', import.meta.url);
const files = readdirSync(dir).filter((f) => f.endsWith('.json')).sort();
const operations = { intersection, union, difference, xor };

test('the fixtures are there', () => {
  assert.ok(files.length >= 30, `only ${files.length} fixtures`);
});

for (const file of files) {
  const fixture = JSON.parse(readFileSync(new URL(file, dir), 'utf8'));
  for (const [name, operation] of Object.entries(operations)) {
    test(`${fixture.name} / ${name}`, () => {
      const result = operation(fixture.subject, fixture.clipping, { fillRule: fixture.fill_rule });
      assert.deepEqual(normalise(result), normalise(fixture.expected[name]));
      for (const polygon of result) {
        for (const ring of polygon) {
          assert.deepEqual(ring[0], ring[ring.length - 1], 'rings are closed');
        }
      }
    });
  }
}
