#!/usr/bin/env bash
# doc_block.sh FILE NAME PRODUCER STAMP: replaces the generated block NAME of
# the Markdown file FILE, the lines between
#   <!-- begin NAME: ... -->   and   <!-- end NAME -->
# with standard input, under a line saying which command wrote it and the
# stamp (scripts/stamp.sh) of the measurement. Fails when FILE has no block
# NAME, so that a renamed block is not silently skipped.
set -euo pipefail
file=$1 name=$2 producer=$3 stamp=$4
grep -qx "<!-- begin $name: .* -->" "$file" && grep -qx "<!-- end $name -->" "$file" || {
  echo "doc_block: $file has no block '$name'" >&2
  exit 1
}
body=$(mktemp)
trap 'rm -f "$body" "$body.new"' EXIT
{
  echo "*Written by \`$producer\`: $stamp.*"
  echo
  cat
} > "$body"
awk -v name="$name" -v producer="$producer" -v body="$body" '
  $0 ~ "^<!-- begin " name ": " { print "<!-- begin " name ": written by " producer "; edit the script, not this block -->"
                                   while ((getline line < body) > 0) print line
                                   skip = 1; next }
  $0 == "<!-- end " name " -->" { skip = 0 }
  !skip' "$file" > "$body.new"
mv "$body.new" "$file"
