#!/bin/sh
# Writes every fenced code block of one language in a file to its own file,
# so that the build can compile and run the examples the documentation shows.
# Usage: scripts/code_blocks.sh FILE LANG OUTDIR EXT
#   FILE   a Markdown file, or a C header whose top comment holds the blocks
#          (lines starting with " * " have that prefix taken off)
#   LANG   the fence's language: c, cpp or sh
# Writes OUTDIR/<name>-<n>.EXT (n = 1, 2, ... in order; name = FILE's base
# name without its suffix) and prints their paths, one a line.
set -eu
[ $# -eq 4 ] || { echo "usage: code_blocks.sh FILE LANG OUTDIR EXT" >&2; exit 2; }
file=$1 lang=$2 out=$3 ext=$4
name=$(basename "$file" | sed 's/\.[^.]*$//')
mkdir -p "$out"
rm -f "$out/$name"-*."$ext"
awk -v lang="$lang" -v out="$out" -v name="$name" -v ext="$ext" '
    { line = $0; if (FILENAME ~ /\.h$/) sub(/^ \*( |$)/, "", line) }
    inside && line ~ /^```/ { inside = 0; close(path); print path; next }
    inside { print line > path; next }
    line == "```" lang { inside = 1; n++; path = out "/" name "-" n "." ext; printf "" > path }
' "$file"
