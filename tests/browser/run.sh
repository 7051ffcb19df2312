#!/usr/bin/env bash
# The browser test of csgray view (view_test.mjs) in Debian's chromium,
# headless. Skipped, with the reason, when chromium or node is missing
# (`make deps` installs chromium, `make test` node and npm); puppeteer-core
# is installed from the npm registry into tests/browser/node_modules the
# first time (npm ci, from package-lock.json), never a browser of its own.
#   run.sh CSGRAY [SCREENSHOTS_DIR]
set -euo pipefail
csgray=$1
here=$(cd "$(dirname "$0")" && pwd)
chromium=${CHROMIUM:-/usr/bin/chromium}
skip() { echo "skipped: $*"; exit 77; }

[ -x "$chromium" ] || skip "no chromium at $chromium (make deps installs Debian's chromium)"
command -v node >/dev/null || skip "no node (make test installs nodejs and npm)"
if [ ! -f "$here/node_modules/puppeteer-core/package.json" ]; then
  command -v npm >/dev/null || skip "no npm to install puppeteer-core (make test installs it)"
  echo "installing puppeteer-core into $here/node_modules"
  # A lock taken by one test run at a time (ctest -j).
  (cd "$here" && PUPPETEER_SKIP_DOWNLOAD=1 flock "$here/package.json" \
    npm ci --no-audit --no-fund --loglevel=error)
fi
export CHROMIUM=$chromium
exec node --test-reporter=spec "$here/view_test.mjs" "$csgray" "${2:-}"
