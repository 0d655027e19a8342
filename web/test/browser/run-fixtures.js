// Runs every shared fixture (tests/fixtures) through the four operations, in the browser: used by plain.html and
// by the Vite app, each passing the operations it imported. The comparison with the expected results happens in
// Node (browser.test.mjs), with the same normaliser as the Node tests.
//
// This file only defines a function: `node --test web/test/` loads every .js file under a `test` directory as a
// test file, and this one must do nothing there.

/**
 * Resolves to `{ [fixture name]: { intersection, union, difference, xor } }`; an operation that throws gives
 * `{ error: message }` in place of its result, so one failure does not hide the others.
 */
export async function runFixtures(operations) {
  const response = await fetch('/fixtures-index.json');
  if (!response.ok) throw new Error(`GET /fixtures-index.json: ${response.status}`);
  const files = await response.json();
  const results = {};
  for (const file of files) {
    const fixtureResponse = await fetch(`/tests/fixtures/${encodeURIComponent(file)}`);
    if (!fixtureResponse.ok) throw new Error(`GET /tests/fixtures/${file}: ${fixtureResponse.status}`);
    const fixture = await fixtureResponse.json();
    const options = { fillRule: fixture.fill_rule };
    const outcome = {};
    for (const name of ['intersection', 'union', 'difference', 'xor']) {
      try {
        outcome[name] = operations[name](fixture.subject, fixture.clipping, options);
      } catch (error) {
        outcome[name] = { error: String(error?.stack ?? error) };
      }
    }
    results[fixture.name] = outcome;
  }
  return results;
}
