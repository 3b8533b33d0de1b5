#!/usr/bin/env bash
# Rewrites the generated blocks of the documents (the README's keys table, docs/cli.md's table
# of --ops verbs and of formats, docs/architecture.md's layer table) from what the code generates now, by
# running the tests that check them and pasting what they print.
# Usage: scripts/update_generated_docs.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
update() {  # update FILE NAME TEST_EXECUTABLE FILTER
    local out
    out=$("$3" --gtest_filter="$4" 2>&1 || true)
    python3 - "$1" "$2" "$out" <<'PY'
import sys
path, name, out = sys.argv[1], sys.argv[2], sys.argv[3]
marker = "<!-- %s:end --> with:\n" % name
if marker not in out:
    sys.exit(0)  # already up to date
new = out.split(marker, 1)[1]
new = new[:new.rindex("|\n") + 2] if "|\n" in new else new
text = open(path).read()
begin, end = "<!-- %s:begin -->\n" % name, "<!-- %s:end -->" % name
i, j = text.index(begin) + len(begin), text.index(end)
open(path, "w").write(text[:i] + new + text[j:])
print("updated", path)
PY
}
update "$root/README.md" keys "$build/tests/viewer/viewer_tests" 'Bindings.ReadmeKeysTableIsGenerated'
update "$root/docs/cli.md" ops "$build/tests/ops_tests" 'OpsLanguage.DocsTableIsGenerated'
update "$root/docs/cli.md" formats "$build/tests/formats_tests" 'FormatTable.DocsTableIsGenerated'
cmake -DROOT="$root" -DLAYERS="$build/layers.cmake" -DWRITE_DOCS=ON -P "$root/tests/check_layers.cmake" |
    sed -n 's/^-- updated /updated /p'
