#!/bin/sh
# Provides Box2D v3's C source for the benchmarks, without committing any of
# it. Usage: scripts/fetch_box2d3.sh DEST_DIR
#
# With BOX2D3_DIR set, the user's own copy there (include/box2d/box2d.h and
# src/*.c) is checked and used as is. Otherwise the pinned crates.io package
# boxdd-sys (=0.6.0, which vendors upstream Box2D v3 at revision 56edae7 under
# third-party/box2d/) is fetched with cargo through a throwaway Cargo project
# beside DEST_DIR, and its include/ and src/ are unpacked into DEST_DIR. A
# second run finds them in place and does nothing.
set -eu

BOXDD_SYS_VERSION=0.6.0

die() {
    echo "sepax: fetch_box2d3: $*" >&2
    exit 1
}

# check_box2d3 DIR: the public header, a few sources, and a v3 API (b2World_Step).
check_box2d3() {
    [ -f "$1/include/box2d/box2d.h" ] && [ -f "$1/src/solver.c" ] && [ -f "$1/src/manifold.c" ] ||
        return 1
    grep -q 'b2World_Step' "$1/include/box2d/box2d.h"
}

if [ -n "${BOX2D3_DIR:-}" ]; then
    check_box2d3 "$BOX2D3_DIR" ||
        die "BOX2D3_DIR=$BOX2D3_DIR must hold Box2D v3's include/box2d/box2d.h and src/*.c"
    exit 0
fi

[ $# -eq 1 ] || die "usage: fetch_box2d3.sh DEST_DIR"
dest=$1
if check_box2d3 "$dest"; then
    exit 0
fi

command -v cargo >/dev/null 2>&1 ||
    die "cargo is needed to fetch Box2D v3 (crates.io package boxdd-sys =$BOXDD_SYS_VERSION);" \
        "install Rust's cargo, or set BOX2D3_DIR to a Box2D v3 source tree"

fetch=$(dirname "$dest")/box2d3-fetch
mkdir -p "$fetch/src"
cat >"$fetch/Cargo.toml" <<TOML
[package]
name = "sepax-box2d3-fetch"
version = "0.0.0"
edition = "2021"
publish = false

[dependencies]
boxdd-sys = "=$BOXDD_SYS_VERSION"
TOML
[ -f "$fetch/src/lib.rs" ] || : >"$fetch/src/lib.rs"

echo "sepax: fetching Box2D v3 (crates.io boxdd-sys =$BOXDD_SYS_VERSION) with cargo" >&2
(cd "$fetch" && cargo fetch --quiet) || die "cargo fetch failed"

cargo_home=${CARGO_HOME:-$HOME/.cargo}
crate=$(ls "$cargo_home"/registry/cache/*/boxdd-sys-$BOXDD_SYS_VERSION.crate 2>/dev/null | head -n 1)
[ -n "$crate" ] && [ -f "$crate" ] || die "boxdd-sys-$BOXDD_SYS_VERSION.crate not found under $cargo_home/registry/cache"

tmp="$fetch/unpack"
rm -rf "$tmp"
mkdir -p "$tmp"
tar -xzf "$crate" -C "$tmp" "boxdd-sys-$BOXDD_SYS_VERSION/third-party/box2d" ||
    die "could not unpack $crate"
rm -rf "$dest"
mkdir -p "$(dirname "$dest")"
mv "$tmp/boxdd-sys-$BOXDD_SYS_VERSION/third-party/box2d" "$dest"
rm -rf "$tmp"
check_box2d3 "$dest" || die "the fetched tree is not Box2D v3"
echo "sepax: Box2D v3 source is in $dest" >&2
