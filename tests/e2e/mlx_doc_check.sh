#!/usr/bin/env bash
# docs/mlx-parameters.md is what the filters say now. Usage:
#   mlx_doc_check.sh TOOL PLUGIN_DIR DISPLAY_FILE COMMITTED.md
set -uo pipefail
tool=$1 plugins=$2 committed=$4
export DISPLAY=$(cat "$3")
fresh=$(mktemp --suffix=.md)
trap 'rm -f "$fresh"' EXIT
"$tool" "$plugins" "$fresh" 2>/dev/null || { "$tool" "$plugins" "$fresh"; echo "FAIL: cadlod_mlx_doc failed"; exit 1; }
if ! diff -u "$committed" "$fresh"; then
  echo "FAIL: $committed differs from the filters' parameters: run scripts/make_mlx_doc.sh and commit it"
  exit 1
fi
echo "$committed matches the filters"
