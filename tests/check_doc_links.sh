#!/usr/bin/env bash
# The documents' links, checked: every relative link of a tracked Markdown
# file ([text](path), ![alt](path), with an optional #anchor) names a file
# or folder of the repository, and an anchor names a heading of its target
# (GitHub's rule: lower case, punctuation dropped, blanks turned into
# hyphens, a repeated heading numbered -1, -2, ...). Links inside fenced
# code and to other sites are not checked.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
failures=0
complain() { echo "check_doc_links: $*"; failures=$((failures + 1)); }

# the anchors of a Markdown file's headings, one a line
anchors() {
  awk '/^```/ { fence = !fence; next }
       !fence && /^#+ / {
         h = tolower($0); sub(/^#+ +/, "", h)
         gsub(/[^a-z0-9 _-]/, "", h); gsub(/ /, "-", h)
         n = seen[h]++; print (n ? h "-" n : h) }' "$1"
}

while IFS=$'\t' read -r file line target; do
  path=${target%%#*}
  anchor=
  [[ "$target" == *"#"* ]] && anchor=${target#*#}
  if [ -z "$path" ]; then
    resolved=$file
  else
    resolved=$(dirname "$file")/$path
    if [ ! -e "$resolved" ]; then
      complain "$file:$line: $target: no such file"
      continue
    fi
  fi
  if [ -n "$anchor" ]; then
    case "$resolved" in
      *.md) anchors "$resolved" | grep -qxF -- "$anchor" ||
              complain "$file:$line: $target: no heading with that anchor" ;;
      *) complain "$file:$line: $target: an anchor in a file that is not Markdown" ;;
    esac
  fi
done < <(git ls-files '*.md' | while read -r f; do
  awk -v file="$f" '
    /^```/ { fence = !fence; next }
    fence { next }
    { line = $0
      gsub(/`[^`]*`/, "", line)          # inline code is not a link
      while (match(line, /\]\([^) ]+\)/)) {
        target = substr(line, RSTART + 2, RLENGTH - 3)
        line = substr(line, RSTART + RLENGTH)
        if (target !~ /^(https?|mailto|ftp):/) print file "\t" NR "\t" target
      } }' "$f"
done)

if [ "$failures" -ne 0 ]; then
  echo "check_doc_links: $failures broken link(s)"
  exit 1
fi
echo "check_doc_links: every relative link of the documents resolves"
