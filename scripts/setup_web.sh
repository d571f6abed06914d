#!/usr/bin/env bash
# Installs the locked npm packages of web/ (three, esbuild, playwright-core) into build/npm/.
# The report's replay viewer is bundled with them and tested in Debian's chromium; no browser is downloaded.
# Idempotent and fast: skips npm when build/npm already holds the same lock and its node_modules.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
web="$root/web"
dest="$root/build/npm"

if ! command -v npm >/dev/null 2>&1; then
  echo "setup_web: npm not found; install Debian's nodejs and npm (scripts/setup.sh)" >&2
  exit 1
fi

# The stamp lives inside node_modules (npm ci deletes that first) and is written only after
# npm ci succeeded, so an interrupted install is redone on the next call.
stamp="$dest/node_modules/.crux-package-lock.json"
if [ -f "$stamp" ] && cmp -s "$web/package-lock.json" "$stamp" \
   && cmp -s "$web/package.json" "$dest/package.json"; then
  echo "setup_web: build/npm is up to date"
  exit 0
fi

mkdir -p "$dest"
cp "$web/package.json" "$web/package-lock.json" "$dest/"
echo "setup_web: npm ci in build/npm"
# No browser download: playwright-core has no install step, and chromium comes from Debian.
(cd "$dest" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund)
cp "$web/package-lock.json" "$stamp"
