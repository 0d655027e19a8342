// A static file server for 127.0.0.1 only: `node web/serve.mjs [port]` serves the repository (the playground's
// index.html at its root) and prints the URL; the browser tests import `serve` to do the same on a free port.
import http from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const repositoryRoot = fileURLToPath(new URL('../', import.meta.url));

const CONTENT_TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.wasm': 'application/wasm',
  '.json': 'application/json; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
};

/** Stops a server that `serve` started (or nothing, when none was), dropping open keep-alive connections. */
export async function stopServer(server) {
  if (!server) return;
  server.closeAllConnections();
  await new Promise((resolve) => server.close(resolve));
}

/**
 * Serves `root` at '/', each directory of `mounts` (URL prefix → directory) under its prefix, and each entry of
 * `generated` (URL path → function returning the body) as JSON. Resolves to the running server and its origin.
 */
export async function serve({ root = repositoryRoot, mounts = new Map(), generated = new Map(), port = 0 } = {}) {
  const fileFor = (pathname) => {
    let [base, rest] = [root, pathname];
    for (const [prefix, dir] of mounts) {
      if (pathname.startsWith(prefix)) {
        [base, rest] = [dir, pathname.slice(prefix.length)];
        break;
      }
    }
    const file = path.join(base, rest);
    const inside = path.relative(base, file);
    return inside.startsWith('..') || path.isAbsolute(inside) ? null : file;
  };

  const handle = async (request, response) => {
    const send = (status, body, type = 'text/plain; charset=utf-8') => {
      response.writeHead(status, { 'Content-Type': type, 'Cache-Control': 'no-store' });
      response.end(request.method === 'HEAD' ? undefined : body);
    };
    if (request.method !== 'GET' && request.method !== 'HEAD') return send(405, 'method not allowed');
    let pathname;
    try {
      pathname = decodeURIComponent(new URL(request.url, 'http://localhost').pathname);
    } catch {
      return send(400, 'bad request');
    }
    if (generated.has(pathname)) return send(200, JSON.stringify(generated.get(pathname)()), CONTENT_TYPES['.json']);
    let file = fileFor(pathname);
    if (file === null) return send(403, 'forbidden');
    try {
      if ((await stat(file)).isDirectory()) file = path.join(file, 'index.html');
      return send(200, await readFile(file), CONTENT_TYPES[path.extname(file)] ?? 'application/octet-stream');
    } catch {
      return send(404, `not found: ${pathname}`);
    }
  };

  const server = http.createServer((request, response) => {
    handle(request, response).catch((error) => response.destroy(error));
  });
  await new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', resolve);
  });
  return { server, origin: `http://127.0.0.1:${server.address().port}` };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const port = Number(process.argv[2] ?? process.env.PORT ?? 8080);
  const { origin } = await serve({ port });
  console.log(`polysweep playground: ${origin}/  (Ctrl+C stops the server)`);
}
