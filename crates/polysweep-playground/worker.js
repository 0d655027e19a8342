// The playground's worker (src/background.rs): it loads the playground's own wasm module and runs the jobs the page
// sends, one at a time, answering each with the numbers of what it computed (src/wire.rs), or with the message of
// what went wrong, after which the page runs its jobs itself. web/build-playground.sh copies it beside the module.
import init, { run_job } from './polysweep_playground.js';

const ready = init();

self.onmessage = async ({ data }) => {
  try {
    await ready;
    const answer = run_job(data);
    self.postMessage(answer, [answer.buffer]);
  } catch (error) {
    self.postMessage(String(error?.message ?? error));
  }
};
