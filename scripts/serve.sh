#!/usr/bin/env bash
# Builds the package and serves the playground on http://127.0.0.1:${PORT:-8080}/
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
exec node scripts/static-server.mjs www "${PORT:-8080}"
