// Headless Debian Chromium (/usr/bin/chromium) through playwright-core, with a throw-away profile: the one way the
// browser tests start a browser. No network besides 127.0.0.1 is needed.
import { mkdtempSync } from 'node:fs';
import { rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';

/** Starts the browser. `close()` shuts it down and removes its profile. */
export async function launchChromium() {
  const profile = mkdtempSync(path.join(tmpdir(), 'polysweep-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run', '--disable-sync', '--disable-quic'],
  });
  const close = async () => {
    await context.close();
    // Chromium's helper processes may still be writing the profile for a moment after the context has closed.
    await rm(profile, { recursive: true, force: true, maxRetries: 20, retryDelay: 200 });
  };
  return { context, close };
}
