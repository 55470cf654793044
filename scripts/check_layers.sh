#!/bin/sh
# check_layers.sh: the include lines must prove the layering
#
#     base  <-  shape  <-  collide  <-  world  <-  ecs
#
# Each file of src/, include/sepax/ and ecs/ belongs to one layer (the table
# below) and may include only headers of its own layer or a lower one. No
# file outside src/ and tests/internal/ (the white-box tests) may include a
# private header of src/. A file of src/ or include/sepax/ missing from the
# table fails the check: give it a layer here. Run from the top of the tree
# (make check-layers). Exits 1 and names each offence.
set -eu

layers='
0 include/sepax/base.h include/sepax/vecmath.h src/core.h src/simd.h src/base.c
1 include/sepax/shape.h src/wide.h src/shape.c src/hull.c
2 include/sepax/collide.h include/sepax/compound.h src/narrow.h src/narrow_sat.h src/narrow_closest.h
2 src/collide_world.h src/query.h src/narrow_point.c
2 src/collide.c src/narrow_core.c src/query.c src/raycast.c src/compound.c src/decompose.c
2 src/distance.c src/distance.h
3 include/sepax/world.h include/sepax/sepax.h src/world_internal.h src/world.c src/world_query.c
3 src/body.c src/body_contacts.c src/body_props.c src/broadphase.c src/contact_solver.c
3 src/island.c src/sensor.c src/world_ccd.c src/aabb_tree.h src/aabb_tree.c
3 src/world_array.h src/world_array.c src/world_body.h src/world_contact.h src/world_broadphase.h
3 src/world_island.h src/world_ccd.h src/world_sensor.h src/contact_math.h src/contact_impact.c
4 ecs/sepax_flecs.h ecs/sepax_flecs.c
'
names='base shape collide world ecs'

layer_of() {
    echo "$layers" | awk -v f="$1" '{ for (i = 2; i <= NF; ++i) if ($i == f) { print $1; exit } }'
}
layer_name() {
    echo "$names" | awk -v n="$1" '{ print $(n + 1) }'
}
# The quoted or angled local includes of $1, one a line.
includes_of() {
    sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]\([^">]*\)[">].*/\1/p' "$1"
}
# The file an include of $2 in $1 names (empty when it is not ours).
resolve() {
    dir=$(dirname "$1")
    case $2 in
    sepax/*) if [ -f "include/$2" ]; then echo "include/$2"; fi ;;
    *) if [ -f "$dir/$2" ]; then echo "$dir/$2"; fi ;;
    esac
}

bad=0
for f in src/*.c src/*.h include/sepax/*.h ecs/*.c ecs/*.h; do
    [ -f "$f" ] || continue
    mine=$(layer_of "$f")
    if [ -z "$mine" ]; then
        echo "check-layers: $f has no layer: add it to scripts/check_layers.sh"
        bad=1
        continue
    fi
    for inc in $(includes_of "$f"); do
        target=$(resolve "$f" "$inc")
        [ -n "$target" ] || continue
        theirs=$(layer_of "$target")
        [ -n "$theirs" ] || continue
        if [ "$theirs" -gt "$mine" ]; then
            echo "check-layers: $f ($(layer_name "$mine")) includes $inc ($(layer_name "$theirs")), a layer above it"
            bad=1
        fi
    done
done

# Private headers: only src/ and tests/internal/ see them.
private=$(cd src && ls *.h)
for f in $(find tests bench fuzz samples ecs include -name '*.[ch]' -o -name '*.cpp' 2>/dev/null | sort); do
    case $f in tests/internal/*) continue ;; esac
    for inc in $(includes_of "$f"); do
        case $inc in
        */src/* | ../src/* | src/*)
            echo "check-layers: $f includes $inc: only tests/internal/ may include src/"
            bad=1
            ;;
        *)
            for p in $private; do
                if [ "$(basename "$inc")" = "$p" ] && [ ! -f "$(dirname "$f")/$inc" ]; then
                    echo "check-layers: $f includes $inc, a private header of src/"
                    bad=1
                fi
            done
            ;;
        esac
    done
done

[ "$bad" -eq 0 ] || exit 1
echo "sepax: the includes respect the layers (base <- shape <- collide <- world <- ecs)"
