#!/bin/sh
# Provides flecs's amalgamated flecs.c and flecs.h for the flecs module,
# without committing any flecs code. Usage: scripts/fetch_flecs.sh DEST_DIR
#
# With FLECS_DIR set, the user's own copy there is checked and used as is
# (nothing is written). Otherwise the pinned crates.io package flecs_ecs_sys
# (=0.2.1, which ships flecs 4.1.2 as src/flecs.c and src/flecs.h) is fetched
# with cargo through a throwaway Cargo project in DEST_DIR/../flecs-fetch, and
# the two files are unpacked from the downloaded .crate into DEST_DIR. A second
# run finds the files in place and does nothing. Either way the files must be
# flecs 4.x (checked on FLECS_VERSION_MAJOR in flecs.h).
set -eu

FLECS_SYS_VERSION=0.2.1

die() {
    echo "sepax: fetch_flecs: $*" >&2
    exit 1
}

# check_flecs DIR: both files present and flecs.h says major version 4.
check_flecs() {
    [ -f "$1/flecs.c" ] && [ -f "$1/flecs.h" ] || return 1
    major=$(sed -n 's/^#define FLECS_VERSION_MAJOR \([0-9]*\).*/\1/p' "$1/flecs.h" | head -n 1)
    [ "$major" = "4" ]
}

flecs_version() {
    sed -n 's/^#define FLECS_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\).*/\2/p' "$1/flecs.h" | paste -sd.
}

if [ -n "${FLECS_DIR:-}" ]; then
    check_flecs "$FLECS_DIR" ||
        die "FLECS_DIR=$FLECS_DIR must hold flecs.c and flecs.h of flecs 4.x"
    echo "sepax: using flecs $(flecs_version "$FLECS_DIR") from FLECS_DIR=$FLECS_DIR" >&2
    exit 0
fi

[ $# -eq 1 ] || die "usage: fetch_flecs.sh DEST_DIR"
dest=$1
if check_flecs "$dest"; then
    exit 0
fi

command -v cargo >/dev/null 2>&1 ||
    die "cargo is needed to fetch flecs (crates.io package flecs_ecs_sys =$FLECS_SYS_VERSION);" \
        "install Rust's cargo, or set FLECS_DIR to a directory holding flecs 4.x's flecs.c and flecs.h"

fetch=$(dirname "$dest")/flecs-fetch
mkdir -p "$fetch/src" "$dest"
cat >"$fetch/Cargo.toml" <<TOML
[package]
name = "sepax-flecs-fetch"
version = "0.0.0"
edition = "2021"
publish = false

[dependencies]
flecs_ecs_sys = "=$FLECS_SYS_VERSION"
TOML
[ -f "$fetch/src/lib.rs" ] || : >"$fetch/src/lib.rs"

echo "sepax: fetching flecs (crates.io flecs_ecs_sys =$FLECS_SYS_VERSION) with cargo" >&2
(cd "$fetch" && cargo fetch --quiet) || die "cargo fetch failed"

cargo_home=${CARGO_HOME:-$HOME/.cargo}
crate=$(ls "$cargo_home"/registry/cache/*/flecs_ecs_sys-$FLECS_SYS_VERSION.crate 2>/dev/null | head -n 1)
[ -n "$crate" ] && [ -f "$crate" ] || die "flecs_ecs_sys-$FLECS_SYS_VERSION.crate not found under $cargo_home/registry/cache"

tmp="$fetch/unpack"
rm -rf "$tmp"
mkdir -p "$tmp"
tar -xzf "$crate" -C "$tmp" "flecs_ecs_sys-$FLECS_SYS_VERSION/src/flecs.c" \
    "flecs_ecs_sys-$FLECS_SYS_VERSION/src/flecs.h" || die "could not unpack $crate"
cp "$tmp/flecs_ecs_sys-$FLECS_SYS_VERSION/src/flecs.c" "$tmp/flecs_ecs_sys-$FLECS_SYS_VERSION/src/flecs.h" "$dest/"
rm -rf "$tmp"
check_flecs "$dest" || die "the fetched flecs.h is not flecs 4.x"
echo "sepax: flecs $(flecs_version "$dest") is in $dest" >&2
