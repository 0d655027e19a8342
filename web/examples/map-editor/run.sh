#!/usr/bin/env bash
# The map editor example: installs the npm devDependencies, builds the package into pkg/ (web/build.sh), bundles the
# editor with Vite into web/examples/map-editor/dist and serves it on http://127.0.0.1:${PORT:-8081}/.
set -euo pipefail
cd "$(dirname "$0")/../../.."
source web/tools.sh
npm install --no-audit --no-fund
web/build.sh
node_modules/.bin/vite build web/examples/map-editor --logLevel warn
node web/examples/map-editor/serve.mjs
