#!/bin/sh
# check_exports.sh LIBSO HEADER...: libsepax.so must export exactly the
# functions the public headers declare, each of them marked SX_API.
#
# The declared list is read from the headers themselves, so it cannot drift:
# a declaration is a line at column 0 outside comments and bodies that is
# not a preprocessor line, static inline, typedef or aggregate, and holds a
# "name(" (clang-format starts every file-scope declaration at column 0 and
# indents everything inside braces or comments). Exits 1 and names the
# difference when the lists disagree.
set -eu
lib=$1
shift
tmp=${TMPDIR:-/tmp}/sx_exports.$$
trap 'rm -f "$tmp".*' EXIT

awk '
    /^[A-Za-z_]/ && !/^(static|typedef|extern|struct|enum|union)[ (]/ && /\(/ {
        line = $0
        sub(/\(.*/, "", line)
        n = split(line, w, /[ *]+/)
        name = w[n]
        if (name !~ /^sx_/) next
        if ($0 !~ /^SX_API /) { print FILENAME ": " name " is declared without SX_API" > "/dev/stderr"; bad = 1 }
        print name
    }
    END { exit bad }
' "$@" | sort -u > "$tmp.declared" || { echo "check-exports: every public declaration needs SX_API"; exit 1; }

# Defined global symbols of the dynamic table; the linker's own markers are
# not the library's.
nm -D --defined-only "$lib" | awk 'NF == 3 && $2 ~ /^[A-Z]$/ { print $3 }' |
    grep -v -x -e _init -e _fini -e __bss_start -e _edata -e _end | sort -u > "$tmp.exported"

if ! cmp -s "$tmp.declared" "$tmp.exported"; then
    echo "check-exports: $lib does not export exactly the public API"
    comm -23 "$tmp.declared" "$tmp.exported" | sed 's/^/  declared, not exported: /'
    comm -13 "$tmp.declared" "$tmp.exported" | sed 's/^/  exported, not declared: /'
    exit 1
fi
echo "sepax: $lib exports exactly the $(wc -l < "$tmp.declared") functions the public headers declare"
