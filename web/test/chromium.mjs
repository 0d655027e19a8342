// Headless Debian Chromium (/usr/bin/chromium) through playwright-core, with a throw-away profile: the one way the
// browser tests start a browser and open a test page. No network besides 127.0.0.1 is needed.
import { mkdtempSync } from 'node:fs';
import { rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';

/**
 * Chromium's flags for WebGPU on SwiftShader (its CPU Vulkan), the adapter a machine without a GPU has. Without the
 * Vulkan and ANGLE ones, headless Chromium renders WebGPU canvases but never composites them: screenshots show
 * the page behind.
 */
const WEBGPU = ['--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-vulkan=swiftshader', '--use-angle=swiftshader', '--use-webgpu-adapter=swiftshader'];

/**
 * Starts the browser; with `{ webgpu: true }` with WebGPU (otherwise pages get WebGL2 only). `close()` shuts it
 * down and removes its profile.
 */
export async function launchChromium({ webgpu = false } = {}) {
  const profile = mkdtempSync(path.join(tmpdir(), 'polysweep-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run', '--disable-sync', '--disable-quic', ...(webgpu ? WEBGPU : [])],
  });
  const close = async () => {
    await context.close();
    // Chromium's helper processes may still be writing the profile for a moment after the context has closed.
    await rm(profile, { recursive: true, force: true, maxRetries: 20, retryDelay: 200 });
  };
  return { context, close };
}

/**
 * Opens `url` in a new page of `context` and waits (at most `timeout` ms) until it sets `window.results` or
 * `window.failure`, or until it logs a console error, throws an uncaught error or fails a request. Returns the
 * page's outcome (also `window.lineResults`, which a page sets before its results) with everything it complained
 * about and every URL it requested.
 */
export async function runPage(context, url, timeout) {
  const page = await context.newPage();
  const problems = [];
  const requests = [];
  let complained;
  const complaint = new Promise((resolve) => {
    complained = resolve;
  });
  const problem = (text) => {
    problems.push(text);
    complained();
  };
  const onConsole = (where) => (message) => {
    if (message.type() === 'error') problem(`${where} console.error: ${message.text()}`);
  };
  page.on('console', onConsole('page'));
  page.on('pageerror', (error) => problem(`page error: ${error.stack ?? error.message}`));
  page.on('worker', (worker) => worker.on('console', onConsole('worker')));
  page.on('request', (request) => requests.push(request.url()));
  page.on('requestfailed', (request) => problem(`request failed: ${request.url()}: ${request.failure()?.errorText}`));
  page.on('response', (response) => {
    if (response.status() >= 400) problem(`HTTP ${response.status()}: ${response.url()}`);
  });
  try {
    await page.goto(url);
    const settled = page
      .waitForFunction(() => window.results !== undefined || window.failure !== undefined, null, { timeout })
      .then(() => page.evaluate(() => ({ results: window.results, lineResults: window.lineResults, failure: window.failure })));
    const outcome = await Promise.race([settled, complaint.then(() => ({}))]);
    return { ...outcome, problems, requests };
  } finally {
    await page.close();
  }
}
