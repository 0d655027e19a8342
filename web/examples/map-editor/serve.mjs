// Serves the built editor (web/examples/map-editor/dist) on 127.0.0.1 with the repository's static server.
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve } from '../../serve.mjs';

const root = fileURLToPath(new URL('./dist/', import.meta.url));
const port = Number(process.env.PORT ?? 8081);
const { origin } = await serve({ root, port });
console.log(`polysweep map editor: ${origin}/  (serving ${path.relative(process.cwd(), root) || '.'}; Ctrl+C stops)`);
