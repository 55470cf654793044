#!/bin/sh
# file_map.sh: the map of src/ for a newcomer
#
# Prints each file of src/ with its layer (the table of
# scripts/check_layers.sh, read from there so the two never disagree), its
# line count and its concept (the first line of its header comment), then
# the longest functions of src/ (name, file, first line, lines from the
# signature to the closing brace). Run from the top of the tree (make
# file-map); N=25 sh scripts/file_map.sh lists 25 functions.
set -eu

most=${N:-15}
table=$(sed -n "/^layers='/,/^'/p" scripts/check_layers.sh | sed '1d;$d')
names=$(sed -n "s/^names='\(.*\)'/\1/p" scripts/check_layers.sh)

echo "src/ by layer (base <- shape <- collide <- world):"
printf '  %-8s %-22s %5s  %s\n' layer file lines concept
for f in src/*.c src/*.h; do
    layer=$(echo "$table" | awk -v f="$f" -v names="$names" '
        { for (i = 2; i <= NF; ++i) if ($i == f) { split(names, n, " "); print $1 " " n[$1 + 1]; exit } }')
    [ -n "$layer" ] || layer="? none"
    # the first line of the header comment, without the "/* sepax — " lead
    concept=$(sed -n '1s/^\/\*[[:space:]]*//p' "$f" | sed 's/^sepax[^a-z]*— //')
    printf '%s\t%s\t%s\t%s\n' "$layer" "$f" "$(wc -l <"$f")" "$concept"
done | sort -t "$(printf '\t')" -k1,1n -k2,2 |
    awk -F '\t' '{ printf "  %-8s %-22s %5d  %s\n", substr($1, index($1, " ") + 1), substr($2, 5), $3, $4 }'

echo
echo "the $most longest functions of src/ (lines from the signature to the closing brace):"
printf '  %5s  %-36s %s\n' lines function file:line
# A definition starts at column 0 with a name followed by "(" (not a
# prototype, typedef, macro or initialiser) and ends at the first "}" in
# column 0; the name is the identifier before the first "(".
for f in src/*.c src/*.h; do
    awk -v file="${f#src/}" '
        !body && !sig && /^[A-Za-z_].*\(/ && !/^(typedef|struct|enum|union|extern)/ && !/=/ && !/;[[:space:]]*$/ {
            name = $0
            sub(/\(.*/, "", name)
            sub(/.*[^A-Za-z0-9_]/, "", name)
            start = NR
            sig = 1
        }
        sig && /;[[:space:]]*$/ && !/\{/ { sig = 0; next }
        sig && /\{/ {
            sig = 0
            if (/\}[[:space:]]*$/) next
            body = 1
            next
        }
        body && /^\}/ {
            body = 0
            printf "%d\t%s\t%s:%d\n", NR - start + 1, name, file, start
        }
    ' "$f"
done | sort -t "$(printf '\t')" -k1,1nr -k2,2 | head -n "$most" |
    awk -F '\t' '{ printf "  %5d  %-36s %s\n", $1, $2, $3 }'
