#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Validates a SARIF log against the SARIF 2.1.0 JSON schema, offline after the first run.
#
# Usage: validate_sarif.sh LOG.sarif BUILD_DIR
# The schema is not in this repository: it is read from the npm package @microsoft/jest-sarif
# (MIT), pinned to an exact version, fetched once with `npm pack` into BUILD_DIR/sarif-schema.
# The validator is python3-jsonschema (Debian; scripts/install-deps.sh installs it). A missing
# validator, npm or schema is a failure, never a skip.
set -euo pipefail
log=$1 build_dir=$2
package=@microsoft/jest-sarif@1.0.0-beta.0
schema_dir="$build_dir/sarif-schema"
schema="$schema_dir/package/lib/schemas/sarif-2.1.0-rtm.5.json"

if ! python3 -c 'import jsonschema' 2>/dev/null; then
    echo "validate_sarif: python3-jsonschema is missing (run scripts/install-deps.sh)"; exit 1
fi
if [ ! -f "$schema" ]; then
    command -v npm >/dev/null || { echo "validate_sarif: npm is missing"; exit 1; }
    # Fetched into a fresh folder, then renamed into place: cases running at once do not race.
    fetch=$(mktemp -d "$build_dir/sarif-schema.XXXXXX")
    tarball=$(cd "$fetch" && npm pack --silent "$package" | tail -n 1)
    tar -xzf "$fetch/$tarball" -C "$fetch"
    mv -T "$fetch" "$schema_dir" 2>/dev/null || rm -rf "$fetch"
    [ -f "$schema" ] || { echo "validate_sarif: $package has no $schema"; exit 1; }
fi
python3 - "$schema" "$log" <<'PY'
import json, sys
import jsonschema
schema = json.load(open(sys.argv[1]))
log = json.load(open(sys.argv[2]))
errors = sorted(jsonschema.Draft4Validator(schema).iter_errors(log), key=lambda e: e.path)
for error in errors:
    print("validate_sarif: %s at %s" % (error.message, "/".join(map(str, error.path))))
sys.exit(1 if errors else 0)
PY
