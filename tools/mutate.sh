#!/usr/bin/env bash
# The mutation check (tools/mutate.py): deliberate bugs, one at a time, against the tests that
# should catch them. Slow (a rebuild each); not part of ./test.sh.  tools/mutate.sh [--list] [ID ...]
set -euo pipefail
cd "$(dirname "$0")/.."
exec python3 tools/mutate.py "$@"
